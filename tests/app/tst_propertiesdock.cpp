// The Properties dock shows exactly the fields a light's type and models use, for every combination of
// type × falloff model × cone model; edits apply to every selected light as one undo step; invalid input
// is refused with a reason and never stored.
#include "app/colorbutton.h"
#include "app/numberedit.h"
#include "app/propertiesdock.h"
#include "app/propertyfields.h"
#include "app/vec3edit.h"
#include "editor/document.h"

#include <QApplication>
#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QSet>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>

using namespace lr;

namespace {

// The rule of the rig format (issue: "only the fields a light's type and models use"), written out here
// independently of the dock's own propertyShown().
QSet<QString> expectedFields(LightType type, FalloffModel falloff, ConeModel cone, bool shadowOn = false) {
    QSet<QString> f{"name", "group", "type", "enabled", "color", "temperature", "intensity"};
    const bool positioned = type == LightType::Point || type == LightType::Spot;
    const bool area = type == LightType::Rect || type == LightType::Disk; // issue 16
    if (area) f += {"position", "areaRoll", "areaTwoSided"};
    if (type == LightType::Rect)
        f += {"areaWidth", "areaHeight", "barnDoors"}; // issue 39: angle, length when on
    if (type == LightType::Disk) f += "areaRadius";
    if (positioned) {
        f += {"position", "falloffModel", "iesFile"}; // issue 39: the profile's rows while it has one
        switch (falloff) {
        case FalloffModel::None:
            break;
        case FalloffModel::RangePower:
            f += {"falloffRange", "falloffExponent"};
            break;
        case FalloffModel::InversePolynomial:
            f += {"falloffConstant", "falloffLinear", "falloffQuadratic", "falloffRange"};
            break;
        case FalloffModel::RangeQuadratic:
            f.insert("falloffRange");
            break;
        case FalloffModel::InverseSquare:
            f.insert("falloffRange");
            break;
        }
    }
    if (type != LightType::Point) f += "direction";
    if (type == LightType::Spot) {
        f += {"coneModel", "goboFile"}; // issue 39: scale and rotation only once it has a gobo
        switch (cone) {
        case ConeModel::AnglePower:
            f += {"coneOuter", "coneExponent"};
            break;
        case ConeModel::Smooth:
            f += {"coneInner", "coneOuter", "coneExponent"};
            break;
        case ConeModel::Hard:
            f.insert("coneOuter");
            break;
        }
    }
    if (type == LightType::Rim)
        f += "rimExponent";
    else
        f += {"diffuse", "specular", "ambient"};
    // Issue 14: every type but rim casts; the shadow's details only while it is on, with the emitter's
    // extent as a size (positioned lights) or an angle (directional).
    if (type != LightType::Rim) f += "shadowEnabled";
    if (type != LightType::Rim && shadowOn) {
        f += {"shadowResolution", "shadowBias", "shadowNormalOffset"};
        if (!area) f += positioned ? "shadowSize" : "shadowAngle"; // an area light's own size softens
    }
    return f;
}

const QStringList kAllFields{"name",
                             "group",
                             "type",
                             "enabled",
                             "color",
                             "temperature",
                             "intensity",
                             "position",
                             "direction",
                             "falloffModel",
                             "falloffRange",
                             "falloffExponent",
                             "falloffConstant",
                             "falloffLinear",
                             "falloffQuadratic",
                             "coneModel",
                             "coneInner",
                             "coneOuter",
                             "coneExponent",
                             "diffuse",
                             "specular",
                             "ambient",
                             "rimExponent",
                             "shadowEnabled",
                             "shadowResolution",
                             "shadowBias",
                             "shadowNormalOffset",
                             "shadowSize",
                             "shadowAngle",
                             "areaWidth",
                             "areaHeight",
                             "areaRadius",
                             "areaRoll",
                             "areaTwoSided",
                             "goboFile",
                             "goboScale",
                             "goboRotation",
                             "barnDoors",
                             "barnDoorAngle",
                             "barnDoorLength",
                             "iesFile",
                             "iesMultiplier",
                             "iesLevel",
                             "iesRotation",
                             "iesNadir"};

QSet<QString> visibleFields(PropertiesDock& dock) {
    QSet<QString> out;
    for (const QString& name : kAllFields) {
        auto* w = dock.findChild<QWidget*>(name);
        if (!w) qFatal("no field widget %s", qPrintable(name));
        if (w->isVisibleTo(&dock)) out.insert(name);
    }
    return out;
}

QString describe(const QSet<QString>& s) {
    QStringList l(s.begin(), s.end());
    l.sort();
    return l.join(QLatin1Char(' '));
}

} // namespace

class TestPropertiesDock : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void everyField_hasAWidget() {
        Document doc;
        PropertiesDock dock(&doc);
        for (LightProperty p : propertyRows())
            QVERIFY2(dock.field(p), qPrintable(propertyFieldName(p)));
        QCOMPARE(propertyRows().size(), kAllFields.size());
    }

    void showsExactlyTheUsedFields() {
        Document doc;
        PropertiesDock dock(&doc);
        int combinations = 0;
        for (int t = 0; t < enumCount<LightType>(); ++t) {
            const auto type = LightType(t);
            const bool positioned = type == LightType::Point || type == LightType::Spot;
            for (int fm = 0; fm < enumCount<FalloffModel>(); ++fm) {
                if (!positioned && fm > 0) continue; // no falloff: one combination
                for (int cm = 0; cm < enumCount<ConeModel>(); ++cm) {
                    if (type != LightType::Spot && cm > 0) continue;
                    QVERIFY(doc.addLight(type));
                    const int row = doc.lightCount() - 1;
                    QString error;
                    if (positioned)
                        QVERIFY2(doc.setLightValue({row}, LightProperty::FalloffModel,
                                                   toString(FalloffModel(fm)), &error),
                                 qPrintable(error));
                    if (type == LightType::Spot)
                        QVERIFY2(doc.setLightValue({row}, LightProperty::ConeModel, toString(ConeModel(cm)),
                                                   &error),
                                 qPrintable(error));
                    doc.setSelectedRows({row}, row);
                    const Light& l = doc.light(row);
                    const QSet<QString> want = expectedFields(l.type, l.falloff.model, l.cone.model);
                    const QSet<QString> got = visibleFields(dock);
                    QVERIFY2(got == want,
                             qPrintable(QStringLiteral("%1/%2/%3: shown [%4], expected [%5]")
                                            .arg(toString(type), toString(FalloffModel(fm)),
                                                 toString(ConeModel(cm)), describe(got), describe(want))));
                    if (l.castsShadows()) { // the same light with its shadow on, then off again
                        QVERIFY2(doc.setLightValue({row}, LightProperty::ShadowEnabled, true, &error),
                                 qPrintable(error));
                        const QSet<QString> on = visibleFields(dock);
                        const QSet<QString> wantOn =
                            expectedFields(l.type, l.falloff.model, l.cone.model, true);
                        QVERIFY2(on == wantOn,
                                 qPrintable(QStringLiteral("%1 with its shadow: shown [%2], "
                                                           "expected [%3]")
                                                .arg(toString(type), describe(on), describe(wantOn))));
                        QVERIFY(doc.setLightValue({row}, LightProperty::ShadowEnabled, false));
                    }
                    ++combinations;
                }
            }
        }
        QCOMPARE(combinations, 5 * 3 + 5 + 1 + 1 + 2); // spot, point, directional, rim, rect and disk
    }

    void switchingModels_showsAndHidesFields() {
        Document doc;
        PropertiesDock dock(&doc);
        QVERIFY(doc.addLight(LightType::Spot));
        doc.setSelectedRows({0}, 0);
        QVERIFY(doc.setLightValue({0}, LightProperty::ConeModel, QStringLiteral("hard")));
        QVERIFY(!dock.field(LightProperty::ConeInner)->isVisibleTo(&dock));
        QVERIFY(doc.setLightValue({0}, LightProperty::ConeModel, QStringLiteral("smooth")));
        QVERIFY(dock.field(LightProperty::ConeInner)->isVisibleTo(&dock));
        // Undo hides it again: the dock follows the document, not its own state.
        doc.undoStack()->undo();
        QVERIFY(!dock.field(LightProperty::ConeInner)->isVisibleTo(&dock));
    }

    void noSelection_showsNoFields() {
        Document doc;
        PropertiesDock dock(&doc);
        QVERIFY(doc.addLight(LightType::Point));
        doc.setSelectedRows({});
        QVERIFY(visibleFields(dock).isEmpty());
    }

    void multiSelection_showsCommonFields_andEditsAllInOneStep() {
        Document doc;
        PropertiesDock dock(&doc);
        dock.show();
        QVERIFY(doc.addLight(LightType::Point));
        QVERIFY(doc.addLight(LightType::Spot));
        doc.setSelectedRows({0, 1}, 1);
        const QSet<QString> got = visibleFields(dock);
        QVERIFY(got.contains("position"));
        QVERIFY(!got.contains("direction")); // the point light has none
        QVERIFY(!got.contains("coneModel"));
        QVERIFY(!dock.field(LightProperty::Name)->isEnabled()); // one name per light

        auto* intensity = dock.findChild<QWidget*>("intensity")->findChild<NumberEdit*>();
        QVERIFY(intensity);
        const int before = doc.undoStack()->count();
        intensity->setFocus();
        intensity->selectAll();
        QTest::keyClicks(intensity, "7.5");
        QTest::keyClick(intensity, Qt::Key_Return);
        QCOMPARE(doc.light(0).intensity, 7.5);
        QCOMPARE(doc.light(1).intensity, 7.5);
        QCOMPARE(doc.undoStack()->count(), before + 1);
        doc.undoStack()->undo();
        QVERIFY(doc.light(0).intensity != 7.5 && doc.light(1).intensity != 7.5);
    }

    // Issue 37: a group typed once with three lights selected puts all three in it (one step); lights in
    // different groups show none, and leaving the field untouched changes nothing; a light without a group
    // shows its own group's name as the placeholder.
    void group_isSetOnSeveralLightsAtOnce() {
        Document doc;
        PropertiesDock dock(&doc);
        dock.show();
        for (int i = 0; i < 4; ++i)
            QVERIFY(doc.addLight(LightType::Point));
        doc.setSelectedRows({0}, 0);
        auto* group = qobject_cast<QLineEdit*>(dock.field(LightProperty::Group));
        QVERIFY(group && group->isEnabled());
        QCOMPARE(group->placeholderText(), doc.light(0).name);
        doc.setSelectedRows({0, 1, 3}, 1);
        QVERIFY(group->isEnabled()); // not one value per light, unlike the name
        const int before = doc.undoStack()->count();
        group->setFocus();
        QTest::keyClicks(group, "key");
        QTest::keyClick(group, Qt::Key_Return);
        for (int r : {0, 1, 3})
            QCOMPARE(doc.light(r).group, QStringLiteral("key"));
        QVERIFY(doc.light(2).group.isEmpty());
        QCOMPARE(doc.undoStack()->count(), before + 1);
        // Different groups: blank; focus in and out without typing edits nothing.
        doc.setSelectedRows({1, 2}, 1);
        QVERIFY(group->text().isEmpty());
        QCOMPARE(group->placeholderText(), QStringLiteral("(several values)"));
        emit group->editingFinished(); // what leaving the field untouched sends
        QCOMPARE(doc.undoStack()->count(), before + 1);
        QCOMPARE(doc.light(1).group, QStringLiteral("key"));
        QVERIFY(doc.light(2).group.isEmpty());
        doc.undoStack()->undo();
        for (int r : {0, 1, 3})
            QVERIFY(doc.light(r).group.isEmpty());
    }

    // Issue 41: no intensity showed its unit; a disabled Temperature field showed another light's value.
    void intensityShowsItsUnit() {
        Document doc;
        PropertiesDock dock(&doc);
        dock.show();
        QVERIFY(doc.setRigValue(RigProperty::ShadingModel, QStringLiteral("pbr")));
        const std::pair<LightType, const char*> units[] = {
            {LightType::Point, " cd"},  {LightType::Spot, " cd"},   {LightType::Directional, " lx"},
            {LightType::Rect, " nits"}, {LightType::Disk, " nits"}, {LightType::Rim, " (classic)"}};
        for (const auto& [type, unit] : units)
            QVERIFY(doc.addLight(type));
        auto* intensity = dock.findChild<QWidget*>("intensity")->findChild<NumberEdit*>();
        QVERIFY(intensity);
        for (int row = 0; row < int(std::size(units)); ++row) {
            doc.setSelectedRows({row}, row);
            QCOMPARE(intensity->suffix(), QString::fromUtf8(units[row].second));
            QVERIFY2(intensity->text().endsWith(QString::fromUtf8(units[row].second)),
                     qPrintable(intensity->text()));
        }
        doc.setSelectedRows({2, 3}, 2); // lux and nits: no one unit
        QCOMPARE(intensity->suffix(), QString());
        doc.setSelectedRows({0, 1}, 0);
        QCOMPARE(intensity->suffix(), QStringLiteral(" cd"));
        QVERIFY(doc.setRigValue(RigProperty::ShadingModel, QStringLiteral("classic")));
        QCOMPARE(intensity->suffix(), QStringLiteral(" (classic)"));
    }

    void temperatureFieldIsItsLightsOwn() {
        Document doc;
        PropertiesDock dock(&doc);
        dock.show();
        QVERIFY(doc.addLight(LightType::Point));
        QVERIFY(doc.addLight(LightType::Spot));
        // Light 0 has 3000 K, light 1 none: its disabled field is blank, not 3000.
        QVERIFY(doc.setLightValue({0}, LightProperty::Temperature, 3000.0));
        auto* temperature = dock.findChild<QWidget*>("temperature")->findChild<NumberEdit*>();
        QVERIFY(temperature);
        doc.setSelectedRows({0}, 0);
        QVERIFY2(temperature->text().contains(QLatin1String("3000")), qPrintable(temperature->text()));
        doc.setSelectedRows({1}, 1);
        QVERIFY(!temperature->isEnabled());
        QVERIFY2(temperature->text().trimmed().isEmpty(), qPrintable(temperature->text()));
        // Switching it on offers the row's initial value, not the other light's.
        auto* has = dock.findChild<QWidget*>("temperature")->findChild<QCheckBox*>();
        QVERIFY(has);
        has->click();
        QCOMPARE(doc.light(1).temperature.value_or(0.0), propertyField(LightProperty::Temperature).initial);
        QVERIFY(temperature->isEnabled() && temperature->text().contains(QLatin1String(" K")));
    }

    // Issue 41: colour fields showed linear values and the colour dialog sRGB hex, neither labelled.
    void colourFieldsSayLinear_theDialogSaysSrgb() {
        ColorButton button;
        button.setColor(glm::dvec3(1.0, 0.5, 0.25));
        QVERIFY2(button.text().startsWith(QLatin1String("linear ")), qPrintable(button.text()));
        QVERIFY2(button.toolTip().contains(ColorButton::toDisplay(glm::dvec3(1.0, 0.5, 0.25)).name()),
                 qPrintable(button.toolTip()));
        QString title;
        QTimer::singleShot(0, [&] {
            if (auto* d = qobject_cast<QColorDialog*>(QApplication::activeModalWidget())) {
                title = d->windowTitle();
                d->reject();
            }
        });
        button.click();
        QVERIFY2(title.contains(QLatin1String("sRGB")) && title.contains(QLatin1String("linear")),
                 qPrintable(title));
    }

    // Issue 11: typing x, y and z of a position made three "Change position" steps; one edit of a vector
    // field is one step, however long the user pauses between the components.
    void vectorEdit_isOneStep() {
        Document doc;
        PropertiesDock dock(&doc);
        dock.show();
        dock.activateWindow(); // no window manager under Xvfb: ask for focus directly
        QVERIFY(QTest::qWaitForWindowActive(&dock));
        QVERIFY(doc.addLight(LightType::Point));
        doc.setSelectedRows({0}, 0);
        auto* position = qobject_cast<Vec3Edit*>(dock.field(LightProperty::Position));
        QVERIFY(position);
        const glm::dvec3 start = doc.light(0).position;
        const glm::dvec3 typed(1.5, -2.25, 3.0);
        const int before = doc.undoStack()->count();
        position->component(0)->setFocus();
        for (int axis = 0; axis < 3; ++axis) {
            NumberEdit* e = position->component(axis);
            QTRY_VERIFY(e->hasFocus());
            e->selectAll();
            QTest::keyClicks(e, QByteArray::number(typed[axis]));
            if (axis == 1) QTest::qWait(1300); // longer than the dock's pause that ends other gestures
            if (axis < 2) QTest::keyClick(e, Qt::Key_Tab);
        }
        dock.field(LightProperty::Name)->setFocus(); // leave the vector
        QTRY_VERIFY(dock.field(LightProperty::Name)->hasFocus());
        QCOMPARE(doc.light(0).position, typed);
        QCOMPARE(doc.undoStack()->count(), before + 1);
        QCOMPARE(doc.undoStack()->text(before), QStringLiteral("Change position of Point"));
        // The next edit of the vector, after leaving it, is a step of its own.
        position->component(2)->setFocus();
        QTRY_VERIFY(position->component(2)->hasFocus());
        position->component(2)->selectAll();
        QTest::keyClicks(position->component(2), "4");
        dock.field(LightProperty::Name)->setFocus();
        QTRY_COMPARE(doc.light(0).position.z, 4.0);
        QCOMPARE(doc.undoStack()->count(), before + 2);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(doc.light(0).position, start);
    }

    void spinSteps_mergeIntoOneStep() {
        Document doc;
        PropertiesDock dock(&doc);
        dock.show();
        QVERIFY(doc.addLight(LightType::Spot));
        doc.setSelectedRows({0}, 0);
        auto* outer = qobject_cast<NumberEdit*>(dock.field(LightProperty::ConeOuter));
        QVERIFY(outer);
        const double start = doc.light(0).cone.outer;
        const int before = doc.undoStack()->count();
        outer->setFocus();
        for (int i = 0; i < 5; ++i)
            QTest::keyClick(outer, Qt::Key_Up);
        QTest::keyClick(outer, Qt::Key_Return); // editingFinished ends the gesture
        QVERIFY(doc.light(0).cone.outer > start);
        QCOMPARE(doc.undoStack()->count(), before + 1);
        doc.undoStack()->undo();
        QCOMPARE(doc.light(0).cone.outer, start);
    }

    // Issue 14: the shadow rows come from the property table by themselves: the checkbox shows the details,
    // a resolution that is not a power of two is refused with the rule, a valid one is one undo step.
    // Issue 39: the profile's rows show while a light has one, with the profile's peak and beam angle below
    // the file, or the reader's reason.
    void iesProfile_showsItsRowsAndItsPeak() {
        Document doc;
        PropertiesDock dock(&doc);
        dock.show();
        QVERIFY(doc.addLight(LightType::Point));
        doc.setSelectedRows({0}, 0);
        QVERIFY(dock.field(LightProperty::IesFile)->isVisibleTo(&dock));
        QVERIFY(!dock.field(LightProperty::IesMultiplier)->isVisibleTo(&dock));
        auto* summary = dock.findChild<QLabel*>(QStringLiteral("iesSummary"));
        QVERIFY(summary && !summary->isVisibleTo(&dock));
        QVERIFY(doc.setLightValue({0}, LightProperty::IesFile,
                                  QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies")));
        for (LightProperty p :
             {LightProperty::IesMultiplier, LightProperty::IesLevel, LightProperty::IesRotation,
              LightProperty::IesNadir}) // a point light's nadir too (a spot's is its Direction row)
            QVERIFY2(dock.field(p)->isVisibleTo(&dock), qPrintable(propertyFieldName(p)));
        QVERIFY(summary->isVisibleTo(&dock));
        QVERIFY2(summary->text().startsWith(QStringLiteral("Peak 1500 cd, beam ")),
                 qPrintable(summary->text()));
        QVERIFY(doc.setLightValue({0}, LightProperty::IesFile,
                                  QStringLiteral(LIGHTRIG_TEST_DATA "/ies/truncated.ies")));
        QVERIFY2(summary->text().contains(QStringLiteral("truncated.ies:9: ")), qPrintable(summary->text()));
    }

    void shadowFields_showWhenOn() {
        Document doc;
        PropertiesDock dock(&doc);
        dock.show();
        QVERIFY(doc.addLight(LightType::Directional));
        doc.setSelectedRows({0}, 0);
        auto* on = qobject_cast<QCheckBox*>(dock.field(LightProperty::ShadowEnabled));
        QVERIFY(on && on->isVisibleTo(&dock) && !on->isChecked());
        QVERIFY(!dock.field(LightProperty::ShadowResolution)->isVisibleTo(&dock));
        const int steps = doc.undoStack()->count();
        on->click();
        QVERIFY(doc.light(0).shadow.enabled);
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        for (LightProperty p : {LightProperty::ShadowResolution, LightProperty::ShadowBias,
                                LightProperty::ShadowNormalOffset, LightProperty::ShadowAngle})
            QVERIFY2(dock.field(p)->isVisibleTo(&dock), qPrintable(propertyFieldName(p)));
        QVERIFY(
            !dock.field(LightProperty::ShadowSize)->isVisibleTo(&dock)); // a size is for positioned lights

        // The resolution offers exactly the format's values (a spin box would step to 1025).
        auto* resolution = qobject_cast<QComboBox*>(dock.field(LightProperty::ShadowResolution));
        QVERIFY(resolution);
        QStringList offered;
        for (int i = 0; i < resolution->count(); ++i) {
            offered << resolution->itemText(i);
            QVERIFY(validateLightValue(LightProperty::ShadowResolution, resolution->itemData(i)).isEmpty());
        }
        QCOMPARE(offered,
                 (QStringList{"256 texels", "512 texels", "1024 texels", "2048 texels", "4096 texels"}));
        QCOMPARE(resolution->currentText(), QStringLiteral("1024 texels"));
        resolution->setCurrentIndex(3);
        emit resolution->activated(3);
        QCOMPARE(doc.light(0).shadow.resolution, 2048);
        QCOMPARE(doc.undoStack()->count(), steps + 2);
        doc.undoStack()->undo();
        QCOMPARE(resolution->currentText(), QStringLiteral("1024 texels")); // follows the document
        doc.undoStack()->redo();
        QCOMPARE(resolution->currentText(), QStringLiteral("2048 texels"));
        // A bias out of the format's range is refused in place.
        auto* bias = qobject_cast<NumberEdit*>(dock.field(LightProperty::ShadowBias));
        QVERIFY(bias);
        QSignalSpy rejected(bias, &NumberEdit::rejected);
        bias->setFocus();
        bias->selectAll();
        QTest::keyClicks(bias, "17");
        QTest::keyClick(bias, Qt::Key_Return);
        QVERIFY(rejected.count() > 0);
        QCOMPARE(doc.light(0).shadow.bias, 1.0);

        // Undo the switch: the details hide again, the dock following the document.
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(!on->isChecked());
        QVERIFY(!dock.field(LightProperty::ShadowBias)->isVisibleTo(&dock));

        // A 17th caster is refused with the limit; the box shows the stored state again.
        for (int i = 0; i < kMaxShadowCasters; ++i)
            QVERIFY(doc.addLight(LightType::Spot));
        QList<int> spots;
        for (int i = 1; i <= kMaxShadowCasters; ++i)
            spots << i;
        QVERIFY(doc.setLightValue(spots, LightProperty::ShadowEnabled, true));
        doc.setSelectedRows({0}, 0);
        on->click();
        QVERIFY(!doc.light(0).shadow.enabled);
        QVERIFY(!on->isChecked());
        QVERIFY2(dock.message().contains(QLatin1String("at most 16")), qPrintable(dock.message()));
    }

    void invalidInput_isRefusedWithAReason() {
        Document doc;
        PropertiesDock dock(&doc);
        dock.show();
        QVERIFY(doc.addLight(LightType::Spot));
        doc.setSelectedRows({0}, 0);
        const QByteArray before = QByteArray::number(doc.light(0).cone.outer);
        const int steps = doc.undoStack()->index();

        // Out of the format's range (0 < outer <= 90): the keystroke is refused in place.
        auto* outer = qobject_cast<NumberEdit*>(dock.field(LightProperty::ConeOuter));
        QSignalSpy rejected(outer, &NumberEdit::rejected);
        outer->setFocus();
        outer->selectAll();
        QTest::keyClicks(outer, "95");
        QTest::keyClick(outer, Qt::Key_Return);
        QVERIFY(rejected.count() > 0);
        const QString reason = rejected.last().at(0).toString();
        QVERIFY2(reason.contains(QLatin1String("90")), qPrintable(reason)); // states the rule
        QVERIFY(!dock.message().isEmpty());
        QCOMPARE(QByteArray::number(doc.light(0).cone.outer), before);
        // A valid angle typed into the same (degree-suffixed) field is stored.
        outer->selectAll();
        QTest::keyClicks(outer, "50");
        QTest::keyClick(outer, Qt::Key_Return);
        QCOMPARE(doc.light(0).cone.outer, 50.0);
        doc.undoStack()->undo();

        // In range on its own but inconsistent with the light (inner > outer): refused by the document.
        auto* inner = qobject_cast<NumberEdit*>(dock.field(LightProperty::ConeInner));
        inner->setFocus();
        inner->selectAll();
        QTest::keyClicks(inner, QByteArray::number(doc.light(0).cone.outer + 10.0));
        QTest::keyClick(inner, Qt::Key_Return);
        QVERIFY(doc.light(0).cone.inner <= doc.light(0).cone.outer);
        QVERIFY(dock.message().contains(QLatin1String("inner"), Qt::CaseInsensitive) ||
                dock.message().contains(QLatin1String("outer"), Qt::CaseInsensitive));
        QCOMPARE(doc.undoStack()->index(), steps);
        QCOMPARE(inner->value(), doc.light(0).cone.inner); // the field shows the stored value again

        // Not a number at all.
        auto* range = dock.field(LightProperty::FalloffRange)->findChild<NumberEdit*>();
        range->setFocus();
        range->selectAll();
        QTest::keyClicks(range, "abc");
        QVERIFY(!range->text().contains(QLatin1String("abc")));
    }
};

QTEST_MAIN(TestPropertiesDock)
#include "tst_propertiesdock.moc"
