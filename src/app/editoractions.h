// The main window's menus and actions (File, Edit, View, Presets, Window, Help) with the standard shortcuts.
// Actions are public by name so tests and the screenshot mode can trigger them.
#pragma once

#include <QObject>

class QAction;
class QMenu;

namespace lr {

class MainWindow;
class ViewBookmarks;

class EditorActions : public QObject {
    Q_OBJECT
  public:
    explicit EditorActions(MainWindow* window);

    QAction* newRig = nullptr;
    QAction* openRig = nullptr;
    QAction* openModel = nullptr;
    QAction* save = nullptr;
    QAction* saveAs = nullptr;
    QAction* importLights = nullptr;
    QAction* exportScreenshot = nullptr;
    QAction* exportTurntable = nullptr; // issue 17 (turntableexport.h)
    QAction* quit = nullptr;
    QAction* undo = nullptr;
    QAction* redo = nullptr;
    QAction* frame = nullptr; // F: the model and the selected lights, or the model when none is selected
    QAction* frameAll = nullptr;
    QAction* frameAllLights = nullptr; // Shift+F: the model and every light around it
    QAction* lookThroughLight = nullptr;
    QAction* showGizmos = nullptr;
    QAction* showGrid = nullptr;
    QAction* controls = nullptr; // Help > Controls (F1): the mouse and key bindings (controlshelp.h)
    QMenu* recentMenu = nullptr;
    QMenu* standardViewsMenu = nullptr;
    QMenu* modelCamerasMenu = nullptr;
    ViewBookmarks* viewBookmarks = nullptr; // View › Saved views (issue 41, viewbookmarks.h)

    void exportScreenshotInteractive();

  private:
    void createFileMenu();
    void createEditMenu();
    void createViewMenu();
    void createOtherMenus();
    void rebuildModelCameras();
    void updateEnabled();

    MainWindow* m_window;
};

} // namespace lr
