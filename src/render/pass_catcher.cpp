// The shadow catcher pass: the ground's shadows alone, over the opaque scene (passes.h CatcherPass).
#include "gpumodel.h"
#include "passes.h"
#include "targets.h"

namespace lr::render {

bool CatcherPass::run(const FrameContext& frame, PassScene& scene) {
    if (!scene.ground || scene.groundMode != GroundMode::Catcher || !scene.model->model()) return true;
    const RenderSettings& settings = *frame.settings;
    const ShaderOutput output =
        frame.colourPath == ColourPath::Hdr ? ShaderOutput::Radiance : ShaderOutput::Display;
    // No environment: the catcher shows the lights' shadows only (the environment casts none).
    const RigFeatures shaded =
        frameRigFeatures(*scene.rig, frame.farLights, settings.forceAllFeatures, false);
    DrawOrder order;
    for (const GpuDraw& d : scene.ground->draws()) {
        FeatureKey key = meshKey(frame, scene, d, output, false, shaded, scene.ground);
        key.material.shadowCatcher = true;
        order.emplace_back(key, &d);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->drawFbo());
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    return drawMeshes(frame, scene, order, false, true, scene.ground);
}

} // namespace lr::render
