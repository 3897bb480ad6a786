// Issue 14 in the editor's document: the shadow rows of the light-property table (which types they apply to,
// when they are shown, their checks), the Lights table's Shadow column under QAbstractItemModelTester (a
// checkbox where the type casts, one undo step for one or many rows), the kMaxShadowCasters limit (the 17th
// caster refused with the limit in the message, by the table, the Properties values, duplication and whole
// rigs), the ground's rig values, and the Space switch converting the emitter size.
#include "editor/changerigspace.h"
#include "editor/lighttablemodel.h"
#include "rigfixture.h"

#include <QAbstractItemModelTester>
#include <QSignalSpy>
#include <QTest>
#include <functional>
#include <memory>

using namespace lr;
using lrtest::bytes;
using lrtest::checkDoUndoRedo;

namespace {
constexpr int kShadow = LightTableModel::ShadowColumn;

QList<int> firstRows(int n) {
    QList<int> rows;
    for (int i = 0; i < n; ++i)
        rows << i;
    return rows;
}
} // namespace

class TestShadowEdits : public QObject {
    Q_OBJECT

  private slots:
    // Which light types each shadow row applies to, and that the details show only while the shadow is on.
    void rowsApplyAndShow() {
        const Light point = makeLight(LightType::Point, QStringLiteral("p"));
        const Light spot = makeLight(LightType::Spot, QStringLiteral("s"));
        const Light sun = makeLight(LightType::Directional, QStringLiteral("d"));
        const Light rim = makeLight(LightType::Rim, QStringLiteral("r"));
        using P = LightProperty;
        const P details[] = {P::ShadowResolution, P::ShadowBias, P::ShadowNormalOffset};
        for (const Light* l : {&point, &spot, &sun}) {
            QVERIFY(lightPropertyApplies(*l, P::ShadowEnabled));
            QVERIFY(lightPropertyInfo(P::ShadowEnabled)->isShown(*l));
            for (P p : details) {
                QVERIFY(lightPropertyApplies(*l, p));
                QVERIFY(!lightPropertyInfo(p)->isShown(*l)); // shadow off: hidden
                Light on = *l;
                on.shadow.enabled = true;
                QVERIFY(lightPropertyInfo(p)->isShown(on));
            }
        }
        for (P p : {P::ShadowEnabled, P::ShadowResolution, P::ShadowBias, P::ShadowNormalOffset,
                    P::ShadowSize, P::ShadowAngle})
            QVERIFY2(!lightPropertyApplies(rim, p), qPrintable(lightPropertyName(p)));
        // The emitter's extent: a size for lights at a position, an angle for lights at infinity.
        QVERIFY(lightPropertyApplies(point, P::ShadowSize) && lightPropertyApplies(spot, P::ShadowSize));
        QVERIFY(!lightPropertyApplies(sun, P::ShadowSize));
        QVERIFY(lightPropertyApplies(sun, P::ShadowAngle));
        QVERIFY(!lightPropertyApplies(point, P::ShadowAngle) && !lightPropertyApplies(spot, P::ShadowAngle));
        QCOMPARE(QString::fromLatin1(lightPropertyInfo(P::ShadowNormalOffset)->jsonField),
                 QStringLiteral("shadow.normalOffset"));
    }

    void valueChecks() {
        using P = LightProperty;
        for (int r : {256, 512, 1024, 2048, 4096})
            QVERIFY2(validateLightValue(P::ShadowResolution, r).isEmpty(), qPrintable(QString::number(r)));
        QVERIFY(validateLightValue(P::ShadowResolution, 2048.0).isEmpty());
        for (const QVariant& bad : {QVariant(128), QVariant(3000), QVariant(8192), QVariant(1024.5),
                                    QVariant(std::nan("")), QVariant(QStringLiteral("1k")), QVariant()}) {
            const QString e = validateLightValue(P::ShadowResolution, bad);
            QVERIFY2(e.contains(QLatin1String("power of two between 256 and 4096")), qPrintable(e));
        }
        QCOMPARE(validateLightValue(P::ShadowResolution, 3000),
                 QStringLiteral("shadow resolution must be a power of two between 256 and 4096, got 3000"));
        QVERIFY(validateLightValue(P::ShadowBias, 16.0).isEmpty());
        QVERIFY(!validateLightValue(P::ShadowBias, 16.5).isEmpty());
        QVERIFY(!validateLightValue(P::ShadowNormalOffset, -0.1).isEmpty());
        QVERIFY(validateLightValue(P::ShadowSize, 0.0).isEmpty()); // a point emitter: hard shadows
        QVERIFY(!validateLightValue(P::ShadowSize, -1.0).isEmpty());
        QVERIFY(!validateLightValue(P::ShadowSize, std::numeric_limits<double>::infinity()).isEmpty());
        QVERIFY(validateLightValue(P::ShadowAngle, 0.53).isEmpty());
        QVERIFY(!validateLightValue(P::ShadowAngle, 10.5).isEmpty());
        QVERIFY(!validateLightValue(P::ShadowEnabled, QStringLiteral("yes")).isEmpty());
    }

    // Each shadow value is one undo step through ChangeLightValue, and what it stores saves and loads.
    void eachValueIsOneStep_data() {
        QTest::addColumn<int>("row");
        QTest::addColumn<LightProperty>("property");
        QTest::addColumn<QVariant>("value");
        QTest::newRow("point on") << 0 << LightProperty::ShadowEnabled << QVariant(true);
        QTest::newRow("spot resolution") << 1 << LightProperty::ShadowResolution << QVariant(2048);
        QTest::newRow("directional resolution typed")
            << 2 << LightProperty::ShadowResolution << QVariant(QStringLiteral("512"));
        QTest::newRow("spot bias") << 1 << LightProperty::ShadowBias << QVariant(2.5);
        QTest::newRow("directional normal offset") << 2 << LightProperty::ShadowNormalOffset << QVariant(0.0);
        QTest::newRow("point size") << 0 << LightProperty::ShadowSize << QVariant(0.3);
        QTest::newRow("directional angle") << 2 << LightProperty::ShadowAngle << QVariant(0.53);
    }
    void eachValueIsOneStep() {
        QFETCH(int, row);
        QFETCH(LightProperty, property);
        QFETCH(QVariant, value);
        Document doc;
        doc.newRig(lrtest::sampleRig());
        QString error;
        checkDoUndoRedo(doc, [&] { return doc.setLightValue({row}, property, value, &error); });
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(lightValue(doc.light(row), property).toDouble(), value.toDouble());
        const RigReadResult back = readRigJson(bytes(doc), QStringLiteral("edited.json"));
        QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));
        QVERIFY(back.rig->lights[size_t(row)].shadow == doc.light(row).shadow);
        QCOMPARE(writeRigJson(*back.rig), bytes(doc));
        const QString text = doc.undoStack()->text(0);
        if (property == LightProperty::ShadowEnabled)
            QCOMPARE(text, QStringLiteral("Switch on the shadow of L0"));
        else
            QVERIFY2(text.startsWith(QStringLiteral("Change ")), qPrintable(text));
    }

    void multiEditSkipsLightsWithoutIt() {
        Document doc;
        doc.newRig(lrtest::sampleRig()); // L0 point, L1 spot, L2 directional, L3 rim, L4 point, L5 spot
        QVERIFY(doc.setLightValue({0, 1, 2, 3}, LightProperty::ShadowSize, 0.5));
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.light(0).shadow.size, 0.5);
        QCOMPARE(doc.light(1).shadow.size, 0.5);
        QCOMPARE(doc.light(2), lrtest::sampleRig().lights[2]);
        QCOMPARE(doc.light(3), lrtest::sampleRig().lights[3]);
        QString error;
        QVERIFY(!doc.setLightValue({3}, LightProperty::ShadowEnabled, true, &error));
        QVERIFY2(error.contains(QLatin1String("does not apply")), qPrintable(error));
        QVERIFY(!doc.setLightValue({0, 1}, LightProperty::ShadowAngle, 1.0, &error));
        QCOMPARE(doc.undoStack()->count(), 1);
    }

    // The Shadow column: header, checkboxes only where the type casts, edits as commands, the model
    // consistent (QAbstractItemModelTester, fatal) through edits, undo and redo.
    void shadowColumn() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        LightTableModel model(&doc);
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
        QCOMPARE(model.columnCount(), int(LightTableModel::ColumnCount));
        QCOMPARE(model.headerData(kShadow, Qt::Horizontal).toString(), QStringLiteral("Shadow"));
        QVERIFY(model.headerData(kShadow, Qt::Horizontal, Qt::ToolTipRole)
                    .toString()
                    .contains(QLatin1String("16")));
        QCOMPARE(LightTableModel::propertyOf(kShadow), LightProperty::ShadowEnabled);
        for (int r : {0, 1, 2, 4, 5}) {
            QCOMPARE(model.index(r, kShadow).data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
            QVERIFY(model.flags(model.index(r, kShadow)) & Qt::ItemIsUserCheckable);
            QVERIFY(!(model.flags(model.index(r, kShadow)) & Qt::ItemIsEditable));
        }
        // The rim light: no checkbox at all, and a tooltip saying why.
        QVERIFY(!model.index(3, kShadow).data(Qt::CheckStateRole).isValid());
        QVERIFY(!(model.flags(model.index(3, kShadow)) & Qt::ItemIsUserCheckable));
        QVERIFY(
            model.index(3, kShadow).data(Qt::ToolTipRole).toString().contains(QLatin1String("no shadow")));

        QSignalSpy changed(&model, &QAbstractItemModel::dataChanged);
        QVERIFY(model.setData(model.index(1, kShadow), Qt::Checked, Qt::CheckStateRole));
        QVERIFY(doc.light(1).shadow.enabled);
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.undoStack()->text(0), QStringLiteral("Switch on the shadow of L1"));
        QCOMPARE(changed.count(), 1);
        QCOMPARE(changed[0][0].toModelIndex(), model.index(1, kShadow));
        QCOMPARE(model.index(1, kShadow).data(Qt::CheckStateRole).toInt(), int(Qt::Checked));
        QVERIFY(model.index(1, kShadow).data(Qt::ToolTipRole).toString().contains(QLatin1String("1024")));

        // Several rows, the rim light among them skipped: one step.
        QVERIFY(model.setDataForRows({0, 2, 3, 4}, kShadow, Qt::Checked, Qt::CheckStateRole));
        QCOMPARE(doc.undoStack()->count(), 2);
        QCOMPARE(doc.undoStack()->text(1), QStringLiteral("Switch on the shadow of 3 lights"));
        for (int r : {0, 1, 2, 4})
            QVERIFY(doc.light(r).shadow.enabled);
        QVERIFY(!doc.light(3).shadow.enabled && !doc.light(5).shadow.enabled);
        QCOMPARE(shadowCasterCount(doc.rig().lights), 4);
        doc.undoStack()->undo();
        QCOMPARE(shadowCasterCount(doc.rig().lights), 1);
        QCOMPARE(model.index(0, kShadow).data(Qt::CheckStateRole).toInt(), int(Qt::Unchecked));
        doc.undoStack()->undo();
        QCOMPARE(doc.rig(), lrtest::sampleRig());
        doc.undoStack()->redo();
        doc.undoStack()->redo();
        QCOMPARE(shadowCasterCount(doc.rig().lights), 4);

        // The rim light alone: refused with a reason, not silently.
        QSignalSpy refused(&model, &LightTableModel::editRefused);
        QVERIFY(!model.setData(model.index(3, kShadow), Qt::Checked, Qt::CheckStateRole));
        QCOMPARE(refused.count(), 1);
        QVERIFY(!refused[0][0].toString().isEmpty());
    }

    // kMaxShadowCasters: the 17th is refused with the limit in the message, in every way a caster can come.
    void seventeenthCasterRefused() {
        Document doc;
        doc.newRig(lrtest::pointRig(kMaxShadowCasters + 2));
        LightTableModel model(&doc);
        QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::Fatal);
        QVERIFY(model.setDataForRows(firstRows(kMaxShadowCasters), kShadow, Qt::Checked, Qt::CheckStateRole));
        QCOMPARE(shadowCasterCount(doc.rig().lights), kMaxShadowCasters);
        const QByteArray full = bytes(doc);

        QSignalSpy refused(&model, &LightTableModel::editRefused);
        QVERIFY(!model.setData(model.index(kMaxShadowCasters, kShadow), Qt::Checked, Qt::CheckStateRole));
        QCOMPARE(refused.count(), 1);
        const QString message = refused[0][0].toString();
        QCOMPARE(message,
                 QStringLiteral("17 lights would cast shadows; at most 16 can (one shadow map each): "
                                "switch off another light's shadow first"));
        QCOMPARE(model.lastError(), message);
        QVERIFY(!model.setDataForRows({16, 17}, kShadow, Qt::Checked, Qt::CheckStateRole));
        QVERIFY(refused.last()[0].toString().startsWith(QStringLiteral("18 lights would cast shadows")));
        QCOMPARE(bytes(doc), full);
        QCOMPARE(doc.undoStack()->count(), 1);

        // Switching lights themselves off and on never runs into the limit (off lights keep their maps'
        // slots).
        QVERIFY(model.setDataForRows(firstRows(kMaxShadowCasters + 2), LightTableModel::OnColumn,
                                     Qt::Unchecked, Qt::CheckStateRole));
        QVERIFY(!model.setData(model.index(17, kShadow), Qt::Checked, Qt::CheckStateRole));
        QVERIFY(model.setDataForRows(firstRows(kMaxShadowCasters + 2), LightTableModel::OnColumn, Qt::Checked,
                                     Qt::CheckStateRole));
        // Edits that add no caster pass: the casters' own values, switching one off.
        QVERIFY(doc.setLightValue(firstRows(kMaxShadowCasters), LightProperty::ShadowBias, 2.0));
        // A type change that would bring a kept shadow back counts too (a rim light keeps its shadow values).
        QVERIFY(doc.setLightValue({0}, LightProperty::Type, QVariant::fromValue(LightType::Rim)));
        QCOMPARE(shadowCasterCount(doc.rig().lights), kMaxShadowCasters - 1);
        QVERIFY(model.setData(model.index(16, kShadow), Qt::Checked, Qt::CheckStateRole));
        QString error;
        QVERIFY(!doc.setLightValue({0}, LightProperty::Type, QVariant::fromValue(LightType::Point), &error));
        QVERIFY2(error.contains(QLatin1String("at most 16")), qPrintable(error));
        // Duplicating a caster would make a 17th: refused; a light without a shadow duplicates.
        QVERIFY(!doc.duplicateLights({1}, &error));
        QVERIFY2(error.contains(QLatin1String("at most 16")), qPrintable(error));
        QVERIFY(doc.duplicateLights({17}, &error));
        // A whole rig of 17 casters (an applied preset, imported lights) is refused too.
        Rig seventeen = lrtest::pointRig(kMaxShadowCasters + 1);
        for (Light& l : seventeen.lights)
            l.shadow.enabled = true;
        QVERIFY(!doc.replaceRig(seventeen, QStringLiteral("Apply"), &error));
        QVERIFY2(error.contains(QLatin1String("at most 16")), qPrintable(error));
        seventeen.lights.pop_back();
        QVERIFY(doc.replaceRig(seventeen, QStringLiteral("Apply"), &error));
    }

    void groundValues_data() {
        QTest::addColumn<RigProperty>("property");
        QTest::addColumn<QVariant>("value");
        QTest::newRow("visible") << RigProperty::GroundMode << QVariant::fromValue(GroundMode::Visible);
        QTest::newRow("catcher by name") << RigProperty::GroundMode << QVariant(QStringLiteral("catcher"));
        QTest::newRow("colour") << RigProperty::GroundColor << QVariant::fromValue(glm::dvec3(0.2, 0.3, 0.4));
    }
    void groundValues() {
        QFETCH(RigProperty, property);
        QFETCH(QVariant, value);
        Document doc;
        doc.newRig(lrtest::sampleRig());
        checkDoUndoRedo(doc, [&] { return doc.setRigValue(property, value); });
        const RigReadResult back = readRigJson(bytes(doc), QStringLiteral("ground.json"));
        QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));
        QVERIFY(back.rig->ground == doc.rig().ground);
    }

    void groundValuesRefused() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        const QByteArray before = bytes(doc);
        QString error;
        QVERIFY(!doc.setRigValue(RigProperty::GroundMode, QStringLiteral("shadow"), &error));
        QVERIFY2(error.contains(QLatin1String("ground")), qPrintable(error));
        QVERIFY(
            !doc.setRigValue(RigProperty::GroundColor, QVariant::fromValue(glm::dvec3(1.5, 0, 0)), &error));
        QVERIFY(!doc.setRigValue(RigProperty::GroundColor, QVariant::fromValue(glm::dvec3(std::nan(""))),
                                 &error));
        QCOMPARE(bytes(doc), before);
        QCOMPARE(doc.undoStack()->count(), 0);
        QCOMPARE(rigPropertyName(RigProperty::GroundColor), QStringLiteral("ground colour"));
    }

    // The emitter's size is a distance in the rig's units: the Space switch converts it as it converts
    // positions and ranges (an angle needs nothing), and back.
    void spaceSwitchConvertsSize() {
        Rig rig = lrtest::sampleRig(); // world space
        rig.lights[1].shadow = {true, 1024, 1.0, 1.0, 0.5, 0.0};
        rig.lights[2].shadow = {true, 1024, 1.0, 1.0, 0.0, 2.0};
        const SceneFrame frame{glm::dvec3(1.0, 0.0, 0.0), 4.0};
        QString error;
        const std::optional<Rig> model = convertRigSpace(rig, RigSpace::Model, frame, &error);
        QVERIFY2(model, qPrintable(error));
        QCOMPARE(model->lights[1].shadow.size, 0.125);
        QCOMPARE(model->lights[2].shadow.angle, 2.0);
        const std::optional<Rig> world = convertRigSpace(*model, RigSpace::World, frame, &error);
        QVERIFY2(world, qPrintable(error));
        QCOMPARE(world->lights[1].shadow.size, 0.5);
    }
};

QTEST_GUILESS_MAIN(TestShadowEdits)
#include "tst_shadowedits.moc"
