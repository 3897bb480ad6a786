#include "input_ground.h"

#include "renderplan.h"
#include "scene/scenedescription.h"

namespace lr::render {

void GroundInput::release(QOpenGLFunctions_3_3_Core* gl) {
    m_gpu.release(gl);
    m_revision = -1;
}

bool GroundInput::prepare(InputFrame& f, QString* error) {
    const SceneDescription& scene = *f.scene;
    m_mode = scene.ground() ? scene.rig().ground.mode : GroundMode::Off;
    f.plan->set(PlanBit::Catcher, m_mode == GroundMode::Catcher);
    if (!scene.ground()) {
        if (m_gpu.model()) release(f.gl);
        return true;
    }
    if (m_gpu.model() && m_revision == scene.groundRevision()) return true;
    if (!m_gpu.upload(f.gl, scene.ground(), error)) {
        m_revision = -1;
        m_mode = GroundMode::Off;
        return false;
    }
    m_revision = scene.groundRevision();
    return true;
}

} // namespace lr::render
