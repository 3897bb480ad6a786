// The editor's main window: a central Viewport and the docks (Lights, Properties, Render settings, Presets,
// History, Model, Mixer). It wires the parts together and little else: menus and actions live in
// EditorActions, file handling in DocumentFiles, persistence in SessionSettings/ViewSettings/RecentFiles.
#pragma once

#include <QMainWindow>

class QUndoView;

namespace lr {

class AbCompare;
class Document;
class DocumentFiles;
class EditorActions;
class EditorStatusBar;
class EnvironmentLightTool;
class EnvironmentLoading;
class LightsDock;
class LinkTools;
class MixerDock;
class ModelDock;
class PresetStore;
class PresetsDock;
class PropertiesDock;
class RecentFiles;
class RenderSettingsDock;
class Scene;
class ViewSettings;
class Viewport;
struct EditorOptions;

class MainWindow : public QMainWindow {
    Q_OBJECT
  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    Document* document() const { return m_doc; }
    Scene* scene() const { return m_scene; }
    ViewSettings* viewSettings() const { return m_viewSettings; }
    DocumentFiles* files() const { return m_files; }
    RecentFiles* recentFiles() const { return m_recent; }
    PresetStore* presetStore() const { return m_presets; }
    Viewport* viewport() const { return m_viewport; }
    LightsDock* lightsDock() const { return m_lightsDock; }
    PropertiesDock* propertiesDock() const { return m_propertiesDock; }
    RenderSettingsDock* renderSettingsDock() const { return m_renderDock; }
    PresetsDock* presetsDock() const { return m_presetsDock; }
    QDockWidget* historyDock() const { return m_historyDock; }
    ModelDock* modelDock() const { return m_modelDock; }
    EditorActions* actions() const { return m_actions; }
    EditorStatusBar* editorStatusBar() const { return m_status; }
    EnvironmentLoading* environmentLoading() const { return m_environment; }
    EnvironmentLightTool* environmentLightTool() const { return m_environmentLight; }
    AbCompare* compare() const { return m_compare; }     // View › Compare A/B (issue 17)
    MixerDock* mixerDock() const { return m_mixerDock; } // issue 37: light mixing
    LinkTools* linkTools() const { return m_linkTools; } // issue 38: light linking (linktools.h)

    // Startup: the model and rig from the command line, else the last session's (when restoring), else the
    // bundled model lit by its sample rig (core/defaultrig.h). Restores geometry and dock layout when options
    // allow it.
    void openInitial(const EditorOptions& options);
    // The bundled model the editor opens on (issue 41): the Avocado (CC0), physically based, on a ground in
    // studio.exr with a soft key (resources/models/avocado/showcase.json).
    static QString bundledModelPath(); // ":/resources/models/avocado/Avocado.gltf"
    // The classic showcase, still bundled (File › Open sample): Suzanne, lit by the classic default rig.
    static QString suzannePath(); // ":/resources/models/suzanne/Suzanne.gltf"

  public slots:
    // The Mixer's Capture (issue 37): fills the Mixer dock with the current scene's RenderLayers
    // (MixerDock::setLayers). Until the raster and the path tracer split their renders into light groups it
    // only says so in the status bar.
    void captureMixerLayers();
    bool captureTracedLayers(); // false when the traced view has no layers to give

  protected:
    void closeEvent(QCloseEvent* event) override;
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;

  private:
    void createDocks();
    void connectStatus();
    void updateTitle();
    void saveSession();

    Document* m_doc;
    Scene* m_scene;
    ViewSettings* m_viewSettings;
    RecentFiles* m_recent;
    PresetStore* m_presets;
    DocumentFiles* m_files;
    Viewport* m_viewport;
    EditorStatusBar* m_status;
    LightsDock* m_lightsDock = nullptr;
    PropertiesDock* m_propertiesDock = nullptr;
    RenderSettingsDock* m_renderDock = nullptr;
    PresetsDock* m_presetsDock = nullptr;
    QDockWidget* m_historyDock = nullptr;
    ModelDock* m_modelDock = nullptr;
    EditorActions* m_actions = nullptr;
    EnvironmentLoading* m_environment = nullptr; // the rig's environment, loaded in the background
    EnvironmentLightTool* m_environmentLight = nullptr;
    AbCompare* m_compare = nullptr;
    MixerDock* m_mixerDock = nullptr;
    LinkTools* m_linkTools = nullptr;
    bool m_restoreSession = true;
};

} // namespace lr
