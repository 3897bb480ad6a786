// What the editor restores at the next start, in QSettings: window geometry and dock layout
// (saveGeometry/saveState), the last model and the last rig file. Kept separate from the main window so the
// window only says when to save and restore.
#pragma once

#include <QString>

class QMainWindow;

namespace lr {

class SessionSettings {
  public:
    // Bump when the dock set changes so an old layout is not restored onto new docks.
    static constexpr int kStateVersion = 1;

    static void saveWindow(const QMainWindow* window);
    static bool restoreWindow(QMainWindow* window); // false when nothing was stored

    static void setLastModel(const QString& path); // "" for the bundled model
    static void setLastRig(const QString& path);   // "" for an untitled rig
    // The stored paths when they still exist, else "".
    static QString lastModel();
    static QString lastRig();
};

} // namespace lr
