// Every lighting formula of LightRig, written once over GLM and templated on the scalar so that the
// renderer's GLSL (shaders/lighting.glsl, same names, same guards) has a double-precision twin for tests
// and the accuracy benchmark. Conventions: right-handed OpenGL view space (eye at the origin looking
// down -Z; a camera-facing normal has z > 0). L = unit vector surface->light, d = distance, N = unit
// normal, V = unit vector to the eye. Angles in radians. See docs/lighting-models.md.
//
// Guards: no formula relies on max(NaN, 0). Every comparison is written so that NaN falls to the safe
// branch, pow/acos get arguments inside their domains, and normalising a zero vector returns a fallback.
#pragma once

#include "colour.h"
#include "types.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <limits>

namespace lr::lighting {

template <typename T> using Vec3 = glm::vec<3, T, glm::defaultp>;

// Floor of d² (inverse-square) and of the inverse-polynomial denominator: attenuation never exceeds 1e4.
template <typename T> constexpr T kMinDenominator = T(1e-4);
// Narrowest smooth-cone width (cos inner - cos outer) treated as a smooth edge; below it the cone is hard.
template <typename T> constexpr T kMinConeWidth = T(1e-7);

// x clamped to [0, 1]; NaN -> 0.
template <typename T> T saturate(T x) {
    return x > T(0) ? (x < T(1) ? x : T(1)) : T(0);
}

// max(x, 0) that maps NaN to 0.
template <typename T> T positive(T x) {
    return x > T(0) ? x : T(0);
}

// pow(base, exponent) for base >= 0 (negative or NaN base -> 0) and exponent >= 0 (else treated as 0).
// pow(0, 0) = 1. Results are finite for base in [0, 1], the only range the formulas feed it.
template <typename T> T safePow(T base, T exponent) {
    if (!(exponent > T(0))) return T(1);
    if (!(base > T(0))) return T(0);
    return std::pow(base, exponent);
}

// acos with its argument clamped into [-1, 1] (dot products of unit vectors overshoot by an ulp).
template <typename T> T safeAcos(T c) {
    return std::acos(c > T(-1) ? (c < T(1) ? c : T(1)) : T(-1));
}

// v / |v|, scale-invariant (works for denormal and huge components); zero, NaN or Inf -> fallback.
// After the division by the largest magnitude m one component is exactly ±1, so dot(v, v) is in [1, 3]
// unless a component is NaN (which max() may skip): the second test catches that.
template <typename T> Vec3<T> safeNormalize(Vec3<T> v, Vec3<T> fallback) {
    const T m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(m > T(0)) || !(m <= std::numeric_limits<T>::max())) return fallback;
    v /= m;
    const T s = glm::dot(v, v);
    if (!(s >= T(1))) return fallback;
    return v / std::sqrt(s);
}

// ---- distance falloff a(d); range < 0 means "no range" where the range is optional ----

// Where 1 - d/range is below this, range-power gives 0 in float and double alike: float cannot resolve
// it (1 - d/range carries ~1e-7 of rounding), and the two disagreed there by rounding alone, visibly
// at high exposure (a light 1e12 away at range 1e12, +60 EV: white in double, black on the GPU).
inline constexpr double kRangeEdge = 1e-6;

// Doc 000: clamp(1 - d/range, 0, 1)^exponent. range <= 0 or d >= range (1 - kRangeEdge) -> 0.
template <typename T> T falloffRangePower(T d, T range, T exponent) {
    if (!(d < range)) return T(0);
    const T t = T(1) - d / range;
    if (!(t > T(kRangeEdge))) return T(0);
    return safePow(saturate(t), exponent);
}

// glTF/Filament smooth range window clamp(1 - (d/range)^4, 0, 1)^2; range < 0 -> 1, d >= range -> 0.
template <typename T> T rangeWindow(T d, T range) {
    if (range < T(0)) return T(1);
    if (!(d < range)) return T(0);
    const T r = d / range, r2 = r * r;
    const T w = saturate(T(1) - r2 * r2);
    return w * w;
}

// Doc 001 (Direct3D): 1 / (c + l d + q d²), denominator floored at kMinDenominator, windowed by range.
template <typename T> T falloffInversePolynomial(T d, T constant, T linear, T quadratic, T range) {
    const T w = rangeWindow(d, range);
    if (!(w > T(0))) return T(0);
    T denom = constant + linear * d + quadratic * d * d;
    if (!(denom > kMinDenominator<T>)) denom = kMinDenominator<T>;
    return w / denom; // denom = +Inf -> 0
}

// Doc 003: clamp(1 - (d/range)², 0, 1). range <= 0 or d >= range -> 0.
template <typename T> T falloffRangeQuadratic(T d, T range) {
    if (!(d < range)) return T(0);
    const T r = d / range;
    return saturate(T(1) - r * r);
}

// glTF KHR_lights_punctual: 1 / max(d², kMinDenominator), windowed by range.
template <typename T> T falloffInverseSquare(T d, T range) {
    const T w = rangeWindow(d, range);
    if (!(w > T(0))) return T(0);
    T d2 = d * d;
    if (!(d2 > kMinDenominator<T>)) d2 = kMinDenominator<T>;
    return w / d2;
}

// ---- spot cone s(cosθ), cosθ = dot(-L, spotDirection) ----

// Doc 000: clamp(1 - acos(cosθ)/outer, 0, 1)^exponent. outer <= 0 -> 0.
template <typename T> T coneAnglePower(T cosTheta, T outer, T exponent) {
    const T theta = safeAcos(cosTheta);
    if (!(theta < outer)) return T(0);
    return safePow(saturate(T(1) - theta / outer), exponent);
}

// Doc 003: cosθ >= cos outer ? 1 : 0.
template <typename T> T coneHard(T cosTheta, T cosOuter) {
    return cosTheta >= cosOuter ? T(1) : T(0);
}

// Doc 001 / glTF: clamp((cosθ - cos outer) / (cos inner - cos outer), 0, 1)^exponent, with the cosines
// precomputed. Outside the outer cone -> 0 (also with exponent 0); a width below kMinConeWidth
// (inner = outer, or a cone too narrow for T to resolve) -> exactly the hard cone, edge included.
template <typename T> T coneSmooth(T cosTheta, T cosInner, T cosOuter, T exponent) {
    const T width = cosInner - cosOuter;
    if (!(width > kMinConeWidth<T>)) return coneHard(cosTheta, cosOuter);
    if (!(cosTheta > cosOuter)) return T(0);
    return safePow(saturate((cosTheta - cosOuter) / width), exponent);
}

// ---- surface terms ----

// Docs 003/004: N·L clamped to [0, 1] (Direct3D's saturate). The upper clamp matters: with float unit
// vectors N·L can exceed 1 by an ulp or two (dot(normalize(a), normalize(a)) > 1).
template <typename T> T diffuseLambert(T nDotL) {
    return saturate(nDotL);
}

// Doc 001: (N·L · 0.5 + 0.5)².
template <typename T> T diffuseHalfLambert(T nDotL) {
    const T h = saturate(nDotL * T(0.5) + T(0.5));
    return h * h;
}

// Doc 000: max(0, reflect(-L, N)·V)^shininess.
template <typename T> T specularPhong(Vec3<T> N, Vec3<T> L, Vec3<T> V, T shininess) {
    const Vec3<T> R = T(2) * glm::dot(N, L) * N - L; // reflect(-L, N)
    return safePow(saturate(glm::dot(R, V)), shininess);
}

// Doc 004: max(0, N·normalize(L + V))^shininess; L = -V gives H = N.
template <typename T> T specularBlinnPhong(Vec3<T> N, Vec3<T> L, Vec3<T> V, T shininess) {
    const Vec3<T> H = safeNormalize(L + V, N);
    return safePow(saturate(glm::dot(N, H)), shininess);
}

// Doc 000: ((1 - max(0, direction·N)) (1 - max(0, N·V)))^exponent.
template <typename T> T rimTerm(Vec3<T> direction, Vec3<T> N, Vec3<T> V, T exponent) {
    const T p1 = T(1) - saturate(glm::dot(direction, N));
    const T p2 = T(1) - saturate(glm::dot(N, V));
    return safePow(p1 * p2, exponent);
}

// ---- physically based: the glTF 2.0 metal-rough BRDF (specification, Appendix B) ----
// α = roughness²; D Trowbridge-Reitz/GGX; V the height-correlated Smith visibility G / (4 |N·L| |N·V|);
// F Schlick's Fresnel; diffuse (1 - F_dielectric) c_diff / π. Radiance of a punctual light = f · E · N·L,
// where E is the light's illuminance at the surface (candela / d² × falloff × cone, or lux for a
// directional light).
//
// The diffuse weight is the specification's own material, mix(dielectric_brdf, metal_brdf, metallic)
// (Appendix B.3.5, as the Khronos sample viewer and three.js evaluate it), not its simplified "final" form:
// the diffuse lobe belongs to the dielectric alone, whose fresnel_mix weighs it by 1 - F with the
// dielectric's F0 = 0.04, so c_diff (1 - F_dielectric) = baseColor (1 - metallic) (1 - 0.04) (1 - w). The
// "final" form's (1 - F) with F0 = mix(0.04, baseColor, metallic) is the same at metallic 0 and 1 only;
// on a partly metallic texel it darkened the diffuse by the metal's Fresnel. The specular lobe is the
// same in both (F with the mixed F0, Schlick being linear in F0).

inline constexpr double kPi = 3.14159265358979323846;
// Perceptual roughness is floored here (three.js's floor; Filament's is 0.045): at 0 a punctual light's
// highlight is a Dirac delta that no renderer can show, and D = α² / (π (...)²) is 0/0 at N·H = 1.
inline constexpr double kMinRoughness = 0.0525;
// |N·V| is floored here: at a silhouette N·V reaches 0 and the visibility's denominator with it.
inline constexpr double kMinNDotV = 1e-5;
// Dielectric reflectance at normal incidence (IOR 1.5).
inline constexpr double kDielectricF0 = 0.04;
// The diffuse lobe's weight 1 - F_dielectric for a Schlick weight w = (1 - |V·H|)^5: (1 - 0.04)(1 - w).
template <typename T> T dielectricDiffuseWeight(T w) {
    return T(1.0 - kDielectricF0) * (T(1) - w);
}

// α = max(roughness, kMinRoughness)²; roughness above 1 or NaN -> 1.
template <typename T> T pbrAlpha(T roughness) {
    const T r = roughness > T(kMinRoughness) ? (roughness < T(1) ? roughness : T(1))
                                             : (roughness <= T(kMinRoughness) ? T(kMinRoughness) : T(1));
    return r * r;
}

// D(h) = α² / (π ((N·H)² (α² - 1) + 1)²) for N·H > 0, else 0. The bracket is written as
// (N·H)² α² + |N×H|² (Lagrange's identity, Filament): 1 - (N·H)² cancels catastrophically in float near
// the highlight's centre, where the cross product keeps its precision.
template <typename T> T ggxDistribution(Vec3<T> N, Vec3<T> H, T alpha) {
    const T nDotH = glm::dot(N, H);
    if (!(nDotH > T(0))) return T(0);
    const Vec3<T> c = glm::cross(N, H);
    const T a2 = alpha * alpha;
    const T k = nDotH * nDotH * a2 + glm::dot(c, c);
    return a2 / (T(kPi) * k * k); // k >= (N·H)² α² > 0
}

// Height-correlated Smith visibility (Heitz 2014; glTF sample viewer, three.js, Filament):
// 0.5 / (N·L sqrt((N·V)² (1 - α²) + α²) + N·V sqrt((N·L)² (1 - α²) + α²)), for N·L > 0 and N·V > 0.
template <typename T> T smithVisibility(T nDotL, T nDotV, T alpha) {
    const T a2 = alpha * alpha;
    const T gv = nDotL * std::sqrt(nDotV * nDotV * (T(1) - a2) + a2);
    const T gl = nDotV * std::sqrt(nDotL * nDotL * (T(1) - a2) + a2);
    const T denom = gv + gl;
    return denom > T(0) ? T(0.5) / denom : T(0);
}

// Schlick: F0 + (1 - F0) w, w = (1 - |V·H|)^5 (the weight alone also serves the area lights' Fresnel).
template <typename T> T schlickWeight(T vDotH) {
    const T m = T(1) - saturate(std::abs(vDotH));
    const T m2 = m * m;
    return m2 * m2 * m;
}
template <typename T> Vec3<T> fresnelSchlick(const Vec3<T>& f0, T vDotH) {
    return f0 + (Vec3<T>(1) - f0) * schlickWeight(vDotH);
}

// The material's diffuse colour c_diff = baseColor (1 - metallic) and F0 = mix(0.04, baseColor, metallic),
// metallic clamped to [0, 1] (NaN -> 0) and base colour to >= 0.
template <typename T> Vec3<T> pbrDiffuseColor(const Vec3<T>& baseColor, T metallic) {
    const Vec3<T> b(positive(baseColor.x), positive(baseColor.y), positive(baseColor.z));
    return b * (T(1) - saturate(metallic));
}
template <typename T> Vec3<T> pbrF0(const Vec3<T>& baseColor, T metallic) {
    const Vec3<T> b(positive(baseColor.x), positive(baseColor.y), positive(baseColor.z));
    const T m = saturate(metallic);
    return Vec3<T>(T(kDielectricF0)) * (T(1) - m) + b * m;
}

// One punctual light's two lobes at the surface, per unit of light: diffuse = (1 - F_dielectric) c_diff / π ·
// cosTerm
// (cosTerm: N·L, or the half-Lambert wrap when a light asks for it), specular = F D V · N·L. The caller
// multiplies by the light's colour, intensity and attenuation.
template <typename T> struct PbrLobes {
    Vec3<T> diffuse{0};
    Vec3<T> specular{0};
};

template <typename T>
PbrLobes<T> pbrLobes(Vec3<T> N, Vec3<T> L, Vec3<T> V, const Vec3<T>& cDiff, const Vec3<T>& f0, T alpha,
                     T cosTerm) {
    PbrLobes<T> o;
    // H from two unit vectors: |L + V| <= 2, so the plain quotient cannot overflow, and the scale-invariant
    // safeNormalize (which lightArrival needs for L, from positions of any magnitude) would only cost time
    // here. L = -V (or a NaN): H = N.
    const Vec3<T> h = L + V;
    const T hh = glm::dot(h, h);
    const Vec3<T> H = hh > T(1e-12) ? h / std::sqrt(hh) : N;
    const T w = schlickWeight(glm::dot(V, H));
    const Vec3<T> F = f0 + (Vec3<T>(1) - f0) * w;
    o.diffuse = cDiff * (dielectricDiffuseWeight(w) * cosTerm * T(1.0 / kPi));
    const T nDotL = glm::dot(N, L);
    if (!(nDotL > T(0))) return o; // no specular from behind (a wrapped diffuse may still light it)
    T nDotV = std::abs(glm::dot(N, V));
    if (!(nDotV > T(kMinNDotV))) nDotV = T(kMinNDotV);
    const T nl = nDotL < T(1) ? nDotL : T(1);
    o.specular = F * (ggxDistribution(N, H, alpha) * smithVisibility(nl, nDotV, alpha) * nl);
    return o;
}

// ---- tone mapping and output encoding: core/colour.h, here under their lighting:: names ----

using colour::linearToSrgb;
using colour::srgbToLinear;
using colour::toneMap;

} // namespace lr::lighting
