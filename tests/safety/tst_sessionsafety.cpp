// SessionSafety on a real main window (src/app/sessionsafety.h): the recovery question after a crash
// (Restore puts the rig back and keeps it safe under the new session; Discard deletes it), autosave of the
// window's document, and the "changed on disk" check wired into the window's Save.
#include "app/documentfiles.h"
#include "app/filewatch.h"
#include "app/mainwindow.h"
#include "app/sessionsafety.h"
#include "editor/rigfixture.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace lr;

namespace {

QString canonical(const Rig& rig) {
    return QString::fromUtf8(writeRigJson(rig));
}

// What a crashed session leaves: its autosave and sidecar, and a lock whose process is gone (here: none).
void leaveCrashedAutosave(const QString& dir, const QString& original, const Rig& rig) {
    Document doc;
    QCOMPARE(doc.load(original), QString());
    QVERIFY(doc.replaceRig(rig, QStringLiteral("edit")));
    QTemporaryDir scratch;
    {
        Autosave autosave(&doc, scratch.path());
        QVERIFY(autosave.saveNow());
        QVERIFY(QFile::copy(autosave.rigPath(), dir + QStringLiteral("/crashed.rig.json")));
        QVERIFY(QFile::copy(autosave.metaPath(), dir + QStringLiteral("/crashed.meta.json")));
    }
}

} // namespace

class TestSessionSafety : public QObject {
    Q_OBJECT
    QTemporaryDir m_tmp;
    QString dir() const { return m_tmp.filePath(QStringLiteral("autosave")); }
    QString original() const { return m_tmp.filePath(QStringLiteral("user.json")); }

    Rig editedRig() const {
        Rig rig = lrtest::sampleRig();
        rig.name = QStringLiteral("Unsaved work");
        rig.lights[0].intensity = 12.5;
        return rig;
    }

  private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    void init() {
        QDir(dir()).removeRecursively();
        QDir().mkpath(dir());
        QString error;
        QVERIFY(saveRigFile(lrtest::sampleRig(), original(), &error));
    }

    void restore_putsTheRigBack_andKeepsItSafe() {
        leaveCrashedAutosave(dir(), original(), editedRig());
        MainWindow window;
        auto* safety = new SessionSafety(&window, dir());
        int asked = 0;
        safety->askRecovery = [&](const RecoveredAutosave& a) {
            ++asked;
            [&] { QCOMPARE(a.originalPath, original()); }();
            return SessionSafety::RecoveryAnswer::Restore;
        };
        QVERIFY(safety->offerRecovery());
        QCOMPARE(asked, 1);
        Document* doc = window.document();
        QCOMPARE(canonical(doc->rig()), canonical(editedRig()));
        QCOMPARE(doc->filePath(), original());
        QVERIFY(doc->isModified());
        // Safe under this session (its own autosave), and the crashed session's copy is gone.
        QVERIFY(QFile::exists(safety->autosave()->rigPath()));
        QVERIFY(!QFile::exists(dir() + QStringLiteral("/crashed.rig.json")));
        // Nothing more to offer.
        QVERIFY(!safety->offerRecovery());
        QCOMPARE(asked, 1);
    }

    void discard_deletesIt_andChangesNothing() {
        leaveCrashedAutosave(dir(), original(), editedRig());
        MainWindow window;
        window.document()->newRig(lrtest::sampleRig());
        const QString before = canonical(window.document()->rig());
        auto* safety = new SessionSafety(&window, dir());
        safety->askRecovery = [](const RecoveredAutosave&) { return SessionSafety::RecoveryAnswer::Discard; };
        QVERIFY(!safety->offerRecovery());
        QCOMPARE(canonical(window.document()->rig()), before);
        QVERIFY(!window.document()->isModified());
        QVERIFY(!QFile::exists(dir() + QStringLiteral("/crashed.rig.json")));
        QVERIFY(Autosave::findRecoverable(dir()).empty());
    }

    void windowEdits_areAutosaved_andAClosedWindowLeavesNothing() {
        {
            MainWindow window;
            auto* safety = new SessionSafety(&window, dir());
            safety->autosave()->setDelay(10);
            QSignalSpy saved(safety->autosave(), &Autosave::saved);
            QVERIFY(window.document()->addLight(LightType::Spot));
            QTRY_VERIFY_WITH_TIMEOUT(!saved.isEmpty(), 10000);
            QVERIFY(QFile::exists(safety->autosave()->rigPath()));
        }
        QCOMPARE(QDir(dir()).entryList(QDir::Files).size(), 0);
    }

    void save_overAFileChangedOnDisk_asksFirst() {
        MainWindow window;
        auto* safety = new SessionSafety(&window, dir());
        QVERIFY(window.files()->confirmWrite);
        int asked = 0;
        safety->fileWatch()->askOverwrite = [&](const QString&) {
            ++asked;
            return false;
        };
        safety->fileWatch()->askChanged = [](const QString&, bool) {
            return RigFileWatch::ChangedAnswer::KeepMine;
        };
        safety->fileWatch()->setDebounce(60000);
        QVERIFY(window.files()->openRig(original()));
        QVERIFY(window.document()->setLightValue({0}, LightProperty::Intensity, 3.0));
        Rig other = lrtest::sampleRig();
        other.name = QStringLiteral("Written by someone else");
        QString error;
        QVERIFY(saveRigFile(other, original(), &error));
        QVERIFY(!window.files()->save());
        QCOMPARE(asked, 1);
        QCOMPARE(readRigFile(original()).rig->name, QStringLiteral("Written by someone else"));
    }
};

QTEST_MAIN(TestSessionSafety)
#include "tst_sessionsafety.moc"
