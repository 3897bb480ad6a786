// The LTC table of the area lights (core/ltc.h) as the GL texture shaders/area.glsl reads (uLtc): a
// kLtcSize × kLtcSize × 2 RGBA32F array, layer 0 = M⁻¹'s (m00, m02, m20, m22), layer 1 = (scale, bias, 0,
// 0). Created by LightSet only when a rect or disk light is uploaded (TextureUnit::Ltc).
#pragma once

#include <QOpenGLFunctions_3_3_Core>

namespace lr::render {

GLuint createLtcTexture(QOpenGLFunctions_3_3_Core* gl);

} // namespace lr::render
