// Whole-surface shading: one light's contribution and the sum over a rig, templated on the scalar.
// This is the reference the GPU is tested and benchmarked against (evaluated in double), and the exact
// twin of shaders/shade.glsl's shadeLight()/shadeSurface().
#pragma once

#include "gobo.h"
#include "lighting.h"
#include "lighting_area.h"
#include "lighttypes.h"
#include "shadetypes.h"

#include <span>

namespace lr::lighting {

template <typename T> T evalFalloff(const ShadeLight<T>& l, T d) {
    switch (l.falloff) {
    case FalloffModel::None:
        return T(1);
    case FalloffModel::RangePower:
        return falloffRangePower(d, l.range, l.falloffExponent);
    case FalloffModel::InversePolynomial:
        return falloffInversePolynomial(d, l.constant, l.linear, l.quadratic, l.range);
    case FalloffModel::RangeQuadratic:
        return falloffRangeQuadratic(d, l.range);
    case FalloffModel::InverseSquare:
        return falloffInverseSquare(d, l.range);
    }
    return T(0);
}

template <typename T> T evalCone(const ShadeLight<T>& l, T cosTheta) {
    switch (l.cone) {
    case ConeModel::AnglePower:
        return coneAnglePower(cosTheta, l.outer, l.coneExponent);
    case ConeModel::Smooth:
        return coneSmooth(cosTheta, l.cosInner, l.cosOuter, l.coneExponent);
    case ConeModel::Hard:
        return coneHard(cosTheta, l.cosOuter);
    }
    return T(0);
}

// A spot's gobo tint for the direction L (surface to light): 1 without a gobo (core/gobo.h).
template <typename T> Vec3<T> goboTint(const ShadeLight<T>& l, const Vec3<T>& L) {
    if (!l.gobo) return Vec3<T>(1);
    return gobo::tint(*l.gobo, -L, l.direction, l.axisX, l.axisY, l.goboHalf);
}

template <typename T> Vec3<T> viewVector(const ShadeSettings<T>& s, const Vec3<T>& P) {
    const Vec3<T> infinite(0, 0, 1);
    return s.viewer == ViewerModel::Local ? safeNormalize(-P, infinite) : infinite;
}

// The direction to a light and its attenuation (falloff × cone; 1 for a directional light) at the surface.
// False when the light adds nothing there.
template <typename T>
bool lightArrival(const ShadeLight<T>& l, const Surface<T>& s, const ShadeSettings<T>& st, Vec3<T>* L,
                  T* attenuation) {
    *L = -l.direction;
    *attenuation = T(1);
    if (!traitsOf(l.type).usesPosition) return true;
    const Vec3<T> toLight = l.position - s.position;
    *L = safeNormalize(toLight, s.normal); // a light on the surface shines along the normal
    // |toLight| as dot(toLight, L): no squared intermediate, so no overflow or underflow where
    // glm::length's would (float: |toLight| > 1.8e19 or < 1e-19), and one sqrt fewer. An overflowing
    // distance (positions more than ~1.7e38 apart, where L falls back to N) becomes the largest finite
    // value: every falloff then returns its limit.
    T d = glm::dot(toLight, *L) * st.distanceScale;
    if (!(std::abs(d) <= std::numeric_limits<T>::max())) d = std::numeric_limits<T>::max();
    *attenuation = evalFalloff(l, d);
    if (traitsOf(l.type).usesCone) *attenuation *= evalCone(l, glm::dot(-*L, l.direction));
    if (l.ies) *attenuation *= l.iesScale * iesCandelaToward<T>(*l.ies, -*L, l.iesNadir, l.iesX, l.iesY);
    return *attenuation > T(0);
}

// Radiance one light adds at the surface (linear, HDR), classic models. `visibility` (the fraction of
// the emitter the surface sees, 0..1; the traced reference's shadows, reference.h) scales the direct
// terms, never the light's ambient; at 1 the result is bit for bit what it was without it.
template <typename T>
Vec3<T> shadeLight(const ShadeLight<T>& l, const Surface<T>& s, const ShadeSettings<T>& st, const Vec3<T>& V,
                   T visibility = T(1)) {
    const Vec3<T>& N = s.normal;
    if (l.type == LightType::Rim) return l.color * rimTerm(l.direction, N, V, l.rimExponent);
    if (traitsOf(l.type).isArea) return shadeAreaLight(l, s, st, V, visibility);
    Vec3<T> L;
    T attenuation;
    if (!lightArrival(l, s, st, &L, &attenuation)) return Vec3<T>(0);
    const T nDotL = glm::dot(N, L);
    const T D = l.diffuse == DiffuseModel::Lambert ? diffuseLambert(nDotL) : diffuseHalfLambert(nDotL);
    T S = T(0);
    if (nDotL > T(0))
        S = st.specular == SpecularModel::Phong ? specularPhong(N, L, V, s.shininess)
                                                : specularBlinnPhong(N, L, V, s.shininess);
    const Vec3<T> c = attenuation * (visibility * (l.color * s.albedo * D + l.specular * s.specular * S) +
                                     l.ambient * s.albedo);
    return l.gobo ? c * goboTint(l, L) : c;
}

// Radiance one light adds at the surface under physically based shading (docs/lighting-models.md):
//   attenuation · (colour·intensity · diffuse lobe + Sc·intensity · specular lobe + Ac·intensity · c_diff/π);
// the falloff, cone and diffuse models are the light's own (glTF lights: inverse-square with the range
// window, smooth cone of exponent 2, Lambert). A rim light adds its classic term. `visibility` as in
// shadeLight.
template <typename T>
Vec3<T> shadeLightPbr(const ShadeLight<T>& l, const Surface<T>& s, const ShadeSettings<T>& st,
                      const Vec3<T>& V, const Vec3<T>& cDiff, const Vec3<T>& f0, T alpha,
                      T visibility = T(1)) {
    const Vec3<T>& N = s.normal;
    if (l.type == LightType::Rim) return l.color * rimTerm(l.direction, N, V, l.rimExponent);
    if (traitsOf(l.type).isArea) return shadeAreaLightPbr(l, s, st, V, cDiff, f0, alpha, visibility);
    Vec3<T> L;
    T attenuation;
    if (!lightArrival(l, s, st, &L, &attenuation)) return Vec3<T>(0);
    const T nDotL = glm::dot(N, L);
    const T cosTerm = l.diffuse == DiffuseModel::Lambert ? diffuseLambert(nDotL) : diffuseHalfLambert(nDotL);
    const PbrLobes<T> f = pbrLobes(N, L, V, cDiff, f0, alpha, cosTerm);
    const Vec3<T> c = attenuation * (visibility * (l.color * f.diffuse + l.specular * f.specular) +
                                     l.ambient * cDiff * (saturate(s.occlusion) * T(1.0 / kPi)));
    return l.gobo ? c * goboTint(l, L) : c;
}

// Scene ambient + every light + emissive. `visibility`: empty (every light unshadowed) or one value per
// light, in the order of `lights` (shadeLight's visibility).
template <typename T>
Vec3<T> shadeSurface(const Surface<T>& s, std::span<const ShadeLight<T>> lights, const ShadeSettings<T>& st,
                     std::span<const T> visibility = {}) {
    const auto visible = [&](size_t i) { return i < visibility.size() ? visibility[i] : T(1); };
    const Vec3<T> V = viewVector(st, s.position);
    if (st.model == ShadingModel::Pbr) {
        // The scene ambient is an irradiance (lux, as three.js's AmbientLight) on the diffuse lobe,
        // scaled by the material's occlusion.
        const Vec3<T> cDiff = pbrDiffuseColor(s.albedo, s.metallic);
        const Vec3<T> f0 = pbrF0(s.albedo, s.metallic);
        const T alpha = pbrAlpha(s.roughness);
        Vec3<T> sum = st.ambient * cDiff * (saturate(s.occlusion) * T(1.0 / kPi));
        for (size_t i = 0; i < lights.size(); ++i)
            sum += shadeLightPbr(lights[i], s, st, V, cDiff, f0, alpha, visible(i));
        return sum + s.emissive;
    }
    Vec3<T> sum = st.ambient * s.albedo;
    for (size_t i = 0; i < lights.size(); ++i)
        sum += shadeLight(lights[i], s, st, V, visible(i));
    return sum + s.emissive;
}

} // namespace lr::lighting
