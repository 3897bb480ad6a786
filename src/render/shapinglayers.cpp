#include "shapinglayers.h"

#include "scene/lightassets.h"

#include <algorithm>

namespace lr::render {

std::vector<float> resampleIes(const IesProfile& profile) {
    std::vector<float> out(size_t(kIesGridVertical) * kIesGridHorizontal, 0.0f);
    if (!(profile.peak > 0.0)) return out;
    for (int j = 0; j < kIesGridVertical; ++j)
        for (int i = 0; i < kIesGridHorizontal; ++i)
            out[size_t(j) * kIesGridHorizontal + size_t(i)] = float(
                iesCandela(profile, j * kIesGridVerticalStep, i * kIesGridHorizontalStep) / profile.peak);
    return out;
}

ShapingLayers shapingLayers(const Rig& rig, const LightAssets& assets) {
    ShapingLayers s;
    const size_t n = rig.lights.size();
    s.iesLayer.assign(n, -1);
    s.iesNorm.assign(n, 1.0f);
    s.goboLayer.assign(n, -1);
    for (size_t i = 0; i < n; ++i) {
        const Light& l = rig.lights[i];
        const bool positional = l.type == LightType::Point || l.type == LightType::Spot;
        if (l.ies && positional && i < assets.ies.size() && assets.ies[i]) {
            const auto& p = assets.ies[i];
            const auto at = std::find(s.profiles.begin(), s.profiles.end(), p);
            s.iesLayer[i] = int(at - s.profiles.begin());
            if (at == s.profiles.end()) s.profiles.push_back(p);
            s.iesNorm[i] = float(p->peak);
        }
        if (l.gobo && l.type == LightType::Spot && i < assets.gobos.size() && assets.gobos[i] &&
            !assets.gobos[i]->isNull()) {
            const auto& g = assets.gobos[i];
            const auto at = std::find(s.gobos.begin(), s.gobos.end(), g);
            s.goboLayer[i] = int(at - s.gobos.begin());
            if (at == s.gobos.end()) {
                s.gobos.push_back(g);
                s.goboWidth = std::max(s.goboWidth, g->width);
                s.goboHeight = std::max(s.goboHeight, g->height);
            }
        }
    }
    return s;
}

} // namespace lr::render
