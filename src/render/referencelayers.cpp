#include "referencelayers.h"

#include "layerscommon.h"

#include <algorithm>

namespace lr {

void setReferenceGroups(ReferenceScene* scene, const Rig& rig, const std::vector<LightGroup>& groups) {
    ReferenceScene::Groups& out = scene->groups;
    out = {};
    out.count = int(groups.size());
    const std::vector<int> of = groupOfLights(rig, groups);
    for (size_t i = 0; i < rig.lights.size(); ++i) // the lights prepareLights() kept, in its order
        if (rig.lights[i].enabled) out.ofLight.push_back(of[i]);
    for (size_t g = 0; g < groups.size(); ++g) {
        if (groups[g].kind == LightGroupKind::Environment) out.environment = int(g);
        if (groups[g].kind == LightGroupKind::Emissive) out.emissive = int(g);
        if (groups[g].kind == LightGroupKind::Ambient) out.ambient = int(g);
    }
}

void splitReferencePixel(const ReferenceScene& sc, std::span<const lighting::ShadeLight<double>> lights,
                         const lighting::Surface<double>& s, std::span<const double> shaded,
                         std::span<const double> visibility, std::span<const glm::dvec3> areaDirect,
                         const glm::dvec3& environment, glm::dvec3* groups) {
    const ReferenceScene::Groups& gr = sc.groups;
    std::fill(groups, groups + gr.count, glm::dvec3(0.0));
    const auto add = [&](int g, const glm::dvec3& v) {
        if (g >= 0 && g < gr.count) groups[g] += v;
    };
    // Each light's term as shadeSurface adds it (shade.h), with the view vector and the physically based
    // lobes' inputs computed once for the pixel.
    const glm::dvec3 V = lighting::viewVector(sc.settings, s.position);
    const bool pbr = sc.settings.model == ShadingModel::Pbr;
    const glm::dvec3 cDiff = lighting::pbrDiffuseColor(s.albedo, s.metallic),
                     f0 = lighting::pbrF0(s.albedo, s.metallic);
    const double alpha = lighting::pbrAlpha(s.roughness);
    for (size_t k = 0; k < lights.size() && k < gr.ofLight.size(); ++k) {
        const double v = k < shaded.size() ? shaded[k] : 1.0;
        glm::dvec3 light = pbr ? lighting::shadeLightPbr(lights[k], s, sc.settings, V, cDiff, f0, alpha, v)
                               : lighting::shadeLight(lights[k], s, sc.settings, V, v);
        if (k < areaDirect.size()) light += (k < visibility.size() ? visibility[k] : 1.0) * areaDirect[k];
        add(gr.ofLight[k], light);
    }
    lighting::Surface<double> dark = s; // the scene ambient alone: no lights, no emission
    dark.emissive = glm::dvec3(0.0);
    add(gr.ambient, lighting::shadeSurface<double>(dark, {}, sc.settings));
    add(gr.emissive, s.emissive);
    add(gr.environment, environment);
}

RenderLayers referenceLayers(const ReferenceImage& r, const std::vector<LightGroup>& groups,
                             const GBuffer& gbuffer, const glm::dmat4& view) {
    RenderLayers layers;
    const size_t n = size_t(std::max(0, r.width)) * size_t(std::max(0, r.height));
    const auto image = [&] {
        FloatImage f;
        f.width = r.width;
        f.height = r.height;
        f.pixels.assign(n, glm::vec4(0.0f));
        return f;
    };
    layers.beauty = image();
    for (size_t i = 0; i < n; ++i)
        layers.beauty.pixels[i] = glm::vec4(glm::vec3(r.radiance[i]), r.covered[i] ? 1.0f : 0.0f);
    if (r.groupCount == int(groups.size()) && r.groupCount > 0) {
        layers.groups = groups;
        layers.groupImages.assign(groups.size(), image());
        const glm::dvec3* radiance = r.groupRadiance.data(); // pixel-major: read in order
        for (size_t i = 0; i < n; ++i)
            for (size_t g = 0; g < groups.size(); ++g)
                layers.groupImages[g].pixels[i] =
                    glm::vec4(glm::vec3(*radiance++), layers.beauty.pixels[i].w);
    }
    fillAuxiliaryLayers(gbuffer, view, &layers);
    return layers;
}

std::optional<RenderLayers> computeReferenceLayers(const SceneDescription& scene, const GBuffer& gbuffer,
                                                   const glm::dmat4& view, const RenderSettings& settings,
                                                   QString* error, ReferenceImage* reference) {
    std::optional<ReferenceScene> rs = makeReferenceScene(scene, view, settings, error);
    if (!rs) return std::nullopt;
    const std::vector<LightGroup> groups = sceneLightGroups(scene);
    setReferenceGroups(&*rs, scene.rig(), groups);
    ReferenceJob job(gbuffer, *std::move(rs));
    job.start().waitForFinished();
    job.finish();
    RenderLayers layers = referenceLayers(job.result(), groups, gbuffer, view);
    if (reference) *reference = job.result(); // a copy only when asked for: its per-group radiance is big
    return layers;
}

} // namespace lr
