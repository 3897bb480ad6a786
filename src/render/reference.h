// The double-precision reference of a frame: the rig evaluated by src/core (lighting::shadeSurface<double>)
// at every pixel's surface point as the renderer's G-buffer recorded it (view-space position, normal,
// albedo, ks, shininess, emissive), then exposure, tone map and sRGB encoding exactly as the tone-map
// pass does them, rounded to 8 bits. The GPU's output at each quality tier is compared with it
// (imagecompare.h); docs/quality.md describes the method.
//
// The per-pixel evaluation runs on a thread pool (QtConcurrent, one task per row) and can be cancelled.
#pragma once

#include "core/imagecompare.h"
#include "core/prepare.h"
#include "floatimage.h"
#include "renderer.h"

#include <QFuture>
#include <QImage>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

namespace lr {

// What the reference needs besides the G-buffer: the lights prepared in double for the frame's view.
struct ReferenceScene {
    std::vector<lighting::ShadeLight<double>> lights;
    lighting::ShadeSettings<double> settings;
    double exposureEV = 0.0;
    ToneMap toneMap = ToneMap::Clamp;
    glm::dvec3 background{0.0}; // linear; uncovered pixels
};

// The reference scene of `rig` seen through `view` (the renderer's effective camera view matrix).
ReferenceScene makeReferenceScene(const Rig& rig, const SceneFrame& frame, const glm::dmat4& view,
                                  const RenderSettings& settings);

struct ReferenceImage {
    int width = 0, height = 0;
    std::vector<glm::dvec3> radiance;  // linear HDR before exposure, top row first; 0 where uncovered
    QImage srgb;                       // Format_RGBA8888, alpha 255: what the renderer should output
    std::vector<std::uint8_t> covered; // 1 where the G-buffer has a surface
    bool isNull() const { return width <= 0 || height <= 0; }
};

// The tone-map pass on one radiance, in double: ×2^EV (EV clamped to ±60), tone map, sRGB, 0..255.
glm::dvec3 encodeSrgb(const glm::dvec3& radiance, double exposureEV, ToneMap op); // in [0, 1]
std::uint8_t toLevel(double srgb01); // round to nearest, as GL's unorm conversion

// Evaluates the reference, row by row on QThreadPool::globalInstance(). start() returns at once; the
// job must outlive the future. Cancel with future.cancel() (result() is then incomplete).
class ReferenceJob {
  public:
    ReferenceJob(GBuffer gbuffer, ReferenceScene scene);
    QFuture<void> start();
    const ReferenceImage& result() const { return m_out; }
    int rows() const { return m_out.height; }

  private:
    void evaluateRow(int y);

    GBuffer m_gbuffer;
    ReferenceScene m_scene;
    ReferenceImage m_out;
    std::vector<int> m_rowIndices;
};

// Blocking convenience (tests): the whole reference on the thread pool.
ReferenceImage computeReference(const GBuffer& gbuffer, const ReferenceScene& scene);

// Error figures of an 8-bit frame (any QImage format; converted to RGBA8888) against the reference,
// over the reference's covered pixels. nonFinite is left 0 (the caller counts it in its float buffer).
ErrorFigures compareWithReference(const QImage& frame, const ReferenceImage& reference);

} // namespace lr
