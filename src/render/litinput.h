// The lit inputs: what a lit program reads besides its material, each owned by one object behind one
// interface (Filament's idea of passes that declare what they read, applied to the scene's inputs). The
// lights with their LTC table and clusters (input_lights.h), the shadow maps (input_shadows.h), the
// environment (input_environment.h) and the ground (input_ground.h). Each one, every frame:
//   prepare()         builds its GL objects from the scene description (scene/scenedescription.h),
//                     uploading only what changed, and fills its part of the frame: its FrameContext
//                     fields (the lit programs' feature bits are made from them: FrameContext::features)
//                     and its plan bits (PlanKey);
//   provides()        declares the resources it makes available before the first pass (RenderPlan::check
//                     verifies every pass's reads against them and the passes' writes);
//   resolve()         finishes one still being made (an environment loading), called by RenderPlan::run
//                     before the first pass that reads it;
//   bind(), setUniforms(), unbind()   give a lit program its textures and uniforms: the forward, deferred,
//                     blend and catcher passes all go through LitInputs, never through an input by name.
// Renderer::render loops over the inputs and never branches on a feature. Adding an input is its own file
// plus one registration line in litinputs.cpp (docs/architecture.md, "Where to add things").
#pragma once

#include "renderlog.h"
#include "renderpass.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QString>
#include <memory>
#include <vector>

namespace lr {
class SceneDescription;
}

namespace lr::render {

struct FeatureKey;
struct MeshProgram;
struct PlanKey;
struct ShadowView;
struct ShapingLayers;

// One frame as the inputs prepare it, in registration order: an input may read what an earlier one left
// (the light buffer packs the shadow plan's slots).
struct InputFrame {
    QOpenGLFunctions_3_3_Core* gl = nullptr;
    SceneDescription* scene = nullptr; // the environment input takes a loaded environment into it
    const GpuModel* model = nullptr;   // the GPU scene
    FrameContext* frame = nullptr;     // the inputs fill their fields
    PlanKey* plan = nullptr;           // ... and their plan bits
    RenderStats* stats = nullptr;
    // The shadow input's plan for this frame (empty without casters).
    const std::vector<ShadowView>* shadowViews = nullptr;
    // The shaping input's layers per rig light (lightshapinggl.h), for the light buffer.
    const ShapingLayers* shaping = nullptr;
};

class LitInput {
  public:
    virtual ~LitInput() = default;
    virtual const char* name() const = 0;
    virtual void initialize(QOpenGLFunctions_3_3_Core* gl) { (void)gl; }
    virtual void release(QOpenGLFunctions_3_3_Core* gl) = 0;
    // Before the frame's targets exist. False with *error when the frame cannot be drawn.
    virtual bool prepare(InputFrame& f, QString* error) = 0;
    // Once the targets exist (the frame's projection and size are final; the fast tier never bins).
    virtual void prepareTargets(InputFrame& f) { (void)f; }
    // Resources (renderpass.h) there before the first pass runs, this frame.
    virtual PassResources provides() const { return 0; }
    // Whether a resource it provides is still being made; resolve() finishes it (false: the frame fails,
    // *inputError when the caller's input is at fault, such as an environment file that did not load).
    virtual bool pending() const { return false; }
    virtual bool resolve(QOpenGLFunctions_3_3_Core* gl, QString* error, bool* inputError) {
        (void)gl, (void)error, (void)inputError;
        return true;
    }
    // Its textures for the lit programs about to draw (`clustered`: they read the cluster lists).
    virtual void bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext& frame, bool clustered) const {
        (void)gl, (void)frame, (void)clustered;
    }
    // Its uniforms on the bound program `p`, compiled for `key`.
    virtual void setUniforms(QOpenGLFunctions_3_3_Core* gl, const MeshProgram& p, const FeatureKey& key,
                             const FrameContext& frame) const {
        (void)gl, (void)p, (void)key, (void)frame;
    }
    virtual void unbind(QOpenGLFunctions_3_3_Core* gl) const { (void)gl; }
};

// The registered inputs (litinputs.cpp), in their order.
class LitInputs {
  public:
    LitInputs();
    ~LitInputs();
    void initialize(QOpenGLFunctions_3_3_Core* gl);
    void release(QOpenGLFunctions_3_3_Core* gl);
    bool prepare(InputFrame& f, QString* error);
    void prepareTargets(InputFrame& f);
    PassResources provides() const;
    // Finishes every pending input that provides one of `reads` (with the context prepare() had); false
    // with the first failure.
    bool resolve(PassResources reads, QString* error, bool* inputError) const;
    void bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext& frame, bool clustered) const;
    void setUniforms(QOpenGLFunctions_3_3_Core* gl, const MeshProgram& p, const FeatureKey& key,
                     const FrameContext& frame) const;
    void unbind(QOpenGLFunctions_3_3_Core* gl) const;
    // The input of type T (a pass that draws one, such as the shadow pass or the background); nullptr
    // when it is not registered.
    template <typename T> T* find() const {
        for (const auto& i : m_inputs)
            if (auto* t = dynamic_cast<T*>(i.get())) return t;
        return nullptr;
    }

  private:
    std::vector<std::unique_ptr<LitInput>> m_inputs;
    QOpenGLFunctions_3_3_Core* m_gl = nullptr; // prepare()'s
};

} // namespace lr::render
