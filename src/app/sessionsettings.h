// What the editor restores at the next start, in QSettings: the window's client rectangle and maximized
// state (not saveGeometry's frame position, which drifted under some window managers), the dock layout
// (saveState), the last model and the last rig file. Kept separate from the main window so the
// window only says when to save and restore.
#pragma once

#include <QString>

class QMainWindow;

namespace lr {

class SessionSettings {
  public:
    // Bump when the dock set changes so an old layout is not restored onto new docks.
    // 2: the default layout of issue 12 (table at the bottom, Properties the whole right column).
    // 3: issue 13's Model dock, a tab beside Presets and History.
    // 4: issue 37's Mixer dock, a tab behind Properties.
    static constexpr int kStateVersion = 4;

    static void saveWindow(const QMainWindow* window);
    static bool restoreWindow(QMainWindow* window); // false when nothing was stored

    static void setLastModel(const QString& path); // "" for the bundled model
    static void setLastRig(const QString& path);   // "" for an untitled rig
    // The stored paths when they still exist, else "".
    static QString lastModel();
    static QString lastRig();
};

} // namespace lr
