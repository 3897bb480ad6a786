#include "atomicwrite.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QMutex>
#include <QRandomGenerator>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSet>
#include <algorithm>
#include <cerrno>
#include <climits>
#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace lr {

namespace {

const QLatin1String kTag(".lightrig-");
const QLatin1String kTmpSuffix(".tmp");

// The temporaries this process is writing now (absolute paths): never stale, whatever their PID says.
QMutex activeMutex;
QSet<QString> active;

QString reasonOf(int errorNumber) {
    QString reason = qt_error_string(errorNumber);
    if (reason.size() > 1 && reason[0].isUpper() && reason[1].isLower()) reason[0] = reason[0].toLower();
    return reason;
}

// PATH with symbolic links followed: the file that is replaced.
QString resolvedTarget(const QString& path) {
    QFileInfo info(path);
    for (int hops = 0; info.isSymLink() && hops < 40; ++hops)
        info = QFileInfo(info.symLinkTarget());
    return info.absoluteFilePath();
}

QString randomTag() {
    static const char kChars[] = "abcdefghijklmnopqrstuvwxyz0123456789";
    QString s;
    for (int i = 0; i < 6; ++i)
        s += QLatin1Char(kChars[QRandomGenerator::global()->bounded(int(sizeof kChars) - 1)]);
    return s;
}

// The PID in `fileName` when it is a temporary of `targetName`, else -1.
qint64 temporaryPid(const QString& fileName, const QString& targetName) {
    static const QRegularExpression kRest(QStringLiteral("^([0-9]{1,10})-[a-z0-9]{6}\\.tmp$"));
    if (!fileName.startsWith(targetName + kTag)) return -1;
    const QRegularExpressionMatch m = kRest.match(fileName.mid(targetName.size() + kTag.size()));
    return m.hasMatch() ? m.captured(1).toLongLong() : -1;
}

bool isStale(const QString& tmpPath, qint64 pid) {
    if (pid == qint64(::getpid())) {
        const QMutexLocker lock(&activeMutex);
        return !active.contains(tmpPath);
    }
    return pid <= 0 || pid > INT_MAX || (::kill(pid_t(pid), 0) != 0 && errno == ESRCH);
}

QStringList staleOf(const QString& target) {
    const QFileInfo info(target);
    const QDir dir = info.absoluteDir();
    const QString name = info.fileName();
    QStringList out;
    const QStringList candidates =
        dir.entryList({name + kTag + QLatin1Char('*')}, QDir::Files | QDir::Hidden | QDir::System);
    for (const QString& f : candidates) {
        const qint64 pid = temporaryPid(f, name);
        if (pid >= 0 && isStale(dir.filePath(f), pid)) out << dir.filePath(f);
    }
    return out;
}

struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

} // namespace

bool isAtomicTemporaryOf(const QString& fileName, const QString& targetName) {
    return temporaryPid(fileName, targetName) >= 0;
}

QStringList staleTemporaries(const QString& path) {
    return staleOf(resolvedTarget(path));
}

QString writeFileAtomically(const QString& path, const QByteArray& data, const std::atomic<bool>* cancel,
                            bool* cancelled) {
    if (cancelled) *cancelled = false;
    const auto stop = [&] {
        if (!cancel || !cancel->load()) return false;
        if (cancelled) *cancelled = true;
        return true;
    };
    if (stop()) return QStringLiteral("cancelled");
    const QString target = resolvedTarget(path);
    const QByteArray targetNative = QFile::encodeName(target);

    struct stat existing {};
    const bool exists = ::stat(targetNative.constData(), &existing) == 0;
    if (exists && S_ISDIR(existing.st_mode)) return reasonOf(EISDIR);
    if (exists && ::access(targetNative.constData(), W_OK) != 0) return reasonOf(errno);

    for (const QString& stale : staleOf(target))
        QFile::remove(stale); // best effort: another saver may have removed it first

    // Create the temporary beside the target (same file system: the rename is atomic).
    QString tmp;
    Fd file;
    for (int attempt = 0; file.fd < 0; ++attempt) {
        tmp = target + kTag + QString::number(::getpid()) + QLatin1Char('-') + randomTag() + kTmpSuffix;
        file.fd = ::open(QFile::encodeName(tmp).constData(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (file.fd < 0 && (errno != EEXIST || attempt > 100)) return reasonOf(errno);
    }
    const QByteArray tmpNative = QFile::encodeName(tmp);
    {
        const QMutexLocker lock(&activeMutex);
        active.insert(tmp);
    }
    // From here on every exit removes the temporary (unless it became the target).
    bool renamed = false;
    const auto cleanup = qScopeGuard([&] {
        if (file.fd >= 0) ::close(file.fd), file.fd = -1;
        if (!renamed) ::unlink(tmpNative.constData());
        const QMutexLocker lock(&activeMutex);
        active.remove(tmp);
    });

    if (exists && ::fchmod(file.fd, existing.st_mode & 07777) != 0) return reasonOf(errno);
    // Every byte, checked: a short write is followed by the write that fails with the reason (ENOSPC).
    const char* p = data.constData();
    qint64 left = data.size();
    while (left > 0) {
        const ssize_t n = ::write(file.fd, p, size_t(std::min<qint64>(left, qint64(1) << 30)));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return reasonOf(errno);
        if (n == 0) return reasonOf(ENOSPC);
        p += n, left -= n;
    }
    // Delayed allocation (and NFS) report a full disk only here; the size check catches anything else.
    if (::fdatasync(file.fd) != 0 && errno != EINVAL) return reasonOf(errno);
    struct stat written {};
    if (::fstat(file.fd, &written) != 0) return reasonOf(errno);
    if (qint64(written.st_size) != data.size())
        return QStringLiteral("only %1 of %2 bytes reached the disk")
            .arg(qint64(written.st_size))
            .arg(data.size());
    const int fd = std::exchange(file.fd, -1);
    if (::close(fd) != 0) return reasonOf(errno);

    if (stop()) return QStringLiteral("cancelled");
    if (::rename(tmpNative.constData(), targetNative.constData()) != 0) return reasonOf(errno);
    renamed = true;
    // Make the rename itself durable (best effort: not every file system can sync a directory).
    Fd dir;
    dir.fd = ::open(QFile::encodeName(QFileInfo(target).absolutePath()).constData(),
                    O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir.fd >= 0) ::fsync(dir.fd);
    return {};
}

} // namespace lr
