#include "tracedview.h"

#include "core/colour.h"
#include "editor/document.h"
#include "scene.h"
#include "scene/scenedescription.h"
#include "trace/pathtracer.h"
#include "tracedoverlay.h"
#include "tracedshot.h"
#include "viewsettings.h"

#include <QMutex>
#include <QPointer>
#include <algorithm>
#include <atomic>
#include <cmath>

namespace lr {

namespace {
constexpr double kPassSeconds = 0.4; // a pass's aim: the image updates about this often
constexpr int kMaxPassSamples = 16;

} // namespace

// One traced view: what it shows (camera, size, settings) and the scene it traces or builds. The worker
// owns the tracer; the GUI thread only cancels it (under `lock`, since the worker creates it).
// The traced scene of the latest scene revision a job built, shared by the jobs (which run one at a time on
// the worker): a camera change reuses it, and a job queued behind a build does not build again.
struct TracedView::SceneCache {
    QMutex lock;
    int revision = -1;
    std::shared_ptr<const trace::TraceScene> scene;
    QString error; // why it could not be built
};

struct TracedView::Job {
    int generation = 0;
    int sceneRevision = 0;
    std::shared_ptr<SceneCache> cache;
    std::shared_ptr<const Model> model; // what the scene is built from when the cache is older
    Rig rig;
    std::shared_ptr<const LoadedEnvironment> environment;
    ViewCamera camera;
    QSize size;
    trace::TraceSettings settings;
    bool layers = false;                 // the tracer keeps the light groups' layers (setLayers)
    std::atomic<bool> wantLayers{false}; // post them after the next pass (requestLayers)
    std::atomic<bool> cancelled{false};
    QMutex lock;
    std::unique_ptr<trace::PathTracer> tracer;
    // Under `lock`: the options the worker reads before every pass (the exposure, the tone map and the
    // targets may change while the samples are kept), their revision, and whether the worker runs the job.
    ViewOptions options;
    int optionsRevision = 0;
    bool running = false;
    double secondsBefore = 0.0; // tracing seconds of the job's earlier runs (the worker's only)

    // New display options or targets; true when the job has stopped and must be run again to show them.
    bool setOptions(const ViewOptions& o) {
        QMutexLocker locker(&lock);
        options = o;
        ++optionsRevision;
        return !running && !cancelled.load();
    }

    void cancel() {
        QMutexLocker locker(&lock);
        cancelled.store(true);
        if (tracer) tracer->cancel();
    }
    void run(QPointer<TracedView> view);
};

void TracedView::Job::run(QPointer<TracedView> view) {
    // Results go to the GUI thread, queued; a view that is gone (it waits for this job first) gets none.
    auto post = [&](auto&& f) {
        if (view) QMetaObject::invokeMethod(view.data(), std::forward<decltype(f)>(f), Qt::QueuedConnection);
    };
    {
        QMutexLocker locker(&lock);
        if (cancelled.load() || running) return;
        running = true;
    }
    // Every return below ends the run; the GUI thread runs the job again when it asks for more.
    struct Stopped {
        Job* job;
        ~Stopped() {
            QMutexLocker locker(&job->lock);
            job->running = false;
        }
    } stopped{this};
    std::shared_ptr<const trace::TraceScene> scene;
    QString error;
    bool built = false;
    {
        QMutexLocker locker(&cache->lock);
        if (cache->revision != sceneRevision) {
            SceneDescription description;
            description.setModel(model);
            description.setRig(rig);
            description.setEnvironment(environment);
            cache->scene =
                model && !model->meshes.empty() ? trace::TraceScene::build(description, &error) : nullptr;
            if (!cache->scene && error.isEmpty()) error = QObject::tr("no model is loaded");
            cache->error = error;
            cache->revision = sceneRevision;
            built = true;
        }
        scene = cache->scene;
        error = cache->error;
    }
    if (built || !scene) {
        const int g = generation, r = sceneRevision;
        post([v = view, g, r, ok = scene != nullptr, error] {
            if (v) v->onSceneBuilt(g, r, ok, error);
        });
    }
    if (!scene) return;
    {
        QMutexLocker locker(&lock);
        if (cancelled.load()) return;
        settings = viewTraceSettings(options, *scene); // the background: a change of it is a new job
        if (!tracer) {
            tracer = std::make_unique<trace::PathTracer>(scene, camera, size, settings);
            tracer->setLayers(layers);
        }
    }
    QElapsedTimer clock;
    clock.start();
    const double before = secondsBefore;
    double perSample = 0.0; // seconds, measured
    for (;;) {
        ViewOptions options;
        int revision;
        {
            QMutexLocker locker(&lock);
            options = this->options;
            revision = optionsRevision;
        }
        const int done = tracer->samplesDone();
        const double seconds = before + clock.nsecsElapsed() * 1e-9;
        secondsBefore = seconds;
        const double noise = done > 1 ? tracer->noiseEstimate() : -1.0; // relative; +inf: not yet
        QString why;
        if (options.traceSamples > 0 && done >= options.traceSamples)
            why = QObject::tr("target of %1 samples reached").arg(options.traceSamples);
        else if (options.traceSeconds > 0.0 && seconds >= options.traceSeconds)
            why = QObject::tr("time target of %1 s reached").arg(options.traceSeconds);
        else if (options.traceNoise > 0.0 && noise >= 0.0 && done >= 4 && noise <= options.traceNoise)
            why = QObject::tr("noise target of %1 % reached").arg(100.0 * options.traceNoise);
        if (done > 0 || !why.isEmpty()) {
            const QImage image = tracedDisplay(*tracer, options, false);
            const int g = generation;
            post([v = view, g, image, done, seconds, noise, finished = !why.isEmpty(), why] {
                if (v) v->onPass(g, image, done, seconds, noise, finished, why);
            });
        }
        if (done > 0 && tracer->layersOn() && wantLayers.exchange(false)) {
            // Between passes: no tile is being added to the sums.
            const int g = generation;
            post([v = view, g, layers = tracer->layers(), done] {
                if (v && g == v->m_generation) emit v->layersReady(layers, done);
            });
        }
        if (cancelled.load()) return;
        if (!why.isEmpty()) {
            QMutexLocker locker(&lock);
            if (optionsRevision != revision) continue; // new options came since: show them too
            running = false; // under the lock with the check: setOptions then knows to run the job again
            return;
        }
        // A pass of about kPassSeconds (one sample first, so the image appears at once).
        int n = perSample > 0.0 ? int(std::clamp(kPassSeconds / perSample, 1.0, double(kMaxPassSamples))) : 1;
        if (options.traceSamples > 0) n = std::min(n, options.traceSamples - done);
        QElapsedTimer pass;
        pass.start();
        if (!tracer->render(n)) return; // cancelled: a newer job follows
        perSample = pass.nsecsElapsed() * 1e-9 / n;
    }
}

TracedView::TracedView(QWidget* viewport, Document* document, Scene* scene, ViewSettings* settings)
    : QObject(viewport), m_doc(document), m_scene(scene), m_settings(settings),
      m_overlay(new TracedOverlay(this, viewport)), m_cache(std::make_shared<SceneCache>()) {
    m_worker.setMaxThreadCount(1);
    m_settle.setSingleShot(true);
    m_settle.setInterval(kSettleMs);
    connect(&m_settle, &QTimer::timeout, this, &TracedView::startJob);
    auto sceneChanged = [this] { restart(true); };
    connect(m_doc, &Document::rigChanged, this, sceneChanged);
    connect(m_doc, &Document::soloChanged, this, sceneChanged);
    connect(m_scene, &Scene::modelChanged, this, sceneChanged);
    connect(m_scene, &Scene::environmentChanged, this, sceneChanged);
    connect(m_settings, &ViewSettings::changed, this, &TracedView::onSettingsChanged);
    onSettingsChanged();
}

TracedView::~TracedView() {
    m_settle.stop();
    cancelJob();
    m_worker.clear();
    m_worker.waitForDone(); // a tile's time, or a scene build that cannot be cancelled
}

void TracedView::onSettingsChanged() {
    const ViewOptions& o = m_settings->options();
    if (!o.pathTraced) {
        cancelJob();
        m_settle.stop();
        m_image = QImage();
        setState(State::Off);
        return;
    }
    // Grid and gizmos are not in the traced image; everything else is.
    ViewOptions a = o;
    a.grid = m_options.grid;
    a.gizmos = m_options.gizmos;
    const bool same = a == m_options && m_state != State::Off;
    // The exposure, the tone map and the targets act on the samples already traced: the job shows them
    // with the new display, goes on to a raised target, or stops at a lowered one, without starting over.
    ViewOptions b = a;
    b.exposure = m_options.exposure;
    b.toneMap = m_options.toneMap;
    b.traceSamples = m_options.traceSamples;
    b.traceSeconds = m_options.traceSeconds;
    b.traceNoise = m_options.traceNoise;
    const bool keep = b == m_options && m_job && (m_state == State::Tracing || m_state == State::Done);
    m_options = o;
    if (same) return;
    if (!keep) return restart(false);
    const bool targets =
        b.traceSamples != o.traceSamples || b.traceSeconds != o.traceSeconds || b.traceNoise != o.traceNoise;
    if (targets && m_state == State::Done) setState(State::Tracing); // until the job says where it stops
    if (m_job->setOptions(o))
        m_worker.start([job = m_job, view = QPointer<TracedView>(this)] { job->run(view); });
}

void TracedView::viewDrawn(const ViewCamera& camera, const QSize& size, bool changing) {
    const bool same = m_haveView && camera == m_camera && size == m_size;
    m_camera = camera;
    m_size = size;
    m_haveView = true;
    if (!m_settings->options().pathTraced) return;
    if (changing || !same || m_state == State::Off) restart(false);
}

void TracedView::restart(bool sceneChanged) {
    if (sceneChanged) ++m_sceneRevision;
    if (!m_settings->options().pathTraced) return;
    cancelJob();
    ++m_generation;
    m_image = QImage();
    m_samples = 0;
    m_seconds = 0.0;
    m_noise = -1.0;
    if (m_state != State::Refused || sceneChanged) m_message.clear();
    // A refused scene stays refused until the scene changes: the camera moving does not build it again.
    if (!(m_state == State::Refused && m_builtRevision == m_sceneRevision)) setState(State::Settling);
    m_settle.start();
}

void TracedView::cancelJob() {
    if (m_job) m_job->cancel();
    m_job.reset();
}

void TracedView::startJob() {
    if (!m_haveView || !m_settings->options().pathTraced || m_size.isEmpty()) return;
    if (m_state == State::Refused && m_builtRevision == m_sceneRevision) return;
    auto job = std::make_shared<Job>();
    job->generation = m_generation;
    job->sceneRevision = m_sceneRevision;
    job->cache = m_cache;
    job->model = m_scene->model();
    job->rig = m_doc->renderRig();
    job->environment = m_scene->environment();
    job->camera = m_camera;
    job->size = m_size;
    job->options = m_settings->options();
    job->layers = m_layers;
    m_job = job;
    setState(m_builtRevision == m_sceneRevision ? State::Tracing : State::Building);
    m_worker.start([job, view = QPointer<TracedView>(this)] { job->run(view); });
}

void TracedView::onSceneBuilt(int generation, int sceneRevision, bool ok, const QString& error) {
    if (sceneRevision != m_sceneRevision) return; // the scene changed since
    m_builtRevision = sceneRevision;
    if (generation != m_generation) return;
    if (!ok) {
        m_message = error;
        m_job.reset();
        setState(State::Refused);
    } else {
        setState(State::Tracing);
    }
}

void TracedView::onPass(int generation, const QImage& image, int samples, double seconds, double noise,
                        bool done, const QString& why) {
    if (generation != m_generation) return; // a superseded job's last pass
    m_image = image;
    m_samples = samples;
    m_seconds = seconds;
    m_noise = noise;
    if (done) m_message = why; // the job is kept: a new exposure or a raised target goes on from it
    setState(done ? State::Done : State::Tracing);
    emit updated();
}

void TracedView::setLayers(bool on) {
    if (on == m_layers) return;
    m_layers = on;
    restart(false); // samples already averaged cannot be split afterwards
}

bool TracedView::requestLayers() {
    if (!m_layers || !m_job || m_samples <= 0 || (m_state != State::Tracing && m_state != State::Done))
        return false;
    m_job->wantLayers.store(true);
    if (m_job->setOptions(m_settings->options())) // stopped at its target: run it once more to post them
        m_worker.start([job = m_job, view = QPointer<TracedView>(this)] { job->run(view); });
    return true;
}

void TracedView::setState(State state) {
    m_state = state;
    emit updated();
}

TracedInputs TracedView::inputs() const {
    return {m_scene->model(), m_doc->renderRig(), m_scene->environment(), m_camera, m_settings->options()};
}

QString TracedView::readout() const {
    const QString noise = m_noise >= 0.0 && std::isfinite(m_noise)
                              ? tr(", noise %1 %").arg(100.0 * m_noise, 0, 'f', 2)
                              : QString();
    const QString progress = (m_samples == 1 ? tr("1 sample") : tr("%1 samples").arg(m_samples)) +
                             tr(", %1 s%2").arg(m_seconds, 0, 'f', 1).arg(noise);
    switch (m_state) {
    case State::Off:
        return {};
    case State::Settling:
        return tr("Path traced: waiting for the view to be still");
    case State::Building:
        return tr("Path traced: building the traced scene…");
    case State::Tracing:
        return m_samples > 0 ? tr("Path traced: %1").arg(progress) : tr("Path traced: first pass…");
    case State::Done:
        return tr("Path traced: %1 (%2)").arg(progress, m_message);
    case State::Refused:
        return tr("Path traced: not available: %1. The raster view is shown.").arg(m_message);
    }
    return {};
}

} // namespace lr
