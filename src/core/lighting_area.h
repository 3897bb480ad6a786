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
// shadeAreaLightPbr approximate it (LTC: Heitz, Dupuy, Hill and Neubelt 2016).
#pragma once

#include "lighting.h"
#include "lighttypes.h"
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

// PLACEHOLDER until the LTC evaluation lands: the emitter as one sample at its centre, its solid angle
// A·cos θe / d² (at most 2π). Finite everywhere; exact only for small, distant emitters.
template <typename T>
Vec3<T> areaDirectRepresentative(const ShadeLight<T>& l, const Surface<T>& s, const ShadeSettings<T>& st,
                                 const Vec3<T>& V, const Vec3<T>& cDiff, const Vec3<T>& f0, T alpha) {
    const Vec3<T> toLight = l.position - s.position;
    const Vec3<T> w = safeNormalize(toLight, s.normal);
    const T d = glm::dot(toLight, w);
    T cosE = -glm::dot(w, l.direction); // at the emitter: > 0 when P is on its front side
    if (l.twoSided) cosE = std::abs(cosE);
    if (!(cosE > T(0)) || !(d > T(0))) return Vec3<T>(0);
    const T omega = std::min(T(2 * kPi), areaOf(l) * cosE / (d * d));
    if (!(omega > T(0))) return Vec3<T>(0);
    return directionalResponse(l, s, st, V, w, cDiff, f0, alpha) * omega;
}

// What an area light adds under the classic models (the definition above, with its 1/π).
template <typename T>
Vec3<T> shadeAreaLight(const ShadeLight<T>& l, const Surface<T>& s, const ShadeSettings<T>& st,
                       const Vec3<T>& V, T visibility = T(1)) {
    const Vec3<T> direct = areaDirectRepresentative(l, s, st, V, s.albedo, s.specular, T(1)) * T(1.0 / kPi);
    return visibility * direct + l.ambient * s.albedo;
}

// What an area light adds under physically based shading.
template <typename T>
Vec3<T> shadeAreaLightPbr(const ShadeLight<T>& l, const Surface<T>& s, const ShadeSettings<T>& st,
                          const Vec3<T>& V, const Vec3<T>& cDiff, const Vec3<T>& f0, T alpha,
                          T visibility = T(1)) {
    const Vec3<T> direct = areaDirectRepresentative(l, s, st, V, cDiff, f0, alpha);
    return visibility * direct + l.ambient * cDiff * (saturate(s.occlusion) * T(1.0 / kPi));
}

} // namespace lr::lighting
