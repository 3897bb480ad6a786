// Issue 37: a light mix written into the document's rig (editor/applylightmix.h): the rig applyLightMix
// makes, as one undo step that restores the exact bytes, keeps every light's id and the selection, refuses a
// mix that changes nothing, and finds a render's groups by the ids their lights had then.
#include "core/lightgroups.h"
#include "editor/applylightmix.h"
#include "rigfixture.h"

#include <QSignalSpy>
#include <QTest>

using namespace lr;
using lrtest::bytes;
using lrtest::checkDoUndoRedo;

namespace {

// sampleRig with L0, L2 and L4 in group "key", an ambient and a studio environment.
Rig groupedRig() {
    Rig rig = lrtest::sampleRig();
    for (int i : {0, 2, 4})
        rig.lights[size_t(i)].group = QStringLiteral("key");
    rig.ambient = glm::dvec3(0.05, 0.04, 0.03);
    rig.environment.source = EnvironmentSource::Studio;
    rig.environment.intensity = 1.0;
    return rig;
}

LightMix sampleMix() {
    LightMix mix;
    mix.groups[QStringLiteral("key")] = {true, 1.5, glm::dvec3(1.0, 0.5, 0.25)};
    mix.groups[QStringLiteral("L1")] = {false, 0.0, glm::dvec3(1.0)};
    mix.groups[QStringLiteral("ambient")] = {true, -1.0, glm::dvec3(1.0)};
    mix.groups[QStringLiteral("environment")] = {true, 0.5, glm::dvec3(1.0)};
    return mix;
}

} // namespace

class TestApplyLightMix : public QObject {
    Q_OBJECT
  private slots:
    void appliesAsOneStepKeepingIds() {
        Document doc;
        doc.newRig(groupedRig());
        const QList<LightId> ids = doc.lightIds();
        doc.setSelectedRows({1, 2}, 2);
        const std::vector<LightGroup> groups = lightGroups(doc.rig());
        QStringList expectedNotes;
        const Rig expected = applyLightMix(doc.rig(), groups, sampleMix(), &expectedNotes);
        QVERIFY(expected != doc.rig());
        QStringList notes;
        checkDoUndoRedo(doc, [&] {
            notes.clear();
            return applyLightMixToDocument(&doc, groups, sampleMix(), &notes);
        });
        QCOMPARE(doc.rig(), expected);
        QCOMPARE(notes, expectedNotes);
        QCOMPARE(doc.lightIds(), ids);
        QCOMPARE(doc.selectedRows(), (QList<int>{1, 2}));
        QCOMPARE(doc.currentRow(), 2);
        QCOMPARE(doc.undoStack()->undoText(), QStringLiteral("Apply light mix"));
        QVERIFY(!doc.light(1).enabled);
        QCOMPARE(doc.rig().environment.intensity, 1.5);
        doc.undoStack()->undo();
        QCOMPARE(doc.rig(), groupedRig());
        QCOMPARE(doc.lightIds(), ids);
    }

    void viewsHearOnlyWhatChanged() {
        Document doc;
        doc.newRig(groupedRig());
        QSignalSpy about(&doc, &Document::rigAboutToChange);
        QSignalSpy changed(&doc, &Document::rigChanged);
        LightMix mix;
        mix.groups[QStringLiteral("L3")] = {true, 1.0, glm::dvec3(1.0)};
        QVERIFY(applyLightMixToDocument(&doc, lightGroups(doc.rig()), mix));
        QCOMPARE(about.count(), 0); // nothing structural: no model reset
        QCOMPARE(changed.count(), 1);
        const RigChange c = changed[0][0].value<RigChange>();
        QCOMPARE(c.kind, RigChange::LightValues);
        QCOMPARE(c.first, 3);
        QCOMPARE(c.last, 3);
        QCOMPARE(doc.light(3).intensity, 2.0 * groupedRig().lights[3].intensity);
    }

    void refusesAMixThatChangesNothing() {
        Document doc;
        doc.newRig(groupedRig());
        QString error;
        QVERIFY(!applyLightMixToDocument(&doc, lightGroups(doc.rig()), LightMix{}, nullptr, &error));
        QVERIFY(!error.isEmpty());
        // What a rig cannot hold (the background's tint) is listed, and nothing else changes: no step.
        LightMix background;
        background.groups[QStringLiteral("background")] = {true, 0.0, glm::dvec3(0.5)};
        QStringList notes;
        error.clear();
        QVERIFY(!applyLightMixToDocument(&doc, lightGroups(doc.rig()), background, &notes, &error));
        QVERIFY(!error.isEmpty());
        QCOMPARE(notes.size(), 1);
        QVERIFY2(notes[0].startsWith(QStringLiteral("background")), qPrintable(notes[0]));
        QCOMPARE(doc.undoStack()->count(), 0);
        QCOMPARE(doc.rig(), groupedRig());
    }

    void groupsFollowTheirLightsIds() {
        Document doc;
        doc.newRig(groupedRig());
        const QList<LightId> idsThen = doc.lightIds();
        const std::vector<LightGroup> then = lightGroups(doc.rig()); // "key" = lights 0, 2, 4
        QVERIFY(doc.moveLights({4}, 0));                             // L4 L0 L1 L2 L3 L5
        QVERIFY(doc.removeLights({3}));                              // L4 L0 L1 L3 L5
        QStringList missing;
        const std::vector<LightGroup> now = groupsAtRows(doc, then, idsThen, &missing);
        QCOMPARE(now.size(), then.size());
        QCOMPARE(now.front().name, QStringLiteral("key"));
        QCOMPARE(now.front().lights, (std::vector<int>{1, 0})); // L0 and L4 where they are now
        QCOMPARE(missing.size(), 1);
        QVERIFY2(missing[0].startsWith(QStringLiteral("key:")), qPrintable(missing[0]));
        for (size_t g = 1; g < now.size(); ++g)
            if (now[g].kind != LightGroupKind::Lights) QCOMPARE(now[g], then[g]);
        // The mix reaches the lights that are left, by their new rows.
        LightMix mix;
        mix.groups[QStringLiteral("key")] = {true, 1.0, glm::dvec3(1.0)};
        const double l4 = doc.light(0).intensity, l0 = doc.light(1).intensity;
        QVERIFY(applyLightMixToDocument(&doc, now, mix));
        QCOMPARE(doc.light(0).intensity, 2.0 * l4);
        QCOMPARE(doc.light(1).intensity, 2.0 * l0);
        // A group naming a light the rig does not have (a stale index) is harmless.
        std::vector<LightGroup> bad = now;
        bad.front().lights.push_back(99);
        QVERIFY(applyLightMixToDocument(&doc, bad, mix));
    }
};

QTEST_GUILESS_MAIN(TestApplyLightMix)
#include "tst_applylightmix.moc"
