#include "snapshotrenderer.h"

#include "render/rasterlayers.h"

#include "render/offscreen.h"
#include "scene.h"

#include <QOpenGLContext>

namespace lr {

SnapshotRenderer::SnapshotRenderer(const Scene* scene) : m_scene(scene) {}

SnapshotRenderer::~SnapshotRenderer() {
    if (m_offscreen) m_offscreen->makeCurrent(); // the renderer releases its GL objects in its context
}

bool SnapshotRenderer::prepare(QString* error) {
    if (!m_offscreen) {
        auto offscreen = std::make_unique<OffscreenRenderer>();
        if (!offscreen->initialize(error)) return false;
        m_offscreen = std::move(offscreen);
        m_uploaded = nullptr;
    } else if (!m_offscreen->makeCurrent()) {
        if (error) *error = QObject::tr("could not make the offscreen OpenGL context current");
        return false;
    }
    if (m_uploaded != m_scene->model().get()) {
        m_keepAlive = m_scene->model();
        if (!m_offscreen->setModel(m_keepAlive, error)) {
            m_uploaded = nullptr;
            return false;
        }
        m_uploaded = m_keepAlive.get();
    }
    // The viewport's environment (scene.h), so a snapshot shows what the viewport does.
    if (m_offscreen->renderer().environment() != m_scene->environment())
        m_offscreen->renderer().setEnvironment(m_scene->environment());
    return true;
}

QImage SnapshotRenderer::render(const Rig& rig, const ViewCamera& camera, QSize size,
                                const RenderSettings& settings, int supersample, QString* error,
                                const TileProgress& progress, int tileSize) {
    const int call = ++m_renders;
    m_rigOwner = 0;
    QOpenGLContext* previous = QOpenGLContext::currentContext();
    QSurface* previousSurface = previous ? previous->surface() : nullptr;
    QImage image;
    if (prepare(error)) {
        m_offscreen->setRig(rig);
        const std::shared_ptr<const Model> model = m_keepAlive;
        QString problem; // a failure between tiles, not a cancellation
        TileProgress between;
        if (progress)
            between = [&](int done, int total) {
                if (!progress(done, total)) return false;
                if (m_renders == call) return true;
                // Something rendered through this object meanwhile (another rig, maybe a newer model):
                // put back what this render draws.
                if (m_uploaded != model.get()) {
                    m_keepAlive = model;
                    m_uploaded = m_offscreen->setModel(model, &problem) ? model.get() : nullptr;
                    if (!m_uploaded) return false;
                }
                m_offscreen->setRig(rig);
                m_renders = call;
                return true;
            };
        const int tileLimit = m_offscreen->maxTileSize();
        if (tileSize > 0) m_offscreen->setMaxTileSize(tileSize);
        image =
            m_offscreen->renderImage(camera, size, settings, std::clamp(supersample, 1, 4), error, between);
        if (tileSize > 0) m_offscreen->setMaxTileSize(tileLimit);
        if (!problem.isEmpty() && error) *error = problem;
    }
    if (previous && previousSurface) previous->makeCurrent(previousSurface);
    return image;
}

std::optional<RenderLayers> SnapshotRenderer::renderLayers(const Rig& rig, const ViewCamera& camera,
                                                           QSize size, const RenderSettings& settings,
                                                           QString* error) {
    ++m_renders;
    m_rigOwner = 0;
    QOpenGLContext* previous = QOpenGLContext::currentContext();
    QSurface* previousSurface = previous ? previous->surface() : nullptr;
    std::optional<RenderLayers> layers;
    if (prepare(error)) {
        m_offscreen->setRig(rig);
        const int side = m_offscreen->maxTileSize();
        if (size.width() > side || size.height() > side) size.scale(side, side, Qt::KeepAspectRatio);
        layers = renderRasterLayers(*m_offscreen, camera, size, settings, error);
    }
    if (previous && previousSurface) previous->makeCurrent(previousSurface);
    return layers;
}

std::unique_ptr<SnapshotJob> SnapshotRenderer::begin(const Rig& rig, const ViewCamera& camera, QSize size,
                                                     const RenderSettings& settings, int supersample,
                                                     int tileSize, QString* error) {
    QOpenGLContext* previous = QOpenGLContext::currentContext();
    QSurface* previousSurface = previous ? previous->surface() : nullptr;
    auto job = std::make_unique<SnapshotJob>();
    bool ok = prepare(error);
    if (ok) {
        job->rig = rig;
        job->model = m_keepAlive;
        job->environment = m_scene->environment();
        job->id = ++m_jobs;
        const int tileLimit = m_offscreen->maxTileSize();
        if (tileSize > 0) m_offscreen->setMaxTileSize(tileSize);
        ok = m_offscreen->beginImage(&job->tiles, camera, size, settings, supersample, error);
        if (tileSize > 0) m_offscreen->setMaxTileSize(tileLimit);
    }
    if (previous && previousSurface) previous->makeCurrent(previousSurface);
    return ok ? std::move(job) : nullptr;
}

bool SnapshotRenderer::renderNext(SnapshotJob* job, QString* error) {
    if (job->tiles.finished()) return true;
    QOpenGLContext* previous = QOpenGLContext::currentContext();
    QSurface* previousSurface = previous ? previous->surface() : nullptr;
    bool ok = m_offscreen && m_offscreen->makeCurrent();
    if (!ok && error) *error = QObject::tr("could not make the offscreen OpenGL context current");
    // Put back what this job draws if something rendered through this object since its last tile.
    if (ok && m_uploaded != job->model.get()) {
        m_keepAlive = job->model;
        ok = m_offscreen->setModel(job->model, error);
        m_uploaded = ok ? job->model.get() : nullptr;
    }
    if (ok && m_offscreen->renderer().environment() != job->environment)
        m_offscreen->renderer().setEnvironment(job->environment);
    if (ok && m_rigOwner != job->id) {
        m_offscreen->setRig(job->rig);
        m_rigOwner = job->id;
    }
    if (ok) ok = m_offscreen->renderNextTile(&job->tiles, error);
    if (previous && previousSurface) previous->makeCurrent(previousSurface);
    return ok;
}

} // namespace lr
