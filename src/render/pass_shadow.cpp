// The shadow pass: the casting lights' depth maps, re-rendered only where they changed (input_shadows.h).
#include "gpumodel.h"
#include "input_shadows.h"
#include "litinput.h"
#include "passes.h"
#include "programcache.h"
#include "scene/scenedescription.h"

namespace lr::render {

bool ShadowPass::run(const FrameContext& frame, PassScene& scene) {
    ShadowInput* shadows = scene.inputs->find<ShadowInput>();
    if (!shadows) return true;
    QString error;
    QOpenGLShaderProgram* p = scene.programs->fixedProgram(kShadowDepthShader, &error);
    if (!p) return fail(scene, error);
    const bool ok = shadows->render(this, *scene.model, frame.scene->modelGeneration(), p->programId(),
                                    p->uniformLocation("uLightMatrix"), frame.settings->waitForShadowMaps,
                                    scene.stats, &error);
    // The next pass sets its own framebuffer and viewport; restore the defaults renderpass.h promises.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glActiveTexture(GL_TEXTURE0);
    return ok || fail(scene, error);
}

} // namespace lr::render
