#include "targets.h"

namespace lr::render {

namespace {

GLuint makeTexture(QOpenGLFunctions_3_3_Core* gl, GLenum internal, GLenum format, GLenum type, QSize size) {
    GLuint t = 0;
    gl->glGenTextures(1, &t);
    gl->glBindTexture(GL_TEXTURE_2D, t);
    gl->glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), size.width(), size.height(), 0, format, type, nullptr);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

bool complete(QOpenGLFunctions_3_3_Core* gl, const char* what, QSize size, QString* error) {
    const GLenum status = gl->glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status == GL_FRAMEBUFFER_COMPLETE) return true;
    if (error)
        *error = QStringLiteral("the %1 framebuffer (%2x%3) is incomplete (status 0x%4)")
                     .arg(QLatin1String(what))
                     .arg(size.width())
                     .arg(size.height())
                     .arg(status, 0, 16);
    return false;
}

}  // namespace

bool Targets::create(QOpenGLFunctions_3_3_Core* gl, QSize s, int n, bool f32, QString* error) {
    releaseHdr(gl);
    size = s;
    samples = n > 1 ? n : 0;
    float32 = f32;
    const GLenum colorFormat = f32 ? GL_RGBA32F : GL_RGBA16F;
    while (gl->glGetError() != GL_NO_ERROR) {
    }
    gl->glGenFramebuffers(1, &fbo);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    color = makeTexture(gl, colorFormat, GL_RGBA, GL_FLOAT, s);
    depth = makeTexture(gl, GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, s);
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    bool ok = complete(gl, "HDR", s, error);
    if (ok && samples > 1) {
        gl->glGenFramebuffers(1, &msaaFbo);
        gl->glBindFramebuffer(GL_FRAMEBUFFER, msaaFbo);
        gl->glGenRenderbuffers(1, &msaaColor);
        gl->glBindRenderbuffer(GL_RENDERBUFFER, msaaColor);
        gl->glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, colorFormat, s.width(), s.height());
        gl->glGenRenderbuffers(1, &msaaDepth);
        gl->glBindRenderbuffer(GL_RENDERBUFFER, msaaDepth);
        gl->glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT32F, s.width(), s.height());
        gl->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaaColor);
        gl->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, msaaDepth);
        ok = complete(gl, "multisampled HDR", s, error);
    }
    if (ok && gl->glGetError() == GL_OUT_OF_MEMORY) {
        if (error) *error = QStringLiteral("out of GPU memory for a %1x%2 render target").arg(s.width()).arg(s.height());
        ok = false;
    }
    gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!ok) releaseHdr(gl);
    return ok;
}

bool Targets::createGBuffer(QOpenGLFunctions_3_3_Core* gl, QSize s, QString* error) {
    releaseGBuffer(gl);
    gbufferSize = s;
    gl->glGenFramebuffers(1, &gbufferFbo);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, gbufferFbo);
    GLenum buffers[kGBufferTargets];
    for (int i = 0; i < kGBufferTargets; ++i) {
        gbuffer[i] = makeTexture(gl, GL_RGBA32F, GL_RGBA, GL_FLOAT, s);
        gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, gbuffer[i], 0);
        buffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    }
    gbufferDepth = makeTexture(gl, GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, s);
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, gbufferDepth, 0);
    gl->glDrawBuffers(kGBufferTargets, buffers);
    const bool ok = complete(gl, "G-buffer", s, error);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!ok) releaseGBuffer(gl);
    return ok;
}

void Targets::release(QOpenGLFunctions_3_3_Core* gl) {
    releaseHdr(gl);
    releaseGBuffer(gl);
}

void Targets::releaseHdr(QOpenGLFunctions_3_3_Core* gl) {
    GLuint fbos[] = {msaaFbo, fbo};
    GLuint rbs[] = {msaaColor, msaaDepth};
    GLuint texs[] = {color, depth};
    gl->glDeleteFramebuffers(2, fbos);
    gl->glDeleteRenderbuffers(2, rbs);
    gl->glDeleteTextures(2, texs);
    msaaFbo = msaaColor = msaaDepth = fbo = color = depth = 0;
    size = QSize();
}

void Targets::releaseGBuffer(QOpenGLFunctions_3_3_Core* gl) {
    if (gbufferFbo) gl->glDeleteFramebuffers(1, &gbufferFbo);
    gl->glDeleteTextures(kGBufferTargets, gbuffer);
    if (gbufferDepth) gl->glDeleteTextures(1, &gbufferDepth);
    gbufferFbo = gbufferDepth = 0;
    for (GLuint& t : gbuffer) t = 0;
    gbufferSize = QSize();
}

}  // namespace lr::render
