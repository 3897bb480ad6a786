// Analytic test scenes for the renderer tests: a plane and a sphere built in the test, a camera, and
// one rig per light type and model of the core.
#pragma once

#include "core/rig.h"
#include "model/model.h"
#include "scene/camera.h"

#include <QString>
#include <functional>
#include <memory>
#include <vector>

namespace lr::test {

inline std::shared_ptr<Model> planeScene() {
    auto m = std::make_shared<Model>(makePlane(2.0));
    m->materials[0].baseColor = {0.8f, 0.6f, 0.4f, 1.0f};
    m->materials[0].specular = {0.5f, 0.6f, 0.7f};
    m->materials[0].shininess = 24.0f;
    m->materials[0].emissive = {0.01f, 0.02f, 0.03f};
    return m;
}

inline std::shared_ptr<Model> sphereScene() {
    auto m = std::make_shared<Model>(makeSphere(1.0, 96, 48));
    m->materials[0].baseColor = {0.7f, 0.7f, 0.9f, 1.0f};
    m->materials[0].specular = {1.0f, 1.0f, 1.0f};
    m->materials[0].shininess = -1.0f; // the rig's shading.shininess
    return m;
}

inline ViewCamera planeCamera() {
    ViewCamera c;
    c.eye = {0.4, 0.3, 3.0};
    c.target = {0.0, 0.0, 0.0};
    c.yfovDeg = 60.0;
    return c;
}

inline ViewCamera sphereCamera() {
    ViewCamera c;
    c.eye = {0.0, 0.5, 3.5};
    c.target = {0.0, 0.0, 0.0};
    c.yfovDeg = 45.0;
    return c;
}

inline Light point(glm::dvec3 p, FalloffModel f, double range = -1.0) {
    Light l = makeLight(LightType::Point, QStringLiteral("point"));
    l.position = p;
    l.falloff.model = f;
    l.falloff.range = range;
    l.intensity = 0.9;
    l.color = {1.0, 0.9, 0.8};
    return l;
}

inline Light spot(glm::dvec3 p, glm::dvec3 target, ConeModel cone, double inner, double outer,
                  double exponent) {
    Light l = makeLight(LightType::Spot, QStringLiteral("spot"));
    l.position = p;
    l.direction = glm::normalize(target - p);
    l.falloff.model = FalloffModel::None;
    l.falloff.range = -1.0;
    l.cone = {cone, inner, outer, exponent};
    l.intensity = 1.2;
    return l;
}

inline Light directional(glm::dvec3 d, DiffuseModel diffuse) {
    Light l = makeLight(LightType::Directional, QStringLiteral("sun"));
    l.direction = glm::normalize(d);
    l.diffuse = diffuse;
    l.color = {0.9, 0.95, 1.0};
    return l;
}

inline Light rim(glm::dvec3 d, double exponent) {
    Light l = makeLight(LightType::Rim, QStringLiteral("rim"));
    l.direction = glm::normalize(d);
    l.rimExponent = exponent;
    l.color = {0.3, 0.5, 1.0};
    return l;
}

struct RigCase {
    const char* name;
    std::function<Rig()> make;
};

inline Rig rigOf(std::vector<Light> lights) {
    Rig r;
    r.name = QStringLiteral("test");
    r.lights = std::move(lights);
    return r;
}

// One rig per light type and per falloff, cone, diffuse, specular, viewer and rim model.
inline std::vector<RigCase> rigCases() {
    const glm::dvec3 p(0.5, 0.5, 1.5);
    return {
        {"point-none", [=] { return rigOf({point(p, FalloffModel::None)}); }},
        {"point-range-power",
         [=] {
             Light l = point(p, FalloffModel::RangePower, 3.0);
             l.falloff.exponent = 2.0;
             return rigOf({l});
         }},
        {"point-range-power-0.7",
         [=] {
             Light l = point(p, FalloffModel::RangePower, 2.2);
             l.falloff.exponent = 0.7;
             return rigOf({l});
         }},
        {"point-inverse-polynomial",
         [=] {
             Light l = point(p, FalloffModel::InversePolynomial);
             l.falloff.constant = 1.0, l.falloff.linear = 0.3, l.falloff.quadratic = 0.2;
             return rigOf({l});
         }},
        {"point-inverse-polynomial-range",
         [=] {
             Light l = point(p, FalloffModel::InversePolynomial, 2.5);
             l.falloff.constant = 0.5, l.falloff.linear = 0.0, l.falloff.quadratic = 1.0;
             return rigOf({l});
         }},
        {"point-range-quadratic", [=] { return rigOf({point(p, FalloffModel::RangeQuadratic, 2.5)}); }},
        {"point-inverse-square",
         [=] {
             Light l = point(p, FalloffModel::InverseSquare);
             l.intensity = 2.0;
             return rigOf({l});
         }},
        {"point-inverse-square-range",
         [=] {
             Light l = point(p, FalloffModel::InverseSquare, 2.5);
             l.intensity = 2.0;
             return rigOf({l});
         }},
        {"spot-smooth",
         [] {
             return rigOf({spot({0.0, 0.3, 2.0}, {0.2, 0.1, 0.0}, ConeModel::Smooth, 15.0, 30.0, 1.0)});
         }},
        {"spot-smooth-exp2-inverse-square",
         [] {
             Light l = spot({-0.3, 0.2, 1.8}, {0.0, 0.0, 0.0}, ConeModel::Smooth, 10.0, 28.0, 2.0);
             l.falloff.model = FalloffModel::InverseSquare;
             l.intensity = 3.0;
             return rigOf({l});
         }},
        {"spot-angle-power",
         [] {
             return rigOf({spot({0.0, 0.0, 2.0}, {0.1, -0.1, 0.0}, ConeModel::AnglePower, 0.0, 35.0, 1.5)});
         }},
        {"spot-hard",
         [] {
             return rigOf({spot({0.2, 0.0, 2.0}, {0.0, 0.0, 0.0}, ConeModel::Hard, 0.0, 25.0, 1.0)});
         }},
        {"directional-lambert",
         [] {
             return rigOf({directional({-0.3, -0.4, -1.0}, DiffuseModel::Lambert)});
         }},
        {"directional-half-lambert",
         [] {
             return rigOf({directional({0.5, -0.2, -1.0}, DiffuseModel::HalfLambert)});
         }},
        {"rim",
         [] {
             return rigOf({rim({0.0, 0.0, -1.0}, 1.3)});
         }},
        {"rim-sideways",
         [] {
             return rigOf({rim({1.0, -0.5, -0.3}, 3.0)});
         }},
        {"blinn-phong",
         [=] {
             Rig r = rigOf({point(p, FalloffModel::None)});
             r.shading.specular = SpecularModel::BlinnPhong;
             return r;
         }},
        {"phong-infinite-viewer",
         [=] {
             Rig r = rigOf({point(p, FalloffModel::None)});
             r.shading.viewer = ViewerModel::Infinite;
             return r;
         }},
        {"blinn-phong-infinite-viewer",
         [] {
             Rig r = rigOf({directional({-0.3, -0.4, -1.0}, DiffuseModel::Lambert)});
             r.shading.specular = SpecularModel::BlinnPhong;
             r.shading.viewer = ViewerModel::Infinite;
             r.shading.shininess = 80.0;
             return r;
         }},
        {"light-ambient",
         [=] {
             Light l = point(p, FalloffModel::RangeQuadratic, 3.0);
             l.ambient = glm::dvec3(0.05, 0.04, 0.03);
             return rigOf({l});
         }},
        {"scene-ambient-only",
         [] {
             Rig r = rigOf({});
             r.ambient = {0.1, 0.2, 0.3};
             return r;
         }},
        {"model-space",
         [] {
             Rig r = rigOf({point({0.4, 0.5, 0.8}, FalloffModel::RangePower, 1.5)});
             r.space = RigSpace::Model;
             return r;
         }},
        {"temperature",
         [=] {
             Light l = point(p, FalloffModel::None);
             l.temperature = 3200.0;
             return rigOf({l});
         }},
        {"mixed-all-types",
         [=] {
             Light a = point(p, FalloffModel::InverseSquare, 4.0);
             Light b = point({-0.6, 0.2, 1.0}, FalloffModel::RangePower, 2.5);
             b.diffuse = DiffuseModel::HalfLambert;
             Light c = spot({0.0, 0.3, 2.0}, {0.2, 0.1, 0.0}, ConeModel::Smooth, 15.0, 30.0, 1.0);
             Light d = spot({0.2, 0.0, 2.0}, {-0.3, 0.0, 0.0}, ConeModel::AnglePower, 0.0, 25.0, 2.0);
             d.falloff.model = FalloffModel::InversePolynomial;
             d.falloff.linear = 0.5;
             Light e = directional({-0.3, -0.4, -1.0}, DiffuseModel::Lambert);
             e.intensity = 0.3;
             Light f = rim({0.0, 0.0, -1.0}, 2.0);
             Light g = point({0.0, -0.5, 0.7}, FalloffModel::RangeQuadratic, 1.2);
             g.ambient = glm::dvec3(0.02);
             Light off = point({0, 0, 1}, FalloffModel::None);
             off.enabled = false;
             Rig r = rigOf({a, b, c, d, e, f, g, off});
             r.ambient = {0.02, 0.02, 0.03};
             return r;
         }},
    };
}

// Physically based (issue 13): six spheres in one model, metallic 0 (top row) and 1 (bottom row) by
// roughness 0 (floored to kMinRoughness), 0.4 and 1, each its own material; occlusion strength 1.
inline std::shared_ptr<Model> pbrSpheresScene() {
    auto m = std::make_shared<Model>();
    m->origin = glm::dvec3(0.0);
    m->bounds.min = glm::dvec3(-1.5, -1.0, -0.5);
    m->bounds.max = glm::dvec3(1.5, 1.0, 0.5);
    const float roughness[] = {0.0f, 0.4f, 1.0f};
    for (int row = 0; row < 2; ++row) {
        for (int col = 0; col < 3; ++col) {
            const glm::dvec3 c(-1.0 + col, row == 0 ? 0.5 : -0.5, 0.0);
            Model one = makeSphere(0.45, 64, 32, c);
            Mesh mesh = one.meshes.front();
            for (Vertex& v : mesh.vertices)
                v.position += glm::vec3(one.origin - m->origin);
            Material mat;
            mat.name = QStringLiteral("m%1r%2").arg(row).arg(col);
            mat.pbr = true;
            mat.baseColor =
                row == 0 ? glm::vec4(0.8f, 0.3f, 0.2f, 1.0f) : glm::vec4(0.95f, 0.75f, 0.35f, 1.0f);
            mat.metallic = float(row);
            mat.roughness = roughness[col];
            mesh.material = int(m->materials.size());
            m->materials.push_back(mat);
            m->meshes.push_back(std::move(mesh));
        }
    }
    return m;
}

inline ViewCamera pbrSpheresCamera() {
    ViewCamera c;
    c.eye = {0.0, 0.3, 4.0};
    c.target = {0.0, 0.0, 0.0};
    c.yfovDeg = 45.0;
    return c;
}

// Lights as glTF imports them (KHR_lights_punctual): inverse square with the range window, smooth cone of
// exponent 2, candela / lux.
inline Light gltfPoint(glm::dvec3 p, double candela, double range) {
    Light l = point(p, FalloffModel::InverseSquare, range);
    l.intensity = candela;
    return l;
}

inline Light gltfSpot(glm::dvec3 p, glm::dvec3 target, double candela) {
    Light l = spot(p, target, ConeModel::Smooth, 10.0, 35.0, 2.0);
    l.falloff.model = FalloffModel::InverseSquare;
    l.falloff.range = -1.0;
    l.intensity = candela;
    return l;
}

inline Rig pbrRig(std::vector<Light> lights, glm::dvec3 ambient = glm::dvec3(0.0)) {
    Rig r = rigOf(std::move(lights));
    r.shading.model = ShadingModel::Pbr;
    r.ambient = ambient;
    return r;
}

// One physically based rig per light type, and one mixing them with a rim, a half-Lambert light, a light
// with an ambient colour and the scene ambient.
inline std::vector<RigCase> pbrRigCases() {
    return {
        {"pbr-point",
         [] {
             return pbrRig({gltfPoint({1.0, 1.5, 2.5}, 12.0, 12.0)});
         }},
        {"pbr-spot",
         [] {
             return pbrRig({gltfSpot({-0.5, 2.0, 3.0}, {0.0, 0.0, 0.0}, 20.0)});
         }},
        {"pbr-directional",
         [] {
             Light sun = directional({-0.4, -0.5, -1.0}, DiffuseModel::Lambert);
             sun.intensity = 2.5; // lux
             return pbrRig({sun});
         }},
        {"pbr-mixed",
         [] {
             Light half = directional({0.6, -0.2, -1.0}, DiffuseModel::HalfLambert);
             Light amb = gltfPoint({-1.5, -1.0, 2.0}, 6.0, -1.0);
             amb.ambient = glm::dvec3(0.2, 0.1, 0.05);
             return pbrRig({gltfPoint({1.0, 1.5, 2.5}, 12.0, 12.0),
                            gltfSpot({-0.5, 2.0, 3.0}, {0, 0, 0}, 20.0), half, amb,
                            rim({1.0, -0.5, -0.3}, 2.0)},
                           glm::dvec3(0.3, 0.3, 0.35));
         }},
        // A light 1e16 away whose falloff does not fade with distance (None): its direction must come out
        // right, so the renderer compiles the rescaled normalisation (LR_FAR_LIGHTS) for this frame.
        {"pbr-far-light",
         [] {
             Light far = point({4e15, 6e15, 7e15}, FalloffModel::None);
             far.intensity = 1.5;
             return pbrRig({far, gltfPoint({1.0, 1.5, 2.5}, 12.0, 12.0)});
         }},
    };
}

} // namespace lr::test
