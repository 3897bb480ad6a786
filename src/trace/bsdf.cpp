#include "bsdf.h"

#include "core/envintegrate.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lr::trace {

using envintegrate::luminance;

Bsdf::Bsdf(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& baseColor, double metallic,
           double roughness)
    : m_n(n), m_v(v), m_cDiff(lighting::pbrDiffuseColor(baseColor, metallic)),
      m_f0(lighting::pbrF0(baseColor, metallic)), m_alpha(lighting::pbrAlpha(roughness)),
      m_specular(n, v, true, m_alpha, SpecularModel::BlinnPhong, 1.0) {
    const double nDotV = std::clamp(glm::dot(n, v), 0.0, 1.0);
    // The lobes' shares at normal-ish incidence (V·H ≈ N·V), to choose which to sample: the diffuse weighed
    // by the dielectric's Fresnel as pbrLobes weighs it (the specification's mix).
    const double w = lighting::schlickWeight(nDotV);
    const glm::dvec3 f = m_f0 + (glm::dvec3(1.0) - m_f0) * w;
    const double spec = luminance(f), diff = luminance(m_cDiff) * lighting::dielectricDiffuseWeight(w);
    m_pSpecular = spec + diff > 0.0 ? std::clamp(spec / (spec + diff), 0.1, 0.9) : 0.5;
    if (!(luminance(m_cDiff) > 0.0)) m_pSpecular = 1.0;
}

lighting::PbrLobes<double> Bsdf::lobes(const glm::dvec3& l, double cosTerm) const {
    return lighting::pbrLobes(m_n, l, m_v, m_cDiff, m_f0, m_alpha, cosTerm);
}

glm::dvec3 Bsdf::eval(const glm::dvec3& l) const {
    const double nDotL = glm::dot(m_n, l);
    if (!(nDotL > 0.0)) return glm::dvec3(0.0);
    const lighting::PbrLobes<double> f = lobes(l, lighting::diffuseLambert(nDotL));
    return f.diffuse + f.specular;
}

double Bsdf::pdf(const glm::dvec3& l) const {
    const double nDotL = glm::dot(m_n, l);
    if (!(nDotL > 0.0)) return 0.0;
    const double p = (1.0 - m_pSpecular) * nDotL / std::numbers::pi + m_pSpecular * m_specular.pdf(l);
    return std::isfinite(p) ? p : 0.0;
}

BsdfSample Bsdf::sample(double u0, double u1, double u2) const {
    BsdfSample s;
    const glm::dvec3 l = u0 < m_pSpecular ? m_specular.sample(u1, u2)
                                          : montecarlo::around(m_n, std::sqrt(std::max(0.0, 1.0 - u1)),
                                                               2.0 * std::numbers::pi * u2);
    const double len = glm::length(l);
    if (!(len > 0.0) || !std::isfinite(len)) return s;
    s.direction = l / len;
    s.pdf = pdf(s.direction);
    if (s.pdf > 0.0) s.value = eval(s.direction);
    return s;
}

} // namespace lr::trace
