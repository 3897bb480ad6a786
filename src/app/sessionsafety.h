// Wires the safety features (issue 6) into a main window: autosave with crash recovery (autosave.h), the
// on-disk change watch for the open rig (filewatch.h) with its questions as message boxes, and the
// "changed on disk, overwrite?" check before every save (DocumentFiles::confirmWrite). Kept out of
// MainWindow so the window's own code stays about the window: runEditor installs it after openInitial.
#pragma once

#include "autosave.h"

#include <QObject>
#include <functional>

namespace lr {

class MainWindow;
class RigFileWatch;

class SessionSafety : public QObject {
    Q_OBJECT
  public:
    enum class RecoveryAnswer { Restore, Discard };

    // Parented to the window; a clean exit (the window destroyed) removes this session's autosave.
    explicit SessionSafety(MainWindow* window, const QString& autosaveDir = Autosave::defaultDir());

    Autosave* autosave() const { return m_autosave; }
    RigFileWatch* fileWatch() const { return m_watch; }

    // The recovery question (default: a QMessageBox with Restore / Discard).
    std::function<RecoveryAnswer(const RecoveredAutosave&)> askRecovery;
    // Offers the newest autosave of a session that did not exit cleanly (older ones wait for the next start).
    // Restore puts it into the document (Autosave::restore) and autosaves it again at once under this
    // session; Discard deletes it. Returns true when a rig was restored.
    bool offerRecovery();

  private:
    MainWindow* m_window;
    Autosave* m_autosave;
    RigFileWatch* m_watch;
};

// runEditor's hook: installs SessionSafety on the window; with offerRecovery, asks about a crashed session's
// autosave once the event loop runs (not in scripted runs: screenshot mode, --no-restore).
SessionSafety* installSessionSafety(MainWindow* window, bool offerRecovery);

} // namespace lr
