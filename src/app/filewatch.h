// Notices when the open rig's file changes on disk behind the editor's back (issue 6), and makes sure nothing
// is overwritten without asking. A QFileSystemWatcher watches the file (and its folder, so a file replaced
// by rename — how most editors and our own QSaveFile write — or deleted and recreated is followed).
//
// The fingerprint (size + SHA-256) of what the editor last loaded or saved is the baseline. A change on disk
// that matches neither the baseline nor what the editor would write now asks: Reload (the disk version
// replaces the rig; unsaved changes are lost, so the question says so) or Keep mine (the disk version is
// acknowledged; the next save overwrites it). Saving over a file whose content differs from the baseline
// (changed since it was loaded, and not acknowledged) asks first too: confirmSave().
#pragma once

#include <QByteArray>
#include <QFileSystemWatcher>
#include <QObject>
#include <QString>
#include <QTimer>
#include <functional>

namespace lr {

class Document;

class RigFileWatch : public QObject {
    Q_OBJECT
  public:
    enum class ChangedAnswer { Reload, KeepMine };

    explicit RigFileWatch(Document* document, QObject* parent = nullptr);

    // The questions (defaults: none set -> Reload when unmodified, KeepMine when modified; sessionsafety.cpp
    // installs QMessageBox versions). `modified`: the document has unsaved changes that a reload would lose.
    std::function<ChangedAnswer(const QString& path, bool modified)> askChanged;
    // Saving would overwrite a file that changed on disk since it was loaded: true to overwrite.
    std::function<bool(const QString& path)> askOverwrite;
    // Shown when a reload fails (the rig stays as it was) or the file disappears.
    std::function<void(const QString& text)> notify;

    // Call before writing the rig to `path`. True when it is fine to write: `path` is not the watched file,
    // or the file on disk is what was loaded/saved/acknowledged (or already what would be written, or gone),
    // or askOverwrite() said yes.
    bool confirmSave(const QString& path);

    QString watchedPath() const { return m_path; }
    // Checks the file now instead of waiting for the watcher's (debounced) signal; tests use it.
    void checkNow();
    void setDebounce(int ms) { m_debounce.setInterval(ms); }

  signals:
    void changedOnDisk(const QString& path); // an external change was noticed (before asking)
    void reloaded(const QString& path);

  private:
    struct Fingerprint {
        qint64 size = -1; // -1: no file
        QByteArray sha256;
        bool operator==(const Fingerprint&) const = default;
    };
    static Fingerprint fingerprintOf(const QByteArray& data);
    static Fingerprint readFingerprint(const QString& path, QByteArray* data = nullptr);
    bool isOurs(const Fingerprint& f) const; // what the editor would write for the current rig

    void follow(const QString& path); // start watching path (""): nothing; baseline = disk now
    void rewatch();
    void resetBaseline();

    Document* m_doc;
    QFileSystemWatcher m_watcher;
    QString m_path;
    Fingerprint m_baseline;
    QTimer m_debounce;
    bool m_asking = false;
};

} // namespace lr
