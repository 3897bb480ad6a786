// Autosave and crash recovery (src/app/autosave.h): the rig is autosaved (debounced) into the autosave folder
// and never over the user's file, removed on a clean save, undo to clean, load, new rig and a clean exit; a
// session killed with SIGKILL leaves an autosave that the next start finds (a running one's is left alone),
// restores as one undo step on top of the original file, or discards for good.
#include "app/autosave.h"
#include "editor/rigfixture.h"
#include "safety/childmain.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>
#include <cstdio>

using namespace lr;

namespace {

QString writeRig(const QString& path, const Rig& rig) {
    QString error;
    if (!saveRigFile(rig, path, &error)) qFatal("%s", qPrintable(error));
    return path;
}

Rig readRig(const QString& path) {
    const RigReadResult r = readRigFile(path);
    if (!r.ok()) qFatal("%s", qPrintable(r.errors.join(u'\n')));
    return *r.rig;
}

// Rigs compared in their file form: values a light's type does not use (a directional light's falloff)
// are not saved, so a rig made in memory and the same rig read back may differ only there.
QString canonical(const Rig& rig) {
    return QString::fromUtf8(writeRigJson(rig));
}

// The edits the child makes after loading the original; the parent repeats them to know what to expect.
void makeEdits(Document& doc) {
    doc.setLightValue({0}, LightProperty::Intensity, 7.5);
    doc.addLight(LightType::Spot);
    doc.renameLight(doc.lightCount() - 1, QStringLiteral("Recovered spot"));
}

// --child-session DIR ORIGINAL: load ORIGINAL, edit, autosave quickly into DIR, say "saved", then idle until
// killed. With an empty DIR argument never happens (the parent always passes one).
int childMain(const QStringList& args) {
    if (args.value(0) != QLatin1String("--child-session") || args.size() != 3) return 2;
    Document doc;
    if (const QString e = doc.load(args[2]); !e.isEmpty()) {
        std::fprintf(stdout, "load failed: %s\n", qPrintable(e));
        return 3;
    }
    Autosave autosave(&doc, args[1]);
    autosave.setDelay(20);
    QObject::connect(&autosave, &Autosave::saved, [] {
        std::fputs("saved\n", stdout);
        std::fflush(stdout);
    });
    makeEdits(doc);
    return QCoreApplication::exec();
}

} // namespace

class TestAutosave : public QObject {
    Q_OBJECT
    QTemporaryDir m_tmp;
    QString dir() const { return m_tmp.filePath(QStringLiteral("autosave")); }
    QString original() const { return m_tmp.filePath(QStringLiteral("user.json")); }
    int files() const { return int(QDir(dir()).entryList(QDir::Files | QDir::Hidden).size()); }

  private slots:
    void init() {
        QDir(dir()).removeRecursively();
        writeRig(original(), lrtest::sampleRig());
    }

    void defaultDir_isInAppData() {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(Autosave::defaultDir().startsWith(
            QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)));
        QVERIFY(Autosave::defaultDir().endsWith(QLatin1String("/autosave")));
    }

    void changes_areAutosavedAfterADelay_notOverTheUsersFile() {
        const QByteArray userBytes = [&] {
            QFile f(original());
            return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
        }();
        Document doc;
        QCOMPARE(doc.load(original()), QString());
        Autosave autosave(&doc, dir());
        QVERIFY(autosave.isLocked());
        autosave.setDelay(200);
        QSignalSpy saved(&autosave, &Autosave::saved);
        QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 3.0));
        QVERIFY(autosave.isPending());
        QVERIFY(!QFile::exists(autosave.rigPath())); // debounced: not written at once
        QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 4.0));
        QTRY_COMPARE_WITH_TIMEOUT(saved.count(), 1, 10000);
        QCOMPARE(canonical(readRig(autosave.rigPath())), canonical(doc.rig()));
        // The sidecar names the original file and the time.
        QFile metaFile(autosave.metaPath());
        QVERIFY(metaFile.open(QIODevice::ReadOnly));
        const QJsonObject meta = QJsonDocument::fromJson(metaFile.readAll()).object();
        QCOMPARE(meta.value(QStringLiteral("original")).toString(), original());
        const QDateTime when =
            QDateTime::fromString(meta.value(QStringLiteral("saved")).toString(), Qt::ISODateWithMs);
        QVERIFY(when.isValid());
        QVERIFY(qAbs(when.secsTo(QDateTime::currentDateTimeUtc())) < 60);
        // The user's file is untouched.
        QFile user(original());
        QVERIFY(user.open(QIODevice::ReadOnly));
        QCOMPARE(user.readAll(), userBytes);
    }

    void aStreamOfChanges_isStillSavedWithinTheMaximumDelay() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        Autosave autosave(&doc, dir());
        autosave.setDelay(60000);
        autosave.setMaxDelay(300);
        QSignalSpy saved(&autosave, &Autosave::saved);
        for (int i = 0; i < 200 && saved.isEmpty(); ++i) {
            QVERIFY(doc.setLightValue({0}, LightProperty::Intensity, 1.0 + i));
            QTest::qWait(20);
        }
        QVERIFY(!saved.isEmpty());
    }

    void cleanStates_removeTheAutosave() {
        Document doc;
        QCOMPARE(doc.load(original()), QString());
        Autosave autosave(&doc, dir());
        const auto edited = [&] {
            if (!doc.setLightValue({0}, LightProperty::Intensity, doc.light(0).intensity + 1.0)) return false;
            return autosave.saveNow() && QFile::exists(autosave.rigPath()) &&
                   QFile::exists(autosave.metaPath());
        };
        // Undo back to the saved state.
        QVERIFY(edited());
        doc.undoStack()->undo();
        QVERIFY(!QFile::exists(autosave.rigPath()));
        QVERIFY(!QFile::exists(autosave.metaPath()));
        // A clean save.
        QVERIFY(edited());
        QCOMPARE(doc.save(), QString());
        QVERIFY(!QFile::exists(autosave.rigPath()));
        // Loading another rig (the unsaved changes were discarded by the user).
        QVERIFY(edited());
        const QString other = writeRig(m_tmp.filePath(QStringLiteral("other.json")), Rig{});
        QCOMPARE(doc.load(other), QString());
        QVERIFY(!QFile::exists(autosave.rigPath()));
        // A new rig.
        QVERIFY(doc.addLight(LightType::Point));
        QVERIFY(autosave.saveNow());
        QVERIFY(QFile::exists(autosave.rigPath()));
        doc.newRig();
        QVERIFY(!QFile::exists(autosave.rigPath()));
        // Nothing unsaved: saveNow writes nothing.
        QVERIFY(autosave.saveNow());
        QVERIFY(!QFile::exists(autosave.rigPath()));
    }

    // The debounced autosave writes on a worker thread. A clean save while that write is in flight must win:
    // the autosave must not reappear afterwards.
    void backgroundWrite_thenCleanSave_leavesNoAutosave() {
        Document doc;
        doc.newRig(lrtest::pointRig(kMaxRigLights)); // large: the write takes a while
        QCOMPARE(doc.saveAs(original()), QString());
        Autosave autosave(&doc, dir());
        autosave.setDelay(0);
        QSignalSpy saved(&autosave, &Autosave::saved);
        for (int round = 0; round < 5; ++round) {
            QVERIFY(doc.setLightValue({round}, LightProperty::Intensity, 2.0 + round));
            if (round % 2)
                QTest::qWait(5); // odd rounds: the timer fired, the write is (most likely) in flight
            else
                QTRY_VERIFY(!autosave.isPending()); // even rounds: after it finished
            QCOMPARE(doc.save(), QString());
            QTest::qWait(50);
            QVERIFY(!QFile::exists(autosave.rigPath()));
            QVERIFY(!QFile::exists(autosave.metaPath()));
        }
        // And a background write that completes leaves exactly the rig.
        QVERIFY(doc.setLightValue({7}, LightProperty::Intensity, 9.0));
        const int before = saved.count();
        QTRY_VERIFY_WITH_TIMEOUT(saved.count() > before, 20000);
        QCOMPARE(canonical(readRig(autosave.rigPath())), canonical(doc.rig()));
    }

    void cleanExit_removesEverything() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        {
            Autosave autosave(&doc, dir());
            QVERIFY(doc.addLight(LightType::Rim));
            QVERIFY(autosave.saveNow());
            QCOMPARE(files(), 3); // lock, rig, sidecar
        }
        QCOMPARE(files(), 0);
        QVERIFY(Autosave::findRecoverable(dir()).empty());
    }

    void aRunningSession_isNotOffered() {
        Document doc;
        doc.newRig(lrtest::sampleRig());
        Autosave autosave(&doc, dir());
        QVERIFY(doc.addLight(LightType::Rim));
        QVERIFY(autosave.saveNow());
        QVERIFY(Autosave::findRecoverable(dir()).empty());
        QVERIFY(QFile::exists(autosave.rigPath()));
    }

    // The real thing: a session in another process is killed with SIGKILL after autosaving.
    void killedSession_isRecovered() {
        QProcess child;
        safetytest::startChild(child, QStringLiteral("session"), {dir(), original()});
        QByteArray out;
        QVERIFY2(safetytest::waitForLine(child, "saved", &out), out.constData());
        // While it runs, its autosave is its own.
        QVERIFY(Autosave::findRecoverable(dir()).empty());
        child.kill(); // SIGKILL: no destructor, no cleanup
        QVERIFY(child.waitForFinished(10000));
        QCOMPARE(child.exitStatus(), QProcess::CrashExit);

        std::vector<RecoveredAutosave> found = Autosave::findRecoverable(dir());
        QCOMPARE(found.size(), size_t(1));
        QCOMPARE(found[0].originalPath, original());
        QVERIFY(found[0].saved.isValid());
        QCOMPARE(found[0].rigName, lrtest::sampleRig().name);
        // Held by us now: another starting editor would not offer it too.
        QVERIFY(Autosave::findRecoverable(dir()).empty());

        Document expected;
        QCOMPARE(expected.load(original()), QString());
        makeEdits(expected);

        Document doc; // a fresh start: the default rig, untitled
        QString note;
        QCOMPARE(Autosave::restore(&doc, found[0], &note), QString());
        QCOMPARE(note, QString());
        QCOMPARE(canonical(doc.rig()), canonical(expected.rig()));
        QCOMPARE(doc.filePath(), original());
        QVERIFY(doc.isModified()); // closing asks to save; saving writes the original file
        doc.undoStack()->undo();   // one step back: what the file holds
        QCOMPARE(canonical(doc.rig()), canonical(readRig(original())));

        Autosave::remove(found[0]);
        QVERIFY(Autosave::findRecoverable(dir()).empty());
        QCOMPARE(files(), 0);
    }

    void declining_discardsForGood() {
        QProcess child;
        safetytest::startChild(child, QStringLiteral("session"), {dir(), original()});
        QByteArray out;
        QVERIFY2(safetytest::waitForLine(child, "saved", &out), out.constData());
        child.kill();
        QVERIFY(child.waitForFinished(10000));
        {
            std::vector<RecoveredAutosave> found = Autosave::findRecoverable(dir());
            QCOMPARE(found.size(), size_t(1));
            Autosave::remove(found[0]);
        }
        QVERIFY(Autosave::findRecoverable(dir()).empty());
        QCOMPARE(files(), 0);
    }

    void originalGone_restoresUntitled() {
        Document doc;
        QCOMPARE(doc.load(original()), QString());
        Rig edited;
        {
            // A session that "crashed": its lock is released without removing the autosave.
            Autosave autosave(&doc, dir());
            QVERIFY(doc.addLight(LightType::Directional));
            QVERIFY(autosave.saveNow());
            edited = doc.rig();
            QFile::copy(autosave.rigPath(), m_tmp.filePath(QStringLiteral("keep.rig.json")));
            QFile::copy(autosave.metaPath(), m_tmp.filePath(QStringLiteral("keep.meta.json")));
        }
        QFile::copy(m_tmp.filePath(QStringLiteral("keep.rig.json")),
                    dir() + QStringLiteral("/crashed.rig.json"));
        QFile::copy(m_tmp.filePath(QStringLiteral("keep.meta.json")),
                    dir() + QStringLiteral("/crashed.meta.json"));
        QVERIFY(QFile::remove(original()));

        std::vector<RecoveredAutosave> found = Autosave::findRecoverable(dir());
        QCOMPARE(found.size(), size_t(1));
        Document fresh;
        QString note;
        QCOMPARE(Autosave::restore(&fresh, found[0], &note), QString());
        QVERIFY(note.contains(original()));
        QCOMPARE(canonical(fresh.rig()), canonical(edited));
        QCOMPARE(fresh.filePath(), QString());
        QVERIFY(fresh.isModified());
        Autosave::remove(found[0]);
    }

    void brokenAutosave_isReportedNotLoaded() {
        QDir().mkpath(dir());
        QFile broken(dir() + QStringLiteral("/crashed.rig.json"));
        QVERIFY(broken.open(QIODevice::WriteOnly));
        broken.write("{\"format\": \"lightrig\", \"version\": 1, \"lights\": ["); // cut short
        broken.close();
        std::vector<RecoveredAutosave> found = Autosave::findRecoverable(dir());
        QCOMPARE(found.size(), size_t(1));
        Document doc;
        doc.newRig(lrtest::sampleRig());
        QVERIFY(!Autosave::restore(&doc, found[0]).isEmpty());
        QCOMPARE(canonical(doc.rig()), canonical(lrtest::sampleRig())); // unchanged
        Autosave::remove(found[0]);
    }

    void leftoverLockWithoutAutosave_isCleanedUp() {
        // A session killed before its first autosave leaves only its lock. Make one as QLockFile writes it,
        // then put in a pid that cannot be running.
        QDir().mkpath(dir());
        const QString path = dir() + QStringLiteral("/old.lock");
        QByteArray content;
        {
            QLockFile lock(path);
            QVERIFY(lock.tryLock(0));
            QFile f(path);
            QVERIFY(f.open(QIODevice::ReadOnly));
            content = f.readAll();
        } // unlocked and removed here
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("2147483000" + content.mid(content.indexOf('\n')));
        f.close();
        QVERIFY(Autosave::findRecoverable(dir()).empty());
        QVERIFY(!QFile::exists(path));
    }
};

LIGHTRIG_TEST_MAIN_WITH_CHILD(QCoreApplication, TestAutosave, childMain)
#include "tst_autosave.moc"
