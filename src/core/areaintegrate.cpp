#include "areaintegrate.h"

#include "barndoors.h"
#include "lighting_area.h"
#include "montecarlo.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lr::areaintegrate {

namespace {

using V = glm::dvec3;
using lighting::kPi;

double maxOf(const V& v) {
    return std::max({v.x, v.y, v.z});
}

bool finite(const V& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finitePositive(double x) {
    return x > 0.0 && x <= std::numeric_limits<double>::max();
}

// Which side of the emitter P is on: +1 its emitting front, -1 behind, 0 in its plane (or not finite).
int sideOf(const lighting::ShadeLight<double>& l, const V& P) {
    const double d = glm::dot(P - l.position, l.direction);
    return d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
}

bool seesEmitter(const lighting::ShadeLight<double>& l, const V& P) {
    if (!traitsOf(l.type).isArea || !finitePositive(l.halfWidth) || !finitePositive(l.halfHeight))
        return false;
    const int side = sideOf(l, P);
    return side > 0 || (side < 0 && l.twoSided);
}

// Shirley and Chiu's concentric map of the unit square onto the unit disk.
glm::dvec2 concentricDisk(double u0, double u1) {
    const double a = 2.0 * u0 - 1.0, b = 2.0 * u1 - 1.0;
    if (a == 0.0 && b == 0.0) return {0.0, 0.0};
    if (std::abs(a) > std::abs(b)) {
        const double phi = kPi / 4.0 * (b / a);
        return {a * std::cos(phi), a * std::sin(phi)};
    }
    const double phi = kPi / 2.0 - kPi / 4.0 * (a / b);
    return {b * std::cos(phi), b * std::sin(phi)};
}

// One emitter as seen from P: its sampling by solid angle (rect) or area, and the density of any direction.
class Emitter {
  public:
    Emitter(const lighting::ShadeLight<double>& l, const V& P) : m_l(l), m_P(P) {
        m_disk = l.type == LightType::Disk;
        m_area = lighting::areaOf(l);
        if (m_disk) return;
        // Ureña et al. 2013 (as pbrt-v4's SampleSphericalRectangle): the rect in a frame at P with x, y
        // along its edges and z towards it from P (z0 < 0 after the flip).
        m_x = l.axisX, m_y = l.axisY, m_z = glm::cross(m_x, m_y);
        const V d = l.position - l.halfWidth * m_x - l.halfHeight * m_y - P;
        m_x0 = glm::dot(d, m_x), m_y0 = glm::dot(d, m_y), m_z0 = glm::dot(d, m_z);
        if (m_z0 > 0.0) m_z = -m_z, m_z0 = -m_z0;
        m_x1 = m_x0 + 2.0 * l.halfWidth, m_y1 = m_y0 + 2.0 * l.halfHeight;
        const V v00(m_x0, m_y0, m_z0), v01(m_x0, m_y1, m_z0), v10(m_x1, m_y0, m_z0), v11(m_x1, m_y1, m_z0);
        const V n0 = glm::normalize(glm::cross(v00, v10)), n1 = glm::normalize(glm::cross(v10, v11));
        const V n2 = glm::normalize(glm::cross(v11, v01)), n3 = glm::normalize(glm::cross(v01, v00));
        const auto angle = [](const V& a, const V& b) { return lighting::safeAcos(glm::dot(a, b)); };
        m_g0 = angle(-n0, n1), m_g1 = angle(-n1, n2), m_g2 = angle(-n2, n3), m_g3 = angle(-n3, n0);
        m_b0 = n0.z, m_b1 = n2.z;
        const double omega = m_g0 + m_g1 + m_g2 + m_g3 - 2.0 * kPi;
        if (omega > kSmallSolidAngle && std::isfinite(omega)) m_omega = omega;
    }

    double solidAngleSampled() const { return m_omega; } // 0: sampled by area

    // A direction towards the emitter and its density; false when the sample is degenerate.
    bool sample(double u0, double u1, V* w, double* pdf) const {
        if (m_omega > 0.0) {
            const double au = u0 * (m_g0 + m_g1 - 2.0 * kPi) + (u0 - 1.0) * (m_g2 + m_g3);
            const double fu = (std::cos(au) * m_b0 - m_b1) / std::sin(au);
            double cu = std::copysign(1.0 / std::sqrt(fu * fu + m_b0 * m_b0), fu);
            cu = std::clamp(cu, -1.0 + 1e-15, 1.0 - 1e-15);
            double xu = -(cu * m_z0) / std::sqrt(std::max(0.0, 1.0 - cu * cu));
            xu = std::clamp(xu, m_x0, m_x1);
            const double dd = std::sqrt(xu * xu + m_z0 * m_z0);
            const double h0 = m_y0 / std::sqrt(dd * dd + m_y0 * m_y0),
                         h1 = m_y1 / std::sqrt(dd * dd + m_y1 * m_y1);
            const double hv = h0 + u1 * (h1 - h0), hv2 = hv * hv;
            const double yv = hv2 < 1.0 - 1e-14 ? hv * dd / std::sqrt(1.0 - hv2) : m_y1;
            const V local = xu * m_x + std::clamp(yv, m_y0, m_y1) * m_y + m_z0 * m_z;
            if (!finite(local)) return false;
            *w = lighting::safeNormalize(local, m_z);
            *pdf = 1.0 / m_omega;
            return true;
        }
        glm::dvec2 q;
        if (m_disk)
            q = concentricDisk(u0, u1);
        else
            q = {2.0 * u0 - 1.0, 2.0 * u1 - 1.0};
        const V toPoint =
            m_l.position + q.x * m_l.halfWidth * m_l.axisX + q.y * m_l.halfHeight * m_l.axisY - m_P;
        const double d2 = glm::dot(toPoint, toPoint);
        if (!finitePositive(d2)) return false;
        *w = toPoint / std::sqrt(d2);
        const double cosE = std::abs(glm::dot(*w, m_l.direction));
        if (!(cosE > 0.0)) return false;
        *pdf = d2 / (m_area * cosE);
        return finitePositive(*pdf);
    }

    // The density of direction w under sample(): 0 where w misses the emitter.
    double pdf(const V& w) const {
        const double cosW = glm::dot(w, m_l.direction);
        if (cosW == 0.0) return 0.0;
        const double t = glm::dot(m_l.position - m_P, m_l.direction) / cosW;
        if (!finitePositive(t)) return 0.0;
        const V q = m_P + t * w - m_l.position;
        const double u = glm::dot(q, m_l.axisX) / m_l.halfWidth, v = glm::dot(q, m_l.axisY) / m_l.halfHeight;
        const bool inside = m_disk ? u * u + v * v <= 1.0 : std::abs(u) <= 1.0 && std::abs(v) <= 1.0;
        if (!inside) return 0.0;
        if (m_omega > 0.0) return 1.0 / m_omega;
        const double pdf = t * t / (m_area * std::abs(cosW));
        return std::isfinite(pdf) ? pdf : 0.0;
    }

  private:
    const lighting::ShadeLight<double>& m_l;
    V m_P;
    bool m_disk = false;
    double m_area = 0.0, m_omega = 0.0;
    V m_x{1, 0, 0}, m_y{0, 1, 0}, m_z{0, 0, 1};
    double m_x0 = 0, m_y0 = 0, m_z0 = 0, m_x1 = 0, m_y1 = 0;
    double m_g0 = 0, m_g1 = 0, m_g2 = 0, m_g3 = 0, m_b0 = 0, m_b1 = 0;
};

// One light at one surface point: the balance-heuristic estimate of one point (one sample per strategy).
class LightIntegrand {
  public:
    LightIntegrand(const lighting::ShadeLight<double>& l, const lighting::Surface<double>& s,
                   const lighting::ShadeSettings<double>& st)
        : m_l(l), m_s(s), m_st(st), m_emitter(l, s.position), m_pbr(st.model == ShadingModel::Pbr),
          m_v(lighting::viewVector(st, s.position)),
          m_cDiff(m_pbr ? lighting::pbrDiffuseColor(s.albedo, s.metallic) : s.albedo),
          m_f0(m_pbr ? lighting::pbrF0(s.albedo, s.metallic) : s.specular),
          m_alpha(m_pbr ? lighting::pbrAlpha(s.roughness) : 1.0),
          m_lobe(s.normal, m_v, m_pbr, m_alpha, st.specular,
                 s.shininess > 0.0 ? std::min(s.shininess, 1e6) : 0.0) {
        m_scale = m_pbr ? 1.0 : 1.0 / kPi;
        m_useLobe = maxOf(l.specular) > 0.0 && (m_pbr || maxOf(s.specular) > 0.0);
        m_useCosine = maxOf(l.color) > 0.0 && maxOf(m_cDiff) > 0.0;
    }

    V point(const std::array<double, 6>& u) const {
        V y(0.0), w;
        double pdf;
        if (m_emitter.sample(u[0], u[1], &w, &pdf)) y += weighted(w, pdf, pdf);
        if (m_useLobe) {
            w = m_lobe.sample(u[2], u[3]);
            if (const double pe = m_emitter.pdf(w); pe > 0.0) y += weighted(w, pe, m_lobe.pdf(w));
        }
        if (m_useCosine) {
            w = montecarlo::around(m_s.normal, std::sqrt(std::max(0.0, 1.0 - u[4])), 2.0 * kPi * u[5]);
            if (const double pe = m_emitter.pdf(w); pe > 0.0) y += weighted(w, pe, cosinePdf(w));
        }
        return finite(y) ? y : V(0.0);
    }

  private:
    V f(const V& w) const {
        return lighting::directionalResponse(m_l, m_s, m_st, m_v, w, m_cDiff, m_f0, m_alpha) * m_scale;
    }
    double cosinePdf(const V& w) const { return std::max(0.0, glm::dot(m_s.normal, w)) / kPi; }
    // f(w)/p × the power heuristic's weight p² / Σ p_j² (Veach 1997; β = 2), p the density of the strategy
    // that drew w, pe the emitter's. The balance heuristic (β = 1) left a rarely successful strategy a
    // share it seldom collected: a small far disk's cosine samples hit it once in 200, and runs that
    // stopped before one did were 0.5 % low with a standard error of 0.05 %.
    V weighted(const V& w, double pe, double p) const {
        double sum = pe * pe;
        if (m_useLobe) sum += sq(m_lobe.pdf(w));
        if (m_useCosine) sum += sq(cosinePdf(w));
        return sum > 0.0 ? f(w) * (p / sum) : V(0.0);
    }
    static double sq(double x) { return x * x; }

    const lighting::ShadeLight<double>& m_l;
    const lighting::Surface<double>& m_s;
    const lighting::ShadeSettings<double>& m_st;
    Emitter m_emitter;
    bool m_pbr;
    V m_v, m_cDiff, m_f0;
    double m_alpha, m_scale = 1.0;
    montecarlo::SpecularLobe m_lobe;
    bool m_useLobe = false, m_useCosine = false;
};

} // namespace

envintegrate::Convergence defaultConvergence(double exposureEV, ToneMap toneMap) {
    envintegrate::Convergence c;
    c.exposureEV = exposureEV;
    c.toneMap = toneMap;
    c.targetLevels = 0.5;
    // 16 × 2 = 32 points a batch, 64 to 16,384 per light. Fewer replicates (8) made the standard error itself
    // too noisy: stopping at the first batch whose estimate fell below the target then picked the
    // underestimates (a plane under a rect: 20 % of pixels more than a level off at a stated 0.5).
    c.replicates = 16;
    c.batch = 2;
    c.minBatches = 2;
    c.maxBatches = 512;
    return c;
}

bool reaches(const lighting::ShadeLight<double>& l, const lighting::Surface<double>& s) {
    if (!seesEmitter(l, s.position)) return false;
    if (!(maxOf(l.color) > 0.0) && !(maxOf(l.specular) > 0.0)) return false;
    if (l.diffuse == DiffuseModel::HalfLambert) return true;
    // The emitter's highest point above the surface's plane (a rect's corner; a disk's rim).
    const V& N = s.normal;
    const double ax = l.halfWidth * glm::dot(l.axisX, N), ay = l.halfHeight * glm::dot(l.axisY, N);
    const double reach =
        l.type == LightType::Disk ? std::sqrt(ax * ax + ay * ay) : std::abs(ax) + std::abs(ay);
    return glm::dot(l.position - s.position, N) + reach > 0.0;
}

Estimate integrate(std::span<const lighting::ShadeLight<double>> lights, std::span<const double> visibility,
                   const lighting::Surface<double>& s, const lighting::ShadeSettings<double>& st,
                   std::uint64_t seed, const envintegrate::Convergence& conv, const V& rest,
                   std::vector<V>* direct) {
    Estimate e;
    if (direct) direct->assign(lights.size(), V(0.0));
    // Barn doors (core/barndoors.h): the part of each emitter this point sees is one rectangle, which is
    // integrated as the emitter (exactly the flaps' cut).
    std::vector<lighting::ShadeLight<double>> seen(lights.begin(), lights.end());
    for (auto& l : seen)
        l = barndoors::visiblePart(l, s.position);
    std::vector<size_t> active;
    for (size_t k = 0; k < seen.size(); ++k)
        if (reaches(seen[k], s)) active.push_back(k);
    if (active.empty()) return e;
    const auto visible = [&](size_t k) { return k < visibility.size() ? visibility[k] : 1.0; };
    std::vector<LightIntegrand> integrands;
    integrands.reserve(active.size());
    for (size_t k : active)
        integrands.emplace_back(seen[k], s, st);

    const int replicates = std::max(2, conv.replicates), perBatch = std::max(1, conv.batch);
    const size_t na = active.size(), nr = size_t(replicates);
    montecarlo::Rng rng(seed);
    std::vector<std::array<double, 6>> shift(na * nr);
    for (auto& sh : shift)
        for (double& x : sh)
            x = rng.next();
    const std::array<double, 6>& alpha = montecarlo::rSequence6();
    std::vector<V> sums(na * nr, V(0.0)), mean(na, V(0.0));
    int points = 0;
    e.converged = false;
    for (int b = 0; b < std::max(1, conv.maxBatches); ++b) {
        for (size_t a = 0; a < na; ++a)
            for (size_t r = 0; r < nr; ++r)
                for (int i = points; i < points + perBatch; ++i) {
                    std::array<double, 6> u;
                    for (size_t j = 0; j < 6; ++j) {
                        const double x = shift[a * nr + r][j] + double(i + 1) * alpha[j];
                        u[j] = std::min(x - std::floor(x), 0x1.fffffffffffffp-1);
                    }
                    sums[a * nr + r] += integrands[a].point(u);
                }
        points += perBatch;
        V total(0.0), variance(0.0);
        for (size_t a = 0; a < na; ++a) {
            V m(0.0), sq(0.0);
            for (size_t r = 0; r < nr; ++r) {
                const V x = sums[a * nr + r] / double(points);
                m += x, sq += x * x;
            }
            m /= double(nr);
            const V var = glm::max(sq - double(nr) * m * m, V(0.0)) / double(nr - 1) / double(nr);
            const double vis = visible(active[a]);
            mean[a] = m;
            total += vis * m, variance += vis * vis * var;
        }
        e.radiance = total;
        e.standardError = glm::sqrt(variance);
        e.errorLevels = envintegrate::displayErrorLevels(rest + total, e.standardError, conv);
        if (b + 1 >= conv.minBatches && e.errorLevels <= conv.targetLevels) {
            e.converged = true;
            break;
        }
    }
    e.samples = points * replicates * int(na);
    if (direct)
        for (size_t a = 0; a < na; ++a)
            (*direct)[active[a]] = mean[a];
    return e;
}

Estimate integrateOne(const lighting::ShadeLight<double>& l, const lighting::Surface<double>& s,
                      const lighting::ShadeSettings<double>& st, std::uint64_t seed,
                      const envintegrate::Convergence& convergence, const V& rest) {
    return integrate(std::span<const lighting::ShadeLight<double>>(&l, 1), {}, s, st, seed, convergence,
                     rest);
}

} // namespace lr::areaintegrate
