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

namespace lr {
struct TextureSampling;
}

namespace lr::render {

struct Targets {
    QSize size;
    int samples = 0;        // > 1: MSAA
    GLenum colorFormat = 0; // GL_RGBA8, GL_RGBA16F or GL_RGBA32F
    GLuint msaaFbo = 0, msaaColor = 0, msaaDepth = 0;
    GLuint fbo = 0, color = 0, depth = 0; // single-sample: textures
    GLuint gbufferFbo = 0;
    GLuint gbuffer[kGBufferTargets] = {};
    // Light linking only (RigFeatures::linking): an R8UI texture of each pixel's lighting class, the
    // G-buffer's fifth colour attachment (made by useGBufferLink at the first linking frame); the deferred
    // lighting pass reads it (TextureUnit::GBufferLink). 0: never needed.
    GLuint gbufferLink = 0;
    // The G-buffer and the scene depth it shares as the passes left them: one more revision whenever they
    // may have changed (create(), and RenderPlan::runPass after every pass whose declared writes include
    // resource::kDepthSharing and that did not keep them: the G-pass, the forward geometry pass, the MSAA
    // resolve), and the pass that wrote them last (nullptr after create()). What was built from them (the
    // kept G-buffer, Surfaces and background) is valid while the revision holds.
    int gbufferRevision = 0;
    const void* gbufferWriter = nullptr;
    void wroteDepth(const void* pass) {
        ++gbufferRevision;
        gbufferWriter = pass;
    }
    // The kept surfaces (passes.h DeferredLightingPass), on demand: four RGBA32F textures in the Surface
    // layout sharing the depth, and the G-buffer revision they were built from (-1: none).
    GLuint surfaceFbo = 0;
    GLuint surfaces[kGBufferTargets] = {};
    int surfacesRevision = -1;

    // What every frame uses whatever the size (createCommon, releaseCommon): an empty vertex array for
    // full-screen triangles, a 1x1 texture for MeshPass::primeSamplerSlots, and the material textures'
    // samplers: one per wrap S × wrap T × magnification filter (the glTF sampler, model.h TextureSampling)
    // × the tier's minification (trilinear; the fast tier's F4: bilinear within the nearest mip level).
    GLuint emptyVao = 0, slotTexture = 0;
    GLuint materialSamplers[2][3][3][2] = {}; // [fast][wrapS][wrapT][nearest magnification]
    GLuint materialSampler(const TextureSampling& sampling, bool fast) const;
    void createCommon(QOpenGLFunctions_3_3_Core* gl);
    void releaseCommon(QOpenGLFunctions_3_3_Core* gl);

    GLuint drawFbo() const { return samples > 1 ? msaaFbo : fbo; }
    bool create(QOpenGLFunctions_3_3_Core* gl, QSize size, int samples, GLenum colorFormat, QString* error);
    // create() unless the targets already have this size, sample count and format; without multisampling
    // (and a warning) when a multisampled target cannot be made.
    bool ensure(QOpenGLFunctions_3_3_Core* gl, QSize size, int samples, GLenum colorFormat, QString* error);
    bool createGBuffer(QOpenGLFunctions_3_3_Core* gl, QString* error); // for the current size
    // With the G-buffer's framebuffer bound: draws into the link target too (linking; made on demand) or
    // into the four Surface targets alone, as without linking. False (with error) when it cannot be made.
    bool useGBufferLink(QOpenGLFunctions_3_3_Core* gl, bool linking, QString* error);
    bool createSurfaces(QOpenGLFunctions_3_3_Core* gl, QString* error); // for the current size
    void release(QOpenGLFunctions_3_3_Core* gl);
};

} // namespace lr::render
