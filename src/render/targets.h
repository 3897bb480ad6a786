// The renderer's offscreen framebuffers, all of one size:
// - the scene target: colour (RGBA8 display colours, or RGBA16F/RGBA32F radiance for the HDR path) and a
//   depth texture; with MSAA, multisampled renderbuffers that resolve into it;
// - on demand, the G-buffer: four RGBA32F textures sharing the scene's depth texture, so the deferred
//   lighting pass (drawn into the scene target) can depth-test away the background. Layout: gbuffer.h.
#pragma once

#include "gbuffer.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QSize>
#include <QString>

namespace lr::render {

struct Targets {
    QSize size;
    int samples = 0;        // > 1: MSAA
    GLenum colorFormat = 0; // GL_RGBA8, GL_RGBA16F or GL_RGBA32F
    GLuint msaaFbo = 0, msaaColor = 0, msaaDepth = 0;
    GLuint fbo = 0, color = 0, depth = 0; // single-sample: textures
    GLuint gbufferFbo = 0;
    GLuint gbuffer[kGBufferTargets] = {};
    // One more whenever the G-buffer or the scene depth it shares may have changed: create(), and every
    // pass that writes them (the G-pass, the forward geometry pass, the MSAA resolve of depth). What was
    // built from them (the kept G-buffer, Surfaces and background) is valid while it holds.
    int gbufferRevision = 0;
    // The kept surfaces (passes.h DeferredLightingPass), on demand: four RGBA32F textures in the Surface
    // layout sharing the depth, and the G-buffer revision they were built from (-1: none).
    GLuint surfaceFbo = 0;
    GLuint surfaces[kGBufferTargets] = {};
    int surfacesRevision = -1;

    GLuint drawFbo() const { return samples > 1 ? msaaFbo : fbo; }
    bool create(QOpenGLFunctions_3_3_Core* gl, QSize size, int samples, GLenum colorFormat, QString* error);
    bool createGBuffer(QOpenGLFunctions_3_3_Core* gl, QString* error);  // for the current size
    bool createSurfaces(QOpenGLFunctions_3_3_Core* gl, QString* error); // for the current size
    void release(QOpenGLFunctions_3_3_Core* gl);
};

} // namespace lr::render
