#include "ltcgl.h"

#include "core/ltc.h"

#include <vector>

namespace lr::render {

GLuint createLtcTexture(QOpenGLFunctions_3_3_Core* gl) {
    constexpr int n = ltc::kLtcSize;
    std::vector<float> texels(size_t(n * n * 4 * 2), 0.0f);
    const float* table = ltc::ltcTable();
    for (int c = 0; c < n * n; ++c) {
        const float* cell = table + size_t(c * ltc::kLtcFloats);
        for (int k = 0; k < 4; ++k)
            texels[size_t(c * 4 + k)] = cell[k];
        texels[size_t((n * n + c) * 4 + 0)] = cell[4];
        texels[size_t((n * n + c) * 4 + 1)] = cell[5];
    }
    GLuint texture = 0;
    gl->glGenTextures(1, &texture);
    gl->glBindTexture(GL_TEXTURE_2D_ARRAY, texture);
    gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl->glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, n, n, 2, 0, GL_RGBA, GL_FLOAT, texels.data());
    // Read with texelFetch (bilinear in the shader): no filtering, no mipmaps.
    gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
    gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
    return texture;
}

} // namespace lr::render
