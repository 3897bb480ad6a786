// The background pass: the environment behind the model (passes.h BackgroundPass).
#include "environmentgl.h"
#include "passes.h"
#include "programcache.h"
#include "targets.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

namespace lr::render {

bool BackgroundPass::run(const FrameContext& frame, PassScene& scene) {
    if (!frame.environment || frame.environmentBackgroundLod < 0.0f || !scene.environment) return true;
    const bool display = frame.colourPath == ColourPath::Display;
    const QByteArray defines = "#define LR_ENVIRONMENT_BACKGROUND 1\n" +
                               (display ? "#define LR_OUTPUT_DISPLAY 1\n" + toneMapDefine(frame.toneMap)
                                        : QByteArray("#define LR_OUTPUT_RADIANCE 1\n"));
    QString error;
    QOpenGLShaderProgram* p = scene.programs->fixedProgram(kBackgroundShader, &error, defines);
    if (!p) return fail(scene, error);
    glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->drawFbo());
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    p->bind();
    scene.environment->setUniforms(this, p, frame.environmentUniforms);
    const glm::mat4 viewFromClip(glm::inverse(frame.projection));
    glUniformMatrix4fv(p->uniformLocation("uViewFromClip"), 1, GL_FALSE, glm::value_ptr(viewFromClip));
    p->setUniformValue("uTargetSize", float(frame.targetSize.width()), float(frame.targetSize.height()));
    p->setUniformValue("uBackgroundLod", frame.environmentBackgroundLod);
    if (display) p->setUniformValue("uExposureScale", frame.exposureScale);
    scene.environment->bind(this);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL); // the triangle lies on the far plane: passes where nothing was drawn
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(scene.emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    p->release();
    return true;
}

} // namespace lr::render
