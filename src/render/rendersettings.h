// What a frame is asked to be (RenderSettings, compared to decide when the render plan is rebuilt) and
// what it cost (RenderStats). No GL here.
#pragma once

#include "approximations.h"
#include "core/quality.h"
#include "core/types.h"

#include <QColor>
#include <QSize>
#include <QtGlobal>
#include <vector>

namespace lr {

// Forward: one pass shades every fragment of every triangle. Deferred: a G-pass writes the surfaces, then
// one full-screen pass shades each covered pixel once (no MSAA; much cheaper on software rasterisers,
// whose cost is whole 4x4 blocks per small triangle, but the G-pass costs about as much as a forward
// pass without lights). Both give the same radiance. Auto: deferred whenever msaaSamples <= 1, at any
// light count: the G-pass keeps the G-buffer while the view holds (GeometryPass::Key), so a frame in which
// only lights change costs the lighting pass alone (helmet_1pt exact: 3.6-4.1 ms deferred against 13-15 ms
// forward; while the camera moves forward is cheaper at one light, 14-18 against 18 ms, and dearer from a
// few lights on). From kDeferredMsaaMaxLights lights on, Auto shades deferred even when MSAA was asked
// for, without it: forward with MSAA 4 costs ~2.6x forward (64 lights: ~0.6 s a frame on llvmpipe against
// ~0.1 s deferred), which would freeze the editor.
enum class ShadingPath { Auto, Forward, Deferred };
constexpr int kDeferredMsaaMaxLights = 64;
constexpr double kMinRenderScale = 0.125;

struct RenderSettings {
    double exposureEV = 0.0;
    ToneMap toneMap = ToneMap::Clamp;
    QColor background = QColor(38, 38, 42); // sRGB
    bool transparentBackground = false;     // alpha 0 where there is no model (straight alpha)
    int msaaSamples = 4;                    // 0 or 1: off; clamped to what the driver offers
    bool showGizmos = false;
    bool showGrid = false;
    std::vector<int> selectedLights; // indices into the rig's lights, highlighted
    // Parts to highlight (the editor's light-linking view; viewport only: final renders leave it empty):
    // part indices as scene/linkparts.h numbers them (a model mesh's index, then the ground's meshes:
    // SceneDescription::groundPart). The overlay pass draws them tinted with highlightColor over the image,
    // their parts hidden behind other surfaces faintly; indices of no part are ignored. Cheap: one
    // position-only draw per highlighted mesh; the shading and the lighting programs are untouched.
    std::vector<int> highlightedParts;
    QColor highlightColor = QColor(255, 168, 0, 96); // sRGB, alpha = the tint's opacity on visible parts
    // How the rig is evaluated (docs/quality.md): Exact per pixel as src/core; Balanced per pixel with
    // measured cheaper evaluations; Fast per vertex (Gouraud), never MSAA (msaaSamples and the deferred
    // path are ignored). The G-buffer is always the exact per-pixel surface.
    Quality quality = Quality::Exact;
    // The über-shader: compile every light type and model into the lighting code whatever the rig uses
    // (for `lightrig bench`, to measure what specialising the shaders per scene saves). Same pixels.
    bool forceAllFeatures = false;
    // The balanced and fast tiers' approximations (approx:: bits in shadergen.h, docs/quality.md): what the
    // tiers ship with unless a measurement (`lightrig bench --approximations`) picks others.
    std::uint8_t approximations = render::approx::kDefault; // B1, B2, B4
    bool cullBackFaces = true; // single-sided materials; double-sided ones are never culled
    // The default path shades, exposes, tone-maps and encodes each fragment straight into an 8-bit target
    // (MSAA resolves display colours). The HDR path renders linear radiance into a float target and
    // tone-maps it in a full-screen pass (MSAA then resolves radiance); readRadiance() needs it.
    bool hdrTarget = false;
    bool hdrFloat32 = false; // HDR path: RGBA32F instead of RGBA16F
    // Clustered forward shading (render/cluster.h): -1 automatic (when more than a few lights have a
    // bounded range), 0 never, 1 always. Same pixels either way: it only skips exact zeros.
    int clusteredShading = -1;
    ShadingPath shadingPath = ShadingPath::Auto; // Deferred ignores msaaSamples
    // Deferred path: with at most kMaxAttributeMaterials opaque materials (none with vertex colours or
    // alpha MASK) the G-pass writes only the interpolated attributes and a stencil value per material, and
    // the lighting pass samples each material's textures once per pixel in whole 4x4 blocks
    // (shaders/surface.glsl), through kept Surface targets (pass_lighting.cpp). False (the default): the
    // G-pass writes Surfaces, sampling the textures itself. The same radiance either way
    // (tst_deferredtextures). The attribute G-buffer makes a frame of a moving camera 12-18 % cheaper on
    // the helmet alone (nothing on the helmet over a ground) but compiles one more program per material
    // and keeps four more full-size RGBA32F targets: the first draw took 150-600 ms longer on every bench
    // scene (docs/performance.md, "Where the time goes"), the frame of a still view is the same.
    bool deferredTextures = false;
    // Wait for the shadow maps a frame renders (glFinish) so that RenderStats::shadowMapMs is their own
    // time (tests/render/shadow_perf). False (the default): the rasteriser's threads draw the maps while
    // the main thread compiles and submits the passes that read them; the first frame of a scene with
    // casters was 40-70 ms shorter (docs/performance.md, "Where the time goes").
    bool waitForShadowMaps = false;
    // The view or a light is being dragged: dense models draw their interaction proxy (lod.h) once it is
    // built; the full mesh otherwise.
    bool interactive = false;
    // Draw the frame at this fraction of the output's width and height (every pass, the overlays too) and
    // stretch it over the output with bilinear filtering (render/scaledoutput.h): the editor's frame while
    // the view moves (dynamicresolution.h). Clamped to [kMinRenderScale, 1]; 1 (the default) draws at full
    // size. Ignored by tiles and the HDR path (files are always rendered at their size).
    double renderScale = 1.0;
    bool operator==(const RenderSettings&) const = default;
};

struct RenderStats {
    int shaderVariantsCompiled = 0; // since initialize()
    int shaderVariantsCached = 0;
    int lightsUploaded = 0; // in the last frame: enabled and able to reach the model
    int lightsInRig = 0;
    qint64 triangles = 0;
    int drawCalls = 0;
    bool deferred = false;         // the last frame took the deferred path
    bool deferredTextures = false; // ... with the attribute G-buffer (FrameContext::attributeMaterials)
    double lastGpuMs =
        -1.0; // GL_TIME_ELAPSED of a recent frame (asynchronous: a frame or two old); < 0: none yet
    bool clustered = false;        // the last frame used clustered shading
    qint64 clusterLightRefs = 0;   // its light-index list: global lights + per-cluster entries
    double lastCpuMs = 0.0;        // CPU time spent in the last render() call (GL submission, not completion)
    qint64 lightBytesUploaded = 0; // by the last light upload: only the texels that changed
    qint64 trianglesDrawn = 0;     // in the last frame (interaction proxies count their own)
    int renderPlanBuilds = 0; // pass chains built since initialize(): only when the kind of frame changes
    int backgroundBuilds =
        0; // environment backgrounds rendered into the kept image (passes.h BackgroundPass)
    // The deferred G-buffer (passes.h GeometryPass): drawn since initialize(), and whether the last frame
    // kept the one before instead of drawing the model again.
    int gbufferBuilds = 0;
    bool gbufferKept = false;
    // The kept surfaces (passes.h DeferredLightingPass): built since initialize(), and whether the last
    // frame shaded them.
    int surfaceBuilds = 0;
    bool surfacesKept = false;
    // Shadows (shadowmaps.h): casting lights this frame, the maps (lights) and layers (a point light's six
    // faces each) re-rendered by this frame, and the map array's size (0 without casters).
    int shadowCasters = 0;
    int shadowMapsRendered = 0;
    int shadowLayersRendered = 0;
    qint64 shadowMapBytes = 0;
    // Wall time of this frame's map renders (0: none rendered): their own time under
    // RenderSettings::waitForShadowMaps, else only their submission.
    double shadowMapMs = 0.0;
    // The size the last frame's passes drew at: the output's, or smaller under RenderSettings::renderScale.
    QSize drawnSize;
};

} // namespace lr
