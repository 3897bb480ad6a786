// A render pass: one step of a frame in its own file (pass_*.cpp), declaring which targets it reads and
// writes, run in order by a RenderPlan (renderplan.h). A pass gets the frame (framecontext.h) and the
// scene (PassScene: GPU model, light set, targets, programs); it leaves no state for another pass except
// in the targets it declares. GL state a pass changes it restores to the defaults the next pass expects
// (depth test LESS with depth writes, no blending, no culling, texture unit 0 active).
#pragma once

#include "core/prepare.h"
#include "core/rig.h"
#include "framecontext.h"
#include "model/model.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QString>
#include <functional>
#include <vector>

namespace lr::render {

// The targets passes exchange. Lights and Clusters are filled by the light set before the plan runs.
namespace resource {
enum : unsigned {
    Lights = 1u << 0,     // the packed light buffer
    Clusters = 1u << 1,   // the per-cluster light lists (when FrameContext::clustered)
    GBuffer = 1u << 2,    // the surfaces (gbuffer.h)
    SceneColor = 1u << 3, // display colours or radiance, possibly multisampled
    SceneDepth = 1u << 4,
    Resolved = 1u << 5, // single-sample scene colour and depth (MSAA resolved where needed)
    Output = 1u << 6,   // the caller's framebuffer
    // The casting lights' depth maps (shadowmaps.h), written by the shadow pass when some light casts;
    // without casters nothing samples them, and the lit passes' read of them is void (RenderPlan::check).
    ShadowMaps = 1u << 7,
    // The environment's textures (environmentgl.h), there from the start of a frame that has an
    // environment. One still loading (Renderer::setEnvironment with a future) is waited for before the
    // first pass that declares this read (RenderPlan::run): the passes before it run while it loads.
    Environment = 1u << 8,
};
} // namespace resource
using PassResources = unsigned;
QString describeResources(PassResources r); // "scene-color+scene-depth"

class ProgramCache;
class EnvironmentGl;
class GpuModel;
class LightSet;
class ShadowMaps;
struct ShadowView;
struct Targets;

// What the passes share: the scene and the renderer's GL objects. Filled by Renderer once per frame.
struct PassScene {
    ProgramCache* programs = nullptr;
    const GpuModel* model = nullptr;  // the GPU scene
    GpuModel* mutableModel = nullptr; // interaction proxies are uploaded on demand
    const LightSet* lights = nullptr;
    Targets* targets = nullptr;
    const Rig* rig = nullptr;
    SceneFrame frame;
    Bounds bounds;      // the model's
    Bounds drawnBounds; // the model's and the ground's (when drawn): the deferred pass's scissor
    // Shadows: the casting lights' maps this frame (planShadows) and their cache; the ground (a one-mesh
    // model, nullptr when Rig::ground is off) and how it is drawn.
    const std::vector<ShadowView>* shadowViews = nullptr;
    ShadowMaps* shadows = nullptr;
    int modelGeneration = 0; // changes with every setModel: the maps re-render
    int groundRevision = 0;  // changes with every upload of the ground's mesh
    const GpuModel* ground = nullptr;
    GroundMode groundMode = GroundMode::Off;
    RenderStats* stats = nullptr;
    GLuint emptyVao = 0;    // for full-screen triangles
    GLuint fastSampler = 0; // the fast tier's texture filtering (F4)
    GLuint slotTexture = 0; // 1x1, for MeshPass::primeSamplerSlots
    // The environment's textures (environmentgl.h); used when FrameContext::environment.
    const EnvironmentGl* environment = nullptr;
    // Set while the frame's environment is still loading: waits for it and uploads it, false with the
    // reason in error when it did not load. RenderPlan::run calls it once, before the first pass reading
    // it.
    std::function<bool(PassScene& scene)> resolveEnvironment;
    QString error;           // why a pass failed
    bool inputError = false; // error is about the caller's input (an environment that did not load)
};

class RenderPass : protected QOpenGLFunctions_3_3_Core {
  public:
    virtual ~RenderPass() = default;
    virtual const char* name() const = 0;
    virtual PassResources reads() const = 0;
    virtual PassResources writes() const = 0;
    // GL objects of its own (context current); release() frees them.
    virtual bool initialize() { return initializeOpenGLFunctions(); }
    virtual void release() {}
    // False with scene.error set when it failed; later passes still run.
    virtual bool run(const FrameContext& frame, PassScene& scene) = 0;

  protected:
    static bool fail(PassScene& scene, const QString& message) {
        scene.error = message;
        return false;
    }
};

} // namespace lr::render
