// The progressive path tracer of one view: samples accumulate per pixel in a float buffer, pass after
// pass, over square tiles on worker threads (a QThreadPool of its own). Sample k of pixel p draws its
// random numbers from (p, k, seed) alone (sampler.h), so the image is the same whatever the thread count
// or the tiling, and a pass cancelled half-way keeps its finished tiles (each pixel counts its own
// samples; the next pass goes on from there). What the editor's progressive view and the benchmark need:
// render(n) for n more samples per pixel, cancel() from any thread (a running render() returns within
// one tile's time), restart(), samplesDone(), image(), noiseEstimate().
//
// Layers (issue 37, docs/light-mixing.md), opt-in with setLayers(true): per pixel a double sum per light
// group (TraceScene::groups; tracePath's PathSplit) and sums of the first surface's base colour, world
// normal and view-axis depth, so layers() gives the RenderLayers whose group images sum to image(). Off,
// nothing of it is allocated and tracePath is asked for no split.
#pragma once

#include "camerarays.h"
#include "integrator.h"
#include "tracescene.h"

#include "core/types.h"
#include "scene/floatimage.h"
#include "scene/renderlayers.h"

#include <QImage>
#include <QSize>
#include <QThreadPool>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace lr::trace {

inline constexpr int kTileSize = 16;

// Per pixel, the layers' sums besides the groups' (PathTracer::setLayers): of the samples whose camera ray
// met a surface, its base colour, world normal and view-axis depth, and how many they were.
struct PixelLayerSums {
    glm::dvec3 albedo{0.0}, normal{0.0};
    double depth = 0.0;
    std::int64_t hits = 0;
};
// What the layers add to a pixel's accumulation: a dvec3 per group and PixelLayerSums.
constexpr std::size_t layerBytesPerPixel(std::size_t groups) {
    return groups * sizeof(glm::dvec3) + sizeof(PixelLayerSums);
}

class PathTracer {
  public:
    // threads: worker threads (0: QThread::idealThreadCount()).
    PathTracer(std::shared_ptr<const TraceScene> scene, const ViewCamera& camera, QSize size,
               TraceSettings settings = {}, int threads = 0);
    ~PathTracer();

    // Adds `samples` samples to every pixel (blocking). False when cancel() stopped it: finished tiles
    // keep their samples.
    bool render(int samples);
    void cancel() { m_cancel.store(true); }
    // Forgets every sample (and a pending cancel), the layers' too.
    void restart();
    // Layers on or off (off by default). A change forgets the samples taken (restart()): samples already
    // averaged cannot be split afterwards. Not while render() runs.
    void setLayers(bool on);
    bool layersOn() const { return m_layers; }
    // The fewest samples any pixel has.
    int samplesDone() const;
    // The image's remaining noise, relative: the root mean square over pixels of the standard error of
    // each pixel's mean luminance (Rec. 709; sample variance with n − 1, over that pixel's own sample
    // count n), divided by the mean over pixels of the pixel means' luminance. It falls as 1/√samples;
    // 0.01 is about 1 % noise. 0 for an image with no variance (a uniform sky, or an image of no
    // pixels); +infinity while any pixel has fewer than 2 samples (no variance to estimate yet) or when
    // the mean luminance is 0 while the variance is not. Never NaN.
    double noiseEstimate() const;
    std::int64_t nonFiniteSamples() const { return m_nonFinite.load(); }
    QSize size() const { return m_size; }
    int threads() const { return m_pool.maxThreadCount(); }
    // Bytes the per-pixel buffers hold (the layers' included).
    std::size_t bytes() const;

    // The mean of each pixel's samples: linear radiance (rgb) and coverage (alpha; with a transparent
    // background the radiance is of the covered share, unpremultiplied by display()).
    FloatImage image() const;
    // For display: × 2^exposureEV, tone map, sRGB, 8 bits (core/colour.h displayColour, as the raster's
    // tone-map pass); RGBA8888, straight alpha.
    QImage display(double exposureEV, ToneMap toneMap) const;
    // The layers of the samples taken: beauty = image(); with layers on, the scene's groups and their mean
    // images (rgb; alpha: the beauty's), summing to the beauty to float rounding, and of the first surface
    // the camera rays met: the mean base colour (albedo) and world shading normal (normal; not
    // renormalised), each over all of the pixel's samples (0 where a sample saw no surface: the
    // background, an area light or the shadow catcher), and the mean view-axis depth over the samples that
    // met one (depth, in rgb; kBackgroundDepth where none did); alpha: the beauty's. With layers off, the
    // beauty alone.
    RenderLayers layers() const;

  private:
    void renderTile(int tile, int samples);
    void addLayers(std::size_t pixel, const glm::dvec3& dir, const PathSplit& split);

    std::shared_ptr<const TraceScene> m_scene;
    CameraRays m_camera;
    QSize m_size;
    TraceSettings m_settings;
    QThreadPool m_pool;
    std::vector<glm::dvec4> m_sum; // per pixel: radiance, alpha
    std::vector<int> m_count;      // per pixel: samples taken
    // per pixel: the running mean of the samples' luminance and the sum of squared deviations from it
    // (Welford: exact 0 for equal samples, no cancellation)
    std::vector<glm::dvec2> m_luminance;
    bool m_layers = false;
    glm::dvec3 m_forward{0.0, 0.0, -1.0}; // the view axis, for depth
    std::vector<glm::dvec3> m_groupSum;   // layers: per pixel, per group (pixel-major): radiance
    std::vector<PixelLayerSums> m_layerSum;
    std::atomic<bool> m_cancel{false};
    std::atomic<std::int64_t> m_nonFinite{0};
    int m_tilesX = 0, m_tilesY = 0;
};

} // namespace lr::trace
