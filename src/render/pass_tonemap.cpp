// The tone-map pass (HDR path): resolved radiance -> exposure -> tone map -> sRGB, into the output.
#include "passes.h"
#include "programcache.h"
#include "targets.h"
#include "textureunits.h"

namespace lr::render {

bool ToneMapPass::run(const FrameContext& frame, PassScene& scene) {
    QString error;
    QOpenGLShaderProgram* p =
        scene.programs->fixedProgram(kToneMapShader, &error, toneMapDefine(frame.toneMap));
    if (!p) return fail(scene, error);
    glBindFramebuffer(GL_FRAMEBUFFER, frame.outputFbo);
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_FRAMEBUFFER_SRGB);
    p->bind();
    p->setUniformValue("uExposureScale", frame.exposureScale);
    p->setUniformValue("uBackground", frame.backgroundLinear.r, frame.backgroundLinear.g,
                       frame.backgroundLinear.b);
    p->setUniformValue("uTransparent", frame.transparent);
    glActiveTexture(textureUnit(TextureUnit::SceneColor));
    glBindTexture(GL_TEXTURE_2D, scene.targets->color);
    glActiveTexture(GL_TEXTURE0);
    glBindVertexArray(scene.targets->emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    p->release();
    return true;
}

} // namespace lr::render
