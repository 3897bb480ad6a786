#include "lightshapinggl.h"

#include "textureunits.h"

#include <algorithm>
#include <vector>

namespace lr::render {

namespace {

GLuint makeArray(QOpenGLFunctions_3_3_Core* gl, GLenum internalFormat, GLenum format, int w, int h,
                 int layers, GLenum wrapS, bool zeroed) {
    GLuint t = 0;
    gl->glGenTextures(1, &t);
    gl->glBindTexture(GL_TEXTURE_2D_ARRAY, t);
    gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_S, GLint(wrapS));
    gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    // `zeroed`: zeros, not undefined texels, where a gobo smaller than the layer leaves the rest unused
    // (the clamped lookup weighs its neighbour there by exactly 0 at the image's edge, and 0 × NaN would not
    // be 0). Otherwise every texel is uploaded next.
    const int channels = format == GL_RED ? 1 : 3;
    std::vector<float> zeros;
    if (zeroed) zeros.assign(size_t(w) * size_t(h) * size_t(layers) * size_t(channels), 0.0f);
    gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GLint(internalFormat), w, h, layers, 0, format, GL_FLOAT,
                     zeroed ? zeros.data() : nullptr);
    return t;
}

} // namespace

void LightShapingGl::release(QOpenGLFunctions_3_3_Core* gl) {
    if (m_ies) gl->glDeleteTextures(1, &m_ies);
    if (m_gobos) gl->glDeleteTextures(1, &m_gobos);
    m_ies = m_gobos = 0;
    m_profiles.clear();
    m_images.clear();
    m_bytes = 0;
}

void LightShapingGl::update(QOpenGLFunctions_3_3_Core* gl, const ShapingLayers& layers) {
    if (layers.profiles != m_profiles) {
        if (m_ies) gl->glDeleteTextures(1, &m_ies);
        m_ies = 0;
        m_profiles = layers.profiles;
        if (!m_profiles.empty()) {
            m_ies = makeArray(gl, GL_R32F, GL_RED, kIesGridHorizontal, kIesGridVertical,
                              int(m_profiles.size()), GL_REPEAT, false);
            for (size_t k = 0; k < m_profiles.size(); ++k) {
                const std::vector<float> grid = resampleIes(*m_profiles[k]);
                gl->glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, GLint(k), kIesGridHorizontal,
                                    kIesGridVertical, 1, GL_RED, GL_FLOAT, grid.data());
            }
        }
    }
    if (layers.gobos != m_images) {
        if (m_gobos) gl->glDeleteTextures(1, &m_gobos);
        m_gobos = 0;
        m_images = layers.gobos;
        if (!m_images.empty()) {
            const bool fills = std::all_of(m_images.begin(), m_images.end(), [&](const auto& g) {
                return g->width == layers.goboWidth && g->height == layers.goboHeight;
            });
            m_gobos = makeArray(gl, GL_RGB16F, GL_RGB, layers.goboWidth, layers.goboHeight,
                                int(m_images.size()), GL_CLAMP_TO_EDGE, !fills);
            for (size_t k = 0; k < m_images.size(); ++k) // row 0 (the image's top) is t = 0
                gl->glTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, GLint(k), m_images[k]->width,
                                    m_images[k]->height, 1, GL_RGB, GL_FLOAT, m_images[k]->rgb.data());
        }
    }
    gl->glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    m_bytes = m_profiles.size() * size_t(kIesGridHorizontal) * kIesGridVertical * 4 +
              m_images.size() * size_t(layers.goboWidth) * size_t(layers.goboHeight) * 6;
}

void LightShapingGl::bind(QOpenGLFunctions_3_3_Core* gl) const {
    if (m_ies) {
        gl->glActiveTexture(textureUnit(TextureUnit::Ies));
        gl->glBindTexture(GL_TEXTURE_2D_ARRAY, m_ies);
    }
    if (m_gobos) {
        gl->glActiveTexture(textureUnit(TextureUnit::Gobos));
        gl->glBindTexture(GL_TEXTURE_2D_ARRAY, m_gobos);
    }
    gl->glActiveTexture(GL_TEXTURE0);
}

} // namespace lr::render
