// Offscreen renders of the current scene for the editor: screenshots ("Export screenshot", any size,
// supersampled, transparent) and preset thumbnails. Wraps an OffscreenRenderer (its own GL context, created
// on first use) that follows the Scene's model; the pixels match the viewport's (same Renderer).
#pragma once

#include "render/camera.h"
#include "render/offscreen.h"
#include "render/renderer.h"

#include <QImage>
#include <memory>

namespace lr {

class Scene;

class SnapshotRenderer {
  public:
    explicit SnapshotRenderer(const Scene* scene);
    ~SnapshotRenderer();

    // A null image and *error on failure (no OpenGL, model upload failed, ...). With progress: tiles of at
    // most tileSize rendered pixels a side (0: as large as the driver allows), progress called between
    // them (it may run the event loop, even render through this object again: thumbnails); false cancels.
    QImage render(const Rig& rig, const ViewCamera& camera, QSize size, const RenderSettings& settings,
                  int supersample, QString* error, const TileProgress& progress = {}, int tileSize = 0);

  private:
    bool prepare(QString* error);

    const Scene* m_scene;
    std::unique_ptr<OffscreenRenderer> m_offscreen;
    const Model* m_uploaded = nullptr;
    std::shared_ptr<const Model> m_keepAlive;
    int m_renders = 0; // render() calls so far: a change during progress means a nested render
};

} // namespace lr
