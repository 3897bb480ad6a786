// Barn doors on a rect light (issue 39; docs/light-shaping.md, "Barn doors"): four flaps hinged on the
// emitter's edges that cut the directions it emits in. The definition is Unreal Engine 5's rect light
// (URectLightComponent::BarnDoorAngle and BarnDoorLength; the flaps as FRectLightComponentVisualizer draws
// them): each flap is `length` long and leaves its edge at `angle` degrees from the emitter's normal, so
// that its far edge lies depth = length·cos(angle) in front of the emitter's plane and
// extent = length·sin(angle) outside the edge. Angle 0: the flaps stand straight out (a tube, the narrowest
// beam); angle 90 (or length 0): they lie in the emitter's plane and cut nothing. UE clamps the angle to
// 0 ... 88 (its default 88°, length 20 cm); the rig takes 0 ... 90 and 0.2 rig units by default.
//
// The flaps' corners are closed (UE's visualizer draws the edges that close them, and its shaders clip the
// emitter to one rectangle): the four flaps are the side walls of a truncated pyramid, each a trapezoid
// from its hinge (the emitter's edge) to its far edge, which runs the whole far rectangle of half extents
// (hw + extent, hh + extent). The flaps block light only: they cast no other shadow and are not drawn.
//
// Visibility: a point Q of the emitter lights P when the segment Q→P misses every flap (segmentHitsFlaps).
// As the walls are convex and start at the emitter, that holds exactly when the segment is inside the far
// rectangle at the flaps' depth, which is separable in the emitter's axes: the points of the emitter P sees
// form one rectangle, visibleWindow(): the emitter's rectangle cut by the far edges projected from P onto
// its plane. The reference and the path tracer integrate over it; the raster tiers run their polygon
// integrals (LTC) over it instead of the whole emitter, so barn doors cost no approximation of their own.
// The back face of a two-sided rect has no flaps.
#pragma once

#include "lightshaping.h"
#include "shadetypes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

namespace lr::barndoors {

inline constexpr double kMaxAngle = 90.0; // degrees: the flaps in the emitter's plane

// The far edge of every flap relative to its hinge, in rig units: `depth` along the emitter's normal and
// `extent` outwards. Exactly 0 depth at 90° (no effect), and for length 0.
struct FlapShape {
    double depth = 0.0, extent = 0.0;
};
inline FlapShape flapShape(const BarnDoors& b) {
    const double a = std::clamp(std::isfinite(b.angle) ? b.angle : kMaxAngle, 0.0, kMaxAngle);
    const double length = std::isfinite(b.length) ? std::max(0.0, b.length) : 0.0;
    if (a >= kMaxAngle) return {0.0, length};
    const double r = a * (3.14159265358979323846 / 180.0);
    return {length * std::cos(r), length * std::sin(r)};
}

// Whether barn doors change anything: some depth in front of the emitter.
inline bool cuts(const BarnDoors& b) {
    return flapShape(b).depth > 0.0;
}

// A prepared light's barn doors (ShadeLight::barnDepth > 0; view units).
template <typename T> bool hasBarnDoors(const lighting::ShadeLight<T>& l) {
    return l.type == LightType::Rect && l.barnDepth > T(0);
}

// The part of the emitter P sees, in the emitter's own coordinates (along axisX, axisY from its centre,
// view units): [x0, x1] × [y0, y1]. Empty when x0 >= x1 or y0 >= y1. The whole emitter without flaps and
// for a point behind it (a two-sided rect's back).
template <typename T> struct Window {
    T x0 = T(0), x1 = T(0), y0 = T(0), y1 = T(0);
    bool empty() const { return !(x0 < x1) || !(y0 < y1); }
};

// The window in the emitter's frame: P at (px, py) in its plane and pz in front of it, the emitter's half
// extents hw, hh, the flaps' depth d > 0 and extent e. Behind the flaps' far edges (pz > d) each side of
// the window is where the ray from P past that far edge meets the emitter's plane, (±(h + e)·pz − p·d) /
// (pz − d); between the emitter and the far edges (0 < pz <= d) P sees all of it or nothing, as it is inside
// the walls or outside.
template <typename T> Window<T> windowLocal(T hw, T hh, T d, T e, T px, T py, T pz) {
    Window<T> w{-hw, hw, -hh, hh};
    if (!(d > T(0)) || !(pz > T(0))) return w;
    if (pz <= d) {
        const T grow = e * (pz / d);
        if (std::abs(px) <= hw + grow && std::abs(py) <= hh + grow) return w;
        return {};
    }
    const T inv = T(1) / (pz - d);
    const T fx = (hw + e) * pz, fy = (hh + e) * pz;
    w.x0 = std::max(-hw, (-fx - px * d) * inv);
    w.x1 = std::min(hw, (fx - px * d) * inv);
    w.y0 = std::max(-hh, (-fy - py * d) * inv);
    w.y1 = std::min(hh, (fy - py * d) * inv);
    if (!std::isfinite(w.x0) || !std::isfinite(w.x1) || !std::isfinite(w.y0) || !std::isfinite(w.y1))
        return {};
    return w;
}

// The window of a prepared light as seen from P (view space).
template <typename T> Window<T> visibleWindow(const lighting::ShadeLight<T>& l, const lighting::Vec3<T>& P) {
    const lighting::Vec3<T> p = P - l.position;
    if (!hasBarnDoors(l)) return {-l.halfWidth, l.halfWidth, -l.halfHeight, l.halfHeight};
    return windowLocal(l.halfWidth, l.halfHeight, l.barnDepth, l.barnExtent, glm::dot(p, l.axisX),
                       glm::dot(p, l.axisY), glm::dot(p, l.direction));
}

// The light as P sees it: a rect light whose emitter is the window (centre and half extents moved; the
// radiance per unit area is the same), half extents 0 when nothing of it is visible. Unchanged without flaps.
template <typename T>
lighting::ShadeLight<T> visiblePart(const lighting::ShadeLight<T>& l, const lighting::Vec3<T>& P) {
    if (!hasBarnDoors(l)) return l;
    const Window<T> w = visibleWindow(l, P);
    lighting::ShadeLight<T> o = l;
    if (w.empty()) {
        o.halfWidth = o.halfHeight = T(0);
        return o;
    }
    o.position = l.position + l.axisX * ((w.x0 + w.x1) * T(0.5)) + l.axisY * ((w.y0 + w.y1) * T(0.5));
    o.halfWidth = (w.x1 - w.x0) * T(0.5);
    o.halfHeight = (w.y1 - w.y0) * T(0.5);
    o.barnDepth = T(0); // already cut
    return o;
}

// The four flaps of a prepared light (view space), each a quad: hinge start, hinge end, far end, far start.
using Quad = std::array<glm::dvec3, 4>;
inline std::array<Quad, 4> flaps(const lighting::ShadeLight<double>& l) {
    const glm::dvec3 c = l.position, X = l.axisX, Y = l.axisY, N = l.direction;
    const double a = l.halfWidth, b = l.halfHeight, d = l.barnDepth, e = l.barnExtent;
    const auto at = [&](double x, double y, double z) { return c + x * X + y * Y + z * N; };
    const double fa = a + e, fb = b + e;
    return {{{at(a, -b, 0), at(a, b, 0), at(fa, fb, d), at(fa, -fb, d)},
             {at(-a, -b, 0), at(-a, b, 0), at(-fa, fb, d), at(-fa, -fb, d)},
             {at(-a, b, 0), at(a, b, 0), at(fa, fb, d), at(-fa, fb, d)},
             {at(-a, -b, 0), at(a, -b, 0), at(fa, -fb, d), at(-fa, -fb, d)}}};
}

// Whether the open segment from the emitter's point Q to P crosses a triangle (Möller and Trumbore).
inline bool segmentHitsTriangle(const glm::dvec3& Q, const glm::dvec3& P, const glm::dvec3& a,
                                const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 dir = P - Q, e1 = b - a, e2 = c - a;
    const glm::dvec3 h = glm::cross(dir, e2);
    const double det = glm::dot(e1, h);
    if (std::abs(det) < 1e-300) return false;
    const double inv = 1.0 / det;
    const glm::dvec3 s = Q - a;
    const double u = glm::dot(s, h) * inv;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) * inv;
    if (v < 0.0 || u + v > 1.0) return false;
    const double t = glm::dot(e2, q) * inv;
    return t > 1e-12 && t < 1.0 - 1e-12;
}

// The definition, ray by ray: whether the segment from the emitter's point Q to P crosses a flap (the
// tests check visibleWindow against it). A point behind the emitter is not cut.
inline bool segmentHitsFlaps(const lighting::ShadeLight<double>& l, const glm::dvec3& Q,
                             const glm::dvec3& P) {
    if (!hasBarnDoors(l) || !(glm::dot(P - l.position, l.direction) > 0.0)) return false;
    for (const Quad& f : flaps(l))
        if (segmentHitsTriangle(Q, P, f[0], f[1], f[2]) || segmentHitsTriangle(Q, P, f[0], f[2], f[3]))
            return true;
    return false;
}

} // namespace lr::barndoors
