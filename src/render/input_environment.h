// The environment as a lit input (litinput.h): the scene description's loaded environment on the GPU
// (environmentgl.h), uploaded when it changed, and the frame's environment fields (FrameContext:
// rotation, intensity, the classic diffuse model, the background's level; PlanBit::Background when the
// environment is drawn behind the model). One still loading is planned with the rig's environment and
// waited for by RenderPlan::run before the first pass that reads resource::Environment (resolve()).
#pragma once

#include "environmentgl.h"
#include "litinput.h"

namespace lr::render {

class EnvironmentInput final : public LitInput {
  public:
    const char* name() const override { return "environment"; }
    void initialize(QOpenGLFunctions_3_3_Core* gl) override { m_gl.initialize(gl); }
    void release(QOpenGLFunctions_3_3_Core* gl) override { m_gl.release(gl); }
    bool prepare(InputFrame& f, QString* error) override;
    PassResources provides() const override { return m_lights ? PassResources(resource::Environment) : 0; }
    bool pending() const override;
    bool resolve(QOpenGLFunctions_3_3_Core* gl, QString* error, bool* inputError) override;
    void bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext& frame, bool clustered) const override;
    void setUniforms(QOpenGLFunctions_3_3_Core* gl, const MeshProgram& p, const FeatureKey& key,
                     const FrameContext& frame) const override;

    const EnvironmentGl& textures() const { return m_gl; } // the background pass draws them

  private:
    EnvironmentGl m_gl;
    SceneDescription* m_scene = nullptr; // this frame's (resolve() takes the loaded environment into it)
    bool m_lights = false;               // this frame has an environment (FrameContext::environment)
    bool m_warned = false;               // an upload failure was logged once
};

} // namespace lr::render
