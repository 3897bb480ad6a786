// A render pass: one step of a frame in its own file (pass_*.cpp), declaring which targets it reads and
// writes, run in order by a RenderPlan (renderplan.h). A pass gets the frame (framecontext.h) and the
// scene (PassScene: programs, targets, GPU model, lit inputs); it leaves no state for another pass except
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

// The targets passes exchange. The lit inputs (litinput.h) provide Lights, Clusters and Environment before
// the first pass; the passes write the rest.
namespace resource {
enum : unsigned {
    Lights = 1u << 0,     // the packed light buffer
    Clusters = 1u << 1,   // the per-cluster light lists (when FrameContext::clustered)
    GBuffer = 1u << 2,    // the surfaces (gbuffer.h)
    SceneColor = 1u << 3, // display colours or radiance, possibly multisampled
    SceneDepth = 1u << 4,
    Resolved = 1u << 5, // single-sample scene colour and depth (MSAA resolved where needed)
    Output = 1u << 6,   // the caller's framebuffer
    // The casting lights' depth maps (shadowmaps.h), written by the shadow pass when some light casts.
    ShadowMaps = 1u << 7,
    // The environment's textures (environmentgl.h), provided by the environment input in a frame that
    // has an environment. One still loading (Renderer::setEnvironment with a future) is waited for before
    // the first pass that declares this read (RenderPlan::run): the passes before it run while it loads.
    Environment = 1u << 8,
};
// What a lit program samples when the frame has it: a lit pass reads these, and a read of one that no
// input provides and no pass of the chain writes is void (no light casts, no environment: the programs
// sample none). One that some pass writes must be written before it is read (RenderPlan::check).
constexpr unsigned kLitInputs = Lights | Clusters | ShadowMaps | Environment;
// What the G-buffer's keeping depends on: a pass writing any of these counts a revision (targets.h).
constexpr unsigned kDepthSharing = GBuffer | SceneDepth | Resolved;
} // namespace resource
using PassResources = unsigned;
QString describeResources(PassResources r); // "scene-color+scene-depth"

class ProgramCache;
class GpuModel;
class LitInputs;
struct Targets;

// What the passes share: the renderer's programs and targets, the GPU scene and the lit inputs
// (litinput.h). Filled by Renderer once per frame; everything else of the frame is the FrameContext.
struct PassScene {
    ProgramCache* programs = nullptr;
    Targets* targets = nullptr;
    GpuModel* model = nullptr; // the GPU scene (interaction proxies are uploaded on demand)
    const LitInputs* inputs = nullptr;
    RenderStats* stats = nullptr;
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
    // After run(): whether it left its written targets as they were (the G-pass keeping the G-buffer), so
    // RenderPlan::run counts no new revision of them (targets.h).
    virtual bool keptOutputs() const { return false; }

  protected:
    static bool fail(PassScene& scene, const QString& message) {
        scene.error = message;
        return false;
    }
};

} // namespace lr::render
