// Offscreen renders of the current scene for the editor: screenshots ("Export screenshot", any size,
// supersampled, transparent) and preset thumbnails. Wraps an OffscreenRenderer (its own GL context, created
// on first use) that follows the Scene's model; the pixels match the viewport's (same Renderer).
#pragma once

#include "render/camera.h"
#include "render/renderer.h"

#include <QImage>
#include <memory>

namespace lr {

class OffscreenRenderer;
class Scene;

class SnapshotRenderer {
  public:
    explicit SnapshotRenderer(const Scene* scene);
    ~SnapshotRenderer();

    // A null image and *error on failure (no OpenGL, model upload failed, ...).
    QImage render(const Rig& rig, const ViewCamera& camera, QSize size, const RenderSettings& settings,
                  int supersample, QString* error);

  private:
    bool prepare(QString* error);

    const Scene* m_scene;
    std::unique_ptr<OffscreenRenderer> m_offscreen;
    const Model* m_uploaded = nullptr;
    std::shared_ptr<const Model> m_keepAlive;
};

} // namespace lr
