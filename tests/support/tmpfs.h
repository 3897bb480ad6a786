// A small tmpfs mounted on a temporary folder, for writes that must fail on a full file system (atomic
// writes: the old file survives, the error says "no space left on device"). Mounting needs root (CI and the
// development container run as root); without it, or when the mount fails, available() is false and
// reason() says why, for QSKIP.
#pragma once

#include <QString>
#include <QTemporaryDir>

namespace lrtest {

class SmallTmpfs {
  public:
    explicit SmallTmpfs(qint64 bytes); // rounded up to whole pages by the kernel
    ~SmallTmpfs();                     // unmounts (lazily, so an open file cannot keep it)
    SmallTmpfs(const SmallTmpfs&) = delete;
    SmallTmpfs& operator=(const SmallTmpfs&) = delete;

    bool available() const { return m_mounted; }
    QString reason() const { return m_reason; }
    QString path() const { return m_dir.path(); }
    QString filePath(const QString& name) const { return m_dir.filePath(name); }

    // Fills the file system with FILLER until a write fails, then gives `leaveFree` bytes back (rounded
    // down to pages), so the next write of more than that is short. False when it could not.
    bool fill(qint64 leaveFree = 0);
    qint64 freeBytes() const;

  private:
    QTemporaryDir m_dir;
    bool m_mounted = false;
    QString m_reason;
};

} // namespace lrtest
