// Saves are atomic (saveRigFile, core/atomicwrite.h): a child process saves a large rig over the same file
// again and again, alternating two versions, and is killed with SIGKILL at a random moment, many times. After
// every kill the file must read as a complete, valid rig: the last version whose save finished, or the one
// being saved (when the kill came after the rename) — never a partial or mixed file.
#include "core/atomicwrite.h"
#include "core/rigjson.h"
#include "safety/childmain.h"

#include <QCryptographicHash>
#include <QDir>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QThread>
#include <QtTest>
#include <cstdio>

using namespace lr;

namespace {

// A rig near the format's size limits: 4096 lights, every type, long names; `version` changes every value so
// the two versions differ everywhere in the file.
Rig largeRig(int version) {
    Rig rig;
    rig.name = QStringLiteral("Large rig version %1").arg(version);
    rig.ambient = glm::dvec3(0.01 * (version + 1));
    for (int i = 0; i < kMaxRigLights; ++i) {
        const LightType type = LightType(i % 4);
        Light l = makeLight(type, QStringLiteral("light %1 of version %2 ").arg(i).arg(version) +
                                      QString(40, QChar(u'x')));
        l.intensity = 1.0 + i * 0.001 + version;
        l.color = glm::dvec3(0.5 + 0.1 * version, 0.25, 1.0 / (i + 1));
        if (l.usesPosition()) l.position = glm::dvec3(i * 0.1, -i * 0.2, version + 0.5);
        rig.lights.push_back(l);
    }
    return rig;
}

QByteArray hashOf(const QByteArray& data) {
    return QCryptographicHash::hash(data, QCryptographicHash::Sha256);
}

// --child-saver TARGET: prints "ready", then saves version 0, 1, 0, 1, ... forever, printing "begin N" before
// and "end N" after save number N (N = 0, 1, 2, ...; version N % 2).
int childMain(const QStringList& args) {
    if (args.value(0) != QLatin1String("--child-saver") || args.size() != 2) return 2;
    const Rig rigs[2] = {largeRig(0), largeRig(1)};
    std::fputs("ready\n", stdout);
    std::fflush(stdout);
    for (qint64 n = 0;; ++n) {
        std::fprintf(stdout, "begin %lld\n", static_cast<long long>(n));
        std::fflush(stdout);
        QString error;
        if (!saveRigFile(rigs[n % 2], args[1], &error)) {
            std::fprintf(stdout, "error %s\n", qPrintable(error));
            return 1;
        }
        std::fprintf(stdout, "end %lld\n", static_cast<long long>(n));
        std::fflush(stdout);
    }
}

} // namespace

class TestAtomicSave : public QObject {
    Q_OBJECT
  private slots:
    void killedMidSave_leavesOldOrNewFile() {
        QTemporaryDir tmp;
        const QString target = tmp.filePath(QStringLiteral("rig.json"));
        const QByteArray versions[2] = {writeRigJson(largeRig(0)), writeRigJson(largeRig(1))};
        QVERIFY(versions[0].size() > 1'000'000); // large enough that a write takes a while
        const QByteArray hashes[2] = {hashOf(versions[0]), hashOf(versions[1])};
        for (const QByteArray& v : versions)
            QVERIFY(readRigJson(v, target).ok());
        QString error;
        QVERIFY2(saveRigFile(largeRig(1), target, &error), qPrintable(error));
        int lastVersion = 1; // what the file holds before the next child starts

        constexpr int kKills = 60;
        int midSave = 0, totalSaves = 0;
        QRandomGenerator random(20240607);
        for (int k = 0; k < kKills; ++k) {
            QProcess child;
            safetytest::startChild(child, QStringLiteral("saver"), {target});
            QByteArray out;
            QVERIFY2(safetytest::waitForLine(child, "ready", &out), out.constData());
            // Let it complete a few saves sometimes, none other times; kill at a random moment.
            QThread::msleep(random.bounded(0, 400));
            child.kill();
            QVERIFY(child.waitForFinished(10000));
            out += child.readAll();

            // What the child had done when it died.
            qint64 lastBegin = -1, lastEnd = -1;
            for (const QByteArray& line : out.split('\n')) {
                if (line.startsWith("begin "))
                    lastBegin = line.mid(6).toLongLong();
                else if (line.startsWith("end "))
                    lastEnd = line.mid(4).toLongLong();
                else if (line.startsWith("error "))
                    QFAIL(line.constData());
            }
            totalSaves += int(lastEnd + 1);
            const bool killedDuringSave = lastBegin > lastEnd;
            midSave += killedDuringSave ? 1 : 0;

            QFile file(target);
            QVERIFY(file.open(QIODevice::ReadOnly));
            const QByteArray bytes = file.readAll();
            // Byte for byte one of the two complete versions (each read back as a valid rig above). Only a
            // file that is neither is parsed, to say what is wrong with it.
            const QByteArray h = hashOf(bytes);
            if (h != hashes[0] && h != hashes[1]) {
                const RigReadResult read = readRigJson(bytes, target);
                QFAIL(qPrintable(QStringLiteral("kill %1: the file (%2 bytes) is neither version; it %3")
                                     .arg(k)
                                     .arg(bytes.size())
                                     .arg(read.ok()
                                              ? QStringLiteral("reads as a rig")
                                              : QStringLiteral("does not read: ") + read.errors.value(0))));
            }
            const int now = h == hashes[0] ? 0 : 1;
            // The last finished save's version, or the one in progress (killed between rename and "end").
            const int finished = lastEnd >= 0 ? int(lastEnd % 2) : lastVersion;
            const int inProgress = killedDuringSave ? int(lastBegin % 2) : finished;
            QVERIFY2(now == finished || now == inProgress,
                     qPrintable(QStringLiteral("kill %1: holds version %2, expected %3 or %4")
                                    .arg(k)
                                    .arg(now)
                                    .arg(finished)
                                    .arg(inProgress)));
            lastVersion = now;
        }
        qInfo("%d kills, %d of them during a save; %d saves completed in all", kKills, midSave, totalSaves);
        // The point of the test: most kills land inside saveRigFile (the child does nothing else).
        QVERIFY2(midSave >= kKills / 2, qPrintable(QString::number(midSave)));
        // A save killed before its rename leaves its temporary (rig.json.lightrig-PID-XXXXXX.tmp) beside the
        // target, never anything else; the next save removes them all (issue 18 item 3).
        QStringList left = QDir(tmp.path()).entryList(QDir::Files | QDir::Hidden);
        QVERIFY(left.removeOne(QStringLiteral("rig.json")));
        for (const QString& f : left)
            QVERIFY2(isAtomicTemporaryOf(f, QStringLiteral("rig.json")), qPrintable(f));
        qInfo("temporaries left beside the target by %d kills: %lld", kKills,
              static_cast<long long>(left.size()));
        QCOMPARE(staleTemporaries(target).size(), left.size());
        QVERIFY2(saveRigFile(largeRig(0), target, &error), qPrintable(error));
        QCOMPARE(QDir(tmp.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"rig.json"});
    }
};

LIGHTRIG_TEST_MAIN_WITH_CHILD(QCoreApplication, TestAtomicSave, childMain)
#include "tst_atomicsave.moc"
