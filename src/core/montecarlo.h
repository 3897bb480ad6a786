// Monte Carlo building blocks shared by the reference's integrators (core/envintegrate: the environment,
// core/areaintegrate: area lights): a seeded stream, a 6-dimensional low-discrepancy sequence, frames
// around a vector, and the specular lobes' importance sampling with their densities.
#pragma once

#include "lighting.h"
#include "types.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>

namespace lr::montecarlo {

using V = glm::dvec3;

struct Rng { // splitmix64: independent, reproducible streams per pixel
    std::uint64_t state;
    explicit Rng(std::uint64_t seed) : state(seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull) {}
    double next() {
        std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        z ^= z >> 31;
        return double(z >> 11) * 0x1.0p-53; // [0, 1)
    }
};

// The steps of a 6-dimensional R-sequence (Roberts' generalised golden ratio: point i is frac(shift +
// i·α)); α_j = (1/g)^(j+1), g the root of x⁷ = x + 1.
inline const std::array<double, 6>& rSequence6() {
    static const std::array<double, 6> kAlpha = [] {
        double g = 2.0;
        for (int i = 0; i < 60; ++i)
            g = std::pow(1.0 + g, 1.0 / 7.0);
        std::array<double, 6> a{};
        for (int j = 0; j < 6; ++j)
            a[size_t(j)] = std::fmod(std::pow(1.0 / g, j + 1), 1.0);
        return a;
    }();
    return kAlpha;
}

// An orthonormal frame around a unit vector (Duff et al. 2017).
inline void frameAround(const V& n, V* t, V* b) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z), bb = n.x * n.y * a;
    *t = V(1.0 + sign * n.x * n.x * a, sign * bb, -sign * n.x);
    *b = V(bb, sign + n.y * n.y * a, -n.y);
}

inline V around(const V& axis, double cosTheta, double phi) {
    V t, b;
    frameAround(axis, &t, &b);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return sinTheta * std::cos(phi) * t + sinTheta * std::sin(phi) * b + cosTheta * axis;
}

inline V reflectAbout(const V& v, const V& h) {
    return 2.0 * glm::dot(v, h) * h - v;
}

// The specular lobe of a surface (normal n, unit vector to the eye v) as a sampling density over incoming
// directions ω: physically based, GGX's visible normals (Heitz 2018) when v is above the surface, else
// D(h)(n·h); classic, Phong's cosine lobe about the mirror direction or Blinn's about n (in h).
// Physically based lobes sample GGX's visible normals when v is above the surface: the weight f·cos/p is
// then F·G2/G1(v) ≤ 1, where sampling D(h)(n·h) gives G2·(v·h)/((n·v)(n·h)), large and erratic at grazing
// views. Its density at ω is D(h)·G1(v)/(4 n·v) = D(h) / (2 (n·v + √(α² + (1 − α²)(n·v)²))).
class SpecularLobe {
  public:
    SpecularLobe(const V& n, const V& v, bool pbr, double alpha, SpecularModel model, double shininess)
        : m_n(n), m_v(v), m_pbr(pbr), m_alpha(alpha), m_model(model), m_shininess(shininess) {
        m_r = lighting::safeNormalize(reflectAbout(v, n), n);
        const double nv = glm::dot(n, v);
        m_visibleNormals = pbr && nv > 1e-6;
        m_visibleNorm =
            m_visibleNormals ? 2.0 * (nv + std::sqrt(alpha * alpha + (1.0 - alpha * alpha) * nv * nv)) : 0.0;
        frameAround(n, &m_tangent, &m_bitangent);
        m_vLocal = V(glm::dot(v, m_tangent), glm::dot(v, m_bitangent), nv);
    }

    const V& mirror() const { return m_r; } // v reflected about n

    // The density at ω (per steradian). Only where the sampler goes (safePow(x, 0) is 1 even for x <= 0: a
    // density there would be a bias).
    double pdf(const V& w) const {
        constexpr double kPi = lighting::kPi;
        if (m_visibleNormals) {
            V h;
            double vh;
            if (!halfVector(w, &h, &vh)) return 0.0;
            // The sampler only makes half-vectors above the surface that face v; every ω they reflect v
            // into (even below the horizon, where the integrand is 0) has this density.
            if (!(glm::dot(m_v, h) > 0.0) || !(glm::dot(m_n, h) > 0.0)) return 0.0;
            return lighting::ggxDistribution(m_n, h, m_alpha) / m_visibleNorm;
        }
        if (!m_pbr && m_model == SpecularModel::Phong) {
            const double c = glm::dot(m_r, w);
            return c > 0.0
                       ? (m_shininess + 1.0) / (2.0 * kPi) * lighting::safePow(std::min(c, 1.0), m_shininess)
                       : 0.0;
        }
        V h;
        double vh;
        if (!halfVector(w, &h, &vh)) return 0.0;
        const double nh = std::min(glm::dot(m_n, h), 1.0);
        if (!(nh > 0.0)) return 0.0;
        const double pdfH = m_pbr ? lighting::ggxDistribution(m_n, h, m_alpha) * nh
                                  : (m_shininess + 1.0) / (2.0 * kPi) * lighting::safePow(nh, m_shininess);
        return pdfH / (4.0 * vh);
    }

    // A direction ω from two uniform numbers.
    V sample(double u0, double u1) const {
        const double phi = 2.0 * lighting::kPi * u1;
        if (m_visibleNormals) {
            // Heitz 2018, listing 1: stretch v, sample the projected disk, unstretch.
            const double alpha = m_alpha;
            const V vh = glm::normalize(V(alpha * m_vLocal.x, alpha * m_vLocal.y, m_vLocal.z));
            const double lensq = vh.x * vh.x + vh.y * vh.y;
            const V t1 = lensq > 0.0 ? V(-vh.y, vh.x, 0.0) / std::sqrt(lensq) : V(1.0, 0.0, 0.0);
            const V t2 = glm::cross(vh, t1);
            const double rr = std::sqrt(u0);
            const double p1 = rr * std::cos(phi);
            double p2 = rr * std::sin(phi);
            const double sh = 0.5 * (1.0 + vh.z);
            p2 = (1.0 - sh) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + sh * p2;
            const V nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2)) * vh;
            const V hl = glm::normalize(V(alpha * nh.x, alpha * nh.y, std::max(0.0, nh.z)));
            return reflectAbout(m_v, hl.x * m_tangent + hl.y * m_bitangent + hl.z * m_n);
        }
        if (m_pbr) {
            const double a2 = m_alpha * m_alpha;
            const double cosT = std::sqrt((1.0 - u0) / (1.0 + (a2 - 1.0) * u0));
            return reflectAbout(m_v, around(m_n, cosT, phi));
        }
        const double cosT = std::pow(u0, 1.0 / (m_shininess + 1.0));
        if (m_model == SpecularModel::Phong) return around(m_r, cosT, phi);
        return reflectAbout(m_v, around(m_n, cosT, phi));
    }

  private:
    // ω + v is parallel to ±h, so the half-vector is oriented to n's side before the density is read
    // (else reflections of half-vectors facing away from v would be sampled with a density counted as 0:
    // a bias).
    bool halfVector(const V& w, V* h, double* vh) const {
        const V hv = w + m_v;
        const double hh = glm::dot(hv, hv);
        if (!(hh > 1e-24)) return false;
        *h = hv / std::sqrt(hh);
        if (glm::dot(m_n, *h) < 0.0) *h = -*h;
        *vh = std::abs(glm::dot(m_v, *h));
        return *vh > 0.0;
    }

    V m_n, m_v, m_r, m_tangent, m_bitangent, m_vLocal;
    bool m_pbr, m_visibleNormals = false;
    double m_alpha, m_visibleNorm = 0.0;
    SpecularModel m_model;
    double m_shininess;
};

} // namespace lr::montecarlo
