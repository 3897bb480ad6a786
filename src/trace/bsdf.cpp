#include "bsdf.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lr::trace {

namespace {

double luminance(const glm::dvec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

// Below this N·V the visible normals are not sampled (the view is at or behind the shading horizon, as a
// normal map can make it): the half vector is drawn from D(h) (N·H) instead.
constexpr double kMinVisibleNDotV = 1e-4;

// Smith's masking of the view for GGX: G1(v) = 2 N·V / (N·V + sqrt(α² + (1 − α²) (N·V)²)).
double smithG1(double nDotV, double alpha) {
    const double a2 = alpha * alpha;
    return 2.0 * nDotV / (nDotV + std::sqrt(a2 + (1.0 - a2) * nDotV * nDotV));
}

} // namespace

Bsdf::Bsdf(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& baseColor, double metallic,
           double roughness)
    : m_n(n), m_v(v) {
    m_cDiff = lighting::pbrDiffuseColor(baseColor, metallic);
    m_f0 = lighting::pbrF0(baseColor, metallic);
    m_alpha = lighting::pbrAlpha(roughness);
    const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    m_t = glm::normalize(glm::cross(helper, n));
    m_b = glm::cross(n, m_t);
    const double nDotV = std::clamp(glm::dot(n, v), 0.0, 1.0);
    const glm::dvec3 f = lighting::fresnelSchlick(m_f0, nDotV);
    const double spec = luminance(f), diff = luminance(m_cDiff * (glm::dvec3(1.0) - f));
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
    double p = (1.0 - m_pSpecular) * nDotL / std::numbers::pi;
    const glm::dvec3 h = l + m_v;
    const double hh = glm::dot(h, h);
    if (hh > 1e-24) {
        const glm::dvec3 H = h / std::sqrt(hh);
        const double vDotH = std::abs(glm::dot(m_v, H));
        const double nDotV = glm::dot(m_n, m_v);
        if (nDotV > kMinVisibleNDotV) // the visible normals' density D_v(h) = G1(v) (V·H) D(h) / (N·V)
            p += m_pSpecular * smithG1(nDotV, m_alpha) * lighting::ggxDistribution(m_n, H, m_alpha) /
                 (4.0 * nDotV);
        else if (vDotH > 0.0)
            p += m_pSpecular * lighting::ggxDistribution(m_n, H, m_alpha) * std::max(0.0, glm::dot(m_n, H)) /
                 (4.0 * vDotH);
    }
    return std::isfinite(p) ? p : 0.0;
}

BsdfSample Bsdf::sample(double u0, double u1, double u2) const {
    BsdfSample s;
    glm::dvec3 l;
    const double nDotV = glm::dot(m_n, m_v);
    if (u0 < m_pSpecular && nDotV > kMinVisibleNDotV) {
        // The visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals", JCGT 7(4)):
        // the view stretched to α = 1, a point of the projected hemisphere, unstretched. No half vector faces
        // away from the view, so fewer samples are lost below the horizon than with D(h) (N·H).
        const glm::dvec3 ve(glm::dot(m_v, m_t), glm::dot(m_v, m_b), nDotV);
        const glm::dvec3 vh = glm::normalize(glm::dvec3(m_alpha * ve.x, m_alpha * ve.y, ve.z));
        const double lensq = vh.x * vh.x + vh.y * vh.y;
        const glm::dvec3 t1 =
            lensq > 0.0 ? glm::dvec3(-vh.y, vh.x, 0.0) / std::sqrt(lensq) : glm::dvec3(1.0, 0.0, 0.0);
        const glm::dvec3 t2 = glm::cross(vh, t1);
        const double r = std::sqrt(u1), phi = 2.0 * std::numbers::pi * u2;
        const double p1 = r * std::cos(phi), sv = 0.5 * (1.0 + vh.z);
        const double p2 = (1.0 - sv) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + sv * r * std::sin(phi);
        const glm::dvec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
        const glm::dvec3 hl(m_alpha * nh.x, m_alpha * nh.y, std::max(0.0, nh.z));
        const double hlen = glm::length(hl);
        if (!(hlen > 0.0)) return s;
        const glm::dvec3 h = (hl.x * m_t + hl.y * m_b + hl.z * m_n) / hlen;
        l = 2.0 * glm::dot(m_v, h) * h - m_v;
    } else if (u0 < m_pSpecular) {
        // D(h) (n · h): cos²θh = (1 − u) / (1 + (α² − 1) u).
        const double a2 = m_alpha * m_alpha;
        const double cos2 = (1.0 - u1) / (1.0 + (a2 - 1.0) * u1);
        const double cosT = std::sqrt(std::clamp(cos2, 0.0, 1.0)),
                     sinT = std::sqrt(std::max(0.0, 1.0 - cos2));
        const double phi = 2.0 * std::numbers::pi * u2;
        const glm::dvec3 h = sinT * std::cos(phi) * m_t + sinT * std::sin(phi) * m_b + cosT * m_n;
        l = 2.0 * glm::dot(m_v, h) * h - m_v;
    } else {
        const double r = std::sqrt(u1), phi = 2.0 * std::numbers::pi * u2;
        const double z = std::sqrt(std::max(0.0, 1.0 - u1));
        l = r * std::cos(phi) * m_t + r * std::sin(phi) * m_b + z * m_n;
    }
    const double len = glm::length(l);
    if (!(len > 0.0) || !std::isfinite(len)) return s;
    s.direction = l / len;
    s.pdf = pdf(s.direction);
    if (s.pdf > 0.0) s.value = eval(s.direction);
    return s;
}

} // namespace lr::trace
