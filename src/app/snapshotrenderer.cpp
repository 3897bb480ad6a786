#include "snapshotrenderer.h"

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
    return true;
}

QImage SnapshotRenderer::render(const Rig& rig, const ViewCamera& camera, QSize size,
                                const RenderSettings& settings, int supersample, QString* error) {
    QOpenGLContext* previous = QOpenGLContext::currentContext();
    QSurface* previousSurface = previous ? previous->surface() : nullptr;
    QImage image;
    if (prepare(error)) {
        m_offscreen->setRig(rig);
        image = m_offscreen->renderImage(camera, size, settings, std::clamp(supersample, 1, 4), error);
    }
    if (previous && previousSurface) previous->makeCurrent(previousSurface);
    return image;
}

} // namespace lr
