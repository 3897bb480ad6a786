// Polygon integrals of area lights (lighting_area.h), templated on the scalar; shaders/area.glsl has
// the twin (same names, guards and order). Vectors are relative to the surface point, in a local frame
// whose z is the clipping hemisphere's pole.
//
//   edgeIntegral(a, b)   for unit a, b: θ · normalize(a × b), θ = the angle between them (atan2 form: exact
//                        at any angle, no acos; |a × b| = 0 gives 0 for antipodal vertices, a × b otherwise)
//   polygonVector(p, n)  Σ edges, × 1/2 = ∫ ω dω over the polygon's solid angle (the vector irradiance;
//                        Lambert 1760, Arvo 1995): its z is ∫ cos θ dω, signed, without clipping.
//   clipHorizon          the part of a convex polygon with z > 0 (at most one vertex more)
//   clippedCosine(p, n)  (1/π) ∫ max(cos θ, 0) dω over the polygon: the form factor (|·|, either winding)
//   solidAngle(p, n)     ∫ dω (Van Oosterom and Strackee 1983, fan of triangles)
#pragma once

#include "lighting.h"

namespace lr::lighting {

// Rect: 4 vertices; disk: kDiskVertices; each clipping adds at most one (the LTC clips twice).
inline constexpr int kDiskVertices = 8;
inline constexpr int kMaxPolygon = kDiskVertices + 2;

template <typename T> struct Polygon {
    Vec3<T> v[kMaxPolygon];
    int n = 0;
};

template <typename T> Vec3<T> edgeIntegral(const Vec3<T>& a, const Vec3<T>& b) {
    const Vec3<T> c = glm::cross(a, b);
    const T s = std::sqrt(glm::dot(c, c));
    const T d = glm::dot(a, b);
    const T k = s > T(1e-30) ? std::atan2(s, d) / s : (d > T(0) ? T(1) : T(0));
    return c * k;
}

// The polygon's vertices normalised (a vertex at the origin falls back to the pole: it contributes no
// edge of finite length).
template <typename T> Polygon<T> normalized(const Polygon<T>& p) {
    Polygon<T> o;
    o.n = p.n;
    for (int i = 0; i < p.n; ++i)
        o.v[i] = safeNormalize(p.v[i], Vec3<T>(0, 0, 1));
    return o;
}

template <typename T> Vec3<T> polygonVector(const Polygon<T>& unit) {
    Vec3<T> sum(0);
    for (int i = 0; i < unit.n; ++i)
        sum += edgeIntegral(unit.v[i], unit.v[(i + 1) % unit.n]);
    return sum * T(0.5);
}

// Convex polygon ∩ {z > 0} (Sutherland-Hodgman against one plane). A vertex exactly on the plane is
// outside; an edge crossing it gets the crossing point, interpolated from the side above (no division
// by zero: the two z differ in sign).
template <typename T> Polygon<T> clipHorizon(const Polygon<T>& p) {
    Polygon<T> o;
    for (int i = 0; i < p.n; ++i) {
        const Vec3<T>& a = p.v[i];
        const Vec3<T>& b = p.v[(i + 1) % p.n];
        const bool aUp = a.z > T(0), bUp = b.z > T(0);
        if (aUp && o.n < kMaxPolygon) o.v[o.n++] = a;
        if (aUp != bUp && o.n < kMaxPolygon) {
            const T t = a.z / (a.z - b.z);
            Vec3<T> x = a + (b - a) * t;
            x.z = T(0);
            o.v[o.n++] = x;
        }
    }
    return o;
}

template <typename T> T clippedCosine(const Polygon<T>& p) {
    const Polygon<T> c = clipHorizon(p);
    if (c.n < 3) return T(0);
    return std::abs(polygonVector(normalized(c)).z) * T(1.0 / kPi);
}

template <typename T> T solidAngle(const Polygon<T>& unit) {
    T sum = T(0);
    for (int i = 1; i + 1 < unit.n; ++i) {
        const Vec3<T>& a = unit.v[0];
        const Vec3<T>& b = unit.v[i];
        const Vec3<T>& c = unit.v[i + 1];
        const T num = glm::dot(a, glm::cross(b, c));
        const T den = T(1) + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
        sum += T(2) * std::atan2(num, den);
    }
    return std::abs(sum);
}

} // namespace lr::lighting
