// The one atomic write (core/atomicwrite.h) that rigs, autosaves, presets, images and bench files go
// through: it replaces the file whole or not at all, keeps permissions and symbolic links, honours a cancel,
// says the system's reason ("no space left on device", not "Unknown error") on a full file system (a small
// tmpfs, when root) and removes the temporaries a killed writer left, and only those.
#include "core/atomicwrite.h"
#include "core/rigjson.h"
#include "support/files.h"
#include "support/tmpfs.h"

#include <QDir>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>
#include <sys/stat.h>
#include <unistd.h>

using namespace lr;

namespace {

// A PID no process has: one of a child that has exited (and been reaped).
qint64 deadPid() {
    QProcess p;
    p.start(QStringLiteral("true"), {});
    if (!p.waitForStarted()) return -1;
    const qint64 pid = p.processId();
    p.waitForFinished();
    return pid;
}

QString temporaryName(const QString& target, qint64 pid, const char* tag = "abc123") {
    return QStringLiteral("%1.lightrig-%2-%3.tmp").arg(target).arg(pid).arg(QLatin1String(tag));
}

QByteArray pattern(int size, char seed) {
    QByteArray b(size, Qt::Uninitialized);
    for (int i = 0; i < size; ++i)
        b[i] = char(seed + i * 7 + (i >> 9));
    return b;
}

Rig smallRig(const QString& name) {
    Rig rig;
    rig.name = name;
    rig.lights.push_back(makeLight(LightType::Point, QStringLiteral("Key")));
    return rig;
}

} // namespace

class TestAtomicWrite : public QObject {
    Q_OBJECT
  private slots:
    void replacesTheFileWhole() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("data.bin"));
        QCOMPARE(writeFileAtomically(path, pattern(5000, 1)), QString());
        QCOMPARE(lrtest::readFile(path), pattern(5000, 1));
        QCOMPARE(writeFileAtomically(path, "short"), QString());
        QCOMPARE(lrtest::readFile(path), QByteArray("short"));
        QCOMPARE(writeFileAtomically(path, QByteArray()), QString()); // an empty file is a file
        QCOMPARE(QFileInfo(path).size(), qint64(0));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"data.bin"});
    }

    void keepsPermissionsAndLinks() {
        QTemporaryDir dir;
        const QString target = dir.filePath(QStringLiteral("target.json"));
        const QString link = dir.filePath(QStringLiteral("link.json"));
        QVERIFY(lrtest::writeFile(target, "old"));
        QCOMPARE(::chmod(QFile::encodeName(target).constData(), 0640), 0);
        QVERIFY(QFile::link(target, link));
        QCOMPARE(writeFileAtomically(link, "new"), QString());
        QVERIFY(QFileInfo(link).isSymLink()); // the link stays a link; its target was replaced
        QCOMPARE(lrtest::readFile(target), QByteArray("new"));
        struct stat s {};
        QCOMPARE(::stat(QFile::encodeName(target).constData(), &s), 0);
        QCOMPARE(int(s.st_mode & 07777), 0640);
    }

    void failuresSayWhy_andChangeNothing() {
        QTemporaryDir dir;
        QCOMPARE(writeFileAtomically(dir.filePath(QStringLiteral("missing/x.json")), "x"),
                 QStringLiteral("no such file or directory"));
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("folder")));
        QCOMPARE(writeFileAtomically(dir.filePath(QStringLiteral("folder")), "x"),
                 QStringLiteral("is a directory"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList());
    }

    void cancelBeforeTheRename_leavesTheOldFile() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("o.png"));
        QVERIFY(lrtest::writeFile(path, "old"));
        std::atomic<bool> cancel{true};
        bool cancelled = false;
        QCOMPARE(writeFileAtomically(path, "new", &cancel, &cancelled), QStringLiteral("cancelled"));
        QVERIFY(cancelled);
        QCOMPARE(lrtest::readFile(path), QByteArray("old"));
        cancel = false;
        QCOMPARE(writeFileAtomically(path, "new", &cancel, &cancelled), QString());
        QVERIFY(!cancelled);
        QCOMPARE(lrtest::readFile(path), QByteArray("new"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"o.png"});
    }

    // Issue 18 item 3: a writer killed between creating its temporary and the rename leaves it behind; the
    // next save of that file removes it. Temporaries of live writers, of other files, and files that only
    // look similar stay.
    void nextWriteRemovesStaleTemporaries() {
        QTemporaryDir dir;
        const QString name = QStringLiteral("rig.json");
        const QString path = dir.filePath(name);
        const qint64 dead = deadPid();
        QVERIFY(dead > 0);
        const QString staleDead = temporaryName(name, dead);
        const QString staleOwn = temporaryName(name, ::getpid(), "own000"); // this process, not writing it
        const QString live = temporaryName(name, ::getppid());              // ctest (or a shell) is alive
        const QStringList unrelated = {temporaryName(QStringLiteral("other.json"), dead),
                                       name + QStringLiteral(".lightrig-12-abc.tmp"), // not our pattern
                                       name + QStringLiteral(".backup"), QStringLiteral("rig.json.Xy12Zq")};
        for (const QString& f : QStringList{staleDead, staleOwn, live} + unrelated)
            QVERIFY(lrtest::writeFile(dir.filePath(f), "left behind"));
        QVERIFY(isAtomicTemporaryOf(staleDead, name));
        QVERIFY(!isAtomicTemporaryOf(unrelated[0], name));
        QVERIFY(!isAtomicTemporaryOf(unrelated[1], name));

        QStringList stale = staleTemporaries(path);
        stale.sort();
        QStringList expected = {dir.filePath(staleDead), dir.filePath(staleOwn)};
        expected.sort();
        QCOMPARE(stale, expected);

        QString error;
        QVERIFY2(saveRigFile(smallRig(QStringLiteral("Saved")), path, &error), qPrintable(error));
        QStringList left = QDir(dir.path()).entryList(QDir::Files | QDir::Hidden);
        QStringList want = QStringList{name, live} + unrelated;
        left.sort(), want.sort();
        QCOMPARE(left, want);
        QVERIFY(staleTemporaries(path).isEmpty());
    }

    // Issue 11 / 18 item 8, on a real full file system: the old file survives byte for byte, nothing is
    // left beside it, and the reason is errno's.
    void fullDisk_keepsTheOldFile_andSaysWhy() {
        lrtest::SmallTmpfs fs(1024 * 1024);
        if (!fs.available()) QSKIP(qPrintable(fs.reason()));
        const QString path = fs.filePath(QStringLiteral("data.bin"));
        const QString rigPath = fs.filePath(QStringLiteral("rig.json"));
        const QByteArray old = pattern(100 * 1024, 3);
        QCOMPARE(writeFileAtomically(path, old), QString());
        QString error;
        QVERIFY2(saveRigFile(smallRig(QStringLiteral("Old")), rigPath, &error), qPrintable(error));
        const QByteArray oldRig = lrtest::readFile(rigPath);
        QVERIFY(fs.fill(16 * 1024)); // the next writes are short, then fail
        QVERIFY2(fs.freeBytes() < 64 * 1024, qPrintable(QString::number(fs.freeBytes())));

        QCOMPARE(writeFileAtomically(path, pattern(200 * 1024, 5)),
                 QStringLiteral("no space left on device"));
        QCOMPARE(lrtest::readFile(path), old);

        Rig big = smallRig(QStringLiteral("New"));
        for (int i = 0; i < 400; ++i)
            big.lights.push_back(makeLight(LightType::Spot, QStringLiteral("spot %1").arg(i)));
        QVERIFY(writeRigJson(big).size() > 64 * 1024);
        QVERIFY(!saveRigFile(big, rigPath, &error));
        QCOMPARE(error, rigPath + QStringLiteral(": not saved: no space left on device"));
        QCOMPARE(lrtest::readFile(rigPath), oldRig);

        QStringList left = QDir(fs.path()).entryList(QDir::Files | QDir::Hidden);
        left.sort();
        QCOMPARE(left, (QStringList{"FILLER", "data.bin", "rig.json"}));
    }
};

QTEST_GUILESS_MAIN(TestAtomicWrite)
#include "tst_atomicwrite.moc"
