// The shadow catcher pass: the ground's shadows alone, over the opaque scene (passes.h CatcherPass).
#include "gpumodel.h"
#include "input_ground.h"
#include "litinput.h"
#include "passes.h"
#include "targets.h"

namespace lr::render {

bool CatcherPass::run(const FrameContext& frame, PassScene& scene) {
    const GroundInput* input = scene.inputs->find<GroundInput>();
    const GpuModel* ground = input ? input->gpu() : nullptr;
    if (!ground || input->mode() != GroundMode::Catcher || !scene.model->model()) return true;
    const ShaderOutput output =
        frame.colourPath == ColourPath::Hdr ? ShaderOutput::Radiance : ShaderOutput::Display;
    // No environment: the catcher shows the lights' shadows only (the environment casts none).
    RigFeatures shaded = frame.features;
    shaded.environment = false;
    DrawOrder order;
    for (const GpuDraw& d : ground->draws()) {
        FeatureKey key = meshKey(frame, scene, d, output, false, shaded, ground);
        key.material.shadowCatcher = true;
        order.emplace_back(key, &d);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->drawFbo());
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    return drawMeshes(frame, scene, order, false, true, ground);
}

} // namespace lr::render
