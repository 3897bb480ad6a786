#include "input_lights.h"

#include "gpumodel.h"
#include "programcache.h"
#include "scene/scenedescription.h"

namespace lr::render {

void LightInput::release(QOpenGLFunctions_3_3_Core* gl) {
    m_set.release(gl);
    m_rigRevision = m_modelGeneration = -1;
}

bool LightInput::prepare(InputFrame& f, QString*) {
    const SceneDescription& scene = *f.scene;
    if (scene.rigRevision() != m_rigRevision) {
        m_set.setRig(scene.rig());
        m_rigRevision = scene.rigRevision();
    }
    if (scene.modelGeneration() != m_modelGeneration) {
        m_set.invalidate(); // a new scene frame
        m_modelGeneration = scene.modelGeneration();
    }
    // Lights are culled against everything drawn: the model and its ground.
    const SceneFrame reach = scene.reach();
    const LinkResolution& links = scene.links();
    m_set.update(f.gl, scene.frame(), f.frame->view, f.stats, f.shadowViews, &reach, &links, f.shaping);
    f.frame->lightCount = m_set.count();
    f.frame->linking = links.active;
    f.frame->farLights = m_set.farLights();
    return true;
}

void LightInput::prepareTargets(InputFrame& f) {
    FrameContext& frame = *f.frame;
    // Fast lights the vertices, each with every light: clusters (per fragment) do not apply.
    frame.clustered =
        !frame.fast && f.model->model() &&
        m_set.cluster(f.gl, frame.projection, frame.targetSize, frame.settings->clusteredShading, f.stats);
}

void LightInput::bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext&, bool clustered) const {
    m_set.bind(gl, clustered);
}

void LightInput::setUniforms(QOpenGLFunctions_3_3_Core* gl, const MeshProgram& p, const FeatureKey& key,
                             const FrameContext& frame) const {
    m_set.setUniforms(gl, p, frame.shade, key.clustered);
}

} // namespace lr::render
