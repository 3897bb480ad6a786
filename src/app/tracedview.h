// The viewport's "Path traced" view (issue 36): while the camera, the rig or anything else the picture
// depends on changes, the viewport shows its raster tier; once nothing changed for kSettleMs it accumulates
// path-traced samples (trace/pathtracer.h) at the viewport's full device resolution, shows the traced image
// over the raster one (TracedOverlay) with a readout of samples, seconds and estimated noise, stops at the
// first target of the view settings (samples, seconds, noise) and starts over on any change, except the
// exposure, the tone map and the targets: those act on the samples traced (the finished job is kept and
// run again to show them, or to go on to a raised target).
//
// The GUI thread never waits on the tracer. One worker (a QThreadPool of one thread) runs one job at a time:
// it builds the traced scene when the model, the rig or the environment changed (TraceScene::build, which
// refuses classic-shading rigs: the refusal is shown over the raster image), then renders passes of a few
// samples each and posts every pass's display image back (queued). A change cancels the running job
// (PathTracer::cancel: it returns within one tile) and queues the next; the superseded job ends on the
// worker, where its tracer is destroyed. Only the destructor waits, for a job's tile or a scene build.
#pragma once

#include "scene/renderlayers.h"

#include "scene/camera.h"
#include "viewsettings.h"

#include <QElapsedTimer>
#include <QImage>
#include <QObject>
#include <QSize>
#include <QThreadPool>
#include <QTimer>
#include <memory>

namespace lr {

class Document;
class Scene;
class TracedOverlay;
struct TracedInputs;
class TracedView : public QObject {
    Q_OBJECT
  public:
    enum class State {
        Off,      // the view settings do not ask for it
        Settling, // something changed; the raster image is shown until the view is still
        Building, // the traced scene is being built
        Tracing,  // passes accumulate
        Done,     // a target was reached
        Refused,  // the scene cannot be traced (a classic rig, no model): message()
    };
    static constexpr int kSettleMs = 150;

    // The overlay is a child of `viewport` (kept at its size); the view listens to the document's rig and
    // solo, the scene's model and environment and the view settings itself.
    TracedView(QWidget* viewport, Document* document, Scene* scene, ViewSettings* settings);
    ~TracedView() override;

    // Each frame the viewport draws: the camera as drawn and the size in device pixels; `changing` while
    // the user navigates or drags (or the view cannot show a traced image, as in A/B comparison).
    void viewDrawn(const ViewCamera& camera, const QSize& size, bool changing);

    State state() const { return m_state; }
    bool active() const { return m_state != State::Off; }
    // The latest pass's image (display colours, device pixels), null while none is current.
    const QImage& image() const { return m_image; }
    int samples() const { return m_samples; }
    double seconds() const { return m_seconds; }
    double noise() const { return m_noise; } // relative (PathTracer::noiseEstimate); < 0: none yet
    // Restarts since construction (tests: a change restarts).
    int restarts() const { return m_generation; }
    // Why the scene was refused, or why accumulation stopped.
    QString message() const { return m_message; }
    // The scene as drawn now (the camera of the last frame drawn), for a traced screenshot (tracedshot.h).
    TracedInputs inputs() const;
    // One line: the state, samples, seconds and noise, as the overlay shows it.
    QString readout() const;

    // Light-group layers (issue 37, the Mixer dock): with them on, the tracer keeps per light group sums
    // (trace/pathtracer.h setLayers; memory per pixel grows with the groups), so switching restarts the
    // samples. requestLayers asks for the layers of the samples so far: layersReady follows after the
    // current pass (at once when the view has stopped at its target); false when there is nothing to give
    // (layers off, no samples yet, no traced image).
    void setLayers(bool on);
    bool layers() const { return m_layers; }
    bool requestLayers();

  signals:
    void updated(); // a new image, state or readout
    void layersReady(const lr::RenderLayers& layers, int samples);

  private:
    struct Job;
    struct SceneCache;
    void restart(bool sceneChanged);
    void startJob();
    void cancelJob();
    void setState(State state);
    void onSettingsChanged();
    void onPass(int generation, const QImage& image, int samples, double seconds, double noise, bool done,
                const QString& why);
    void onSceneBuilt(int generation, int sceneRevision, bool ok, const QString& error);

    Document* m_doc;
    ViewOptions m_options; // as last seen
    Scene* m_scene;
    ViewSettings* m_settings;
    TracedOverlay* m_overlay;
    QTimer m_settle;
    QThreadPool m_worker;
    std::shared_ptr<Job> m_job;
    State m_state = State::Off;
    int m_generation = 0;     // of the job whose passes are shown
    int m_sceneRevision = 0;  // changes with the model, the rig and the environment
    int m_builtRevision = -1; // the scene revision the worker built last
    std::shared_ptr<SceneCache> m_cache;
    ViewCamera m_camera;
    QSize m_size;
    bool m_haveView = false;
    QImage m_image;
    int m_samples = 0;
    double m_seconds = 0.0;
    double m_noise = -1.0;
    QString m_message;
    bool m_layers = false;
};

} // namespace lr
