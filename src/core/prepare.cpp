#include "prepare.h"

#include "barndoors.h"
#include "fallofftraits.h"
#include "gobo.h"

#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

namespace lr {

namespace {
glm::dvec3 transformPoint(const glm::dmat4& m, const glm::dvec3& p) {
    return glm::dvec3(m * glm::dvec4(p, 1.0));
}
glm::dvec3 transformDirection(const glm::dmat4& m, const glm::dvec3& v) {
    return lighting::safeNormalize(glm::dvec3(m * glm::dvec4(v, 0.0)), glm::dvec3(0, 0, -1));
}
} // namespace

glm::dvec3 rigToWorld(const Rig& rig, const SceneFrame& frame, const glm::dvec3& p) {
    return rig.space == RigSpace::Model ? frame.center + frame.radius * p : p;
}

glm::dvec3 worldToRig(const Rig& rig, const SceneFrame& frame, const glm::dvec3& p) {
    if (rig.space != RigSpace::Model) return p;
    return frame.radius > 0.0 ? (p - frame.center) / frame.radius : glm::dvec3(0.0);
}

double distanceScale(const Rig& rig, const SceneFrame& frame) {
    if (rig.space != RigSpace::Model) return 1.0;
    return frame.radius > 0.0 ? 1.0 / frame.radius : 1.0;
}

bool lightReaches(const Rig& rig, const SceneFrame& frame, const Light& light, const glm::dvec3& center,
                  double radius) {
    if (!light.enabled) return false;
    if (!light.usesFalloff()) return true;
    const Falloff& f = light.falloff;
    if (!falloffBounded(f)) return true;
    const double worldRange = f.range / distanceScale(rig, frame);
    const double d = glm::length(rigToWorld(rig, frame, light.position) - center);
    return d < worldRange + radius; // the falloff is exactly zero at d >= range
}

AreaAxes areaAxes(const glm::dvec3& direction, double rollDegrees) {
    const glm::dvec3 n = lighting::safeNormalize(direction, glm::dvec3(0.0, -1.0, 0.0));
    const glm::dvec3 c = glm::cross(n, glm::dvec3(0.0, 1.0, 0.0));
    const double len = glm::length(c);
    AreaAxes a;
    a.x = len > 1e-6 ? c / len : glm::dvec3(1.0, 0.0, 0.0);
    a.y = glm::normalize(glm::cross(a.x, n));
    a.x = glm::cross(n, a.y); // exactly orthogonal to n when the fallback was used
    const double r = glm::radians(std::isfinite(rollDegrees) ? rollDegrees : 0.0);
    const double cr = std::cos(r), sr = std::sin(r);
    return {cr * a.x - sr * a.y, sr * a.x + cr * a.y}; // right-handed about n
}

lighting::ShadeLight<double> prepareLight(const Rig& rig, const SceneFrame& frame, const glm::dmat4& view,
                                          const Light& light) {
    lighting::ShadeLight<double> o;
    o.type = light.type;
    const glm::dvec3 color = light.effectiveColor();
    o.color = color * light.intensity;
    o.specular = (light.specularIsColor ? light.specular : color * light.specular.x) * light.intensity;
    o.ambient = light.ambient.value_or(glm::dvec3(0.0)) * light.intensity;
    if (light.usesPosition()) o.position = transformPoint(view, rigToWorld(rig, frame, light.position));
    if (light.usesDirection()) o.direction = transformDirection(view, light.direction);
    if (light.usesFalloff()) {
        const Falloff& f = light.falloff;
        o.falloff = f.model;
        o.range = f.range;
        o.falloffExponent = f.exponent;
        o.constant = f.constant, o.linear = f.linear, o.quadratic = f.quadratic;
    }
    if (light.usesCone()) {
        o.cone = light.cone.model;
        o.outer = glm::radians(light.cone.outer);
        o.cosOuter = std::cos(o.outer);
        o.cosInner = std::cos(glm::radians(light.cone.inner));
        o.coneExponent = light.cone.exponent;
    }
    if (light.gobo && light.type == LightType::Spot) { // the image itself is attached by the renderer
        const AreaAxes a = areaAxes(light.direction, light.gobo->rotation);
        o.axisX = transformDirection(view, a.x);
        o.axisY = transformDirection(view, a.y);
        o.goboHalf = gobo::halfExtent(o.outer, light.gobo->scale);
    }
    o.diffuse = light.diffuse;
    o.rimExponent = light.rimExponent;
    if (light.isArea()) {
        const AreaAxes a = areaAxes(light.direction, light.area.roll);
        o.axisX = transformDirection(view, a.x);
        o.axisY = transformDirection(view, a.y);
        const double toView = 1.0 / distanceScale(rig, frame); // rig units -> world (= view) units
        const bool disk = light.type == LightType::Disk;
        o.halfWidth = 0.5 * std::max(0.0, disk ? 2.0 * light.area.radius : light.area.width) * toView;
        o.halfHeight = 0.5 * std::max(0.0, disk ? 2.0 * light.area.radius : light.area.height) * toView;
        o.twoSided = light.area.twoSided;
        if (light.type == LightType::Rect && light.barnDoors) {
            const barndoors::FlapShape f = barndoors::flapShape(*light.barnDoors);
            o.barnDepth = f.depth * toView;
            o.barnExtent = f.extent * toView;
        }
    }
    return o;
}

std::vector<lighting::ShadeLight<double>> prepareLights(const Rig& rig, const SceneFrame& frame,
                                                        const glm::dmat4& view) {
    std::vector<lighting::ShadeLight<double>> out;
    out.reserve(rig.lights.size());
    for (const Light& l : rig.lights)
        if (l.enabled) out.push_back(prepareLight(rig, frame, view, l));
    return out;
}

lighting::ShadeSettings<double> prepareSettings(const Rig& rig, const SceneFrame& frame) {
    lighting::ShadeSettings<double> s;
    s.model = rig.shading.model;
    s.specular = rig.shading.specular;
    // Physically based shading always uses the true (local) viewer.
    s.viewer = rig.shading.model == ShadingModel::Pbr ? ViewerModel::Local : rig.shading.viewer;
    s.ambient = rig.ambient;
    s.distanceScale = distanceScale(rig, frame);
    return s;
}

glm::dvec3 temperatureToRgb(double kelvin) {
    // Tanner Helland's fit of the CIE 1964 black-body colours (sRGB-encoded), converted to linear RGB.
    const double t = std::clamp(std::isfinite(kelvin) ? kelvin : 6600.0, 1000.0, 40000.0) / 100.0;
    double r, g, b;
    if (t <= 66.0) {
        r = 255.0;
        g = 99.4708025861 * std::log(t) - 161.1195681661;
        b = t <= 19.0 ? 0.0 : 138.5177312231 * std::log(t - 10.0) - 305.0447927307;
    } else {
        r = 329.698727446 * std::pow(t - 60.0, -0.1332047592);
        g = 288.1221695283 * std::pow(t - 60.0, -0.0755148492);
        b = 255.0;
    }
    glm::dvec3 c(colour::srgbToLinear(std::clamp(r, 0.0, 255.0) / 255.0),
                 colour::srgbToLinear(std::clamp(g, 0.0, 255.0) / 255.0),
                 colour::srgbToLinear(std::clamp(b, 0.0, 255.0) / 255.0));
    const double m = std::max({c.x, c.y, c.z});
    return m > 0.0 ? c / m : glm::dvec3(1.0);
}

glm::dvec3 Light::effectiveColor() const {
    return temperature ? color * temperatureToRgb(*temperature) : color;
}

Light makeLight(LightType type, const QString& name) {
    const LightTypeTraits& t = traitsOf(type);
    Light l;
    l.name = name;
    l.type = type;
    l.position = glm::dvec3(2.0, 2.0, 2.0);
    if (t.usesDirection) {
        const glm::dvec3 d(t.defaultDirection[0], t.defaultDirection[1], t.defaultDirection[2]);
        l.direction = lighting::safeNormalize(d == glm::dvec3(0.0) ? -l.position : d, glm::dvec3(0, -1, 0));
    }
    if (t.usesFalloff) l.falloff = {FalloffModel::RangePower, t.defaultRange, 2.0};
    return l; // the cone: Cone{} (smooth, 20°/35°, exponent 1)
}

} // namespace lr
