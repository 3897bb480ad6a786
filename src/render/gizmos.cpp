#include "gizmos.h"

#include "core/barndoors.h"
#include "core/fallofftraits.h"
#include "core/lighting.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace lr::render {

namespace {

using lighting::safeNormalize;
constexpr double kTwoPi = 6.283185307179586;

struct Builder {
    const glm::dmat4& view;
    GizmoGeometry& out;
    double nearClip = 0.0;

    glm::dvec3 toView(const glm::dvec3& p) const { return glm::dvec3(view * glm::dvec4(p, 1.0)); }
    // A world segment, clipped to the half-space in front of the near plane (z <= -nearClip).
    void line(const glm::dvec3& worldA, const glm::dvec3& worldB, const glm::vec4& c) {
        glm::dvec3 a = toView(worldA), b = toView(worldB);
        const double limit = -nearClip;
        if (!(a.z <= limit) && !(b.z <= limit)) return;
        if (!(a.z <= limit))
            a = b + (a - b) * ((limit - b.z) / (a.z - b.z));
        else if (!(b.z <= limit))
            b = a + (b - a) * ((limit - a.z) / (b.z - a.z));
        if (!std::isfinite(a.x + a.y + a.z + b.x + b.y + b.z)) return;
        out.lines.push_back({glm::vec3(a), c, {}});
        out.lines.push_back({glm::vec3(b), c, {}});
    }
    void circle(const glm::dvec3& center, const glm::dvec3& normal, double radius, const glm::vec4& c,
                int segments = 48) {
        const glm::dvec3 n = safeNormalize(normal, glm::dvec3(0, 1, 0));
        const glm::dvec3 u =
            safeNormalize(glm::cross(n, std::abs(n.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)),
                          glm::dvec3(1, 0, 0));
        const glm::dvec3 v = glm::cross(n, u);
        glm::dvec3 prev = center + u * radius;
        for (int i = 1; i <= segments; ++i) {
            const double a = kTwoPi * i / segments;
            const glm::dvec3 p = center + (u * std::cos(a) + v * std::sin(a)) * radius;
            line(prev, p, c);
            prev = p;
        }
    }
    void arrow(const glm::dvec3& from, const glm::dvec3& dir, double length, const glm::vec4& c) {
        const glm::dvec3 tip = from + dir * length;
        line(from, tip, c);
        const glm::dvec3 side =
            safeNormalize(glm::cross(dir, std::abs(dir.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)),
                          glm::dvec3(1, 0, 0));
        const glm::dvec3 side2 = glm::cross(dir, side);
        const double head = length * 0.2;
        for (const glm::dvec3& s : {side, -side, side2, -side2})
            line(tip, tip - dir * head + s * head * 0.5, c);
    }
};

// A light's colour for display: hue of the effective colour, brightest channel at 1, sRGB-encoded.
glm::vec4 displayColor(const Light& l, float alpha) {
    glm::dvec3 c = l.effectiveColor();
    const double m = std::max({c.x, c.y, c.z});
    c = m > 0.0 && std::isfinite(m) ? c / m : glm::dvec3(1.0);
    if (!l.enabled) c = glm::dvec3(0.45);
    return {float(lighting::linearToSrgb(c.x)), float(lighting::linearToSrgb(c.y)),
            float(lighting::linearToSrgb(c.z)), alpha};
}

// The finite world range of a point or spot light, or a negative value when it has none.
double worldRange(const Rig& rig, const SceneFrame& frame, const Light& l) {
    const Falloff& f = l.falloff;
    if (!falloffBounded(f)) return -1.0;
    const double r = f.range / distanceScale(rig, frame);
    return std::isfinite(r) ? r : -1.0;
}

void addGrid(Builder& b, const Bounds& bounds, double radius) {
    const double spacing = std::pow(10.0, std::floor(std::log10(radius * 0.5)));
    const int half = int(std::ceil(radius * 1.5 / spacing));
    const glm::dvec3 c = bounds.center();
    const double y = bounds.min.y;
    const double x0 = std::round(c.x / spacing) * spacing, z0 = std::round(c.z / spacing) * spacing;
    const double ext = half * spacing;
    for (int i = -half; i <= half; ++i) {
        const float a = (i % 5 == 0) ? 0.55f : 0.3f;
        const glm::vec4 col(0.6f, 0.6f, 0.6f, a);
        b.line({x0 + i * spacing, y, z0 - ext}, {x0 + i * spacing, y, z0 + ext}, col);
        b.line({x0 - ext, y, z0 + i * spacing}, {x0 + ext, y, z0 + i * spacing}, col);
    }
}

} // namespace

std::vector<glm::dvec3> areaOutline(const Rig& rig, const SceneFrame& frame, const Light& light,
                                    int diskSegments) {
    std::vector<glm::dvec3> out;
    if (!light.isArea()) return out;
    const AreaAxes a = areaAxes(light.direction, light.area.roll);
    const glm::dvec3 c = rigToWorld(rig, frame, light.position);
    const double toWorld = 1.0 / distanceScale(rig, frame);
    if (light.type == LightType::Disk) {
        const double r = std::max(0.0, light.area.radius) * toWorld;
        const int n = std::max(diskSegments, 3);
        out.reserve(size_t(n));
        for (int i = 0; i < n; ++i) {
            const double t = kTwoPi * i / n;
            out.push_back(c + (a.x * std::cos(t) + a.y * std::sin(t)) * r);
        }
        return out;
    }
    const glm::dvec3 hx = a.x * (0.5 * std::max(0.0, light.area.width) * toWorld);
    const glm::dvec3 hy = a.y * (0.5 * std::max(0.0, light.area.height) * toWorld);
    return {c + hx + hy, c - hx + hy, c - hx - hy, c + hx - hy};
}

std::vector<AreaHandle> areaHandles(const Rig& rig, const SceneFrame& frame, const Light& light) {
    if (!light.isArea()) return {};
    const AreaAxes a = areaAxes(light.direction, light.area.roll);
    const glm::dvec3 c = rigToWorld(rig, frame, light.position);
    const double toWorld = 1.0 / distanceScale(rig, frame);
    if (light.type == LightType::Disk) {
        const double r = std::max(0.0, light.area.radius) * toWorld;
        return {{c + a.x * r, a.x, AreaSize::Radius},
                {c - a.x * r, -a.x, AreaSize::Radius},
                {c + a.y * r, a.y, AreaSize::Radius},
                {c - a.y * r, -a.y, AreaSize::Radius}};
    }
    const double hw = 0.5 * std::max(0.0, light.area.width) * toWorld;
    const double hh = 0.5 * std::max(0.0, light.area.height) * toWorld;
    return {{c + a.x * hw, a.x, AreaSize::Width},
            {c - a.x * hw, -a.x, AreaSize::Width},
            {c + a.y * hh, a.y, AreaSize::Height},
            {c - a.y * hh, -a.y, AreaSize::Height}};
}

glm::dvec3 directionalAnchor(const SceneFrame& frame, const glm::dvec3& direction) {
    return frame.center - safeNormalize(direction, glm::dvec3(0, -1, 0)) * (frame.radius * 1.6);
}

GizmoGeometry buildGizmos(const Rig& rig, const SceneFrame& frame, const Bounds& bounds,
                          const glm::dmat4& view, const GizmoOptions& options) {
    GizmoGeometry out;
    Builder b{view, out, std::max(options.nearClip, 0.0)};
    const double radius = frame.radius > 0.0 && std::isfinite(frame.radius) ? frame.radius : 1.0;
    if (options.grid) {
        addGrid(b, bounds, radius);
        for (GizmoVertex& v : out.lines)
            v.point.y = kGridShape;
    }
    if (!options.lights) return out;
    for (size_t i = 0; i < rig.lights.size(); ++i) {
        const Light& l = rig.lights[i];
        const bool selected =
            std::find(options.selected.begin(), options.selected.end(), int(i)) != options.selected.end();
        // Selected lights stand out: their lines in the selection colour at full strength, their icon larger
        // (white-rimmed by gizmo.frag); the others recede a little.
        const glm::vec4 strong = selected ? kSelectedColor : displayColor(l, 0.65f);
        const glm::vec4 faint =
            selected ? glm::vec4(glm::vec3(kSelectedColor), 0.75f) : displayColor(l, 0.3f);
        const glm::dvec3 dir = safeNormalize(l.direction, glm::dvec3(0, -1, 0));
        glm::dvec3 at;
        if (l.usesPosition()) {
            at = rigToWorld(rig, frame, l.position);
            const double range = worldRange(rig, frame, l);
            const bool drawRange = range > 0.0 && range < radius * 1e4;
            if (drawRange && (selected || traitsOf(l.type).alwaysShowsRange)) {
                b.circle(at, {1, 0, 0}, range, faint);
                b.circle(at, {0, 1, 0}, range, faint);
                b.circle(at, {0, 0, 1}, range, faint);
            }
            if (l.isArea()) {
                // The emitter's outline in the light's colour (brighter when selected), and its normal from
                // the centre towards the lit side (both ways when it is two-sided).
                const glm::vec4 edge = displayColor(l, selected ? 1.0f : 0.65f);
                const std::vector<glm::dvec3> outline = areaOutline(rig, frame, l);
                for (size_t k = 0; k < outline.size(); ++k)
                    b.line(outline[k], outline[(k + 1) % outline.size()], edge);
                if (selected) // a second, amber inner trace marks the selection as other gizmos do
                    for (size_t k = 0; k < outline.size(); ++k)
                        b.line(at + (outline[k] - at) * 0.97,
                               at + (outline[(k + 1) % outline.size()] - at) * 0.97, faint);
                // Barn doors (issue 39, core/barndoors.h): each corner's slanted edge and the flaps' far
                // edges.
                if (l.type == LightType::Rect && l.barnDoors && barndoors::cuts(*l.barnDoors) &&
                    outline.size() == 4) {
                    const barndoors::FlapShape f = barndoors::flapShape(*l.barnDoors);
                    const double toWorld = 1.0 / distanceScale(rig, frame);
                    const AreaAxes a = areaAxes(l.direction, l.area.roll);
                    const glm::dvec3 ex = a.x * (f.extent * toWorld), ey = a.y * (f.extent * toWorld);
                    const glm::dvec3 push = dir * (f.depth * toWorld);
                    const glm::dvec3 far[4] = {outline[0] + push + ex + ey, outline[1] + push - ex + ey,
                                               outline[2] + push - ex - ey, outline[3] + push + ex - ey};
                    for (size_t k = 0; k < 4; ++k) {
                        b.line(outline[k], far[k], faint);
                        b.line(far[k], far[(k + 1) % 4], faint);
                    }
                }
                double extent = 0.0;
                for (const glm::dvec3& q : outline)
                    extent = std::max(extent, glm::length(q - at));
                const double len = std::clamp(extent, radius * 0.15, radius * 0.6);
                b.arrow(at, dir, len, strong);
                if (l.area.twoSided) b.arrow(at, -dir, len, strong);
                if (selected && options.selected.size() == 1)
                    for (const AreaHandle& h : areaHandles(rig, frame, l)) {
                        const glm::dvec3 hp = b.toView(h.position);
                        if (hp.z <= -b.nearClip && std::isfinite(hp.x + hp.y + hp.z))
                            out.points.push_back(
                                {glm::vec3(hp),
                                 kSelectedColor,
                                 {float(kAreaHandlePixels), float(int(GizmoShape::Square) + 8)}});
                    }
            }
            // An IES profile (issue 39): the distribution's shape, as long as the cone's lines at its peak.
            if (l.ies && options.ies && i < options.ies->size() && (*options.ies)[i])
                for (const std::vector<glm::dvec3>& curve : iesOutline(
                         l, *(*options.ies)[i], at, drawRange ? std::min(range, radius) : radius * 0.6))
                    for (size_t k = 0; k + 1 < curve.size(); ++k)
                        b.line(curve[k], curve[k + 1], selected ? strong : faint);
            if (l.usesCone()) {
                const double len = drawRange ? std::min(range, radius * 3.0) : radius;
                auto cone = [&](double halfAngleDeg, const glm::vec4& c, int spokes) {
                    const double a = glm::radians(std::clamp(halfAngleDeg, 0.0, 179.0));
                    const glm::dvec3 centre = at + dir * (len * std::cos(a));
                    const double r = len * std::sin(a);
                    b.circle(centre, dir, r, c, 40);
                    const glm::dvec3 u = safeNormalize(
                        glm::cross(dir, std::abs(dir.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0)),
                        glm::dvec3(1, 0, 0));
                    const glm::dvec3 v = glm::cross(dir, u);
                    for (int k = 0; k < spokes; ++k) {
                        const double t = kTwoPi * k / spokes;
                        b.line(at, centre + (u * std::cos(t) + v * std::sin(t)) * r, c);
                    }
                };
                cone(l.cone.outer, strong, 4);
                if (l.cone.model == ConeModel::Smooth) cone(l.cone.inner, faint, 0);
            }
        } else {
            at = directionalAnchor(frame, dir);
            b.arrow(at, dir, radius * 0.6, strong);
        }
        const float shape = float(int(traitsOf(l.type).gizmo) + (selected ? 8 : 0));
        const float size = float(options.iconPixels * (selected ? kSelectedIconScale : 1.0));
        const glm::dvec3 p = b.toView(at);
        if (p.z <= -b.nearClip && std::isfinite(p.x + p.y + p.z))
            out.points.push_back({glm::vec3(p), displayColor(l, 1.0f), {size, shape}});
    }
    return out;
}

} // namespace lr::render
