// The value commands: do, undo, redo of every light and rig value restore the exact rig (serialised bytes);
// several values and lights in one step; merging of continuous edits; invalid values refused with a reason
// and nothing stored; commands keyed on light ids, with texts from the property table. Adding, removing,
// moving and renaming lights: tst_listcommands.
#include "editor/commands.h"
#include "rigfixture.h"

#include <QSignalSpy>
#include <QTest>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

using namespace lr;
using lrtest::bytes;
using lrtest::checkDoUndoRedo;

Q_DECLARE_METATYPE(lr::LightProperty)
Q_DECLARE_METATYPE(lr::RigProperty)

class TestCommands : public QObject {
    Q_OBJECT
  private slots:
    void changeLightValue_data() {
        QTest::addColumn<int>("row");
        QTest::addColumn<LightProperty>("property");
        QTest::addColumn<QVariant>("value");
        const auto v3 = [](double x, double y, double z) { return QVariant::fromValue(glm::dvec3(x, y, z)); };
        QTest::newRow("name") << 0 << LightProperty::Name << QVariant(QStringLiteral("Key"));
        QTest::newRow("group") << 0 << LightProperty::Group << QVariant(QStringLiteral("key"));
        QTest::newRow("type point->spot") << 0 << LightProperty::Type << QVariant::fromValue(LightType::Spot);
        QTest::newRow("type by name") << 2 << LightProperty::Type << QVariant(QStringLiteral("rim"));
        QTest::newRow("enabled") << 1 << LightProperty::Enabled << QVariant(false);
        QTest::newRow("colour") << 1 << LightProperty::Color << v3(15, 0, 0);
        QTest::newRow("colour from QColor") << 1 << LightProperty::Color << QVariant(QColor(255, 128, 0));
        QTest::newRow("intensity") << 2 << LightProperty::Intensity << QVariant(4.5);
        QTest::newRow("temperature") << 0 << LightProperty::Temperature << QVariant(3200.0);
        QTest::newRow("position") << 0 << LightProperty::Position << v3(-3, 1, 1);
        QTest::newRow("direction") << 2 << LightProperty::Direction << v3(0, -2, 0.5);
        QTest::newRow("falloff model")
            << 0 << LightProperty::FalloffModel << QVariant::fromValue(FalloffModel::RangeQuadratic);
        QTest::newRow("falloff model needing a range")
            << 4 << LightProperty::FalloffModel << QVariant::fromValue(FalloffModel::RangePower);
        QTest::newRow("range") << 0 << LightProperty::FalloffRange << QVariant(12.5);
        QTest::newRow("optional range set") << 4 << LightProperty::FalloffRange << QVariant(40.0);
        QTest::newRow("falloff exponent") << 0 << LightProperty::FalloffExponent << QVariant(3.0);
        QTest::newRow("constant") << 4 << LightProperty::FalloffConstant << QVariant(1.0);
        QTest::newRow("linear") << 4 << LightProperty::FalloffLinear << QVariant(0.3);
        QTest::newRow("quadratic") << 4 << LightProperty::FalloffQuadratic << QVariant(0.2);
        QTest::newRow("cone model") << 1 << LightProperty::ConeModel
                                    << QVariant::fromValue(ConeModel::AnglePower);
        QTest::newRow("cone inner") << 1 << LightProperty::ConeInner << QVariant(10.0);
        QTest::newRow("cone outer") << 1 << LightProperty::ConeOuter << QVariant(60.0);
        QTest::newRow("hard cone outer below inner") << 5 << LightProperty::ConeOuter << QVariant(5.0);
        QTest::newRow("cone exponent") << 1 << LightProperty::ConeExponent << QVariant(3.2);
        QTest::newRow("diffuse") << 0 << LightProperty::Diffuse
                                 << QVariant::fromValue(DiffuseModel::HalfLambert);
        QTest::newRow("specular factor") << 0 << LightProperty::Specular << QVariant(0.5);
        QTest::newRow("specular colour") << 0 << LightProperty::Specular << v3(1, 0.5, 0.25);
        QTest::newRow("light ambient") << 2 << LightProperty::Ambient << v3(0.1, 0.1, 0.2);
        QTest::newRow("rim exponent") << 3 << LightProperty::RimExponent << QVariant(2.0);
    }

    void changeLightValue() {
        QFETCH(int, row);
        QFETCH(LightProperty, property);
        QFETCH(QVariant, value);
        Document doc;
        doc.newRig(lrtest::sampleRig());
        QVERIFY(lightPropertyApplies(doc.light(row), property));
        QString error;
        checkDoUndoRedo(doc, [&] { return doc.setLightValue({row}, property, value, &error); });
        QVERIFY2(error.isEmpty(), qPrintable(error));
        // The stored value reads back as given (modulo normalisation and colour conversion) and is valid.
        QVERIFY(validateLight(doc.light(row)).isEmpty());
        QCOMPARE(validateLightValue(doc.light(row), property, lightValue(doc.light(row), property)),
                 QString());
        if (property == LightProperty::Intensity || property == LightProperty::FalloffRange)
            QCOMPARE(lightValue(doc.light(row), property).toDouble(), value.toDouble());
        if (property == LightProperty::Direction)
            QVERIFY(std::abs(glm::length(doc.light(row).direction) - 1.0) < 1e-12);
        // The saved form of the new rig reads back to the same rig.
        const RigReadResult back = readRigJson(bytes(doc), QStringLiteral("edited.json"));
        QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));
        QCOMPARE(writeRigJson(*back.rig), bytes(doc));
    }

    void severalValuesAreOneStep() {
        // ChangeLightValues (place the highlight): a position and a direction of one light, the direction
        // of another, one undo step; a refused value pushes nothing; no change, no step.
        Document doc;
        doc.newRig(lrtest::sampleRig());
        const QVariant down = QVariant::fromValue(glm::dvec3(0, -1, 0));
        const QList<LightValueEdit> edits{
            {1, LightProperty::Position, QVariant::fromValue(glm::dvec3(4, 5, 6))},
            {1, LightProperty::Direction, down},
            {2, LightProperty::Direction, QVariant::fromValue(glm::dvec3(1, 0, 0))}};
        checkDoUndoRedo(doc, [&] {
            auto c = ChangeLightValues::create(&doc, edits, QStringLiteral("Place"));
            if (!c) return false;
            doc.undoStack()->push(c.release());
            return true;
        });
        QCOMPARE(doc.light(1).position, glm::dvec3(4, 5, 6));
        QCOMPARE(doc.light(1).direction, glm::dvec3(0, -1, 0));
        QCOMPARE(doc.light(2).direction, glm::dvec3(1, 0, 0));
        QCOMPARE(doc.undoStack()->text(doc.undoStack()->index() - 1), QStringLiteral("Place"));
        QString error;
        // A point light has no direction; a zero direction is invalid: refused with a reason.
        QVERIFY(!ChangeLightValues::create(&doc, {{0, LightProperty::Direction, down}}, QString(), &error));
        QVERIFY(!error.isEmpty());
        error.clear();
        QVERIFY(!ChangeLightValues::create(
            &doc, {{1, LightProperty::Direction, QVariant::fromValue(glm::dvec3(0))}}, QString(), &error));
        QVERIFY(!error.isEmpty());
        error.clear();
        QVERIFY(!ChangeLightValues::create(&doc, {{1, LightProperty::Direction, down}}, QString(), &error));
        QVERIFY(error.isEmpty()); // already so: nothing to do, not an error
    }

    void dependentValuesAreUndoneExactly() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        // L4 has no range; switching to range-power must give it one, and undo must take it away again.
        QVERIFY(!doc.light(4).falloff.hasRange());
        QVERIFY(doc.setLightValue({4}, LightProperty::FalloffModel,
                                  QVariant::fromValue(FalloffModel::RangePower)));
        QVERIFY(doc.light(4).falloff.hasRange());
        doc.undoStack()->undo();
        QVERIFY(!doc.light(4).falloff.hasRange());
        QCOMPARE(doc.rig(), lrtest::sampleRig());
        // A hard cone's outer angle dropping below its inner angle pulls the inner angle along.
        QVERIFY(doc.setLightValue({5}, LightProperty::ConeOuter, 5.0));
        QCOMPARE(doc.light(5).cone.inner, 5.0);
        QVERIFY(doc.setLightValue({5}, LightProperty::ConeModel, QVariant::fromValue(ConeModel::Smooth)));
        QVERIFY(validateLight(doc.light(5)).isEmpty());
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QCOMPARE(doc.light(5).cone, lrtest::sampleRig().lights[5].cone);
    }

    void perLightValuesAreOneStep() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        const QByteArray before = bytes(doc);
        QVERIFY(doc.setLightValues({4, 0, 2}, LightProperty::Intensity, {4.0, 2.0, 3.0}));
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.light(0).intensity, 2.0);
        QCOMPARE(doc.light(2).intensity, 3.0);
        QCOMPARE(doc.light(4).intensity, 4.0);
        doc.undoStack()->undo();
        QCOMPARE(bytes(doc), before);
        QString error;
        QVERIFY(!doc.setLightValues({0, 1}, LightProperty::Intensity, {1.0}, &error));
        QVERIFY(!error.isEmpty());
    }

    void propertyOnlyTouchesLightsItAppliesTo() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        // Cone outer on point + spot + directional: only the spot changes.
        QVERIFY(doc.setLightValue({0, 1, 2}, LightProperty::ConeOuter, 50.0));
        QCOMPARE(doc.light(1).cone.outer, 50.0);
        QCOMPARE(doc.light(0), lrtest::sampleRig().lights[0]);
        QCOMPARE(doc.light(2), lrtest::sampleRig().lights[2]);
        // On a directional light alone it is refused with a reason.
        QString error;
        QVERIFY(!doc.setLightValue({2}, LightProperty::ConeOuter, 50.0, &error));
        QVERIFY(error.contains(QStringLiteral("does not apply")));
        QCOMPARE(doc.undoStack()->count(), 1);
    }

    void invalidValuesRefused_data() {
        QTest::addColumn<int>("row");
        QTest::addColumn<LightProperty>("property");
        QTest::addColumn<QVariant>("value");
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        const auto v3 = [](double x, double y, double z) { return QVariant::fromValue(glm::dvec3(x, y, z)); };
        QTest::newRow("intensity NaN") << 0 << LightProperty::Intensity << QVariant(nan);
        QTest::newRow("intensity Inf") << 0 << LightProperty::Intensity << QVariant(inf);
        QTest::newRow("intensity negative") << 0 << LightProperty::Intensity << QVariant(-1.0);
        QTest::newRow("intensity too large") << 0 << LightProperty::Intensity << QVariant(1e7);
        QTest::newRow("intensity text")
            << 0 << LightProperty::Intensity << QVariant(QStringLiteral("bright"));
        QTest::newRow("intensity none") << 0 << LightProperty::Intensity << QVariant();
        QTest::newRow("colour negative") << 0 << LightProperty::Color << v3(1, -0.1, 1);
        QTest::newRow("colour NaN") << 0 << LightProperty::Color << v3(1, nan, 1);
        QTest::newRow("colour Inf") << 0 << LightProperty::Color << v3(inf, 1, 1);
        QTest::newRow("colour not a vector") << 0 << LightProperty::Color << QVariant(1.0);
        QTest::newRow("temperature too low") << 0 << LightProperty::Temperature << QVariant(500.0);
        QTest::newRow("temperature too high") << 0 << LightProperty::Temperature << QVariant(50000.0);
        QTest::newRow("position Inf") << 0 << LightProperty::Position << v3(0, inf, 0);
        QTest::newRow("position too far") << 0 << LightProperty::Position << v3(0, 1e13, 0);
        QTest::newRow("direction zero") << 2 << LightProperty::Direction << v3(0, 0, 0);
        QTest::newRow("direction NaN") << 2 << LightProperty::Direction << v3(nan, 1, 0);
        QTest::newRow("range zero") << 0 << LightProperty::FalloffRange << QVariant(0.0);
        QTest::newRow("range negative") << 0 << LightProperty::FalloffRange << QVariant(-5.0);
        QTest::newRow("range NaN") << 0 << LightProperty::FalloffRange << QVariant(nan);
        QTest::newRow("no range for range-power") << 0 << LightProperty::FalloffRange << QVariant();
        QTest::newRow("falloff exponent zero") << 0 << LightProperty::FalloffExponent << QVariant(0.0);
        QTest::newRow("polynomial all zero") << 4 << LightProperty::FalloffLinear << QVariant(0.0);
        QTest::newRow("polynomial negative") << 4 << LightProperty::FalloffConstant << QVariant(-1.0);
        QTest::newRow("falloff model unknown")
            << 0 << LightProperty::FalloffModel << QVariant(QStringLiteral("cubic"));
        QTest::newRow("falloff model index") << 0 << LightProperty::FalloffModel << QVariant(99);
        QTest::newRow("cone outer > 90") << 1 << LightProperty::ConeOuter << QVariant(91.0);
        QTest::newRow("cone outer zero") << 1 << LightProperty::ConeOuter << QVariant(0.0);
        QTest::newRow("smooth cone outer < inner") << 1 << LightProperty::ConeOuter << QVariant(10.0);
        QTest::newRow("smooth cone inner > outer") << 1 << LightProperty::ConeInner << QVariant(40.0);
        QTest::newRow("cone exponent negative") << 1 << LightProperty::ConeExponent << QVariant(-2.0);
        QTest::newRow("rim exponent Inf") << 3 << LightProperty::RimExponent << QVariant(inf);
        QTest::newRow("specular negative") << 0 << LightProperty::Specular << QVariant(-1.0);
        QTest::newRow("light ambient negative") << 0 << LightProperty::Ambient << v3(-1, 0, 0);
        QTest::newRow("empty name") << 0 << LightProperty::Name << QVariant(QStringLiteral("   "));
        QTest::newRow("name too long")
            << 0 << LightProperty::Name << QVariant(QString(300, QLatin1Char('x')));
        QTest::newRow("name with newline") << 0 << LightProperty::Name << QVariant(QStringLiteral("a\nb"));
        QTest::newRow("group too long")
            << 0 << LightProperty::Group << QVariant(QString(300, QLatin1Char('k')));
        QTest::newRow("group with newline") << 0 << LightProperty::Group << QVariant(QStringLiteral("a\nb"));
        QTest::newRow("group not text") << 0 << LightProperty::Group << QVariant(3.0);
        QTest::newRow("type unknown") << 0 << LightProperty::Type << QVariant(QStringLiteral("laser"));
        QTest::newRow("enabled not bool") << 0 << LightProperty::Enabled << QVariant(QStringLiteral("yes"));
    }

    void invalidValuesRefused() {
        QFETCH(int, row);
        QFETCH(LightProperty, property);
        QFETCH(QVariant, value);
        Document doc;
        doc.newRig(lrtest::sampleRig());
        const QByteArray before = bytes(doc);
        QVERIFY(!validateLightValue(doc.light(row), property, value).isEmpty());
        QString error;
        QVERIFY(!doc.setLightValue({row}, property, value, &error));
        QVERIFY2(!error.isEmpty(), "refused without a reason");
        QCOMPARE(bytes(doc), before);
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(!doc.isModified());
        // One bad light in a multi-edit refuses the whole edit.
        if (property != LightProperty::Name && property != LightProperty::Type) {
            QVERIFY(!doc.setLightValue({0, 1, 2, 3, 4, 5}, property, value, &error));
            QCOMPARE(bytes(doc), before);
        }
    }

    void contextFreeValidation() {
        QVERIFY(validateLightValue(LightProperty::Intensity, 1.0).isEmpty());
        QVERIFY(!validateLightValue(LightProperty::Intensity, std::nan("")).isEmpty());
        QVERIFY(validateLightValue(LightProperty::Temperature, QVariant()).isEmpty()); // none
        QVERIFY(validateLightValue(LightProperty::ConeOuter, 90.0).isEmpty());
        QVERIFY(!validateLightValue(LightProperty::ConeOuter, 90.5).isEmpty());
        QVERIFY(
            validateLightValue(LightProperty::Intensity, QStringLiteral(" 2.5 ")).isEmpty()); // typed text
        QVERIFY(!validateLightValue(LightProperty::Any, 1.0).isEmpty());
    }

    void mergeContinuousEdits() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        const QByteArray before = bytes(doc);
        {
            ContinuousEdit drag(&doc);
            for (int i = 1; i <= 50; ++i)
                QVERIFY(doc.setLightValue({0, 1}, LightProperty::Intensity, i * 0.1));
        }
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.light(1).intensity, 5.0);
        doc.undoStack()->undo();
        QCOMPARE(bytes(doc), before);
        doc.undoStack()->redo();
        QCOMPARE(doc.light(0).intensity, 5.0);

        // Without a session, every edit is its own step; a new session does not merge into the old one.
        QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 1.0));
        QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 2.0));
        QCOMPARE(doc.undoStack()->count(), 3);
        {
            ContinuousEdit drag(&doc);
            QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 3.0));
            QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 4.0));
        }
        QCOMPARE(doc.undoStack()->count(), 4);

        // In one session: another property, or other lights, start new steps.
        {
            ContinuousEdit drag(&doc);
            QVERIFY(
                doc.setLightValue({0}, LightProperty::Position, QVariant::fromValue(glm::dvec3(1, 1, 1))));
            QVERIFY(
                doc.setLightValue({0}, LightProperty::Position, QVariant::fromValue(glm::dvec3(2, 1, 1))));
            QVERIFY(
                doc.setLightValue({1}, LightProperty::Position, QVariant::fromValue(glm::dvec3(2, 1, 1))));
            QVERIFY(doc.setLightValue({1}, LightProperty::Intensity, 7.0));
            QVERIFY(doc.setLightValue({1}, LightProperty::Intensity, 8.0));
        }
        QCOMPARE(doc.undoStack()->count(), 7);

        // A drag that ends where it started leaves no step at all.
        const QByteArray here = bytes(doc);
        {
            ContinuousEdit drag(&doc);
            QVERIFY(doc.setLightValue({2}, LightProperty::Intensity, 9.0));
            QVERIFY(doc.setLightValue({2}, LightProperty::Intensity, doc.rig().lights[2].intensity));
            QVERIFY(
                doc.setLightValue({2}, LightProperty::Intensity, lrtest::sampleRig().lights[2].intensity));
        }
        QCOMPARE(doc.undoStack()->count(), 7);
        QCOMPARE(bytes(doc), here);
        // Setting the value a light already has is no step either.
        QVERIFY(doc.setLightValue({2}, LightProperty::Intensity, doc.light(2).intensity));
        QCOMPARE(doc.undoStack()->count(), 7);

        // Nested sessions share the outer one.
        const int outer = doc.beginContinuousEdit();
        const int inner = doc.beginContinuousEdit();
        QCOMPARE(inner, outer);
        doc.endContinuousEdit(inner);
        QCOMPARE(doc.continuousEditSession(), outer);
        doc.endContinuousEdit(outer);
        QCOMPARE(doc.continuousEditSession(), 0);
    }

    void changeRigValue_data() {
        QTest::addColumn<RigProperty>("property");
        QTest::addColumn<QVariant>("value");
        QTest::newRow("name") << RigProperty::Name << QVariant(QStringLiteral("Studio"));
        QTest::newRow("space") << RigProperty::Space << QVariant::fromValue(RigSpace::Model);
        QTest::newRow("ambient") << RigProperty::Ambient << QVariant::fromValue(glm::dvec3(0.1, 0.2, 0.3));
        QTest::newRow("specular") << RigProperty::SpecularModel
                                  << QVariant::fromValue(SpecularModel::BlinnPhong);
        QTest::newRow("viewer") << RigProperty::ViewerModel << QVariant(QStringLiteral("infinite"));
        QTest::newRow("shininess") << RigProperty::Shininess << QVariant(64.0);
        QTest::newRow("shading model") << RigProperty::ShadingModel << QVariant(QStringLiteral("pbr"));
    }

    void changeRigValue() {
        QFETCH(RigProperty, property);
        QFETCH(QVariant, value);
        Document doc;
        doc.newRig(lrtest::sampleRig());
        checkDoUndoRedo(doc, [&] { return doc.setRigValue(property, value); });
    }

    void changeRigValueRefusesAndMerges() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        const QByteArray before = bytes(doc);
        QString error;
        QVERIFY(!doc.setRigValue(RigProperty::Shininess, 0.0, &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(!doc.setRigValue(RigProperty::Ambient, QVariant::fromValue(glm::dvec3(std::nan(""), 0, 0)),
                                 &error));
        QVERIFY(!doc.setRigValue(RigProperty::Space, QStringLiteral("galaxy"), &error));
        QVERIFY(!doc.setRigValue(RigProperty::ShadingModel, QStringLiteral("phong"), &error));
        QVERIFY2(error.contains(QLatin1String("shading model")), qPrintable(error));
        QCOMPARE(bytes(doc), before);
        QCOMPARE(doc.undoStack()->count(), 0);
        {
            ContinuousEdit drag(&doc);
            for (int i = 1; i <= 10; ++i)
                QVERIFY(doc.setRigValue(RigProperty::Ambient, QVariant::fromValue(glm::dvec3(i * 0.01))));
        }
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.rig().ambient, glm::dvec3(0.1));
        doc.undoStack()->undo();
        QCOMPARE(bytes(doc), before);
    }

    // A value command finds its lights by id: rows that moved in between do not redirect it.
    void valueCommandsKeyOnLightIds() {
        Document doc;
        doc.newRig(lrtest::pointRig(4));
        auto cmd = ChangeLightValue::create(&doc, {1}, LightProperty::Intensity, 7.0);
        QVERIFY(cmd);
        QVERIFY(doc.moveLights({1}, 4)); // P1 goes to the end
        doc.undoStack()->push(cmd.release());
        QCOMPARE(doc.light(3).name, QStringLiteral("P1"));
        QCOMPARE(doc.light(3).intensity, 7.0);
        QCOMPARE(doc.light(1).intensity, 1.0);
        doc.undoStack()->undo();
        QCOMPARE(doc.light(3).intensity, 1.0);
    }

    // Names, on/off and values are one command family with texts from the property table.
    void oneValueCommandWithTableTexts() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        auto text = [&] { return doc.undoStack()->text(doc.undoStack()->index() - 1); };
        QVERIFY(doc.renameLight(1, QStringLiteral("Key")));
        QCOMPARE(text(), QStringLiteral("Rename L1 to Key"));
        QVERIFY(doc.setLightsEnabled({1, 2}, false));
        QCOMPARE(text(), QStringLiteral("Switch off 2 lights"));
        QVERIFY(doc.setLightValue({0, 1, 2}, LightProperty::Type, QVariant::fromValue(LightType::Spot)));
        QCOMPARE(text(), QStringLiteral("Change type of 3 lights"));
        QVERIFY(doc.setLightValue({5}, LightProperty::ConeOuter, 50.0));
        QCOMPARE(text(), QStringLiteral("Change cone outer angle of L5"));
        // Issue 37: a group is shared (three lights at once), stored trimmed, and cleared with "".
        QVERIFY(doc.setLightValue({0, 2, 4}, LightProperty::Group, QStringLiteral(" key ")));
        QCOMPARE(text(), QStringLiteral("Put 3 lights in group key"));
        for (int r : {0, 2, 4})
            QCOMPARE(doc.light(r).group, QStringLiteral("key"));
        QVERIFY(doc.light(1).group.isEmpty());
        QVERIFY(doc.setLightValue({2}, LightProperty::Group, QString()));
        QCOMPARE(text(), QStringLiteral("Give L2 a group of its own"));
        QVERIFY(doc.light(2).group.isEmpty());
        for (int i = 0; i < doc.undoStack()->count(); ++i)
            QVERIFY(dynamic_cast<const ChangeLightValue*>(doc.undoStack()->command(i)));
        // Setting what a light already has is no step.
        const int steps = doc.undoStack()->count();
        QString error = QStringLiteral("unset");
        QVERIFY(doc.setLightValue({5}, LightProperty::ConeOuter, 50.0, &error));
        QVERIFY(error.isEmpty());
        QCOMPARE(doc.undoStack()->count(), steps);
    }
};

QTEST_GUILESS_MAIN(TestCommands)
#include "tst_commands.moc"
