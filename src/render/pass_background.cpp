// The background pass: the environment behind the model (passes.h BackgroundPass).
#include "input_environment.h"
#include "litinput.h"
#include "passes.h"
#include "programcache.h"
#include "targets.h"
#include "textureunits.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

namespace lr::render {

bool BackgroundPass::run(const FrameContext& frame, PassScene& scene) {
    // Deferred, the lighting pass after this one reads the colour (it counts on this pass covering every
    // pixel): a failure leaves the clear colour there instead.
    const auto failed = [&](const QString& message) {
        if (frame.deferred) {
            glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->fbo);
            glDisable(GL_SCISSOR_TEST);
            glClearColor(frame.clearColour.r, frame.clearColour.g, frame.clearColour.b, frame.clearColour.a);
            glClear(GL_COLOR_BUFFER_BIT);
        }
        glBindVertexArray(0);
        return fail(scene, message);
    };
    const EnvironmentInput* input = scene.inputs->find<EnvironmentInput>();
    if (!input || !frame.environment || frame.environmentBackgroundLod < 0.0f)
        return failed(QStringLiteral("background: the frame has no environment"));
    const EnvironmentGl& environment = input->textures();
    const bool display = frame.colourPath == ColourPath::Display;
    const QByteArray defines = "#define LR_ENVIRONMENT_BACKGROUND 1\n" +
                               (display ? "#define LR_OUTPUT_DISPLAY 1\n" + toneMapDefine(frame.toneMap)
                                        : QByteArray("#define LR_OUTPUT_RADIANCE 1\n"));
    QString error;
    QOpenGLShaderProgram* p = scene.programs->fixedProgram(kBackgroundShader, &error, defines);
    if (!p) return failed(error);
    Key key;
    key.environment = environment.generation();
    key.fromView = frame.environmentUniforms.fromView;
    key.scale = frame.environmentUniforms.scale;
    key.lod = frame.environmentBackgroundLod;
    key.exposureScale = display ? frame.exposureScale : 0.0f;
    key.projection = glm::mat4(frame.projection);
    key.width = frame.targetSize.width();
    key.height = frame.targetSize.height();
    key.format = scene.targets->colorFormat;
    key.toneMap = display ? frame.toneMap : ToneMap::Clamp;
    key.display = display;
    // The deferred path's depth is the G-buffer's, kept with it: only the pixels it leaves at the far plane
    // are looked up. A texture of every pixel serves any depth.
    key.depth = frame.deferred ? scene.targets->gbufferRevision : -1;
    Key everyPixel = key;
    everyPixel.depth = -1;
    // The background always goes into the kept texture (one compiled variant of the lookup, where a direct
    // draw as well would compile it a second time for another target state), and is copied (passes.h).
    // Rendered again only when the key changes.
    if (!ensureCache(key)) return failed(QStringLiteral("background: could not make its texture"));
    const auto drawEnvironment = [&] {
        p->bind();
        environment.setUniforms(this, p, frame.environmentUniforms);
        const glm::mat4 viewFromClip(glm::inverse(frame.projection));
        glUniformMatrix4fv(p->uniformLocation("uViewFromClip"), 1, GL_FALSE, glm::value_ptr(viewFromClip));
        p->setUniformValue("uTargetSize", float(frame.targetSize.width()), float(frame.targetSize.height()));
        p->setUniformValue("uBackgroundLod", frame.environmentBackgroundLod);
        if (display) p->setUniformValue("uExposureScale", frame.exposureScale);
        environment.bind(this);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        p->release();
    };
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(scene.targets->emptyVao);
    if (m_cached != key && m_cached != everyPixel) {
        glBindFramebuffer(GL_FRAMEBUFFER, m_cacheFbo);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                               key.depth >= 0 ? scene.targets->depth : cacheDepth(key), 0);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            return failed(QStringLiteral("background: its framebuffer is incomplete"));
        if (key.depth < 0) {
            glDepthMask(GL_TRUE);
            glClearDepth(1.0);
            glClear(GL_DEPTH_BUFFER_BIT);
        }
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL); // the triangle lies on the far plane: passes where nothing was drawn
        glDepthMask(GL_FALSE);
        drawEnvironment();
        m_cached = key;
        ++m_builds;
    }
    scene.stats->backgroundBuilds = m_builds;
    if (frame.deferred) {
        // Before the lighting pass (RenderPlan::select), which shades the covered pixels over it: every
        // pixel copied as it is, by the driver (no program; llvmpipe copies the memory).
        glBindFramebuffer(GL_READ_FRAMEBUFFER, m_cacheFbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, scene.targets->fbo);
        glDisable(GL_SCISSOR_TEST); // a blit is scissored
        glBlitFramebuffer(0, 0, key.width, key.height, 0, 0, key.width, key.height, GL_COLOR_BUFFER_BIT,
                          GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->fbo);
    } else {
        QOpenGLShaderProgram* copy = scene.programs->fixedProgram(kBackgroundCopyShader, &error);
        if (!copy) return failed(error);
        glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->drawFbo());
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL); // the triangle lies on the far plane: passes where nothing was drawn
        glDepthMask(GL_FALSE);
        copy->bind();
        glActiveTexture(textureUnit(TextureUnit::BackgroundCache));
        glBindTexture(GL_TEXTURE_2D, m_cacheTexture);
        glActiveTexture(GL_TEXTURE0);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        copy->release();
    }
    glBindVertexArray(0);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    return true;
}

bool BackgroundPass::ensureCache(const Key& key) {
    if (m_cacheTexture && m_cached.width == key.width && m_cached.height == key.height &&
        m_cached.format == key.format)
        return true;
    release();
    glGenTextures(1, &m_cacheTexture);
    glBindTexture(GL_TEXTURE_2D, m_cacheTexture);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(key.format), key.width, key.height, 0, GL_RGBA,
                 key.format == GL_RGBA8 ? GL_UNSIGNED_BYTE : GL_FLOAT, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    glGenFramebuffers(1, &m_cacheFbo);
    glBindFramebuffer(GL_FRAMEBUFFER, m_cacheFbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, m_cacheTexture, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        release(); // run() then fails with its error; the frame shows no background
        return false;
    }
    m_cached = Key(); // nothing kept yet
    m_cached.width = key.width, m_cached.height = key.height, m_cached.format = key.format;
    return true;
}

GLuint BackgroundPass::cacheDepth(const Key& key) {
    if (!m_cacheDepth) { // only the forward path renders against a depth of its own
        glGenTextures(1, &m_cacheDepth);
        glBindTexture(GL_TEXTURE_2D, m_cacheDepth);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, key.width, key.height, 0, GL_DEPTH_STENCIL,
                     GL_UNSIGNED_INT_24_8, nullptr); // the scene depth's format: the same draw state
        glBindTexture(GL_TEXTURE_2D, 0);
    }
    return m_cacheDepth;
}

void BackgroundPass::release() {
    if (m_cacheFbo) glDeleteFramebuffers(1, &m_cacheFbo);
    if (m_cacheTexture) glDeleteTextures(1, &m_cacheTexture);
    if (m_cacheDepth) glDeleteTextures(1, &m_cacheDepth);
    m_cacheFbo = m_cacheTexture = m_cacheDepth = 0;
    m_cached = Key();
}

} // namespace lr::render
