#include "readback.h"

#include <algorithm>

namespace lr::render {

bool readFloatAttachment(QOpenGLFunctions_3_3_Core* gl, GLuint fbo, GLenum attachment, QSize size,
                         FloatImage* out) {
    out->width = size.width();
    out->height = size.height();
    out->pixels.resize(size_t(size.width()) * size_t(size.height()));
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    gl->glReadBuffer(attachment);
    gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
    // Read straight into the image and turn it upside down in place (GL's first row is the bottom one): no
    // second image-sized buffer, whose fresh pages each cost a fault (a light-group split reads back one
    // image per group).
    gl->glReadPixels(0, 0, size.width(), size.height(), GL_RGBA, GL_FLOAT, out->pixels.data());
    const auto row = [&](int y) { return out->pixels.begin() + std::ptrdiff_t(y) * size.width(); };
    for (int y = 0; y < size.height() / 2; ++y)
        std::swap_ranges(row(y), row(y) + size.width(), row(size.height() - 1 - y));
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
