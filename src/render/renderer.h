// LightRig's OpenGL 3.3 core renderer, shared by the viewport, screenshots, the command line and the
// tests so that all of them produce the same pixels.
//
// Frame: the model is shaded with every light of the rig that can reach it (view space, a texture buffer
// of kLightTexels RGBA32F texels per light, any number of lights). By default each fragment is exposed
// (×2^EV), tone-mapped and sRGB-encoded at once into an 8-bit target (optionally MSAA), which is blitted
// (resolved) into the caller's framebuffer. With RenderSettings::hdrTarget the radiance goes to a float
// target instead and one full-screen pass applies the same exposure, tone map and encoding; both give
// the same pixels without MSAA. Gizmos and the grid are drawn over the result.
// Shaders are specialised per FeatureKey (shadergen.h): a value change (colour, position, intensity)
// only re-uploads light data; a new light type or model compiles one new variant, once.
//
// Every call needs the context that was current at initialize() to be current.
#pragma once

#include "camera.h"
#include "core/prepare.h"
#include "core/quality.h"
#include "core/rig.h"
#include "floatimage.h"
#include "model/model.h"

#include <QColor>
#include <QOpenGLFunctions_3_3_Core>
#include <QRect>
#include <QSize>
#include <QString>
#include <memory>
#include <vector>

class QOpenGLContext;
class QOpenGLShaderProgram;

namespace lr {

namespace render {
class ProgramCache;
class GpuModel;
class ClusterBuffers;
struct LightBounds;
struct Targets;
} // namespace render

// Forward: one pass shades every fragment of every triangle. Deferred: a G-pass writes the surfaces, then
// one full-screen pass shades each covered pixel once (no MSAA; much cheaper on software rasterisers,
// whose cost is whole 4x4 blocks per small triangle, but the G-pass costs about as much as a forward
// pass without lights). Both give the same radiance. Auto: deferred when msaaSamples <= 1 and at least
// kDeferredMinLights lights are uploaded (measured crossover on llvmpipe, DamagedHelmet at 1280x720:
// forward ~17 + 3.3 n ms CPU, deferred ~30 + 1.1 n), else forward. From kDeferredMsaaMaxLights lights on,
// Auto shades deferred even when MSAA was asked for, without it: forward with MSAA 4 costs ~2.6x forward
// (64 lights: ~0.6 s a frame on llvmpipe against ~0.1 s deferred), which would freeze the editor.
enum class ShadingPath { Auto, Forward, Deferred };
constexpr int kDeferredMinLights = 6;
constexpr int kDeferredMsaaMaxLights = 64;

struct RenderSettings {
    double exposureEV = 0.0;
    ToneMap toneMap = ToneMap::Clamp;
    QColor background = QColor(38, 38, 42); // sRGB
    bool transparentBackground = false;     // alpha 0 where there is no model (straight alpha)
    int msaaSamples = 4;                    // 0 or 1: off; clamped to what the driver offers
    bool showGizmos = false;
    bool showGrid = false;
    std::vector<int> selectedLights; // indices into the rig's lights, highlighted
    // How the rig is evaluated (docs/quality.md): Exact per pixel as src/core; Balanced per pixel with
    // measured cheaper evaluations; Fast per vertex (Gouraud), never MSAA (msaaSamples and the deferred
    // path are ignored). The G-buffer is always the exact per-pixel surface.
    Quality quality = Quality::Exact;
    // The über-shader: compile every light type and model into the lighting code whatever the rig uses
    // (for `lightrig bench`, to measure what specialising the shaders per scene saves). Same pixels.
    bool forceAllFeatures = false;
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
    // The view or a light is being dragged: dense models draw their interaction proxy (lod.h) once it is
    // built; the full mesh otherwise.
    bool interactive = false;
    bool operator==(const RenderSettings&) const = default;
};

struct RenderStats {
    int shaderVariantsCompiled = 0; // since initialize()
    int shaderVariantsCached = 0;
    int lightsUploaded = 0; // in the last frame: enabled and able to reach the model
    int lightsInRig = 0;
    qint64 triangles = 0;
    int drawCalls = 0;
    bool deferred = false; // the last frame took the deferred path
    double lastGpuMs =
        -1.0; // GL_TIME_ELAPSED of a recent frame (asynchronous: a frame or two old); < 0: none yet
    bool clustered = false;        // the last frame used clustered shading
    qint64 clusterLightRefs = 0;   // its light-index list: global lights + per-cluster entries
    double lastCpuMs = 0.0;        // CPU time spent in the last render() call (GL submission, not completion)
    qint64 lightBytesUploaded = 0; // by the last light upload: only the texels that changed
    qint64 trianglesDrawn = 0;     // in the last frame (interaction proxies count their own)
};

class Renderer : protected QOpenGLFunctions_3_3_Core {
  public:
    Renderer();
    ~Renderer(); // releases GL resources if their context is current, else warns
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Needs a current OpenGL 3.3 (or later) core profile context.
    bool initialize(QString* error);
    bool isInitialized() const { return m_initialized; }
    QOpenGLContext* context() const { return m_context; }

    // Uploads the model (nullptr: no model). False (with lastError) if the upload failed; nothing is drawn
    // then.
    bool setModel(std::shared_ptr<const Model> model);
    // Blocks until the model's interaction proxies (lod.h) are built and uploaded; false when it has none
    // (small models). The viewport never waits: it draws the full mesh until they are ready.
    bool waitForInteractionProxies();
    const Model* model() const;
    void setRig(const Rig& rig); // cheap: no GL work here; light data is refreshed on the next frame
    const Rig& rig() const { return m_rig; }
    // The frame a `model`-space rig is anchored to: the model's bounding sphere (unit sphere without a
    // model).
    SceneFrame sceneFrame() const;
    Bounds bounds() const;

    // Renders into targetFbo (0: the default framebuffer), which must be at least `size` (or tile.size()).
    // `tile`, when valid, is the part of a size-pixel image to draw (image coordinates, top-left origin);
    // the target then receives only that part. False with lastError() when something failed.
    bool render(const ViewCamera& camera, QSize size, const RenderSettings& settings, GLuint targetFbo,
                const QRect& tile = QRect());
    // The last frame's resolved radiance (before exposure and tone mapping; alpha = coverage). Needs the
    // last render() to have used RenderSettings::hdrTarget.
    bool readRadiance(FloatImage* out);
    // Draws the G-buffer for this view and reads it back (no MSAA, float targets; what the deferred path
    // shades).
    bool renderGBuffer(const ViewCamera& camera, QSize size, const RenderSettings& settings, GBuffer* out,
                       const QRect& tile = QRect());

    // The camera as render() uses it: automatic clip planes filled in from the scene.
    ViewCamera effectiveCamera(const ViewCamera& camera) const;

    void releaseResources(); // the viewport calls this from QOpenGLContext::aboutToBeDestroyed
    const RenderStats& stats() const { return m_stats; }
    QString lastError() const { return m_lastError; }
    int maxSamples() const { return m_maxSamples; }
    int maxTargetSize() const { return m_maxTargetSize; } // largest width/height of one render target

    // Replace a shader file's text (tests, live editing); empty restores the embedded one. Clears the cache.
    void setShaderSourceOverride(const QString& name, const QByteArray& source);

  private:
    bool fail(const QString& message);
    bool ensureTargets(QSize size, int samples, GLenum colorFormat);
    void uploadLights(const glm::dmat4& view);
    bool drawModel(const glm::dmat4& view, const glm::dmat4& projection, const RenderSettings& settings,
                   int output); // render::ShaderOutput
    bool lightingPass(const RenderSettings& settings, bool hdr, const QRect& scissor);
    bool toneMapPass(QSize size, const RenderSettings& settings, GLuint targetFbo);
    bool gizmoPass(const glm::dmat4& view, const glm::dmat4& projection, double znear,
                   const RenderSettings& settings, QSize size);
    void beginTimer();
    void endTimer();
    bool readAttachment(GLuint fbo, GLenum attachment, QSize size, FloatImage* out);

    bool m_initialized = false;
    QOpenGLContext* m_context = nullptr;
    QString m_lastError;
    RenderStats m_stats;
    Rig m_rig;
    bool m_lightsDirty = true;
    bool m_lastFrameHdr = false;
    glm::dmat4 m_uploadedView{0.0};
    std::unique_ptr<render::ProgramCache> m_programs;
    std::unique_ptr<render::GpuModel> m_model;
    std::unique_ptr<render::Targets> m_targets;
    std::unique_ptr<render::ClusterBuffers> m_clusters;
    std::vector<render::LightBounds> m_lightBounds; // per uploaded light, view space
    int m_boundedLights = 0;
    bool clusterLights(const glm::dmat4& projection, const RenderSettings& settings);
    void setClusterUniforms(QOpenGLShaderProgram* program);
    glm::vec4 m_clusterUniforms{0.0f}; // tile scale x, y, near, slice scale
    glm::ivec3 m_clusterGrid{0};
    int m_clusterGlobal = 0;
    glm::dmat4 m_drawProjection{1.0}; // the last drawModel's: the deferred lighting pass bins with it
    GLuint m_lightBuffer = 0, m_lightTexture = 0;
    GLuint m_fastSampler = 0;          // the fast tier's texture filtering (F4)
    std::vector<float> m_packedLights; // what the light buffer holds, to upload only what changed
    int m_lightCapacity = 0;           // lights the buffer holds
    GLuint m_emptyVao = 0;
    GLuint m_gizmoVao = 0, m_gizmoVbo = 0;
    GLuint m_queries[4] = {};
    int m_queryNext = 0, m_queriesPending = 0;
    int m_maxSamples = 0, m_maxTargetSize = 0;
};

} // namespace lr
