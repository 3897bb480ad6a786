// Area lights (rect, disk; issue 16): what one adds at a surface point. The definition every tier and the
// reference share (docs/lighting-models.md, "Area lights"):
//
//   The emitter is the set of points c + u·hw·X + v·hh·Y with (u, v) in [-1, 1]² (rect) or u² + v² <= 1
//   (disk); c = ShadeLight::position, X/Y = axisX/axisY, hw/hh = halfWidth/halfHeight. It emits a
//   uniform radiance (a Lambertian emitter) from its front side, the side ShadeLight::direction points
//   to, and from both sides when twoSided. A surface point P sees the front when dot(P - c, direction) > 0.
//
//   What it adds is the integral, over the solid angle Ω the emitter covers as seen from P, of what a
//   directional light from each direction ω in Ω adds (directionalResponse below: the light's diffuse and
//   specular models, colours and intensity):
//     physically based:  Lo = ∫Ω response(ω) dω      (a radiance L in nits; the glTF BRDF × cos θ)
//     classic:           Lo = (1/π) ∫Ω response(ω) dω (so that an emitter filling the hemisphere adds what
//                                                      a directional light of the same intensity adds
//                                                      head on: albedo × L under Lambert)
//   plus the light's own ambient (Ac × intensity × albedo; c_diff × occlusion / π when physically based),
//   neither shadowed nor attenuated. `visibility` scales the direct terms only (shade.h).
//
// The double-precision reference integrates this by Monte Carlo; the GPU tiers and shadeAreaLight /
// shadeAreaLightPbr below approximate it (docs/lighting-models.md, "Area lights", has each error):
//   Lambert diffuse: the horizon-clipped polygon's form factor: exact (for the rect; the disk is the
//     area-preserving kDiskVertices-gon, lighting_area_poly.h).
//   half-Lambert: ((1 + cos)/2)² over the unclipped polygon as (Ω + 2C + C²/Ω)/4 (C = ∫cos dω): exact
//     but for cos² replaced by its mean squared.
//   GGX specular: LTC (ltc.h, our own fit), clipped to the surface's horizon and to the transformed
//     cosine's, × the lobe's norm × Schlick's Fresnel at the lobe's mean direction over the light (exact
//     for small emitters; Hill's F0·scale + bias, the lobe's average Fresnel, made a dielectric's grazing
//     highlight 3–10× too dim and its tail too bright).
//   PBR diffuse's (1 − F_dielectric): Schlick's weight at the polygon's mean direction (exact for small
//   emitters). Phong: (R·ω)^n as the LTC diag(s, s, 1) around R, s² = 2/(n + 1) (same integral and peak);
//   Blinn-Phong:
//     the same with n/4 (the Blinn lobe's width at normal incidence).
#pragma once

#include "barndoors.h"
#include "lighting.h"
#include "lighting_area_poly.h"
#include "lighttypes.h"
#include "ltc.h"
#include "shadetypes.h"

#include <cmath>

namespace lr::lighting {

// What a directional light of the area light's colours arriving from direction `w` (unit, towards the
// light) adds at the surface, without the ambient: the integrand of the definition above.
template <typename T>
Vec3<T> directionalResponse(const ShadeLight<T>& l, const Surface<T>& s, const ShadeSettings<T>& st,
                            const Vec3<T>& V, const Vec3<T>& w, const Vec3<T>& cDiff, const Vec3<T>& f0,
                            T alpha) {
    const Vec3<T>& N = s.normal;
    const T nDotL = glm::dot(N, w);
    const T D = l.diffuse == DiffuseModel::Lambert ? diffuseLambert(nDotL) : diffuseHalfLambert(nDotL);
    if (st.model == ShadingModel::Pbr) {
        const PbrLobes<T> f = pbrLobes(N, w, V, cDiff, f0, alpha, D);
        return l.color * f.diffuse + l.specular * f.specular;
    }
    T S = T(0);
    if (nDotL > T(0))
        S = st.specular == SpecularModel::Phong ? specularPhong(N, w, V, s.shininess)
                                                : specularBlinnPhong(N, w, V, s.shininess);
    return l.color * s.albedo * D + l.specular * s.specular * S;
}

// The emitter's area in view units² (rect 4·hw·hh, disk π·hw·hh).
template <typename T> T areaOf(const ShadeLight<T>& l) {
    const T a = T(4) * l.halfWidth * l.halfHeight;
    return l.type == LightType::Disk ? a * T(kPi / 4.0) : a;
}

// The emitter relative to the surface point P, in the local frame (t1, t2, n): a rect's 4 corners or the
// disk's area-preserving kDiskVertices-gon (circumradius r·kDiskRadiusScale).
inline constexpr double kDiskRadiusScale = 1.0539; // sqrt(2π / (8 sin(π/4)))

template <typename T> struct Frame {
    Vec3<T> t1, t2, n;
    Vec3<T> local(const Vec3<T>& v) const {
        return Vec3<T>(glm::dot(v, t1), glm::dot(v, t2), glm::dot(v, n));
    }
};

// A frame around `n` whose x is `towards`'s component perpendicular to n (any perpendicular when none).
template <typename T> Frame<T> frameAround(const Vec3<T>& n, const Vec3<T>& towards) {
    const Vec3<T> any = std::abs(n.x) < T(0.9) ? Vec3<T>(0, -n.z, n.y) : Vec3<T>(n.z, 0, -n.x);
    const Vec3<T> t1 =
        safeNormalize(towards - n * glm::dot(n, towards), safeNormalize(any, Vec3<T>(1, 0, 0)));
    return {t1, glm::cross(n, t1), n};
}

template <typename T> Polygon<T> emitterPolygon(const ShadeLight<T>& l, const Vec3<T>& P, const Frame<T>& f) {
    Polygon<T> p;
    const Vec3<T> c = l.position - P;
    if (l.type == LightType::Disk) {
        p.n = kDiskVertices;
        const T r = l.halfWidth * T(kDiskRadiusScale);
        for (int i = 0; i < kDiskVertices; ++i) {
            const T a = T(2 * kPi / kDiskVertices) * T(i);
            p.v[i] = f.local(c + l.axisX * (r * std::cos(a)) + l.axisY * (r * std::sin(a)));
        }
        return p;
    }
    // Barn doors (barndoors.h): the rectangle of the emitter P sees; none of it: an empty polygon.
    const barndoors::Window<T> w = barndoors::visibleWindow(l, P);
    if (w.empty()) return p;
    const Vec3<T> x0 = l.axisX * w.x0, x1 = l.axisX * w.x1, y0 = l.axisY * w.y0, y1 = l.axisY * w.y1;
    p.n = 4;
    p.v[0] = f.local(c + x0 + y0);
    p.v[1] = f.local(c + x1 + y0);
    p.v[2] = f.local(c + x1 + y1);
    p.v[3] = f.local(c + x0 + y1);
    return p;
}

// Whether P sees an emitting face: in front of the emitter's plane, or on either side when two-sided.
template <typename T> bool facesEmitter(const ShadeLight<T>& l, const Vec3<T>& P) {
    const T side = glm::dot(P - l.position, l.direction);
    return l.twoSided ? (side > T(0) || side < T(0)) : side > T(0);
}

// The emitter's normal pointing away from P (towards the emitter), in view space.
template <typename T> Vec3<T> emitterToward(const ShadeLight<T>& l, const Vec3<T>& P) {
    return glm::dot(P - l.position, l.direction) > T(0) ? -l.direction : l.direction;
}

// M⁻¹ of the LTC applied to each vertex (ltc.h: m11 = 1).
template <typename T> Polygon<T> transformed(const Polygon<T>& p, T m00, T m02, T m20, T m22) {
    Polygon<T> o;
    o.n = p.n;
    for (int i = 0; i < p.n; ++i) {
        const Vec3<T>& v = p.v[i];
        o.v[i] = Vec3<T>(m00 * v.x + m02 * v.z, v.y, m20 * v.x + m22 * v.z);
    }
    return o;
}

// (1/π) ∫ ((1 + cos)/2)² dω over the unclipped polygon (half-Lambert's wrap reaches below the horizon),
// cos² replaced by (C/Ω)², its mean squared: (Ω + 2C + C²/Ω) / 4π.
// `toward`: the emitter plane's normal on P's side, negated (every direction to the emitter has a positive
// dot product with it, so ∫ ω dω does too: it orients the winding).
template <typename T> T halfLambertIntegral(const Polygon<T>& local, const Vec3<T>& toward) {
    const Polygon<T> u = normalized(local);
    const T omega = solidAngle(u);
    if (!(omega > T(0))) return T(0);
    Vec3<T> e = polygonVector(u);
    T cosSum = e.z;
    if (glm::dot(e, toward) < T(0)) cosSum = -cosSum;
    return positive(omega + T(2) * cosSum + cosSum * cosSum / omega) * T(0.25 / kPi);
}

// The clipped polygon's mean direction (∫ ω dω, oriented), in the local frame; the pole when it has none.
template <typename T> Vec3<T> meanDirection(const Polygon<T>& clippedUnit, const Vec3<T>& toward) {
    Vec3<T> e = polygonVector(clippedUnit);
    if (glm::dot(e, toward) < T(0)) e = -e;
    return safeNormalize(e, Vec3<T>(0, 0, 1));
}

// Schlick's weight (1 − V·H)^5 for light from the unit direction w (local frame).
template <typename T> T schlickWeight(const Vec3<T>& V, const Vec3<T>& w) {
    return schlickWeight(glm::dot(V, safeNormalize(w + V, Vec3<T>(0, 0, 1))));
}

// The lobe's mean direction over the light: the vector of the LTC's polygon e (in the cosine's space, either
// winding) taken back through M (M⁻¹'s xz block inverted, m11 = 1) to the local frame.
template <typename T> Vec3<T> lobeMeanDirection(Vec3<T> e, const ltc::Lookup<T>& k) {
    if (e.z < T(0)) e = -e;
    const T det = k.m00 * k.m22 - k.m02 * k.m20;
    return safeNormalize(Vec3<T>(k.m22 * e.x - k.m02 * e.z, e.y * det, -k.m20 * e.x + k.m00 * e.z),
                         Vec3<T>(0, 0, 1));
}

// (1/π) ∫ (R·ω)^n dω over the polygon's part above the horizon, as the LTC diag(s, s, 1) around R.
template <typename T>
T phongLobeIntegral(const Polygon<T>& clipped, const Frame<T>& f, const Vec3<T>& R, T n) {
    const Frame<T> r = frameAround(R, f.n);
    const T m = n > T(0) ? n : T(0);
    const T invS = std::sqrt((m + T(1)) * T(0.5));
    Polygon<T> p;
    p.n = clipped.n;
    for (int i = 0; i < clipped.n; ++i) {
        const Vec3<T> w = f.t1 * clipped.v[i].x + f.t2 * clipped.v[i].y + f.n * clipped.v[i].z;
        const Vec3<T> q = r.local(w);
        p.v[i] = Vec3<T>(q.x * invS, q.y * invS, q.z);
    }
    return clippedCosine(p) * (T(2) / (m + T(1)));
}

// What an area light adds under the classic models (the definition above, with its 1/π).
template <typename T>
Vec3<T> shadeAreaLight(const ShadeLight<T>& l, const Surface<T>& s, const ShadeSettings<T>& st,
                       const Vec3<T>& V, T visibility = T(1)) {
    const Vec3<T> ambient = l.ambient * s.albedo;
    if (!facesEmitter(l, s.position)) return ambient;
    const Vec3<T>& N = s.normal;
    const Frame<T> f = frameAround(N, V);
    const Polygon<T> local = emitterPolygon(l, s.position, f);
    const Polygon<T> clipped = clipHorizon(local);
    const T D = l.diffuse == DiffuseModel::Lambert
                    ? clippedCosine(local)
                    : halfLambertIntegral(local, f.local(emitterToward(l, s.position)));
    T S = T(0);
    if (clipped.n >= 3) {
        const Vec3<T> R = T(2) * glm::dot(N, V) * N - V; // reflect(-V, N)
        const T n = st.specular == SpecularModel::Phong ? s.shininess : s.shininess * T(0.25);
        S = phongLobeIntegral(clipped, f, safeNormalize(R, N), n);
    }
    return visibility * (l.color * s.albedo * D + l.specular * s.specular * S) + ambient;
}

// What an area light adds under physically based shading.
template <typename T>
Vec3<T> shadeAreaLightPbr(const ShadeLight<T>& l, const Surface<T>& s, const ShadeSettings<T>& st,
                          const Vec3<T>& V, const Vec3<T>& cDiff, const Vec3<T>& f0, T alpha,
                          T visibility = T(1)) {
    (void)st;
    const Vec3<T> ambient = l.ambient * cDiff * (saturate(s.occlusion) * T(1.0 / kPi));
    if (!facesEmitter(l, s.position)) return ambient;
    const Vec3<T>& N = s.normal;
    const Frame<T> f = frameAround(N, V);
    const Polygon<T> local = emitterPolygon(l, s.position, f);
    const Polygon<T> clipped = normalized(clipHorizon(local));
    const Vec3<T> toward = f.local(emitterToward(l, s.position));
    // Diffuse: the form factor (or the half-Lambert wrap) × (1 − F_dielectric) at the mean direction.
    const T D = l.diffuse == DiffuseModel::Lambert
                    ? (clipped.n >= 3 ? std::abs(polygonVector(clipped).z) * T(1.0 / kPi) : T(0))
                    : halfLambertIntegral(local, toward);
    const Vec3<T> Vl = f.local(V);
    const T w = schlickWeight(Vl, meanDirection(clipped, toward));
    const Vec3<T> diffuse = cDiff * (dielectricDiffuseWeight(w) * D);
    // Specular: the LTC integral × the lobe's norm (scale + bias) × Schlick's Fresnel at the lobe's mean
    // direction over the light, the polygon clipped to the surface's horizon (where the BRDF is zero) before
    // the transform and to the cosine's after it.
    T nDotV = std::abs(glm::dot(N, V));
    if (!(nDotV > T(kMinNDotV))) nDotV = T(kMinNDotV);
    const ltc::Lookup<T> k = ltc::lookup(alpha, nDotV);
    const Polygon<T> lobe = clipHorizon(transformed(clipHorizon(local), k.m00, k.m02, k.m20, k.m22));
    Vec3<T> e = lobe.n >= 3 ? polygonVector(normalized(lobe)) : Vec3<T>(0);
    const T I = std::abs(e.z) * T(1.0 / kPi);
    const T ws = schlickWeight(Vl, lobeMeanDirection(e, k));
    const Vec3<T> specular = (f0 + (Vec3<T>(1) - f0) * ws) * ((k.scale + k.bias) * I);
    return visibility * (l.color * diffuse + l.specular * specular) + ambient;
}

} // namespace lr::lighting
