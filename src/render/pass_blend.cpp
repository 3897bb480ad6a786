// The blend pass: glTF alphaMode BLEND meshes over the opaque scene, back to front, shaded forward.
#include "gpumodel.h"
#include "passes.h"
#include "targets.h"

#include <algorithm>
#include <glm/ext/matrix_transform.hpp>

namespace lr::render {

bool BlendPass::run(const FrameContext& frame, PassScene& scene) {
    const Model* model = scene.model->model();
    if (!model) return true;
    const RenderSettings& settings = *frame.settings;
    // Shaded forward whatever the opaque path: per fragment from the cluster lists when the frame has them
    // (fast lights the vertices and never clusters).
    const bool clustered = frame.clustered && settings.quality != Quality::Fast;
    const ShaderOutput output =
        frame.colourPath == ColourPath::Hdr ? ShaderOutput::Radiance : ShaderOutput::Display;
    const RigFeatures& shaded = frame.features;
    const glm::dmat4 modelView = frame.view * glm::translate(glm::dmat4(1.0), model->origin);

    // Back to front: the farthest centre (most negative view z) first. Ties keep the model's order.
    std::vector<std::pair<double, const GpuDraw*>> byDepth;
    for (const GpuDraw& d : scene.model->draws())
        if (d.features.alphaBlend)
            byDepth.emplace_back((modelView * glm::dvec4(glm::dvec3(d.center), 1.0)).z, &d);
    if (byDepth.empty()) return true;
    std::stable_sort(byDepth.begin(), byDepth.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    DrawOrder order;
    order.reserve(byDepth.size());
    for (const auto& [z, d] : byDepth)
        order.emplace_back(meshKey(frame, scene, *d, output, clustered, shaded), d);

    glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->drawFbo());
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    return drawMeshes(frame, scene, order, clustered, true);
}

} // namespace lr::render
