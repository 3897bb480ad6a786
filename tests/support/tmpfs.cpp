#include "support/tmpfs.h"

#include <QByteArray>
#include <QFile>
#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/mount.h>
#include <sys/statvfs.h>
#include <unistd.h>

namespace lrtest {

SmallTmpfs::SmallTmpfs(qint64 bytes) {
    if (::geteuid() != 0) {
        m_reason = QStringLiteral("not root: mounting a small tmpfs to fill needs root (CI runs as root)");
        return;
    }
    if (!m_dir.isValid()) {
        m_reason = QStringLiteral("no temporary folder to mount on: %1").arg(m_dir.errorString());
        return;
    }
    const QByteArray options = "size=" + QByteArray::number(bytes) + ",mode=0755";
    if (::mount("tmpfs", QFile::encodeName(m_dir.path()).constData(), "tmpfs", MS_NOSUID | MS_NODEV,
                options.constData()) != 0) {
        m_reason = QStringLiteral("cannot mount a tmpfs on %1: %2").arg(m_dir.path(), strerror(errno));
        return;
    }
    m_mounted = true;
}

SmallTmpfs::~SmallTmpfs() {
    if (m_mounted) ::umount2(QFile::encodeName(m_dir.path()).constData(), MNT_DETACH);
}

qint64 SmallTmpfs::freeBytes() const {
    struct statvfs s {};
    if (::statvfs(QFile::encodeName(m_dir.path()).constData(), &s) != 0) return -1;
    return qint64(s.f_bavail) * qint64(s.f_frsize);
}

bool SmallTmpfs::fill(qint64 leaveFree) {
    if (!m_mounted) return false;
    const QByteArray filler = QFile::encodeName(filePath(QStringLiteral("FILLER")));
    const int fd = ::open(filler.constData(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) return false;
    const QByteArray chunk(4096, 'x');
    qint64 size = 0;
    for (;;) {
        const ssize_t n = ::write(fd, chunk.constData(), size_t(chunk.size()));
        if (n <= 0) break;
        size += n;
    }
    const bool full = errno == ENOSPC;
    const qint64 page = ::sysconf(_SC_PAGESIZE);
    const qint64 giveBack = (leaveFree + page - 1) / page * page;
    const bool ok = full && ::ftruncate(fd, std::max<qint64>(0, size / page * page - giveBack)) == 0;
    ::close(fd);
    return ok;
}

} // namespace lrtest
