// The 3D viewport: a QOpenGLWidget (OpenGL 3.3 core) that owns a Renderer and shows the Scene's model lit by
// the Document's rig (solo applied), with light gizmos. Camera: orbit (left drag), pan (middle drag or
// Shift+left drag), dolly (wheel), frame (F), standard views, the model file's cameras, look through a spot
// light. Lights: click a gizmo to select it, drag it (Ctrl/Alt: along the view axis), drag a selected spot's
// cone edge, Shift+click the model to aim the selected lights, Ctrl+click it to place their highlight
// (GizmoInteraction), Alt+click it to link them to the part there (linktools.h); a plain click on the model
// moves no light. GL resources are released
// when the context goes away (QOpenGLContext::aboutToBeDestroyed).
#pragma once

#include "picking.h"
#include "render/dynamicresolution.h"
#include "scene/camera.h"
#include "scene/renderlayers.h"

#include <QOpenGLWidget>
#include <QTimer>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace lr {

class AbCompare;
class Document;
class GizmoInteraction;
struct LoadedEnvironment;
struct Rig;
class Scene;
class SnapshotRenderer;
class TracedView;
struct SnapshotJob;
class ViewSettings;
struct RenderSettings;
struct ScreenshotOptions;
struct ViewportRenderer;

class Viewport : public QOpenGLWidget {
    Q_OBJECT
  public:
    Viewport(Document* document, Scene* scene, ViewSettings* settings, QWidget* parent = nullptr);
    static constexpr double kFramedLightRadii = 12.0;
    ~Viewport() override;

    // Requests OpenGL 3.3 core (with a depth buffer and MSAA) for every context; call before QApplication.
    static void setDefaultSurfaceFormat();

    const ViewCamera& camera() const { return m_camera; }
    // The camera as drawn: automatic clip planes enclose the model and every light's gizmo.
    ViewCamera renderCamera() const;
    void setCamera(const ViewCamera& camera);
    // The camera a rig was saved with (Rig::view). With holdForModel (the model is still loading) the
    // next model keeps it instead of being framed.
    void showSavedView(const ViewCamera& camera, bool holdForModel);
    ScreenProjector projector() const; // widget pixels, the current camera
    std::optional<QPointF> lightScreenPosition(int row) const;
    GizmoInteraction* interaction() const { return m_interaction.get(); }
    TracedView* tracedView() const { return m_traced; } // the "Path traced" view (tracedview.h)
    bool hasRenderedFrame() const { return m_framesRendered > 0; }
    // Orbiting, panning, dollying or dragging a light right now: frames take the interactive settings.
    bool isNavigating() const { return m_navigating; }
    // The moving frames' size (dynamicresolution.h): the scale the next one takes (tests may tell it of a
    // frame), and the size the last frame was drawn at (empty before the first).
    DynamicResolution& movingResolution() { return m_moving; }
    QSize lastDrawnSize() const { return m_lastDrawnSize; }
    QString lastError() const { return m_error; }
    // The environment the viewport's renderer draws with (the Scene's, from the last frame on): tests.
    std::shared_ptr<const LoadedEnvironment> renderedEnvironment() const;

    // Offscreen renders of the current model with the current camera (same pixels as the viewport).
    QImage renderThumbnail(const Rig& rig, const QSize& size);
    // The screenshot's pixels; with progress, in tiles of options.tileSize between which progress runs
    // (render/offscreen.h TileProgress; false cancels: a null image, *error "cancelled").
    QImage renderScreenshot(const ScreenshotOptions& options, QString* error,
                            const std::function<bool(int done, int total)>& progress = {});
    // The same for another rig and camera: a turntable's frames (turntableexport.h).
    QImage renderScreenshot(const ScreenshotOptions& options, const Rig& rig, const ViewCamera& camera,
                            QString* error, const std::function<bool(int done, int total)>& progress = {});
    // The same a tile at a time (screenshotjob.h): begin fixes the rig as drawn, the camera and the settings
    // now; each renderScreenshotTile call renders the next tile. nullptr / false and *error on failure.
    std::unique_ptr<SnapshotJob> beginScreenshot(const ScreenshotOptions& options, QString* error);
    bool renderScreenshotTile(SnapshotJob* job, QString* error);
    // The view as drawn now (rig, camera, settings without gizmos) split into light groups, at most `size`
    // (the viewport's aspect): the Mixer dock's raster capture. nullopt and *error on failure.
    std::optional<RenderLayers> renderLayers(QSize size, QString* error);
    // Renders and writes it at once (screenshotexport.h: atomic): error text, "" on success.
    QString exportScreenshot(const ScreenshotOptions& options);

  public slots:
    void frameAll(); // the model
    // F: the model together with the selected lights (the model alone when none is selected).
    void frameSelectionOrAll();
    // Frames the model together with the gizmos of these lights (the README screenshot shows both).
    void frameModelAndLights(const QList<int>& rows);
    // The model and every light within kFramedLightRadii bounding radii of it (farther lights would leave
    // the model a dot). What a newly loaded model starts with, so the presets' key and fill are in view.
    void frameAllLights();
    // Says in the status bar when one of these lights (one just added) is off-screen; the camera stays.
    void reportLightsOutOfView(const QList<int>& rows);
    void setStandardView(const QString& name);
    void setModelCamera(int index);
    void lookThroughLight(int row);
    // While on, a plain click on the background emits environmentClicked (Ctrl+Alt+click always does).
    void setEnvironmentPicking(bool on) { m_pickEnvironment = on; }
    // A/B comparison (abcompare.h): while it is active, frames show A and B and the wipe line drags.
    void setCompare(AbCompare* compare);
    // Issue 38: the parts (scene/linkparts.h indices) to tint while the Properties dock's Linking section is
    // open: the parts the current light lights. renderSettings(gizmos) hands them to the renderer's overlay
    // (RenderSettings::highlightedParts) with the gizmos, so no screenshot without gizmos shows them.
    void setHighlightedParts(std::vector<int> parts);
    const std::vector<int>& highlightedParts() const { return m_highlightedParts; }

  signals:
    void environmentClicked(const QPointF& position); // "Light from environment" (environmentlighttool.h)
    void linkClicked(const QPointF& position);        // Alt+click that hit no gizmo (linktools.h)
    void frameRendered(double gpuMs, double cpuMs);
    void firstFrame();
    void statusMessage(const QString& text);

  protected:
    void initializeGL() override;
    void resizeGL(int w, int h) override;
    void paintGL() override;
    void focusInEvent(QFocusEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;

  private:
    enum class Navigation { None, Orbit, Pan, Gizmo, Wipe };
    void releaseGL();
    RenderSettings renderSettings(bool gizmos) const;
    void onModelChanged();
    double aspect() const;
    bool onScreen(int row) const;
    // Where the document's rig is drawn with the whole camera: the widget, or its half in a side-by-side
    // comparison; picking and gizmo drags work in it (mouse positions relative to its corner).
    QRectF documentRect() const;
    bool paintCompare(const QSize& size); // abcompareframe.h

    Document* m_doc;
    Scene* m_scene;
    ViewSettings* m_settings;
    std::unique_ptr<ViewportRenderer> m_gl; // everything that needs the GL context
    std::unique_ptr<GizmoInteraction> m_interaction;
    std::unique_ptr<SnapshotRenderer> m_snapshots;
    TracedView* m_traced; // a child QObject
    AbCompare* m_compare = nullptr;
    ViewCamera m_camera;
    bool m_cameraFramed = false;
    bool m_holdCamera = false; // showSavedView while the model loads: the next model is not framed
    bool m_modelDirty = true;
    bool m_rigDirty = true;
    Navigation m_nav = Navigation::None;
    QPointF m_pressPos, m_lastPos;
    bool m_moved = false;
    // Navigating or dragging (and briefly after each wheel step): frames take the interactive settings
    // (no MSAA, dense models as their proxy) and the full-quality frame follows when the motion stops.
    bool m_navigating = false;
    QTimer* m_settle = nullptr;
    void setNavigating(bool on);
    DynamicResolution m_moving; // ViewOptions::movingFrameRate's budget
    QSize m_lastDrawnSize;
    bool m_shiftPress = false;
    bool m_focusedByClick = false; // focusInEvent by a mouse press, not yet seen by mousePressEvent
    bool m_pressFocused = false;   // the current press is the one that gave the viewport the focus
    bool m_pickEnvironment = false;
    int m_framesRendered = 0;
    QString m_error;
    std::vector<int> m_highlightedParts; // issue 38: setHighlightedParts
};

} // namespace lr
