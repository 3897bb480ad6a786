// LightRig's OpenGL 3.3 core renderer, shared by the viewport, screenshots, the command line and the
// tests so that all of them produce the same pixels.
//
// Structure: what is drawn is a scene description (scene/scenedescription.h, no GL: the model, the rig, the
// ground, the environment), the same one the reference and the traced renderers read. Each frame Renderer
// computes a FrameContext once (framecontext.h), lets every lit input (litinput.h: lights, shadow maps,
// environment, ground) prepare itself from the description, and runs the RenderPlan (renderplan.h): a
// chain of passes in their own files (passes.h), rebuilt only when the kind of frame changes.
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

#include "core/prepare.h"
#include "core/quality.h"
#include "core/rig.h"
#include "floatimage.h"
#include "model/model.h"
#include "rendersettings.h"
#include "scene/camera.h"
#include "scene/environmentloader.h"
#include "scene/scenedescription.h"

#include <QColor>
#include <QFuture>
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
class LitInputs;
class RenderPlan;
class GpuTimer;
struct AttributeMaterial;
struct InputFrame;
struct PlanKey;
struct Targets;
struct ScaledOutput;
struct FrameContext;
struct PassScene;
} // namespace render

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
    const Rig& rig() const { return m_scene.rig(); }
    // What is drawn (the model uploaded, the rig, the ground, the environment), as every renderer reads it.
    const SceneDescription& scene() const { return m_scene; }
    // The rig's environment decoded and prefiltered (environmentloader.h), or nullptr: none. The rig's
    // Environment says how it is used (intensity, rotation, background); without a loaded environment a
    // rig's environment adds nothing. Cheap: textures are uploaded on the next frame.
    void setEnvironment(std::shared_ptr<const LoadedEnvironment> environment);
    // An environment still loading (loadEnvironment on a worker thread): the next frames are planned with
    // the rig's environment and run their passes up to the first that samples it (resource::Environment),
    // which waits for it. A load that failed fails that frame with its error, and later frames have no
    // environment. The command line starts it after the model's upload, so that its decoding and
    // prefiltering run beside the first frame's G-pass (docs/performance.md, "Where the time goes").
    void setEnvironment(QFuture<EnvironmentLoadResult> loading);
    // Waits for an environment still loading; false with its error when it did not load.
    bool waitForEnvironment(QString* error = nullptr);
    // Null for none and while one is loading.
    const std::shared_ptr<const LoadedEnvironment>& environment() const { return m_scene.environment(); }
    // The frame a `model`-space rig is anchored to: the model's bounding sphere (unit sphere without a
    // model).
    SceneFrame sceneFrame() const { return m_scene.frame(); }
    Bounds bounds() const { return m_scene.bounds(); }
    // The model's bounds grown by the ground (Rig::ground) when it is drawn: the camera's automatic clip
    // planes enclose this.
    Bounds drawnBounds() const { return m_scene.drawnBounds(); }

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
    // The last frame's chain of passes, "geometry (shaded) > present > overlay" (renderplan.h).
    QString renderPlan() const;

    // Replace a shader file's text (tests, live editing); empty restores the embedded one. Clears the cache.
    void setShaderSourceOverride(const QString& name, const QByteArray& source);

  private:
    bool fail(const QString& message, bool log = true); // log: as a warning (not for the caller's input)
    bool ensureTargets(QSize size, int samples, GLenum colorFormat);
    // RenderSettings::renderScale: the frame at drawSize into m_scaled, then stretched over targetFbo.
    bool renderScaled(const ViewCamera& camera, QSize size, QSize drawSize, const RenderSettings& settings,
                      GLuint targetFbo);
    render::FrameContext frameContext(const ViewCamera& camera, QSize size, const RenderSettings& settings,
                                      const QRect& tile) const;
    render::PassScene passScene();
    // Per frame, for render() and renderGBuffer() alike: every lit input prepares itself from the scene
    // description (filling `frame` and its bits of `plan`), then the frame's feature bits; false when one
    // failed (m_lastError says why).
    bool prepareInputs(render::FrameContext& frame, render::PlanKey& plan, render::InputFrame& inputs);
    // The deferred path's opaque materials, the visible ground's too (FrameContext::attributeMaterials);
    // empty when there are more than the attribute G-buffer takes.
    std::vector<render::AttributeMaterial> attributeMaterials() const;

    bool m_initialized = false;
    QOpenGLContext* m_context = nullptr;
    QString m_lastError;
    RenderStats m_stats;
    bool m_lastFrameHdr = false;
    SceneDescription m_scene; // what is drawn
    std::unique_ptr<render::ProgramCache> m_programs;
    std::unique_ptr<render::GpuModel> m_model;   // the GPU scene
    std::unique_ptr<render::LitInputs> m_inputs; // lights, shadow maps, environment, ground
    std::unique_ptr<render::Targets> m_targets;
    std::unique_ptr<render::ScaledOutput> m_scaled;
    std::unique_ptr<render::RenderPlan> m_plan;
    std::unique_ptr<render::GpuTimer> m_timer;
    int m_maxSamples = 0, m_maxTargetSize = 0;
};

} // namespace lr
