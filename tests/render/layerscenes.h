// The scene of the light-group tests (tst_rasterlayers, tst_referencelayers): a sphere floating over a
// visible ground, emitting a little, lit by five groups — a key spot and a sun that cast shadows at
// different map resolutions (so the shadow array's resolution is the sun's), two fill points in one group
// (one with an ambient term of its own), a rim — with scene ambient and a uniform environment, and a
// comparison of float images relative to their brightness.
#pragma once

#include "core/lightgroups.h"
#include "environmentfixture.h"
#include "render/floatimage.h"
#include "scenes.h"
#include "shadowscenes.h"

#include <algorithm>
#include <cmath>

namespace lr::test {

inline const QSize kLayerSize(96, 72);

inline std::shared_ptr<Model> emittingSphere() {
    auto m = floatingSphere();
    m->materials[0].emissive = {0.05f, 0.03f, 0.01f};
    m->materials[0].specular = {0.4f, 0.4f, 0.4f};
    m->materials[0].shininess = 24.0f;
    m->materials[0].roughness = 0.5f;
    return m;
}

inline Rig layerRig(ShadingModel shading, bool environment = true, bool area = false) {
    Light key = spot({1.5, 3.0, 1.5}, {0.0, 0.5, 0.0}, ConeModel::Smooth, 20.0, 35.0, 1.0);
    key.name = QStringLiteral("key light");
    key.group = QStringLiteral("key");
    key.intensity = 2.0;
    key.shadow.enabled = true;
    key.shadow.resolution = 512;
    Light fillA = point({-2.0, 2.0, 2.0}, FalloffModel::None);
    fillA.name = QStringLiteral("fill A");
    fillA.group = QStringLiteral("fill");
    fillA.ambient = glm::dvec3(0.02, 0.03, 0.04);
    Light fillB = point({2.0, 1.0, 2.5}, FalloffModel::None);
    fillB.name = QStringLiteral("fill B");
    fillB.group = QStringLiteral("fill");
    fillB.intensity = 0.4;
    Light sun = directional({-0.4, -1.0, -0.3}, DiffuseModel::Lambert);
    sun.intensity = 0.7;
    sun.shadow.enabled = true;
    sun.shadow.resolution = 1024;
    Light edge = rim({0.0, 0.0, -1.0}, 2.0);
    Rig r = rigOf({key, fillA, fillB, sun, edge});
    if (area) {
        Light box = makeLight(LightType::Rect, QStringLiteral("softbox"));
        box.position = {-1.0, 2.5, 1.0};
        box.direction = glm::normalize(glm::dvec3(0.0, 0.8, 0.0) - box.position);
        box.area.width = 1.0, box.area.height = 0.5;
        box.intensity = 2.0;
        box.shadow.enabled = true;
        r.lights.push_back(box);
    }
    r.shading.model = shading;
    r.ambient = glm::dvec3(0.03, 0.03, 0.035);
    r.ground.mode = GroundMode::Visible;
    if (environment) {
        r.environment.source = EnvironmentSource::Image;
        r.environment.background = EnvironmentBackground::Visible;
        r.environment.intensity = -1.0;
    }
    return r;
}

inline std::shared_ptr<const LoadedEnvironment> layerEnvironment() {
    return uniformEnvironment({0.3f, 0.35f, 0.4f});
}

inline RenderSettings layerSettings(Quality q, int msaa) {
    RenderSettings s;
    s.quality = q;
    s.msaaSamples = msaa;
    s.hdrFloat32 = true;
    return s;
}

// How far `got` is from `want`, relative to each pixel's brightness: per pixel the largest channel
// difference over the largest channel of `want` (at least 1e-3 of the image's peak). mean: over the pixels
// `want` covers (alpha > 0); max: over those at least 5 % of the peak.
struct Relative {
    double mean = 0.0, max = 0.0;
    int pixels = 0, bright = 0;
};

inline Relative relativeDifference(const FloatImage& got, const FloatImage& want) {
    Relative r;
    if (got.pixels.size() != want.pixels.size()) return {INFINITY, INFINITY, 0, 0};
    double peak = 0.0;
    for (const glm::vec4& p : want.pixels)
        peak = std::max({peak, double(p.r), double(p.g), double(p.b)});
    double sum = 0.0;
    for (size_t i = 0; i < want.pixels.size(); ++i) {
        const glm::vec4 w = want.pixels[i], g = got.pixels[i];
        if (!(w.a > 0.0f)) continue;
        const double level = std::max({double(w.r), double(w.g), double(w.b)});
        double d = 0.0;
        for (int c = 0; c < 3; ++c)
            d = std::max(d, std::abs(double(g[c]) - double(w[c])));
        const double rel = d / std::max(level, 1e-3 * peak);
        sum += rel;
        ++r.pixels;
        if (level >= 0.05 * peak) r.max = std::max(r.max, rel), ++r.bright;
    }
    r.mean = r.pixels > 0 ? sum / r.pixels : 0.0;
    return r;
}

inline int groupIndex(const std::vector<LightGroup>& groups, const QString& name) {
    for (size_t g = 0; g < groups.size(); ++g)
        if (groups[g].name == name) return int(g);
    return -1;
}

} // namespace lr::test
