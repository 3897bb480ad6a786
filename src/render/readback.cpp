#include "readback.h"

#include <algorithm>

namespace lr::render {

bool readFloatAttachment(QOpenGLFunctions_3_3_Core* gl, GLuint fbo, GLenum attachment, QSize size,
                         FloatImage* out) {
    out->width = size.width();
    out->height = size.height();
    out->pixels.assign(size_t(size.width()) * size_t(size.height()), glm::vec4(0.0f));
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    gl->glReadBuffer(attachment);
    gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    std::vector<glm::vec4> rows(out->pixels.size());
    gl->glReadPixels(0, 0, size.width(), size.height(), GL_RGBA, GL_FLOAT, rows.data());
    for (int y = 0; y < size.height(); ++y) // GL's first row is the bottom one
        std::copy_n(rows.begin() + std::ptrdiff_t(y) * size.width(), size.width(),
                    out->pixels.begin() + std::ptrdiff_t(size.height() - 1 - y) * size.width());
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return gl->glGetError() == GL_NO_ERROR;
}

std::vector<float> readDepth(QOpenGLFunctions_3_3_Core* gl, GLuint fbo, QSize size) {
    std::vector<float> depth(size_t(size.width()) * size_t(size.height()));
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    gl->glReadPixels(0, 0, size.width(), size.height(), GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    return depth;
}

} // namespace lr::render
