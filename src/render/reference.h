// The double-precision reference of a frame: the rig evaluated by src/core (lighting::shadeSurface<double>)
// at every pixel's surface point as the renderer's G-buffer recorded it (view-space position, normal,
// albedo, ks, shininess, emissive), then exposure, tone map and sRGB encoding exactly as the tone-map
// pass does them, rounded to 8 bits. The GPU's output at each quality tier is compared with it
// (imagecompare.h); docs/quality.md describes the method.
//
// The per-pixel evaluation runs on a thread pool (QtConcurrent, one task per row) and can be cancelled.
//
// Shadows (issue 14): when the rig has lights with hasShadow(), each such light's direct contribution
// (not its ambient) is multiplied by its traced visibility (referencetrace.h): shadow rays against the
// model's triangles and the ground's. The reference keeps each caster's visibility per pixel, and the
// shadow error measure (compareShadows) compares a tier's image with it outside the penumbra band.
//
// Environment (issue 15): when the rig has an environment and the renderer a loaded one, each covered
// pixel also gets what the environment adds, integrated as core/envintegrate.h defines it (no shadowing
// by the model, × occlusion), with its estimated error per pixel; uncovered pixels keep the background
// colour (a visible environment background is the GPU's alone and is not compared: covered pixels only).
//
// Area lights (issue 16): shade.h's shadeAreaLight would be the tiers' own approximation (LTC), so the
// reference evaluates them through shade.h with visibility 0 (their ambient only) and adds their direct
// terms integrated by core/areaintegrate.h (Monte Carlo, to half an 8-bit level of the displayed value),
// × the caster's traced visibility as for any light; the estimated error is kept per pixel.
//
// Light and shadow linking (issue 38, core/lightlink.h): when some light links, the tracer is built (with
// or without casters) with the parts' shadow-class masks, each pixel's part is the one the eye's ray meets
// there (ShadowTracer::surfaceSeen), and the pixel is shaded with the lights of that part's lighting class
// (ReferenceScene::lightsAt: a light that does not light it switched off, so each of its terms is exactly 0
// and areaintegrate leaves it out); a caster's shadow rays pass the parts outside its shadow set.
#pragma once

#include "core/envintegrate.h"
#include "core/gobo.h"
#include "core/imagecompare.h"
#include "core/prepare.h"
#include "floatimage.h"
#include "renderer.h"
#include "scene/environmentloader.h"
#include "scene/referencetrace.h"
#include "scene/scenedescription.h"

#include <QFuture>
#include <QImage>
#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace lr {

// What the reference needs besides the G-buffer: the lights prepared in double for the frame's view.
struct ReferenceScene {
    std::vector<lighting::ShadeLight<double>> lights;
    std::vector<std::shared_ptr<const IesProfile>> iesProfiles; // what lights[k].ies point to (issue 39)
    lighting::ShadeSettings<double> settings;
    double exposureEV = 0.0;
    ToneMap toneMap = ToneMap::Clamp;
    glm::dvec3 background{0.0}; // linear; uncovered pixels
    // Shadows: one emitter per entry of `lights` (casts = false for lights without a shadow; shadowMask
    // its linking's) and the tracer, null when no light casts and none links. viewToWorld maps the
    // G-buffer's view-space positions to world.
    std::vector<ShadowEmitter> emitters;
    std::shared_ptr<const ShadowTracer> tracer;
    glm::dmat4 viewToWorld{1.0};
    int casters() const;
    // Environment: the field integrated at every covered pixel (null: none) and when its integration
    // stops (exposure and tone map are the frame's: the error is counted in displayed 8-bit levels).
    std::shared_ptr<const envintegrate::EnvironmentField> environment;
    envintegrate::Convergence environmentConvergence;
    QString environmentSource; // LoadedEnvironment::source ("studio", "/abs/sky.exr")
    // Area lights: when their Monte Carlo stops (the frame's exposure and tone map).
    envintegrate::Convergence areaConvergence;
    bool hasAreaLights() const;
    // Light groups (issue 37; referencelayers.h setReferenceGroups): when count > 0 the job also keeps
    // each covered pixel's radiance per group. ofLight[k]: the group of lights[k] (-1: none); the others
    // the index of that group, -1 when the scene has none.
    struct Groups {
        int count = 0;
        std::vector<int> ofLight;
        int environment = -1, emissive = -1, ambient = -1;
    } groups;
    // Light linking, when some light links (else both empty): per lighting class, `lights` with those
    // that do not light it switched off (colour, specular and ambient 0); per part (scene/linkparts.h:
    // the model's meshes, then the ground), its lighting class.
    std::vector<std::vector<lighting::ShadeLight<double>>> lightsOfClass;
    std::vector<std::uint8_t> litClass;
    // The gobo images lights[k].gobo points into (issue 39, core/gobo.h), kept alive with the scene.
    std::vector<std::shared_ptr<const GoboImage>> gobos;
    bool linked() const { return !lightsOfClass.empty(); }
    // The lights a point of `part` is shaded with: `lights` without linking or for an unknown part (-1).
    std::span<const lighting::ShadeLight<double>> lightsAt(int part) const {
        if (part < 0 || size_t(part) >= litClass.size()) return lights;
        return lightsOfClass[litClass[size_t(part)]];
    }
};

// The reference scene of `rig` on `model` seen through `view` (the renderer's effective camera view
// matrix). With shadow casters or links in the rig it builds the tracer's scene (the model's triangles,
// and the ground's when rig.ground.mode != Off); null, with *error set, when Embree fails. Links are
// resolved over the model's parts and the ground's (SceneDescription::links()' parts).
// `environment`: what the renderer shades with (Renderer::environment()); integrated when the rig's
// environment is not None, at the rig's intensity and rotation.
std::optional<ReferenceScene>
makeReferenceScene(const Model& model, const Rig& rig, const SceneFrame& frame, const glm::dmat4& view,
                   const RenderSettings& settings, QString* error = nullptr,
                   const std::shared_ptr<const LoadedEnvironment>& environment = {});
// The same for what a renderer draws (Renderer::scene()): its model, rig, scene frame and environment.
std::optional<ReferenceScene> makeReferenceScene(const SceneDescription& scene, const glm::dmat4& view,
                                                 const RenderSettings& settings, QString* error = nullptr);

struct ReferenceImage {
    int width = 0, height = 0;
    std::vector<glm::dvec3> radiance;  // linear HDR before exposure, top row first; 0 where uncovered
    QImage srgb;                       // Format_RGBA8888, alpha 255: what the renderer should output
    std::vector<std::uint8_t> covered; // 1 where the G-buffer has a surface
    // Shadows, when the scene had casters (casters > 0):
    //   visibility  per pixel, per caster (pixel · casters + k, casters in rig order): 0 exactly unlit,
    //               255 exactly lit, 1..254 partly (visibility · 255 rounded, kept off 0 and 255); 255
    //               also where the caster's direct terms add nothing (not traced: it cannot matter)
    //   shadowClass per covered pixel: 0 not compared (the casters' direct light changes the 8-bit image
    //               by at most kShadowThresholdLevels there), 1 compared, 2 penumbra band (markShadowBand)
    int casters = 0;
    std::vector<std::uint8_t> visibility;
    std::vector<std::uint8_t> shadowClass;
    // Environment, when the scene had one: per pixel the integrator's estimated error (8-bit levels of
    // the displayed value, Estimate::errorLevels) and the sample pairs it took; 0 where uncovered.
    bool environment = false;
    std::vector<float> environmentError;
    std::vector<std::int32_t> environmentSamples;
    // Area lights, when the scene had any: per pixel the integrator's estimated error (8-bit levels,
    // areaintegrate::Estimate::errorLevels) and the points it took (all area lights); 0 where uncovered.
    bool area = false;
    std::vector<float> areaError;
    std::vector<std::int32_t> areaSamples;
    // Light groups, when the scene asked for them (ReferenceScene::groups): per pixel, per group (pixel ·
    // groupCount + g) the radiance the group adds, in double; they sum to `radiance` to double rounding.
    int groupCount = 0;
    std::vector<glm::dvec3> groupRadiance;
    bool isNull() const { return width <= 0 || height <= 0; }
};

// A pixel outside the penumbra band "differs" when some channel is more than this many 8-bit levels off
// the reference; the casters' light "matters" at a pixel when removing it changes some channel by more.
inline constexpr int kShadowThresholdLevels = 8;
// The band: pixels where some caster's visibility is partial, or changes within this many pixels.
inline constexpr int kShadowBandRadius = 2;

// Sets shadowClass to 2 on the penumbra band. ReferenceJob::finish() and computeReference() call it.
void markShadowBand(ReferenceImage* reference);

// The shadow error of a tier's 8-bit frame (any format; RGBA8888 compared) against the reference.
struct ShadowFigures {
    std::int64_t compared = 0;  // covered pixels outside the band where the casters' light matters
    std::int64_t differing = 0; // of those, more than kShadowThresholdLevels off in some channel
    double meanLevels = 0.0;    // mean |a − b| over the compared pixels × 3 channels
    std::int64_t band = 0;      // covered pixels in the penumbra band (not compared)
    double shareDiffering() const { return compared > 0 ? double(differing) / double(compared) : 0.0; }
};
ShadowFigures compareShadows(const QImage& frame, const ReferenceImage& reference);

// How well the reference's environment converged: covered pixels whose estimated error exceeds
// kEnvironmentTargetLevels (half an 8-bit level), the largest estimate and the mean sample pairs.
inline constexpr double kEnvironmentTargetLevels = 0.5;
struct EnvironmentConvergence {
    std::int64_t pixels = 0, over = 0;
    double maxErrorLevels = 0.0, meanErrorLevels = 0.0, meanSamples = 0.0;
    double shareOver() const { return pixels > 0 ? double(over) / double(pixels) : 0.0; }
};
EnvironmentConvergence environmentConvergence(const ReferenceImage& reference);
// The same figures for the area lights' integration (target: kEnvironmentTargetLevels, half a level).
EnvironmentConvergence areaConvergence(const ReferenceImage& reference);

// The tone-map pass on one radiance, in double: ×2^EV (EV clamped to ±60), tone map, sRGB, 0..255.
glm::dvec3 encodeSrgb(const glm::dvec3& radiance, double exposureEV, ToneMap op); // in [0, 1]
std::uint8_t toLevel(double srgb01); // round to nearest, as GL's unorm conversion

// Evaluates the reference, row by row on QThreadPool::globalInstance(). start() returns at once; the
// job must outlive the future. Cancel with future.cancel() (result() is then incomplete).
class ReferenceJob {
  public:
    ReferenceJob(GBuffer gbuffer, ReferenceScene scene);
    QFuture<void> start();
    // After the future finished (not cancelled): completes the shadow band. Idempotent.
    void finish();
    const ReferenceImage& result() const { return m_out; }
    int rows() const { return m_out.height; }

  private:
    void evaluateRow(int y);
    // Each caster's visibility at one pixel (into `visibility`, indexed like the scene's lights, and the
    // image's codes).
    void tracePixel(const lighting::Surface<double>& s, std::span<const lighting::ShadeLight<double>> lights,
                    size_t pixel, const glm::dvec3& point, const glm::dvec3& normal,
                    std::vector<double>& visibility);

    GBuffer m_gbuffer;
    ReferenceScene m_scene;
    ReferenceImage m_out;
    std::vector<int> m_rowIndices;
    bool m_finished = false;
};

// Blocking convenience (tests): the whole reference on the thread pool.
ReferenceImage computeReference(const GBuffer& gbuffer, const ReferenceScene& scene);

// Error figures of an 8-bit frame (any QImage format; converted to RGBA8888) against the reference,
// over the reference's covered pixels. nonFinite is left 0 (the caller counts it in its float buffer).
ErrorFigures compareWithReference(const QImage& frame, const ReferenceImage& reference);

} // namespace lr
