// The commands on the list of lights: adding, removing, duplicating (numbered names, spread-out copies),
// renaming, moving, switching on and off, and replacing the whole rig (the built-in presets too); do, undo
// and redo restore the exact rig (serialised bytes), light ids and the selection. Values: tst_commands.
#include "editor/commands.h"
#include "editor/duplicatelights.h"
#include "rigfixture.h"

#include <QSet>
#include <QTest>
#include <cmath>

using namespace lr;
using lrtest::checkDoUndoRedo;
using lrtest::names;

class TestListCommands : public QObject {
    Q_OBJECT
  private slots:
    void addLights() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        for (LightType t : {LightType::Point, LightType::Spot, LightType::Directional, LightType::Rim}) {
            const int n = doc.lightCount();
            checkDoUndoRedo(doc, [&] { return doc.addLight(t); });
            QCOMPARE(doc.lightCount(), n + 1);
            QCOMPARE(doc.light(n).type, t);
            QCOMPARE(doc.selectedRows(), QList<int>{n}); // the new light is selected
        }
        // Unique names.
        QVERIFY(doc.addLight(LightType::Spot));
        QCOMPARE(doc.light(doc.lightCount() - 1).name, QStringLiteral("Spot 2"));
        // Insert several in the middle as one step, keeping ids stable through undo/redo.
        const LightId idOf3 = doc.lightId(3);
        checkDoUndoRedo(doc, [&] {
            return doc.addLights(1,
                                 {makeLight(LightType::Point, QStringLiteral("A")),
                                  makeLight(LightType::Spot, QStringLiteral("B"))},
                                 QStringLiteral("Paste"));
        });
        QCOMPARE(doc.light(1).name, QStringLiteral("A"));
        QCOMPARE(doc.rowOf(idOf3), 5);
        const LightId idA = doc.lightId(1);
        doc.undoStack()->undo();
        QCOMPARE(doc.rowOf(idA), -1);
        doc.undoStack()->redo();
        QCOMPARE(doc.rowOf(idA), 1); // same id after redo
        QString error;
        Light bad = makeLight(LightType::Point, QStringLiteral("bad"));
        bad.intensity = std::nan("");
        QVERIFY(!doc.addLights(-1, {bad}, QStringLiteral("Paste"), &error));
        QVERIFY(error.contains(QStringLiteral("intensity")));
    }

    void removeLights() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        const QList<LightId> ids = doc.lightIds();
        doc.setSelectedRows({1, 4});
        checkDoUndoRedo(doc, [&] { return doc.removeLights({4, 1, 2}); });
        QCOMPARE(names(doc), (QStringList{"L0", "L3", "L5"}));
        QVERIFY(doc.selection().isEmpty()); // removed lights leave the selection
        doc.undoStack()->undo();
        QCOMPARE(doc.lightIds(), ids); // ids come back with their lights
        QCOMPARE(doc.selectedRows(), (QList<int>{1, 2, 4}));
        QString error;
        QVERIFY(!doc.removeLights({}, &error));
        QVERIFY(!doc.removeLights({6}, &error));
        QVERIFY(!error.isEmpty());
    }

    void duplicateLights() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        checkDoUndoRedo(doc, [&] { return doc.duplicateLights({3, 0}); });
        QCOMPARE(names(doc), (QStringList{"L0", "L1", "L2", "L3", "L0 2", "L3 2", "L4", "L5"}));
        QCOMPARE(doc.selectedRows(), (QList<int>{4, 5}));
        Light copy = doc.light(4);
        QCOMPARE(copy.position, doc.light(0).position + duplicateOffset(doc.light(0)));
        copy.name = QStringLiteral("L0");
        copy.position = doc.light(0).position;
        QCOMPARE(copy, doc.light(0));
        QVERIFY(doc.lightId(4) != doc.lightId(0));
        QCOMPARE(doc.light(5).direction, doc.light(3).direction); // a rim light has no position to move
    }

    // Issue 11: Ctrl+D stacked copies in one place and named them "Key copy copy copy".
    void duplicatesAreNumberedAndSpreadOut() {
        Document doc;
        Rig rig;
        Light key = makeLight(LightType::Spot, QStringLiteral("Key"));
        key.position = {0, 0, 0};
        rig.lights = {key};
        doc.newRig(rig);
        QVERIFY(doc.duplicateLights({0}));       // Key -> Key 2
        QVERIFY(doc.duplicateLights({1}));       // Key 2 -> Key 3
        QVERIFY(doc.duplicateLights({0}));       // Key again -> Key 4
        QVERIFY(doc.duplicateLights({0, 1, 2})); // three at once: Key 5, 6, 7
        QCOMPARE(names(doc), (QStringList{"Key", "Key 4", "Key 2", "Key 5", "Key 6", "Key 7", "Key 3"}));
        QCOMPARE(duplicateBaseName(QStringLiteral("Fill 12")), QStringLiteral("Fill"));
        QCOMPARE(duplicateBaseName(QStringLiteral("42")), QStringLiteral("42"));
        QCOMPARE(duplicateBaseName(QStringLiteral("Key copy")), QStringLiteral("Key copy"));
        // No two lights share a position: every copy moved off its original and off the earlier copies.
        for (int i = 0; i < doc.lightCount(); ++i)
            for (int j = i + 1; j < doc.lightCount(); ++j)
                QVERIFY2(doc.light(i).position != doc.light(j).position,
                         qPrintable(doc.light(i).name + QStringLiteral(" and ") + doc.light(j).name));
        QCOMPARE(doc.undoStack()->count(), 4);
    }

    // Issue 11: renaming allowed a name another light had, while Add numbers its names.
    void renameToATakenNameNumbersIt() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        QVERIFY(doc.renameLight(2, QStringLiteral("L4")));
        QCOMPARE(doc.light(2).name, QStringLiteral("L4 2"));
        QCOMPARE(doc.light(4).name, QStringLiteral("L4"));
        QVERIFY(doc.renameLight(3, QStringLiteral("L4")));
        QCOMPARE(doc.light(3).name, QStringLiteral("L4 3"));
        // One name for several lights: numbered in row order.
        QVERIFY(doc.setLightValue({5, 0, 1}, LightProperty::Name, QStringLiteral("Same")));
        QCOMPARE(names(doc), (QStringList{"Same", "Same 2", "L4 2", "L4 3", "L4", "Same 3"}));
        QCOMPARE(doc.undoStack()->count(), 3);
        const QStringList all = names(doc);
        QCOMPARE(QSet<QString>(all.begin(), all.end()).size(), doc.lightCount());
        // Its own name again is no step and no error.
        QString error = QStringLiteral("unset");
        QVERIFY(doc.renameLight(2, QStringLiteral("L4 2"), &error));
        QVERIFY(error.isEmpty());
        QCOMPARE(doc.undoStack()->count(), 3);
        doc.undoStack()->setIndex(0);
        QCOMPARE(doc.rig(), lrtest::sampleRig());
    }

    void moveLights_data() {
        QTest::addColumn<QList<int>>("rows");
        QTest::addColumn<int>("destination");
        QTest::newRow("one down") << QList<int>{1} << 4;
        QTest::newRow("one up") << QList<int>{5} << 0;
        QTest::newRow("to the end") << QList<int>{0} << 8;
        QTest::newRow("block down") << QList<int>{1, 2, 3} << 6;
        QTest::newRow("block up") << QList<int>{5, 6} << 1;
        QTest::newRow("scattered to middle") << QList<int>{0, 2, 5, 7} << 4;
        QTest::newRow("scattered to top") << QList<int>{3, 1, 6} << 0;
        QTest::newRow("scattered to end") << QList<int>{0, 4, 6} << 8;
        QTest::newRow("straddling") << QList<int>{2, 4, 5} << 4;
        QTest::newRow("around destination") << QList<int>{1, 3, 6} << 3;
    }

    void moveLights() {
        QFETCH(QList<int>, rows);
        QFETCH(int, destination);
        Document doc;
        doc.newRig(lrtest::pointRig(8));
        // Expected order, worked out the plain way: the other lights before destination, the moved ones in
        // order, the other lights after.
        QStringList expected, moved, tail;
        for (int i = 0; i < 8; ++i) {
            const QString n = doc.light(i).name;
            if (rows.contains(i))
                moved << n;
            else
                (i < destination ? expected : tail) << n;
        }
        expected << moved << tail;
        const QList<LightId> ids = doc.lightIds();
        doc.setSelectedRows(rows);
        checkDoUndoRedo(doc, [&] { return doc.moveLights(rows, destination); });
        QCOMPARE(names(doc), expected);
        // Ids travel with their lights; the selection stays on the moved lights.
        for (int i = 0; i < 8; ++i)
            QCOMPARE(doc.light(doc.rowOf(ids[i])).name, QStringLiteral("P%1").arg(i));
        QCOMPARE(doc.selectedRows().size(), rows.size());
        for (int r : doc.selectedRows())
            QVERIFY(moved.contains(doc.light(r).name));
    }

    void moveThatChangesNothingIsNoStep() {
        Document doc;
        doc.newRig(lrtest::pointRig(5));
        QString error = QStringLiteral("unset");
        QVERIFY(doc.moveLights({1, 2}, 1, &error));
        QVERIFY(doc.moveLights({1, 2}, 3, &error));
        QVERIFY(error.isEmpty());
        QCOMPARE(doc.undoStack()->count(), 0);
        QVERIFY(!doc.moveLights({1}, 9, &error));
        QVERIFY(!error.isEmpty());
    }

    void renameLight() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        checkDoUndoRedo(doc, [&] { return doc.renameLight(2, QStringLiteral("Sun")); });
        QCOMPARE(doc.light(2).name, QStringLiteral("Sun"));
        QString error;
        QVERIFY(!doc.renameLight(2, QString(), &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(!doc.renameLight(9, QStringLiteral("x"), &error));
        QCOMPARE(doc.undoStack()->count(), 1);
    }

    void enableLights() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        QVERIFY(doc.setLightValue({2}, LightProperty::Enabled, false));
        checkDoUndoRedo(doc, [&] { return doc.setLightsEnabled({0, 1, 2, 3}, false); });
        for (int r = 0; r < 4; ++r)
            QVERIFY(!doc.light(r).enabled);
        checkDoUndoRedo(doc, [&] { return doc.setLightsEnabled({2, 3}, true); });
        QVERIFY(doc.light(2).enabled && doc.light(3).enabled && !doc.light(1).enabled);
        doc.undoStack()->undo();
        doc.undoStack()->undo();
        QVERIFY(!doc.light(2).enabled); // the light that was already off stays off
        QVERIFY(doc.light(0).enabled);
    }

    void replaceRig() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        const QList<LightId> ids = doc.lightIds();
        doc.setSelectedRows({1});
        doc.setSoloed({1}, true);
        checkDoUndoRedo(doc,
                        [&] { return doc.replaceRig(lrtest::pointRig(3), QStringLiteral("Apply preset")); });
        QCOMPARE(doc.rig(), lrtest::pointRig(3));
        QVERIFY(doc.selection().isEmpty());
        QVERIFY(!doc.anySoloed());
        doc.undoStack()->undo();
        QCOMPARE(doc.lightIds(), ids);
        Rig tooMany = lrtest::pointRig(kMaxRigLights + 1);
        QString error;
        QVERIFY(!doc.replaceRig(tooMany, QStringLiteral("x"), &error));
        QVERIFY(error.contains(QString::number(kMaxRigLights)));
    }

    void builtinPresetsApply() {
        const QStringList presets = builtinPresetNames();
        QVERIFY2(!presets.isEmpty(), "no built-in presets (resources/presets/*.json)");
        Document doc;
        for (const QString& name : presets) {
            const RigReadResult preset = readBuiltinPreset(name);
            QVERIFY2(preset.ok(), qPrintable(name));
            QString error;
            QVERIFY2(doc.replaceRig(*preset.rig, QStringLiteral("Apply %1").arg(name), &error),
                     qPrintable(name + QStringLiteral(": ") + error));
            QCOMPARE(doc.rig(), *preset.rig);
        }
    }
};

QTEST_GUILESS_MAIN(TestListCommands)
#include "tst_listcommands.moc"
