#include "scaledoutput.h"

#include "rendersettings.h"

#include <algorithm>
#include <cmath>

namespace lr::render {

QSize scaledDrawSize(QSize size, double scale) {
    if (!(scale < 1.0)) return size; // NaN and anything from 1 up: full size
    scale = std::max(scale, kMinRenderScale);
    const auto side = [scale](int n) { return std::max(1, int(std::lround(double(n) * scale))); };
    return {side(size.width()), side(size.height())};
}

bool ScaledOutput::ensure(QOpenGLFunctions_3_3_Core* gl, QSize drawSize, QString* error) {
    if (fbo && size == drawSize) return true;
    release(gl);
    gl->glGenRenderbuffers(1, &color);
    gl->glBindRenderbuffer(GL_RENDERBUFFER, color);
    gl->glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, drawSize.width(), drawSize.height());
    gl->glGenFramebuffers(1, &fbo);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    gl->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    const GLenum status = gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
        if (error)
            *error = QStringLiteral("the scaled output framebuffer (%1x%2) is incomplete (status 0x%3)")
                         .arg(drawSize.width())
                         .arg(drawSize.height())
                         .arg(status, 0, 16);
        release(gl);
        return false;
    }
    size = drawSize;
    return true;
}

void ScaledOutput::present(QOpenGLFunctions_3_3_Core* gl, GLuint targetFbo, QSize outputSize) const {
    gl->glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targetFbo);
    gl->glBlitFramebuffer(0, 0, size.width(), size.height(), 0, 0, outputSize.width(), outputSize.height(),
                          GL_COLOR_BUFFER_BIT, GL_LINEAR);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, targetFbo);
}

void ScaledOutput::release(QOpenGLFunctions_3_3_Core* gl) {
    if (fbo) gl->glDeleteFramebuffers(1, &fbo);
    if (color) gl->glDeleteRenderbuffers(1, &color);
    fbo = color = 0;
    size = QSize();
}

} // namespace lr::render
