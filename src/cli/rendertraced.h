// The path-traced image of a loaded scene (src/trace), for `lightrig render --quality path` (single images,
// catalogs of models × rigs × views, turntables: renderrun.cpp) and `lightrig compare --quality path`: on
// the CPU, no OpenGL context and no display needed. The scene options (rig, --shading, --ground,
// --environment..., camera, size, exposure, tone map, --transparent) mean what they mean for the raster
// qualities; the options below are the path tracer's own.
#pragma once

#include "sceneoptions.h"

#include "render/rendersettings.h"
#include "scene/floatimage.h"
#include "scene/renderlayers.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>

namespace lr::trace {
class TraceScene;
}

namespace lr::cli {

struct TracedRenderOptions {
    int samples = 64;            // per pixel
    double timeLimit = 0.0;      // seconds; > 0: stop then (trace/progressive.h)
    double noiseThreshold = 0.0; // > 0: stop once the relative noise (PathTracer::noiseEstimate) is ≤ this
    int bounces = 8;             // surface interactions per path
    int threads = 0;             // 0: every core
    double fireflyClamp = 0.0;   // 0: off
    int seed = 0;                // the sampler's seed (trace::TraceSettings::seed)
    bool layers = false;         // also the light-group, albedo, normal and depth layers (Result::layers)
};

class TracedImages {
  public:
    explicit TracedImages(const TracedRenderOptions& options) : m_options(options) {}

    struct Result {
        QImage image;
        // "path traced, 64 samples per pixel, 8 bounces, 2 threads, 3.10 s (4754 samples/s), noise 0.02,
        // stopped by samples; 15964 triangles"
        QString line;
        int samples = 0;
        double seconds = 0.0; // tracing only
        double noise = 0.0;   // PathTracer::noiseEstimate at the end (+infinity under 2 samples)
        QString stoppedBy;    // "samples", "time" or "noise"
        FloatImage linear;    // the mean scene-linear radiance and coverage (premultiplied), for .exr
        // With TracedRenderOptions::layers: the traced scene's light groups (trace::TraceScene::groups),
        // their images summing to `linear`, albedo, normal and depth (trace::PathTracer::layers); its
        // beauty is `linear`. Empty otherwise.
        RenderLayers layers;
    };

    // `scene`'s model and environment lit by `rig`, seen from `camera` at `size` with `settings`' exposure,
    // tone map and transparent background. The traced scene (Embree, textures, the environment's
    // distribution) is built again only when the model, the environment or the rig changed, so the views
    // and the turning camera of one rig share it. Warnings (the scene's, non-finite samples) go to `warn`;
    // nullopt and *error when the scene cannot be traced (a classic-shading rig: the reason says so).
    std::optional<Result> render(const LoadedScene& scene, const Rig& rig, const ViewCamera& camera,
                                 QSize size, const RenderSettings& settings,
                                 const std::function<void(const QString&)>& warn, QString* error);

  private:
    TracedRenderOptions m_options;
    std::shared_ptr<const trace::TraceScene> m_scene;
    std::shared_ptr<const Model> m_model;
    std::shared_ptr<const LoadedEnvironment> m_environment;
    Rig m_rig;
};

// Bytes `lightrig render --quality path` holds for an image of `size` (the accumulation buffers, the display
// image, and the traced scene's share, about); with `layerGroups` > 0, rendering layers of that many light
// groups (TracedRenderOptions::layers): their sums per pixel and the RenderLayers images too.
std::int64_t tracedImageBytes(QSize size, int layerGroups = 0);
// False with the reason, naming --size (and the light groups, with layers), when that is more than this
// process may use (renderestimate.h's availableMemory) and `unchecked` (--no-memory-check) is false.
bool checkTracedMemory(QSize size, bool unchecked, QString* error, int layerGroups = 0);
// The light groups a traced render of `rig` splits into (trace::TraceScene::groups: rims left out), for
// checkTracedMemory before the model is loaded: `hasEmissive` (whether the model has emissive surfaces)
// true counts "emissive" whether or not it will be there (at most one group more than the render has).
int tracedLayerGroups(const Rig& rig, bool hasEmissive = true);

} // namespace lr::cli
