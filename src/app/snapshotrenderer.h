// Offscreen renders of the current scene for the editor: screenshots ("Export screenshot", any size,
// supersampled, transparent) and preset thumbnails. Wraps an OffscreenRenderer (its own GL context, created
// on first use) that follows the Scene's model; the pixels match the viewport's (same Renderer).
#pragma once

#include "render/offscreen.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/renderlayers.h"

#include <QImage>
#include <memory>
#include <optional>

namespace lr {

class Scene;
struct LoadedEnvironment;

// A screenshot rendered a tile at a time (SnapshotRenderer::begin / renderNext): the rig, the camera, the
// settings, the model and the environment as they were when it began, so edits made meanwhile do not
// change it.
struct SnapshotJob {
    Rig rig;
    std::shared_ptr<const Model> model;
    std::shared_ptr<const LoadedEnvironment> environment;
    TiledImage tiles;
    int id = 0; // which job last set the offscreen renderer's rig (SnapshotRenderer::m_rigOwner)
};

class SnapshotRenderer {
  public:
    explicit SnapshotRenderer(const Scene* scene);
    ~SnapshotRenderer();

    // A null image and *error on failure (no OpenGL, model upload failed, ...). With progress: tiles of at
    // most tileSize rendered pixels a side (0: as large as the driver allows), progress called between
    // them (it may run the event loop, even render through this object again: thumbnails); false cancels.
    QImage render(const Rig& rig, const ViewCamera& camera, QSize size, const RenderSettings& settings,
                  int supersample, QString* error, const TileProgress& progress = {}, int tileSize = 0);

    // A job of tiles of at most tileSize rendered pixels a side (0: as large as the driver allows); nullptr
    // and *error when it cannot start. renderNext renders its next tile (thumbnails may render through this
    // object between two calls): false and *error on failure.
    std::unique_ptr<SnapshotJob> begin(const Rig& rig, const ViewCamera& camera, QSize size,
                                       const RenderSettings& settings, int supersample, int tileSize,
                                       QString* error);
    bool renderNext(SnapshotJob* job, QString* error);

    // The scene split into light groups (render/rasterlayers.h: the beauty, a linear image per group,
    // albedo, normal, depth) for the Mixer dock; `size` within one tile. nullopt and *error on failure.
    std::optional<RenderLayers> renderLayers(const Rig& rig, const ViewCamera& camera, QSize size,
                                             const RenderSettings& settings, QString* error);

  private:
    bool prepare(QString* error);
    int m_rigOwner = 0; // the job whose rig the offscreen renderer holds (0: another render's)
    int m_jobs = 0;

    const Scene* m_scene;
    std::unique_ptr<OffscreenRenderer> m_offscreen;
    const Model* m_uploaded = nullptr;
    std::shared_ptr<const Model> m_keepAlive;
    int m_renders = 0; // render() calls so far: a change during progress means a nested render
};

} // namespace lr
