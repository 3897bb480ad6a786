#include "shapinglights.h"

namespace lr {

void applyLightShaping(lighting::ShadeLight<double>& o, const Light& light, const IesProfile* profile,
                       const GoboImage* gobo, const glm::dmat4& view) {
    applyIesProfile(o, light, profile, view);
    if (gobo && light.gobo && light.type == LightType::Spot) o.gobo = gobo;
}

void applyLightShaping(std::vector<lighting::ShadeLight<double>>& lights, const Rig& rig,
                       const std::vector<std::shared_ptr<const IesProfile>>& profiles,
                       const std::vector<std::shared_ptr<const GoboImage>>& gobos, const glm::dmat4& view) {
    const auto at = [](const auto& v, size_t i) { return i < v.size() ? v[i].get() : nullptr; };
    size_t k = 0;
    for (size_t i = 0; i < rig.lights.size() && k < lights.size(); ++i)
        if (rig.lights[i].enabled) {
            applyLightShaping(lights[k], rig.lights[i], at(profiles, i), at(gobos, i), view);
            ++k;
        }
}

} // namespace lr
