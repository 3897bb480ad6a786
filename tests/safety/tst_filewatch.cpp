// Files changed on disk while open (src/app/filewatch.h): an external change is noticed and asked about
// (reload / keep mine) before anything is overwritten; the editor's own saves are not; saving over a file
// that changed since it was loaded asks first, also through DocumentFiles::save (the editor's Save action).
#include "app/documentfiles.h"
#include "app/filewatch.h"
#include "app/recentfiles.h"
#include "app/scene.h"
#include "editor/rigfixture.h"

#include <QApplication>
#include <QFile>
#include <QSaveFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace lr;
using Answer = RigFileWatch::ChangedAnswer;

namespace {

QByteArray readBytes(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Another program writes the file: in place (truncate + write) or, like most editors, by rename.
void writeExternally(const QString& path, const Rig& rig, bool byRename) {
    const QByteArray data = writeRigJson(rig);
    if (byRename) {
        QSaveFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(data);
        QVERIFY(f.commit());
    } else {
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(data);
    }
}

Rig otherRig(double intensity) {
    Rig rig = lrtest::sampleRig();
    rig.name = QStringLiteral("Changed elsewhere");
    rig.lights[0].intensity = intensity;
    return rig;
}

struct Asked {
    int changed = 0, overwrite = 0;
    Answer answer = Answer::KeepMine;
    bool overwriteAnswer = false;
    QStringList notes;
    void install(RigFileWatch& w) {
        w.askChanged = [this](const QString&, bool) {
            ++changed;
            return answer;
        };
        w.askOverwrite = [this](const QString&) {
            ++overwrite;
            return overwriteAnswer;
        };
        w.notify = [this](const QString& text) { notes << text; };
    }
};

} // namespace

class TestFileWatch : public QObject {
    Q_OBJECT
    QTemporaryDir m_tmp;
    QString path() const { return m_tmp.filePath(QStringLiteral("rig.json")); }

  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void init() {
        QString error;
        QVERIFY(saveRigFile(lrtest::sampleRig(), path(), &error));
    }

    void externalChange_unmodified_reloadReplacesTheRig() {
        for (const bool byRename : {false, true}) {
            Document doc;
            QCOMPARE(doc.load(path()), QString());
            RigFileWatch watch(&doc);
            watch.setDebounce(100);
            Asked asked;
            asked.answer = Answer::Reload;
            asked.install(watch);
            QSignalSpy reloaded(&watch, &RigFileWatch::reloaded);
            writeExternally(path(), otherRig(5.0), byRename);
            QTRY_COMPARE_WITH_TIMEOUT(reloaded.count(), 1, 10000);
            QCOMPARE(asked.changed, 1);
            QCOMPARE(doc.rig().name, QStringLiteral("Changed elsewhere"));
            QVERIFY(!doc.isModified());
            // Still watched after a rename replaced the file: a second change is noticed too.
            writeExternally(path(), otherRig(6.0), byRename);
            QTRY_COMPARE_WITH_TIMEOUT(reloaded.count(), 2, 10000);
            QCOMPARE(doc.light(0).intensity, 6.0);
            QCOMPARE(asked.changed, 2);
        }
    }

    void externalChange_modified_keepMine_keepsEditsAndSavesWithoutAskingAgain() {
        Document doc;
        QCOMPARE(doc.load(path()), QString());
        QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 42.0));
        RigFileWatch watch(&doc);
        watch.setDebounce(100);
        Asked asked;
        asked.answer = Answer::KeepMine;
        bool sawModified = false;
        asked.install(watch);
        watch.askChanged = [&](const QString&, bool modified) {
            ++asked.changed;
            sawModified = modified;
            return Answer::KeepMine;
        };
        QSignalSpy changed(&watch, &RigFileWatch::changedOnDisk);
        writeExternally(path(), otherRig(5.0), true);
        QTRY_COMPARE_WITH_TIMEOUT(asked.changed, 1, 10000);
        QVERIFY(sawModified); // the question says that reloading would lose changes
        QCOMPARE(doc.light(0).intensity, 42.0);
        QVERIFY(doc.isModified());
        QCOMPARE(readBytes(path()), writeRigJson(otherRig(5.0))); // nothing overwritten by noticing
        // The user chose to keep theirs: saving overwrites without a second question.
        QVERIFY(watch.confirmSave(path()));
        QCOMPARE(asked.overwrite, 0);
        QCOMPARE(doc.save(), QString());
        QTest::qWait(200);
        QCOMPARE(asked.changed, 1); // our own save is not an external change
        QCOMPARE(changed.count(), 1);
    }

    void ownSaves_areNotExternalChanges() {
        Document doc;
        QCOMPARE(doc.load(path()), QString());
        RigFileWatch watch(&doc);
        watch.setDebounce(100);
        Asked asked;
        asked.install(watch);
        for (int i = 0; i < 3; ++i) {
            QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 10.0 + i));
            QVERIFY(watch.confirmSave(path()));
            QCOMPARE(doc.save(), QString());
            QTest::qWait(100);
        }
        const QString other = m_tmp.filePath(QStringLiteral("saved-as.json"));
        QCOMPARE(doc.saveAs(other), QString());
        QCOMPARE(watch.watchedPath(), QFileInfo(other).absoluteFilePath());
        QTest::qWait(200);
        QCOMPARE(asked.changed, 0);
        QCOMPARE(asked.overwrite, 0);
    }

    // The file changes and the user saves before the watcher's signal arrived (or while ignoring it).
    void savingOverAChangedFile_asksFirst() {
        Document doc;
        QCOMPARE(doc.load(path()), QString());
        RigFileWatch watch(&doc);
        watch.setDebounce(60000); // the watcher will not get to it first
        Asked asked;
        asked.install(watch);
        QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 9.0));
        writeExternally(path(), otherRig(5.0), false);
        asked.overwriteAnswer = false;
        QVERIFY(!watch.confirmSave(path()));
        QCOMPARE(asked.overwrite, 1);
        QCOMPARE(readBytes(path()), writeRigJson(otherRig(5.0)));
        asked.overwriteAnswer = true;
        QVERIFY(watch.confirmSave(path()));
        QCOMPARE(asked.overwrite, 2);
        // Saving somewhere else never asks.
        QVERIFY(watch.confirmSave(m_tmp.filePath(QStringLiteral("elsewhere.json"))));
        QCOMPARE(asked.overwrite, 2);
    }

    // Through the editor's Save: DocumentFiles::confirmWrite is the hook SessionSafety installs.
    void documentFilesSave_refusedOverAChangedFile() {
        Document doc;
        Scene scene;
        RecentFiles recent;
        DocumentFiles files(&doc, &scene, &recent, nullptr);
        RigFileWatch watch(&doc);
        watch.setDebounce(60000);
        files.confirmWrite = [&watch](const QString& p) { return watch.confirmSave(p); };
        Asked asked;
        asked.install(watch);
        QCOMPARE(doc.load(path()), QString());
        QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 9.0));
        writeExternally(path(), otherRig(5.0), true);
        asked.overwriteAnswer = false;
        QVERIFY(!files.save());
        QCOMPARE(readBytes(path()), writeRigJson(otherRig(5.0)));
        QVERIFY(doc.isModified());
        asked.overwriteAnswer = true;
        QVERIFY(files.save());
        QCOMPARE(readBytes(path()), writeRigJson(doc.rig()));
        QVERIFY(!doc.isModified());
    }

    void deletedFile_isReported_notAsked() {
        Document doc;
        QCOMPARE(doc.load(path()), QString());
        RigFileWatch watch(&doc);
        watch.setDebounce(100);
        Asked asked;
        asked.install(watch);
        QVERIFY(QFile::remove(path()));
        QTRY_COMPARE_WITH_TIMEOUT(asked.notes.size(), 1, 10000);
        QVERIFY(asked.notes.first().contains(QLatin1String("deleted")));
        QCOMPARE(asked.changed, 0);
        QVERIFY(watch.confirmSave(path())); // nothing to overwrite
        // It comes back with other content: noticed (the folder is watched).
        writeExternally(path(), otherRig(3.0), true);
        QTRY_COMPARE_WITH_TIMEOUT(asked.changed, 1, 10000);
    }

    void brokenFileOnDisk_reloadFails_rigUnchanged() {
        Document doc;
        QCOMPARE(doc.load(path()), QString());
        const QByteArray before = writeRigJson(doc.rig());
        RigFileWatch watch(&doc);
        watch.setDebounce(100);
        Asked asked;
        asked.answer = Answer::Reload;
        asked.install(watch);
        QFile f(path());
        QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write("{\"format\": \"lightrig\", \"version\": 1, \"lights\": [");
        f.close();
        QTRY_COMPARE_WITH_TIMEOUT(asked.notes.size(), 1, 10000);
        QVERIFY(asked.notes.first().contains(QLatin1String("Could not reload")));
        QCOMPARE(writeRigJson(doc.rig()), before);
        QCOMPARE(doc.filePath(), path());
    }

    void untitledAndBuiltinRigs_areNotWatched() {
        Document doc;
        RigFileWatch watch(&doc);
        QCOMPARE(watch.watchedPath(), QString());
        QCOMPARE(doc.load(builtinPresetPath(QStringLiteral("default"))), QString());
        QCOMPARE(watch.watchedPath(), QString());
        QVERIFY(watch.confirmSave(path()));
    }
};

QTEST_MAIN(TestFileWatch)
#include "tst_filewatch.moc"
