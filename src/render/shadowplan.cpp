#include "shadowplan.h"

#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

namespace lr::render {

namespace {

// The cube faces: the axis each looks along and its right and up vectors (lookAt's s and u for the up
// hints +Y, or +Z for the ±Y faces). shaders/shadows.glsl holds the same table (kFaceRight, kFaceUp).
struct Face {
    glm::dvec3 forward, right, up;
};
constexpr Face kFaces[6] = {
    {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},  {{-1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
    {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},  {{0, -1, 0}, {-1, 0, 0}, {0, 0, 1}},
    {{0, 0, 1}, {-1, 0, 0}, {0, 1, 0}}, {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},
};

glm::dvec3 upFor(const glm::dvec3& axis) {
    return std::abs(axis.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
}

// Near and far planes around a sphere seen from a point at `distance` from its centre; a point inside the
// sphere gets a near plane of far / 1000 (32-bit float depth keeps that ratio well).
void planesAround(double distance, double radius, double* znear, double* zfar) {
    *zfar = distance + radius;
    *znear = std::max(distance - radius, *zfar * 1e-3);
}

// The layers a casting light's map takes at `res` (an area light's kind depends on it, slightly).
int layersOf(const Light& l, const glm::dvec3& position, const glm::dvec3& c, double r, int res) {
    if (l.isArea())
        return areaShadowKind(position, c, r, res) == ShadowKind::Cube ? (l.area.twoSided ? 6 : 5) : 1;
    return shadowKindOf(l.type) == ShadowKind::Cube ? 6 : 1;
}

int arrayResolution(const Rig& rig, const std::vector<int>& casters, const std::vector<glm::dvec3>& positions,
                    const glm::dvec3& c, double r) {
    int res = 256;
    for (int i : casters)
        res = std::max(res, std::clamp(rig.lights[size_t(i)].shadow.resolution, 256, 4096));
    const auto layers = [&](int at) {
        qint64 n = 0;
        for (size_t k = 0; k < casters.size(); ++k)
            n += layersOf(rig.lights[size_t(casters[k])], positions[k], c, r, at);
        return n;
    };
    while (res > 256 && qint64(res) * res * 4 * layers(res) > kMaxShadowBytes)
        res /= 2;
    return res;
}

double finiteSize(double v) {
    return std::isfinite(v) ? std::max(0.0, v) : 0.0;
}

} // namespace

ShadowKind areaShadowKind(const glm::dvec3& position, const glm::dvec3& c, double r, int resolution) {
    const double dist = glm::length(c - position);
    if (!(dist > r)) return ShadowKind::Cube;
    const double tanSphere = r / std::sqrt(dist * dist - r * r);
    return tanSphere <= 1.0 + 2.0 * kAreaFilterTexels / resolution ? ShadowKind::Perspective
                                                                   : ShadowKind::Cube;
}

double areaPenumbraSize(const Light& l) {
    if (l.type == LightType::Disk) return 2.0 * finiteSize(l.area.radius);
    return 2.0 * std::sqrt(finiteSize(l.area.width) * finiteSize(l.area.height) / M_PI);
}

double areaSearchSize(const Light& l) {
    if (l.type == LightType::Disk) return 2.0 * finiteSize(l.area.radius);
    return std::hypot(finiteSize(l.area.width), finiteSize(l.area.height));
}

double ShadowView::texelScale() const {
    return kind == ShadowKind::Orthographic ? 2.0 * halfWidth / resolution : 2.0 * tanHalf / resolution;
}

glm::dmat4 ShadowView::faceViewProj(int face) const {
    if (kind != ShadowKind::Cube) return viewProj;
    const Face& local = kFaces[std::clamp(face, 0, 5)];
    const Face f{axes * local.forward, axes * local.right, axes * local.up}; // the face in world axes
    glm::dmat4 v(1.0); // rows: right, up, -forward (a right-handed view looking down -Z)
    for (int c = 0; c < 3; ++c) {
        v[c][0] = f.right[c];
        v[c][1] = f.up[c];
        v[c][2] = -f.forward[c];
    }
    v[3][0] = -glm::dot(f.right, position);
    v[3][1] = -glm::dot(f.up, position);
    v[3][2] = glm::dot(f.forward, position);
    return glm::perspective(2.0 * std::atan(tanHalf), 1.0, znear, zfar) * v;
}

bool ShadowView::sameMap(const ShadowView& o) const {
    return kind == o.kind && layer == o.layer && resolution == o.resolution && viewProj == o.viewProj &&
           position == o.position && znear == o.znear && zfar == o.zfar && tanHalf == o.tanHalf &&
           halfWidth == o.halfWidth && faces == o.faces && axes == o.axes && casters == o.casters;
}

void linkShadowCasters(std::vector<ShadowView>& views, const LinkResolution& links, std::size_t modelParts) {
    if (!links.active) return;
    for (ShadowView& v : views) {
        v.casters.assign(modelParts, true);
        bool all = true;
        for (std::size_t part = 0; part < modelParts; ++part) {
            const bool casts = links.casts(std::size_t(v.rigIndex), part);
            v.casters[part] = casts;
            all = all && casts;
        }
        if (all) v.casters.clear(); // as unlinked: the same map
    }
}

namespace {

// An area light's map from its centre (docs/lighting-models.md "Shadows", "Area lights"): blockers behind
// its plane cannot shadow its front from there (every segment from the emitter to a point in front stays
// in front), so one centre serves the whole emitter; its extent only widens the PCSS filter.
void planAreaShadow(const Light& l, const glm::dvec3& position, const glm::dvec3& c, double r, double toWorld,
                    ShadowView* v) {
    v->position = position;
    v->emitter = areaPenumbraSize(l) * toWorld;
    v->searchEmitter = areaSearchSize(l) * toWorld;
    v->maxFilterTexels = kAreaFilterTexels;
    v->kind = areaShadowKind(position, c, r, v->resolution);
    const double dist = glm::length(c - position);
    planesAround(dist, r, &v->znear, &v->zfar);
    if (v->kind == ShadowKind::Cube) {
        const glm::dvec3 n = lighting::safeNormalize(l.direction, glm::dvec3(0, -1, 0));
        const AreaAxes a = areaAxes(n, l.area.roll);
        v->axes = glm::dmat3(a.y, a.x, n); // a.y × a.x = n: right-handed, face 4 (+Z) along n
        v->faces = l.area.twoSided ? 6 : 5;
        v->tanHalf = 1.0 + 2.0 * kAreaFilterTexels / v->resolution;
        return;
    }
    v->maxFilterTexels = kAreaMapFilterTexels;
    const double half = std::asin(r / dist);
    const glm::dvec3 look = (c - position) / dist;
    v->tanHalf = std::tan(half);
    v->viewProj = glm::perspective(2.0 * half, 1.0, v->znear, v->zfar) *
                  glm::lookAt(position, position + look, upFor(look));
}

} // namespace

std::vector<ShadowView> planShadows(const Rig& rig, const SceneFrame& frame, const Bounds& bounds) {
    std::vector<int> casters;
    std::vector<glm::dvec3> positions; // world
    for (size_t i = 0; i < rig.lights.size() && int(casters.size()) < kMaxShadowCasters; ++i) {
        if (!rig.lights[i].hasShadow()) continue;
        casters.push_back(int(i));
        positions.push_back(rig.lights[i].usesPosition() ? rigToWorld(rig, frame, rig.lights[i].position)
                                                         : glm::dvec3(0.0));
    }
    std::vector<ShadowView> views;
    if (casters.empty()) return views;
    const glm::dvec3 c = bounds.center();
    const double r = bounds.radius() * 1.02; // a margin for float rounding at the sphere's rim
    const int res = arrayResolution(rig, casters, positions, c, r);
    const double toWorld = 1.0 / distanceScale(rig, frame);
    int layer = 0;
    for (int i : casters) {
        const Light& l = rig.lights[size_t(i)];
        ShadowView v;
        v.rigIndex = i;
        v.layer = layer;
        v.resolution = res;
        v.bias = std::clamp(l.shadow.bias, 0.0, 16.0);
        v.normalOffset = std::clamp(l.shadow.normalOffset, 0.0, 16.0);
        v.kind = shadowKindOf(l.type);
        v.searchEmitter = 0.0;
        if (l.isArea()) {
            planAreaShadow(l, rigToWorld(rig, frame, l.position), c, r, toWorld, &v);
        } else if (v.kind == ShadowKind::Orthographic) {
            const glm::dvec3 d = lighting::safeNormalize(l.direction, glm::dvec3(0, -1, 0));
            v.position = c - d * (2.0 * r);
            v.znear = r;
            v.zfar = 3.0 * r;
            v.halfWidth = r;
            v.viewProj = glm::ortho(-r, r, -r, r, v.znear, v.zfar) * glm::lookAt(v.position, c, upFor(d));
            const double angle = std::clamp(l.shadow.angle, 0.0, 10.0);
            v.emitter = 2.0 * std::tan(0.5 * angle * M_PI / 180.0);
            v.searchEmitter = v.emitter;
        } else {
            v.position = rigToWorld(rig, frame, l.position);
            v.emitter = std::max(0.0, l.shadow.size) * toWorld;
            v.searchEmitter = v.emitter;
            const double dist = glm::length(c - v.position);
            planesAround(dist, r, &v.znear, &v.zfar);
            if (v.kind == ShadowKind::Cube) {
                v.tanHalf = 1.0 + 2.0 * kCubeMarginTexels / res;
            } else {
                // The cone, or only the part of it that can hold the model: the sphere's cone seen from
                // the light when that is narrower (a 179° spot keeps its texels on the model).
                const double outer = std::clamp(l.cone.outer, 0.01, 89.9) * M_PI / 180.0;
                const glm::dvec3 axis = lighting::safeNormalize(l.direction, glm::dvec3(0, -1, 0));
                const bool outside = dist > r;
                const double sphereHalf = outside ? std::asin(r / dist) : M_PI;
                double half = std::min(outer, sphereHalf);
                const glm::dvec3 look = half < outer ? (c - v.position) / dist : axis;
                half = std::min(half, 85.0 * M_PI / 180.0); // a light inside the model: at most 170°
                v.tanHalf = std::tan(half);
                v.viewProj = glm::perspective(2.0 * half, 1.0, v.znear, v.zfar) *
                             glm::lookAt(v.position, v.position + look, upFor(look));
            }
        }
        layer += v.layers();
        views.push_back(v);
    }
    return views;
}

qint64 shadowMapBytes(const std::vector<ShadowView>& views) {
    qint64 layers = 0;
    for (const ShadowView& v : views)
        layers += v.layers();
    return views.empty() ? 0 : layers * views.front().resolution * views.front().resolution * 4;
}

std::array<float, 4 * kShadowTexels> packShadow(const ShadowView& v, const glm::dmat4& view, int lightIndex) {
    const glm::dmat4 toWorld = glm::inverse(view);
    const glm::dmat4 m =
        v.kind == ShadowKind::Cube
            ? glm::dmat4(glm::transpose(v.axes)) * glm::translate(glm::dmat4(1.0), -v.position) * toWorld
            : v.viewProj * toWorld;
    std::array<float, 4 * kShadowTexels> t{};
    const glm::mat4 mf(m);
    std::copy_n(glm::value_ptr(mf), 16, t.begin());
    const float rest[] = {float(v.layer),         float(int(v.kind)),
                          float(v.znear),         float(v.zfar),
                          float(v.texelScale()),  float(v.bias),
                          float(v.normalOffset),  float(v.emitter),
                          float(lightIndex),      float(v.tanHalf),
                          float(v.resolution),    0.0f,
                          float(v.searchEmitter), float(v.maxFilterTexels),
                          float(v.layers()),      0.0f};
    std::copy(std::begin(rest), std::end(rest), t.begin() + 16);
    return t;
}

} // namespace lr::render
