#include "referencetrace.h"

#include "core/lighting.h"
#include "core/lowdiscrepancy.h"
#include "model/ground.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>
#include <numbers>

namespace lr {

namespace {

double uniform01(std::uint32_t* state) {
    *state = pcgHash(*state);
    return double(*state >> 8) * (1.0 / 16777216.0); // [0, 1)
}

// Shirley and Chiu's concentric map from the unit square to the unit disk: equal-area, so stratified
// squares become stratified disk areas.
glm::dvec2 concentricDisk(double u, double v) {
    const double a = 2.0 * u - 1.0, b = 2.0 * v - 1.0;
    if (a == 0.0 && b == 0.0) return glm::dvec2(0.0);
    constexpr double quarterPi = std::numbers::pi / 4.0;
    const double r = std::abs(a) > std::abs(b) ? a : b;
    const double phi =
        std::abs(a) > std::abs(b) ? quarterPi * (b / a) : 2.0 * quarterPi - quarterPi * (a / b);
    return r * glm::dvec2(std::cos(phi), std::sin(phi));
}

// The point a fraction s (0..1) along the unit square [-1, 1]²'s perimeter (counter-clockwise).
glm::dvec2 squareRim(double s) {
    const double t = 4.0 * (s - std::floor(s));
    const int side = std::min(3, int(t));
    const double f = 2.0 * (t - side) - 1.0;
    switch (side) {
    case 0:
        return {f, -1.0};
    case 1:
        return {1.0, f};
    case 2:
        return {-f, 1.0};
    default:
        return {-1.0, -f};
    }
}

// Two unit vectors completing unit `w` to an orthonormal basis.
void basisAround(const glm::dvec3& w, glm::dvec3* t, glm::dvec3* b) {
    const glm::dvec3 helper = std::abs(w.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    *t = glm::normalize(glm::cross(helper, w)); // |cross| >= sqrt(1 - 0.81): never normalize(0)
    *b = glm::cross(w, *t);
}

} // namespace

ShadowEmitter shadowEmitter(const Rig& rig, const SceneFrame& frame, const Light& light) {
    ShadowEmitter e;
    e.casts = light.hasShadow();
    e.directional = !light.usesPosition();
    const double toWorld = 1.0 / distanceScale(rig, frame); // rig units -> world units, as positions
    if (e.directional) {
        e.toLight = -lighting::safeNormalize(light.direction, glm::dvec3(0.0, -1.0, 0.0));
        const double angle = std::isfinite(light.shadow.angle) ? std::max(0.0, light.shadow.angle) : 0.0;
        e.halfAngle = 0.5 * glm::radians(std::min(angle, 180.0));
    } else if (light.isArea()) {
        e.position = rigToWorld(rig, frame, light.position);
        e.area = light.type == LightType::Disk ? ShadowEmitter::Area::Disk : ShadowEmitter::Area::Rect;
        e.normal = lighting::safeNormalize(light.direction, glm::dvec3(0.0, -1.0, 0.0));
        const AreaAxes a = areaAxes(e.normal, light.area.roll);
        e.axisX = a.x;
        e.axisY = a.y;
        const auto half = [&](double v) { return std::isfinite(v) ? 0.5 * std::max(0.0, v) * toWorld : 0.0; };
        const bool disk = e.area == ShadowEmitter::Area::Disk;
        e.halfWidth = half(disk ? 2.0 * light.area.radius : light.area.width);
        e.halfHeight = half(disk ? 2.0 * light.area.radius : light.area.height);
        e.twoSided = light.area.twoSided;
    } else {
        e.position = rigToWorld(rig, frame, light.position);
        const double size = std::isfinite(light.shadow.size) ? std::max(0.0, light.shadow.size) : 0.0;
        e.radius = 0.5 * size * toWorld;
    }
    return e;
}

ShadowTracer::ShadowTracer(const Model& model, bool ground, std::vector<std::uint32_t> partMasks) {
    m_epsilon = kShadowRayEpsilon * model.bounds.radius();
    std::vector<const Model*> models{&model};
    if (ground) {
        const GroundPlane g = groundPlane(model.bounds);
        m_groundQuad.origin = (g.corners[0] + g.corners[2]) * 0.5;
        Mesh quad;
        for (const glm::dvec3& c : g.corners)
            quad.vertices.push_back({glm::vec3(c - m_groundQuad.origin)});
        quad.indices = {0, 1, 2, 0, 2, 3};
        m_groundQuad.meshes.push_back(std::move(quad));
        models.push_back(&m_groundQuad);
    }
    m_scene = std::make_unique<EmbreeScene>(models, model.bounds.center(), std::move(partMasks));
}

ShadowTracer::~ShadowTracer() = default;

bool ShadowTracer::occluded(const glm::dvec3& origin, const glm::dvec3& dir, double distance,
                            std::uint32_t mask) const {
    return ok() && m_scene->occluded(origin, dir, distance, 0.0, mask);
}

glm::dvec3 ShadowTracer::geometricNormal(const glm::dvec3& eye, const glm::dvec3& point,
                                         const glm::dvec3& fallback) const {
    return surfaceSeen(eye, point, fallback).normal;
}

ShadowTracer::Seen ShadowTracer::surfaceSeen(const glm::dvec3& eye, const glm::dvec3& point,
                                             const glm::dvec3& fallback) const {
    Seen seen{fallback, -1};
    const glm::dvec3 toPoint = point - eye;
    const double len = glm::length(toPoint);
    if (!ok() || !(len > 0.0) || !std::isfinite(len)) return seen;
    const glm::dvec3 d = toPoint / len;
    const double slack = std::max(1e-3 * len, 10.0 * m_epsilon); // the G-buffer's float position
    const EmbreeHit hit = m_scene->intersect(eye, d, std::max(0.0, len - slack), len + slack);
    if (!hit.hit) return seen;
    const glm::dvec3 n = hit.normal;
    seen.normal = glm::dot(n, eye - point) >= 0.0 ? n : -n;
    seen.part = int(hit.part);
    return seen;
}

double ShadowTracer::visibility(const glm::dvec3& point, const glm::dvec3& normal, const ShadowEmitter& e,
                                std::uint32_t seed, int samples) const {
    if (!e.casts || !ok()) return 1.0;
    const glm::dvec3 origin = point + normal * m_epsilon;
    glm::dvec3 w = e.toLight;
    if (!e.directional) {
        const glm::dvec3 toCentre = e.position - origin;
        const double d = glm::length(toCentre);
        if (!(d > 0.0) || !std::isfinite(d)) return 1.0; // the light at the point: nothing in between
        w = toCentre / d;
    }
    const bool area = e.area != ShadowEmitter::Area::None;
    if (area && !e.twoSided && !(glm::dot(origin - e.position, e.normal) > 0.0)) return 1.0; // behind it
    const bool hard = e.directional ? !(e.halfAngle > 0.0)
                      : area        ? !(e.halfWidth > 0.0 || e.halfHeight > 0.0)
                                    : !(e.radius > 0.0);
    glm::dvec3 t, b;
    basisAround(w, &t, &b);
    const double oneMinusCos = e.directional ? 1.0 - std::cos(e.halfAngle) : 0.0;
    // Whether the ray towards the emitter point `disk` (unit disk coordinates) arrives.
    const auto arrives = [&](glm::dvec2 disk) {
        if (e.directional) {
            const double r2 = glm::dot(disk, disk);
            const double cosT = 1.0 - r2 * oneMinusCos; // equal-area disk -> spherical cap
            const double sinT = std::sqrt(std::max(0.0, 1.0 - cosT * cosT));
            const double r = std::sqrt(r2);
            const glm::dvec3 side = r > 0.0 ? (disk.x * t + disk.y * b) * (sinT / r) : glm::dvec3(0.0);
            return !occluded(origin, glm::normalize(cosT * w + side), std::numeric_limits<double>::infinity(),
                             e.shadowMask);
        }
        const glm::dvec3 target =
            area ? e.position + disk.x * e.halfWidth * e.axisX + disk.y * e.halfHeight * e.axisY
                 : e.position + e.radius * (disk.x * t + disk.y * b);
        const glm::dvec3 toTarget = target - origin;
        const double len = glm::length(toTarget);
        if (!(len > 0.0)) return true;
        return !occluded(origin, toTarget / len, len, e.shadowMask);
    };
    if (hard) return arrives(glm::dvec2(0.0)) ? 1.0 : 0.0;
    // Jittered strata: n × n squares of the unit square, one uniformly placed sample in each.
    const auto count = [&](int wanted, std::uint32_t state) {
        const int n = std::max(1, int(std::lround(std::sqrt(double(std::max(1, wanted))))));
        int arrived = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double u = (i + uniform01(&state)) / n, v = (j + uniform01(&state)) / n;
                const bool square = e.area == ShadowEmitter::Area::Rect;
                arrived +=
                    arrives(square ? glm::dvec2(2.0 * u - 1.0, 2.0 * v - 1.0) : concentricDisk(u, v)) ? 1 : 0;
            }
        return std::pair{arrived, n * n};
    };
    // The probe: the emitter's rim, where an edge crossing the emitter shows first (a visible or hidden
    // sliver of the disk always reaches it), and jittered strata inside.
    std::uint32_t state = pcgHash(seed);
    const double phase = uniform01(&state);
    int probeArrived = 0;
    for (int k = 0; k < kShadowRimSamples; ++k) {
        const double a = 2.0 * std::numbers::pi * (k + phase) / kShadowRimSamples;
        probeArrived +=
            arrives(e.area == ShadowEmitter::Area::Rect ? squareRim((k + phase) / kShadowRimSamples)
                                                        : glm::dvec2(std::cos(a), std::sin(a)))
                ? 1
                : 0;
    }
    const auto [insideArrived, insideRays] = count(kShadowProbeSamples, state);
    probeArrived += insideArrived;
    if (probeArrived == 0) return 0.0;
    if (probeArrived == insideRays + kShadowRimSamples) return 1.0;
    const auto [arrived, rays] = count(samples, pcgHash(seed ^ 0x9e3779b9u));
    return double(arrived) / double(rays);
}

} // namespace lr
