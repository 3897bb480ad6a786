// The renderer's offscreen framebuffers: the HDR scene target (multisampled renderbuffers when MSAA is
// on), its single-sample resolve (colour and depth textures: input of the tone-map pass and of the gizmo
// occlusion test) and, on demand, the float G-buffer.
#pragma once

#include <QOpenGLFunctions_3_3_Core>
#include <QSize>
#include <QString>

namespace lr::render {

constexpr int kGBufferTargets = 5;  // position, normal, albedo, specular, emissive (floatimage.h)

struct Targets {
    QSize size;
    int samples = 0;  // > 1: MSAA
    bool float32 = false;
    GLuint msaaFbo = 0, msaaColor = 0, msaaDepth = 0;
    GLuint fbo = 0, color = 0, depth = 0;  // resolve: textures

    QSize gbufferSize;
    GLuint gbufferFbo = 0, gbufferDepth = 0;
    GLuint gbuffer[kGBufferTargets] = {};

    GLuint drawFbo() const { return samples > 1 ? msaaFbo : fbo; }
    bool create(QOpenGLFunctions_3_3_Core* gl, QSize size, int samples, bool float32, QString* error);
    bool createGBuffer(QOpenGLFunctions_3_3_Core* gl, QSize size, QString* error);
    void release(QOpenGLFunctions_3_3_Core* gl);
    void releaseHdr(QOpenGLFunctions_3_3_Core* gl);
    void releaseGBuffer(QOpenGLFunctions_3_3_Core* gl);
};

}  // namespace lr::render
