#include "targets.h"

#include "model/model.h"
#include "renderlog.h"

#include <algorithm>
#include <cstdint>

namespace lr::render {

namespace {

GLuint makeTexture(QOpenGLFunctions_3_3_Core* gl, GLenum internal, GLenum format, GLenum type, QSize size) {
    GLuint t = 0;
    gl->glGenTextures(1, &t);
    gl->glBindTexture(GL_TEXTURE_2D, t);
    gl->glTexImage2D(GL_TEXTURE_2D, 0, GLint(internal), size.width(), size.height(), 0, format, type,
                     nullptr);
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

// Four RGBA32F textures of `size` and the depth-stencil texture `depth` in one framebuffer.
bool createMrt(QOpenGLFunctions_3_3_Core* gl, const char* what, QSize size, GLuint depth, GLuint* fbo,
               GLuint (&textures)[kGBufferTargets], QString* error) {
    gl->glGenFramebuffers(1, fbo);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, *fbo);
    GLenum buffers[kGBufferTargets];
    for (int i = 0; i < kGBufferTargets; ++i) {
        textures[i] = makeTexture(gl, GL_RGBA32F, GL_RGBA, GL_FLOAT, size);
        gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D,
                                   textures[i], 0);
        buffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    }
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    gl->glDrawBuffers(kGBufferTargets, buffers);
    const bool ok = complete(gl, what, size, error);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!ok) {
        gl->glDeleteFramebuffers(1, fbo);
        gl->glDeleteTextures(kGBufferTargets, textures);
        *fbo = 0;
        for (GLuint& t : textures)
            t = 0;
    }
    return ok;
}

} // namespace

bool Targets::create(QOpenGLFunctions_3_3_Core* gl, QSize s, int n, GLenum format, QString* error) {
    release(gl);
    wroteDepth(nullptr); // new textures: nothing drawn into the old ones is there
    size = s;
    samples = n > 1 ? n : 0;
    colorFormat = format;
    const GLenum pixelType = format == GL_RGBA8 ? GL_UNSIGNED_BYTE : GL_FLOAT;
    while (gl->glGetError() != GL_NO_ERROR) {
    }
    gl->glGenFramebuffers(1, &fbo);
    gl->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    color = makeTexture(gl, colorFormat, GL_RGBA, pixelType, s);
    // Depth and a stencil: the attribute G-buffer marks each pixel's material in it (FrameContext). 24-bit
    // depth, not 32-bit float: llvmpipe stores GL_DEPTH32F_STENCIL8 in 64 bits a pixel, and its clear alone
    // took ~10 % of helmet_1pt's frame (perf: a 64-bit `rep stos` over the target, bound by this VM's memory
    // bandwidth; cachegrind counts it as a few instructions). With the usual [near, far] -> [0, 1] mapping
    // both formats have the same 2^-24 steps beyond twice the near distance, where scenes lie.
    depth = makeTexture(gl, GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, s);
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, depth, 0);
    bool ok = complete(gl, "scene", s, error);
    if (ok && samples > 1) {
        gl->glGenFramebuffers(1, &msaaFbo);
        gl->glBindFramebuffer(GL_FRAMEBUFFER, msaaFbo);
        gl->glGenRenderbuffers(1, &msaaColor);
        gl->glBindRenderbuffer(GL_RENDERBUFFER, msaaColor);
        gl->glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, colorFormat, s.width(), s.height());
        gl->glGenRenderbuffers(1, &msaaDepth);
        gl->glBindRenderbuffer(GL_RENDERBUFFER, msaaDepth);
        gl->glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, s.width(),
                                             s.height()); // as `depth`: the resolve blits between them
        gl->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msaaColor);
        gl->glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                                      msaaDepth);
        ok = complete(gl, "multisampled scene", s, error);
    }
    if (ok && gl->glGetError() == GL_OUT_OF_MEMORY) {
        if (error)
            *error =
                QStringLiteral("out of GPU memory for a %1x%2 render target").arg(s.width()).arg(s.height());
        ok = false;
    }
    gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!ok) release(gl);
    return ok;
}

bool Targets::ensure(QOpenGLFunctions_3_3_Core* gl, QSize s, int n, GLenum format, QString* error) {
    n = n > 1 ? n : 0;
    if (fbo && size == s && samples == n && colorFormat == format) return true;
    if (create(gl, s, n, format, error)) return true;
    if (n > 1 && create(gl, s, 0, format, error)) {
        qCWarning(lcRender) << "multisampling unavailable for this target, rendering without it";
        return true;
    }
    return false;
}

bool Targets::createGBuffer(QOpenGLFunctions_3_3_Core* gl, QString* error) {
    return gbufferFbo || createMrt(gl, "G-buffer", size, depth, &gbufferFbo, gbuffer, error);
}

bool Targets::useGBufferLink(QOpenGLFunctions_3_3_Core* gl, bool linking, QString* error) {
    GLenum buffers[kGBufferTargets + 1];
    for (int i = 0; i <= kGBufferTargets; ++i)
        buffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    if (!linking) {
        if (gbufferLink) gl->glDrawBuffers(kGBufferTargets, buffers);
        return true;
    }
    if (!gbufferLink) {
        gbufferLink = makeTexture(gl, GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, size);
        gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + kGBufferTargets),
                                   GL_TEXTURE_2D, gbufferLink, 0);
    }
    gl->glDrawBuffers(kGBufferTargets + 1, buffers);
    if (complete(gl, "G-buffer with its link target", size, error)) return true;
    gl->glFramebufferTexture2D(GL_FRAMEBUFFER, GLenum(GL_COLOR_ATTACHMENT0 + kGBufferTargets), GL_TEXTURE_2D,
                               0, 0);
    gl->glDeleteTextures(1, &gbufferLink);
    gbufferLink = 0;
    gl->glDrawBuffers(kGBufferTargets, buffers);
    return false;
}

bool Targets::createSurfaces(QOpenGLFunctions_3_3_Core* gl, QString* error) {
    return surfaceFbo || createMrt(gl, "kept surfaces", size, depth, &surfaceFbo, surfaces, error);
}

void Targets::createCommon(QOpenGLFunctions_3_3_Core* gl) {
    // F4 (fast tier): bilinear filtering within the nearest mip level instead of trilinear between two,
    // ~20% of DamagedHelmet's frame on llvmpipe (three 2048² textures); its error is measured with the rest.
    static constexpr GLint kWraps[] = {GL_REPEAT, GL_CLAMP_TO_EDGE,
                                       GL_MIRRORED_REPEAT}; // TextureWrap's order
    for (int fast = 0; fast < 2; ++fast)
        for (int s = 0; s < 3; ++s)
            for (int t = 0; t < 3; ++t)
                for (int nearest = 0; nearest < 2; ++nearest) {
                    GLuint& sampler = materialSamplers[fast][s][t][nearest];
                    gl->glGenSamplers(1, &sampler);
                    gl->glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER,
                                            fast ? GL_LINEAR_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR);
                    gl->glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, nearest ? GL_NEAREST : GL_LINEAR);
                    gl->glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, kWraps[s]);
                    gl->glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, kWraps[t]);
                }
    gl->glGenVertexArrays(1, &emptyVao);
    gl->glGenTextures(1, &slotTexture); // MeshPass::primeSamplerSlots samples it in every slot
    gl->glBindTexture(GL_TEXTURE_2D, slotTexture);
    const std::uint32_t white = 0xffffffffu;
    gl->glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, &white);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl->glBindTexture(GL_TEXTURE_2D, 0);
}

GLuint Targets::materialSampler(const TextureSampling& sampling, bool fast) const {
    return materialSamplers[fast ? 1 : 0][int(sampling.wrapS)][int(sampling.wrapT)]
                           [sampling.nearestMagnification ? 1 : 0];
}

void Targets::releaseCommon(QOpenGLFunctions_3_3_Core* gl) {
    constexpr GLsizei kSamplers = GLsizei(sizeof(materialSamplers) / sizeof(GLuint));
    gl->glDeleteSamplers(kSamplers, &materialSamplers[0][0][0][0]);
    gl->glDeleteVertexArrays(1, &emptyVao);
    gl->glDeleteTextures(1, &slotTexture);
    emptyVao = slotTexture = 0;
    std::fill_n(&materialSamplers[0][0][0][0], kSamplers, 0u);
}

void Targets::release(QOpenGLFunctions_3_3_Core* gl) {
    GLuint fbos[] = {msaaFbo, fbo, gbufferFbo, surfaceFbo};
    GLuint rbs[] = {msaaColor, msaaDepth};
    GLuint texs[] = {color, depth};
    gl->glDeleteFramebuffers(4, fbos);
    gl->glDeleteRenderbuffers(2, rbs);
    gl->glDeleteTextures(2, texs);
    gl->glDeleteTextures(kGBufferTargets, gbuffer);
    gl->glDeleteTextures(kGBufferTargets, surfaces);
    gl->glDeleteTextures(1, &gbufferLink);
    gbufferLink = 0;
    msaaFbo = msaaColor = msaaDepth = fbo = color = depth = gbufferFbo = surfaceFbo = 0;
    for (GLuint& t : gbuffer)
        t = 0;
    for (GLuint& t : surfaces)
        t = 0;
    surfacesRevision = -1;
    size = QSize();
}

} // namespace lr::render
