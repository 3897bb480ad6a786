#include "input_shaping.h"

#include "textureunits.h"

#include "scene/scenedescription.h"

#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcShaping, "lightrig.render.shaping", QtInfoMsg)

namespace lr::render {

void ShapingInput::initialize(QOpenGLFunctions_3_3_Core* gl) {
    GLint units = 0;
    gl->glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
    m_unitsOk = units > GLint(TextureUnit::Gobos);
    if (!m_unitsOk)
        qCWarning(lcShaping) << "the driver has" << units << "texture units; IES profiles and gobos need"
                             << GLint(TextureUnit::Gobos) + 1 << "and are not drawn";
}

void ShapingInput::release(QOpenGLFunctions_3_3_Core* gl) {
    m_gl.release(gl);
    m_layers = {};
    m_rigRevision = -1;
    m_scene = nullptr;
}

bool ShapingInput::prepare(InputFrame& f, QString*) {
    const SceneDescription& scene = *f.scene;
    if (scene.rigRevision() != m_rigRevision || f.scene != m_scene) {
        m_layers = m_unitsOk ? shapingLayers(scene.rig(), scene.lightAssets()) : ShapingLayers{};
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
