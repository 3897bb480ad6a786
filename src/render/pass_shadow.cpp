// The shadow pass: the casting lights' depth maps, re-rendered only where they changed (shadowmaps.h).
#include "gpumodel.h"
#include "passes.h"
#include "programcache.h"
#include "shadowmaps.h"

namespace lr::render {

bool ShadowPass::run(const FrameContext& frame, PassScene& scene) {
    if (!scene.shadows || !scene.shadowViews) return true;
    QString error;
    QOpenGLShaderProgram* p = scene.programs->fixedProgram(kShadowDepthShader, &error);
    if (!p) return fail(scene, error);
    const bool ok = scene.shadows->update(this, *scene.shadowViews, *scene.model, scene.modelGeneration,
                                          p->programId(), p->uniformLocation("uLightMatrix"),
                                          frame.settings->waitForShadowMaps, scene.stats, &error);
    // The next pass sets its own framebuffer and viewport; restore the defaults renderpass.h promises.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glActiveTexture(GL_TEXTURE0);
    return ok || fail(scene, error);
}

} // namespace lr::render
