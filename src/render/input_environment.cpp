#include "input_environment.h"

#include "programcache.h"
#include "renderplan.h"
#include "scene/scenedescription.h"

#include <algorithm>
#include <cmath>

namespace lr::render {

bool EnvironmentInput::prepare(InputFrame& f, QString*) {
    SceneDescription& scene = *f.scene;
    m_scene = &scene;
    FrameContext& frame = *f.frame;
    const Environment& spec = scene.rig().environment;
    if (scene.environmentLoading()) {
        // Planned with the rig's environment; the first pass that samples it waits (resolve()).
        frame.environment = !spec.isNone();
    } else {
        QString error;
        if (!m_gl.update(f.gl, scene.environment(), &error) && !m_warned) {
            qCWarning(lcRender).noquote() << "environment lighting off:" << error;
            m_warned = true;
        }
        frame.environment = scene.environmentLights() && m_gl.ready();
    }
    m_lights = frame.environment;
    if (frame.environment) {
        frame.environmentUniforms.fromView = environmentFromView(frame.view, spec.rotation);
        frame.environmentUniforms.scale = float(std::exp2(std::clamp(spec.intensity, -20.0, 20.0)));
        frame.environmentUniforms.diffuse = environmentDiffuse(scene.rig());
        if (!frame.transparent && spec.background != EnvironmentBackground::Color)
            frame.environmentBackgroundLod =
                spec.background == EnvironmentBackground::Blurred
                    ? float(std::clamp(std::isfinite(spec.blur) ? spec.blur : 0.0, 0.0, 1.0) *
                            (kSpecularLevels - 1))
                    : 0.0f;
    }
    f.plan->set(PlanBit::Background, frame.environmentBackgroundLod >= 0.0f);
    return true;
}

bool EnvironmentInput::pending() const {
    return m_scene && m_scene->environmentLoading();
}

bool EnvironmentInput::resolve(QOpenGLFunctions_3_3_Core* gl, QString* error, bool* inputError) {
    if (!m_scene->waitForEnvironment(error)) {
        *inputError = true; // the caller reports its file
        return false;
    }
    return m_gl.update(gl, m_scene->environment(), error);
}

void EnvironmentInput::bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext& frame, bool) const {
    if (frame.environment) m_gl.bind(gl);
}

void EnvironmentInput::setUniforms(QOpenGLFunctions_3_3_Core* gl, const MeshProgram& p, const FeatureKey& key,
                                   const FrameContext& frame) const {
    if (frame.environment && key.rig.environment)
        m_gl.setUniforms(gl, p.program.get(), frame.environmentUniforms);
}

} // namespace lr::render
