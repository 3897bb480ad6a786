// Autosave and crash recovery (issue 6). The open rig is written to the app-data folder (never over the
// user's file) a few seconds after each change, atomically (saveRigFile), with a small sidecar naming the
// rig's own file and the time. A clean save, undoing back to the saved state, loading another rig or a clean
// exit removes it. Each running editor holds a QLockFile for its autosave, so at the next start an autosave
// whose lock is no longer held (the session crashed or was killed) can be offered for recovery.
//
// Files in dir() for a session ID: ID.lock (QLockFile: pid, app, host), ID.rig.json (the rig), ID.meta.json
// ({"original": "/path/rig.json" or "", "saved": ISO-8601 UTC, "name": rig name, "lights": N}).
// The dialog lives in sessionsafety.cpp; everything here is testable without widgets.
#pragma once

#include "core/rig.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QFutureWatcher>
#include <QLockFile>
#include <QObject>
#include <QString>
#include <QTimer>
#include <memory>
#include <vector>

namespace lr {

class Document;

// An autosave left by a session that is no longer running. While this object lives it holds that session's
// lock, so no other starting editor offers the same autosave.
struct RecoveredAutosave {
    QString id;
    QString rigPath;      // ID.rig.json
    QString metaPath;     // ID.meta.json
    QString originalPath; // the rig's own file when it had one, else ""
    QDateTime saved;      // when it was autosaved (UTC); invalid when the sidecar is missing or broken
    QString rigName;
    std::shared_ptr<QLockFile> lock;
};

class Autosave : public QObject {
    Q_OBJECT
  public:
    static constexpr int kDefaultDelayMs = 3000; // after the last change
    static constexpr int kMaxDelayMs = 30000;    // at the latest, even while changes keep coming

    // QStandardPaths::AppDataLocation + "/autosave".
    static QString defaultDir();

    // Starts autosaving `document` into `dir` (created if needed) under a new session lock.
    explicit Autosave(Document* document, const QString& dir = defaultDir(), QObject* parent = nullptr);
    // A clean exit: removes this session's autosave and lock.
    ~Autosave() override;

    QString dir() const { return m_dir; }
    QString sessionId() const { return m_id; }
    QString rigPath() const; // this session's autosave (may not exist)
    QString metaPath() const;
    bool isLocked() const { return m_lock && m_lock->isLocked(); }
    QString lastError() const { return m_lastError; } // why the last autosave failed ("" when it worked)

    void setDelay(int ms) { m_delayMs = ms; }
    void setMaxDelay(int ms) { m_maxDelayMs = ms; }
    bool isPending() const { return m_timer.isActive() || m_inFlight; }

    // Writes the autosave now (blocking) when the document has unsaved changes, else removes it. False on a
    // write error. The debounced autosaves write on a worker thread (a copy of the rig) instead.
    bool saveNow();
    void discard(); // removes this session's autosave files (keeps the lock)

    // Autosaves in `dir` whose session is gone (its lock is free or stale), newest first, each with its lock
    // now held by the caller. Sessions still running are skipped. Leftover locks without an autosave are
    // cleaned up.
    static std::vector<RecoveredAutosave> findRecoverable(const QString& dir = defaultDir());
    // Puts the recovered rig into the document as one undo step on top of its original file (loaded again
    // when it still reads), or of an empty untitled rig, so the document is modified and undo shows what the
    // file had. Does not remove the autosave. Returns the error text, "" on success (then *note may say that
    // the original file could not be opened and the rig is untitled).
    static QString restore(Document* document, const RecoveredAutosave& autosave, QString* note = nullptr);
    // Removes a recovered autosave's files and releases its lock.
    static void remove(RecoveredAutosave& autosave);

  signals:
    void saved(const QString& rigPath);
    void discarded();
    void failed(const QString& error);

  private:
    void schedule();
    void onModifiedChanged(bool modified);
    void saveInBackground();
    void waitForWrite();
    void finishWrite(const QString& error);

    Document* m_doc;
    QString m_dir, m_id;
    std::unique_ptr<QLockFile> m_lock;
    QTimer m_timer;
    QElapsedTimer m_pendingSince;
    int m_delayMs = kDefaultDelayMs, m_maxDelayMs = kMaxDelayMs;
    QString m_lastError;
    QFutureWatcher<QString> m_writing;
    bool m_inFlight = false, m_writeAgain = false;
};

} // namespace lr
