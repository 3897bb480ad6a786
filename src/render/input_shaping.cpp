#include "input_shaping.h"

#include "scene/scenedescription.h"

namespace lr::render {

void ShapingInput::release(QOpenGLFunctions_3_3_Core* gl) {
    m_gl.release(gl);
    m_layers = {};
    m_rigRevision = -1;
    m_scene = nullptr;
}

bool ShapingInput::prepare(InputFrame& f, QString*) {
    const SceneDescription& scene = *f.scene;
    if (scene.rigRevision() != m_rigRevision || f.scene != m_scene) {
        m_layers = shapingLayers(scene.rig(), scene.lightAssets());
        m_gl.update(f.gl, m_layers);
        m_rigRevision = scene.rigRevision();
        m_scene = f.scene;
    }
    f.shaping = &m_layers;
    return true;
}

void ShapingInput::bind(QOpenGLFunctions_3_3_Core* gl, const FrameContext&, bool) const {
    m_gl.bind(gl);
}

} // namespace lr::render
