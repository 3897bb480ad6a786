#include "layerscommon.h"

#include <algorithm>
#include <glm/matrix.hpp>

namespace lr {

bool modelEmits(const Model* model) {
    return model && std::any_of(model->materials.begin(), model->materials.end(),
                                [](const Material& m) { return m.emissive != glm::vec3(0.0f); });
}

std::vector<LightGroup> sceneLightGroups(const SceneDescription& scene) {
    LightGroupScene what;
    what.hasEmissive = modelEmits(scene.model());
    return lightGroups(scene.rig(), what);
}

void fillAuxiliaryLayers(const GBuffer& g, const glm::dmat4& view, RenderLayers* layers) {
    const int w = g.position.width, h = g.position.height;
    const size_t n = size_t(std::max(0, w)) * size_t(std::max(0, h));
    for (FloatImage* image : {&layers->albedo, &layers->normal, &layers->depth}) {
        image->width = w;
        image->height = h;
        image->pixels.assign(n, glm::vec4(0.0f));
    }
    const glm::dmat3 toWorld(glm::inverse(view));
    for (size_t i = 0; i < n && i < g.position.pixels.size(); ++i) {
        const glm::vec4 p = g.position.pixels[i];
        if (!(p.w >= 0.5f)) {
            layers->depth.pixels[i] = glm::vec4(kBackgroundDepth, 0.0f, 0.0f, 0.0f);
            continue;
        }
        layers->albedo.pixels[i] = glm::vec4(glm::vec3(g.albedo.pixels[i]), 1.0f);
        const glm::dvec3 normal = toWorld * glm::dvec3(glm::vec3(g.normal.pixels[i]));
        const double length = glm::length(normal);
        layers->normal.pixels[i] = glm::vec4(glm::vec3(length > 0.0 ? normal / length : normal), 1.0f);
        layers->depth.pixels[i] = glm::vec4(-p.z, 0.0f, 0.0f, 1.0f);
    }
}

} // namespace lr
