// The Document: file load/save and the modified flag, selection by stable id, transient solo, change signals,
// and the load targets (4096 lights, 10,000 undo steps, a 1,000-light multi-edit as one step).
#include "editor/commands.h"
#include "rigfixture.h"

#include <QFile>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;
using lrtest::bytes;

class TestDocument : public QObject {
    Q_OBJECT

    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }
    static void writeFile(const QString& p, const QByteArray& data) {
        QFile f(p);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(data);
    }

  private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void newDocumentIsEmptyAndClean() {
        Document doc;
        QCOMPARE(doc.lightCount(), 0);
        QVERIFY(!doc.isModified());
        QVERIFY(doc.filePath().isEmpty());
        QCOMPARE(doc.displayName(), QStringLiteral("Untitled"));
        QString error;
        QVERIFY(!doc.save().isEmpty()); // untitled: save needs a path
    }

    void saveLoadAndModifiedFlag() {
        Document doc;
        QSignalSpy modified(&doc, &Document::modifiedChanged);
        QSignalSpy file(&doc, &Document::fileChanged);
        doc.newRig(lrtest::sampleRig());
        QVERIFY(!doc.isModified());
        QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 3.0));
        QVERIFY(doc.isModified());
        QCOMPARE(modified.count(), 1);
        QCOMPARE(modified.last().at(0).toBool(), true);

        const QString p = path(QStringLiteral("saved.json"));
        QCOMPARE(doc.saveAs(p), QString());
        QVERIFY(!doc.isModified());
        QCOMPARE(doc.filePath(), p);
        QCOMPARE(doc.displayName(), QStringLiteral("saved.json"));
        QCOMPARE(file.count(), 1);
        // Undo past the save point is modified again; redo back to it is clean.
        doc.undoStack()->undo();
        QVERIFY(doc.isModified());
        doc.undoStack()->redo();
        QVERIFY(!doc.isModified());

        // The file holds exactly the rig; loading it gives the same rig in a fresh, clean document.
        QFile f(p);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), bytes(doc));
        Document other;
        QCOMPARE(other.load(p), QString());
        QCOMPARE(writeRigJson(other.rig()), bytes(doc)); // unused fields (a point light's cone) are not saved
        QVERIFY(!other.isModified());
        QCOMPARE(other.undoStack()->count(), 0);
        QCOMPARE(other.filePath(), p);

        // save() writes to the same file.
        QVERIFY(doc.setLightValue({1}, LightProperty::Intensity, 9.0));
        QCOMPARE(doc.save(), QString());
        QCOMPARE(other.load(p), QString());
        QCOMPARE(other.light(1).intensity, 9.0);
    }

    void failedLoadChangesNothing_data() {
        QTest::addColumn<QByteArray>("content");
        QTest::newRow("empty") << QByteArray();
        QTest::newRow("truncated") << QByteArray(R"({"format": "lightrig", "version": 1, "lights": [)");
        QTest::newRow("bad value") << QByteArray(
            R"({"format": "lightrig", "version": 1, "lights": [{"name": "a", "type": "point", "position": [0,0,0],)"
            R"( "intensity": -5, "falloff": {"model": "none"}}]})");
        QTest::newRow("binary") << QByteArray("\x00\x01\x02\xff", 4);
        QTest::newRow("missing file") << QByteArray("<missing>");
    }

    void failedLoadChangesNothing() {
        QFETCH(QByteArray, content);
        Document doc;
        const QString good = path(QStringLiteral("good.json"));
        doc.newRig(lrtest::sampleRig());
        QCOMPARE(doc.saveAs(good), QString());
        QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 2.0));
        doc.setSelectedRows({1});
        doc.setSoloed({2}, true);
        const QByteArray before = bytes(doc);
        const QList<LightId> ids = doc.lightIds();

        const QString bad = path(QStringLiteral("bad.json"));
        QFile::remove(bad);
        if (content != "<missing>") writeFile(bad, content);
        QSignalSpy changed(&doc, &Document::rigChanged);
        QSignalSpy file(&doc, &Document::fileChanged);
        const QString error = doc.load(bad);
        QVERIFY(!error.isEmpty());
        QVERIFY2(error.contains(QStringLiteral("bad.json")), qPrintable(error));
        QCOMPARE(bytes(doc), before);
        QCOMPARE(doc.lightIds(), ids);
        QCOMPARE(doc.filePath(), good);
        QVERIFY(doc.isModified());
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.selectedRows(), QList<int>{1});
        QVERIFY(doc.isSoloed(2));
        QCOMPARE(changed.count(), 0);
        QCOMPARE(file.count(), 0);
    }

    void soloIsTransient() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        QVERIFY(doc.setLightsEnabled({3}, false));
        doc.undoStack()->setClean();
        const QByteArray before = bytes(doc);
        QSignalSpy solo(&doc, &Document::soloChanged);
        doc.setSoloed({1, 3}, true);
        QCOMPARE(solo.count(), 1);
        // Not an undo step, not a modification, not in the file.
        QCOMPARE(doc.undoStack()->count(), 1);
        QVERIFY(!doc.isModified());
        QCOMPARE(bytes(doc), before);
        const QString p = path(QStringLiteral("solo.json"));
        QCOMPARE(doc.saveAs(p), QString());
        QFile f(p);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), before);

        // Rendering: only soloed lights that are on; indices unchanged.
        const Rig render = doc.renderRig();
        QCOMPARE(render.lights.size(), doc.rig().lights.size());
        for (int i = 0; i < doc.lightCount(); ++i)
            QCOMPARE(render.lights[size_t(i)].enabled, i == 1);
        // Solo follows its light through a reorder and survives undo/redo of unrelated edits.
        QVERIFY(doc.moveLights({1}, 0));
        QVERIFY(doc.isSoloed(0));
        doc.undoStack()->undo();
        QVERIFY(doc.isSoloed(1));
        // Removing the soloed lights ends solo (nothing would render otherwise).
        QVERIFY(doc.removeLights({1, 3}));
        QVERIFY(!doc.anySoloed());
        QCOMPARE(doc.renderRig(), doc.rig());
        doc.undoStack()->undo();
        doc.setSoloed({0}, true);
        doc.clearSolo();
        QVERIFY(!doc.anySoloed());
        QCOMPARE(doc.renderRig(), doc.rig());
        // Loading a rig clears solo.
        doc.setSoloed({0}, true);
        QCOMPARE(doc.load(p), QString());
        QVERIFY(!doc.anySoloed());
    }

    void selectionByStableId() {
        Document doc;
        doc.newRig(lrtest::pointRig(6));
        QSignalSpy spy(&doc, &Document::selectionChanged);
        doc.setSelectedRows({4, 1}, 4);
        QCOMPARE(spy.count(), 1);
        QCOMPARE(doc.selectedRows(), (QList<int>{1, 4}));
        QCOMPARE(doc.currentRow(), 4);
        doc.setSelectedRows({4, 1}, 4); // same: no signal
        QCOMPARE(spy.count(), 1);
        // Reordering keeps the selection on the same lights.
        QVERIFY(doc.moveLights({4}, 0));
        QCOMPARE(doc.selectedRows(), (QList<int>{0, 2}));
        QCOMPARE(doc.light(doc.currentRow()).name, QStringLiteral("P4"));
        // Unknown ids and rows are dropped.
        doc.setSelection({doc.lightId(3), LightId(999999)});
        QCOMPARE(doc.selectedRows(), QList<int>{3});
        doc.setSelectedRows({-1, 17});
        QVERIFY(doc.selection().isEmpty());
        QCOMPARE(doc.currentLight(), LightId(0));
    }

    void changeSignals() {
        Document doc;
        doc.newRig(lrtest::pointRig(10));
        QList<RigChange> about, after;
        int countAtAbout = -1;
        connect(&doc, &Document::rigAboutToChange, this, [&](const RigChange& c) {
            about << c;
            countAtAbout = doc.lightCount();
        });
        connect(&doc, &Document::rigChanged, this, [&](const RigChange& c) { after << c; });
        // A multi-edit of rows 1,2,3,7 signals two runs with the property.
        QVERIFY(doc.setLightValue({7, 2, 1, 3}, LightProperty::Intensity, 5.0));
        QVERIFY(about.isEmpty());
        QCOMPARE(after.size(), 2);
        QCOMPARE(after[0].kind, RigChange::LightValues);
        QCOMPARE(after[0].first, 1);
        QCOMPARE(after[0].last, 3);
        QCOMPARE(after[1].first, 7);
        QCOMPARE(after[1].lightProperty, LightProperty::Intensity);
        // Structural changes: announced before (old count), reported after.
        after.clear();
        QVERIFY(doc.removeLights({5, 6}));
        QCOMPARE(about.size(), 1);
        QCOMPARE(about[0].kind, RigChange::Removed);
        QCOMPARE(countAtAbout, 10);
        QCOMPARE(after.size(), 1);
        doc.undoStack()->undo();
        QCOMPARE(about.last().kind, RigChange::Inserted);
        QCOMPARE(countAtAbout, 8);
        // A scattered edit of many rows is one span.
        after.clear();
        doc.newRig(lrtest::pointRig(100));
        after.clear();
        QList<int> scattered;
        for (int i = 0; i < 100; i += 3)
            scattered << i;
        QVERIFY(doc.setLightValue(scattered, LightProperty::Intensity, 2.0));
        QCOMPARE(after.size(), 1);
        QCOMPARE(after[0].first, 0);
        QCOMPARE(after[0].last, 99);
        QVERIFY(doc.setRigValue(RigProperty::Shininess, 16.0));
        QCOMPARE(after.last().kind, RigChange::RigValues);
        QCOMPARE(after.last().rigProperty, RigProperty::Shininess);
    }

    // ---- load targets (functional, no timing) ----

    void manyLightsAndUndoSteps() {
        Document doc;
        doc.newRig(lrtest::pointRig(kMaxRigLights));
        QCOMPARE(doc.lightCount(), 4096);
        const QByteArray start = bytes(doc);
        QString error;
        QVERIFY(!doc.addLight(LightType::Point, &error)); // the format's limit
        QVERIFY(error.contains(QStringLiteral("4096")));
        doc.undoStack()->setUndoLimit(0); // unlimited
        for (int i = 0; i < 10000; ++i) {
            const int row = (i * 37) % kMaxRigLights;
            if (i % 2)
                QVERIFY(doc.setLightValue({row}, LightProperty::Intensity, 1.0 + i * 1e-3));
            else
                QVERIFY(doc.setLightValue({row}, LightProperty::Position,
                                          QVariant::fromValue(glm::dvec3(i, 1, 2))));
        }
        QCOMPARE(doc.undoStack()->count(), 10000);
        const QByteArray end = bytes(doc);
        QVERIFY(end != start);
        doc.undoStack()->setIndex(0);
        QCOMPARE(bytes(doc), start);
        doc.undoStack()->setIndex(10000);
        QCOMPARE(bytes(doc), end);
    }

    void multiEditOfThousandLightsIsOneStep() {
        Document doc;
        doc.newRig(lrtest::pointRig(2000));
        QList<int> rows;
        for (int i = 0; i < 1000; ++i)
            rows << i * 2;
        doc.setSelectedRows(rows);
        const QByteArray before = bytes(doc);
        QVERIFY(doc.setLightValue(doc.selectedRows(), LightProperty::Color,
                                  QVariant::fromValue(glm::dvec3(1, 0.5, 0))));
        QCOMPARE(doc.undoStack()->count(), 1);
        for (int i = 0; i < 2000; ++i)
            QCOMPARE(doc.light(i).color, i % 2 ? glm::dvec3(1.0) : glm::dvec3(1, 0.5, 0));
        doc.undoStack()->undo();
        QCOMPARE(bytes(doc), before);
        // Structural edits of 1,000 lights are one step each too.
        QVERIFY(doc.duplicateLights(rows));
        QCOMPARE(doc.lightCount(), 3000);
        QVERIFY(doc.moveLights(rows, 0));
        QVERIFY(doc.removeLights(rows));
        QCOMPARE(doc.undoStack()->count(), 3); // the undone colour edit was discarded by the first push
        doc.undoStack()->setIndex(0);
        QCOMPARE(doc.lightCount(), 2000);
        QCOMPARE(bytes(doc), before);
    }
};

QTEST_GUILESS_MAIN(TestDocument)
#include "tst_document.moc"
