// The glTF 2.0 metal-rough BRDF as the path tracer samples it. Its value is core's, one definition
// (src/core/lighting.h pbrLobes: Trowbridge-Reitz D, height-correlated Smith V, Schlick F, (1 − F_dielectric)
// c_diff / π), so the traced image, the raster and the double reference shade the same material. This
// adds what a path tracer needs besides the value: a direction drawn from the lobes and its density.
//   - specular: core's montecarlo::SpecularLobe, the lobe the reference's integrators sample: the half
//     vector from GGX's visible normals (Heitz 2018), pdf(l) = G1(v) D(h) / (4 n · v), or where the
//     shading normal turns away from the view (a normal map can) from D(h) (n · h), reflected about h
//   - diffuse: the cosine-weighted hemisphere, pdf(l) = (n · l) / π
//   - the lobe is chosen with probability pSpecular from the Fresnel-weighted reflectances at n · v.
// Only reflection: no transmission. Directions below the shading normal's horizon have value and
// density 0.
#pragma once

#include "core/lighting.h"
#include "core/montecarlo.h"

#include <glm/vec3.hpp>

namespace lr::trace {

struct BsdfSample {
    glm::dvec3 direction{0.0};
    glm::dvec3 value{0.0}; // f · (n · l), both lobes
    double pdf = 0.0;      // per steradian, both lobes mixed
};

class Bsdf {
  public:
    // n: the shading normal (unit, on the side of v); v: unit, towards the viewer.
    Bsdf(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& baseColor, double metallic,
         double roughness);

    // f · (n · l) for a unit direction l, as core's pbrLobes (Lambert's cosine).
    glm::dvec3 eval(const glm::dvec3& l) const;
    // The same with the light's diffuse model's cosine term (half-Lambert lights, as shadeLightPbr).
    lighting::PbrLobes<double> lobes(const glm::dvec3& l, double cosTerm) const;
    double pdf(const glm::dvec3& l) const;
    // A direction from three uniform numbers; pdf 0 when it fell below the horizon.
    BsdfSample sample(double u0, double u1, double u2) const;

    const glm::dvec3& normal() const { return m_n; }
    const glm::dvec3& diffuseColor() const { return m_cDiff; }
    double alpha() const { return m_alpha; }

  private:
    glm::dvec3 m_n, m_v;
    glm::dvec3 m_cDiff, m_f0;
    double m_alpha = 1.0;
    montecarlo::SpecularLobe m_specular; // after m_alpha, which it is built from
    double m_pSpecular = 0.5;
};

} // namespace lr::trace
