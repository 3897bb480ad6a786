// The LTC fit (ltc.h): our own implementation from the paper's description (Heitz, Dupuy, Hill and
// Neubelt 2016, section 4): per cell, the BRDF's norm and Fresnel integrals by importance sampling, then
// M's four free entries by Nelder-Mead minimising the L³ distance between the LTC distribution and the
// normalised BRDF × cosine, estimated with fixed stratified samples of both distributions (balance
// heuristic), so that the objective is a smooth function of M. No published table is used.
#include "ltc.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lr::ltc {

namespace {

using V3 = lighting::Vec3<double>;
constexpr double kPi = lighting::kPi;
constexpr int kNormSamples = 96; // per axis, for scale and bias

double alphaOf(int i) {
    const double r = cellRoughness(i);
    return r * r;
}

struct Cell {
    double alpha, nDotV;
    V3 v;
};

// D·V·N·L (no Fresnel) and the BRDF-sampling pdf of ω (GGX normals: D·N·H / (4 |V·H|)).
void brdf(const Cell& c, const V3& w, double* f, double* pdf, double* weight) {
    const V3 N(0, 0, 1);
    const V3 H = lighting::safeNormalize(w + c.v, N);
    const double d = lighting::ggxDistribution(N, H, c.alpha);
    const double vh = std::abs(glm::dot(c.v, H));
    *pdf = vh > 0 ? d * H.z / (4 * vh) : 0;
    *f = w.z > 0 ? d * lighting::smithVisibility(std::min(w.z, 1.0), c.nDotV, c.alpha) * w.z : 0;
    const double m = 1 - std::min(vh, 1.0);
    *weight = m * m * m * m * m;
}

V3 sampleBrdf(const Cell& c, double u1, double u2) {
    const double a2 = c.alpha * c.alpha;
    const double cosT = std::sqrt((1 - u1) / (1 + (a2 - 1) * u1));
    const double sinT = std::sqrt(std::max(0.0, 1 - cosT * cosT));
    const double phi = 2 * kPi * u2;
    const V3 H(sinT * std::cos(phi), sinT * std::sin(phi), cosT);
    return 2 * glm::dot(c.v, H) * H - c.v;
}

// M = R(φ) · S: S = [[a, 0, b], [0, c, 0], [0, 0, 1]] shapes the cosine, R turns its pole about y to the
// BRDF's mean direction (fixed per cell), so that only the lobe's shape is fitted.
struct Matrix {
    double a, b, c, phi;
    V3 apply(const V3& o) const {
        const V3 q(a * o.x + b * o.z, c * o.y, o.z);
        return V3(std::cos(phi) * q.x + std::sin(phi) * q.z, q.y, -std::sin(phi) * q.x + std::cos(phi) * q.z);
    }
    V3 inverse(const V3& w) const {
        const V3 q(std::cos(phi) * w.x - std::sin(phi) * w.z, w.y, std::sin(phi) * w.x + std::cos(phi) * w.z);
        return V3((q.x - b * q.z) / a, q.y / c, q.z);
    }
    // The LTC density at unit ω: D_o(M⁻¹ω/|M⁻¹ω|) · |det M⁻¹| / |M⁻¹ω|³, det M = a·c.
    double density(const V3& w) const {
        const V3 o = inverse(w);
        const double l = std::sqrt(glm::dot(o, o));
        if (!(l > 0)) return 0;
        return std::max(o.z / l, 0.0) / kPi / (a * c * l * l * l);
    }
};

struct Sample {
    V3 w;
    double f, pdf;
};

double objective(const Cell& cell, const Matrix& m, const std::vector<Sample>& brdfSamples, int s,
                 double norm) {
    if (!(m.a > 1e-7) || !(m.c > 1e-7)) return 1e300;
    double sum = 0;
    for (const Sample& x : brdfSamples) {
        const double dl = m.density(x.w);
        const double e = std::abs(dl - x.f / norm);
        sum += e * e * e / (x.pdf + dl);
    }
    for (int p = 0; p < s; ++p)
        for (int q = 0; q < s; ++q) {
            const double u1 = (p + 0.5) / s, u2 = (q + 0.5) / s;
            const double r = std::sqrt(u1), phi = 2 * kPi * u2;
            const V3 o(r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - u1));
            V3 w = m.apply(o);
            w /= std::sqrt(glm::dot(w, w));
            const double dl = m.density(w);
            double f, pdf, weight;
            brdf(cell, w, &f, &pdf, &weight);
            const double e = std::abs(dl - f / norm);
            if (pdf + dl > 0) sum += e * e * e / (pdf + dl);
        }
    return sum / double(s * s);
}

} // namespace

double cellRoughness(int i) {
    return lighting::kMinRoughness + (1 - lighting::kMinRoughness) * double(i) / (kLtcSize - 1);
}

double cellNDotV(int j) {
    const double x = double(j) / (kLtcSize - 1);
    return std::max(1 - x * x, 1e-3);
}

std::array<double, 4> Fit::inverse() const {
    // M⁻¹ = S⁻¹ R(φ)ᵀ, divided by its m11 = 1/c.
    const double cs = std::cos(phi), sn = std::sin(phi);
    return {c * (cs - b * sn) / a, c * (-sn - b * cs) / a, c * sn, c * cs};
}

Fit fitCell(int i, int j, const Fit& start, int samples) {
    const double nv = cellNDotV(j);
    const Cell cell{alphaOf(i), nv, V3(std::sqrt(1 - nv * nv), 0, nv)};
    Fit out = start;
    // Norm and Fresnel integrals: ∫ f (1 − w) and ∫ f w by sampling GGX normals.
    double scale = 0, bias = 0;
    V3 mean(0);
    for (int p = 0; p < kNormSamples; ++p)
        for (int q = 0; q < kNormSamples; ++q) {
            const V3 w = sampleBrdf(cell, (p + 0.5) / kNormSamples, (q + 0.5) / kNormSamples);
            double f, pdf, weight;
            brdf(cell, w, &f, &pdf, &weight);
            if (!(pdf > 0) || !(f > 0)) continue;
            scale += f * (1 - weight) / pdf;
            bias += f * weight / pdf;
            mean += w * (f / pdf);
        }
    out.scale = scale / (kNormSamples * kNormSamples);
    out.bias = bias / (kNormSamples * kNormSamples);
    const double norm = out.scale + out.bias;
    out.phi = std::atan2(mean.x, mean.z);
    std::vector<Sample> set;
    set.reserve(size_t(samples * samples));
    for (int p = 0; p < samples; ++p)
        for (int q = 0; q < samples; ++q) {
            Sample x;
            x.w = sampleBrdf(cell, (p + 0.5) / samples, (q + 0.5) / samples);
            double weight;
            brdf(cell, x.w, &x.f, &x.pdf, &weight);
            if (x.pdf > 0) set.push_back(x);
        }
    // Nelder-Mead over (a, b, c, φ), φ from the mean direction, the shape from the neighbour.
    using P = std::array<double, 4>;
    const auto eval = [&](const P& p) {
        return objective(cell, Matrix{p[0], p[1], p[2], p[3]}, set, samples, norm);
    };
    std::array<P, 5> x;
    std::array<double, 5> fx;
    x[0] = {start.a, start.b, start.c, out.phi};
    const double minStep = 0.05 * std::min(start.a, start.c);
    for (int k = 0; k < 4; ++k) {
        x[size_t(k + 1)] = x[0];
        x[size_t(k + 1)][size_t(k)] += std::max(0.1 * std::abs(x[0][size_t(k)]), minStep);
    }
    for (size_t k = 0; k < 5; ++k)
        fx[k] = eval(x[k]);
    for (int iter = 0; iter < 500; ++iter) {
        std::array<size_t, 5> idx{0, 1, 2, 3, 4};
        std::sort(idx.begin(), idx.end(), [&](size_t l, size_t r) { return fx[l] < fx[r]; });
        const size_t best = idx[0], worst = idx[4], second = idx[3];
        if (fx[worst] - fx[best] <= 1e-9 * std::abs(fx[best])) break;
        P centre{0, 0, 0, 0};
        for (size_t k = 0; k < 4; ++k)
            for (size_t e = 0; e < 4; ++e)
                centre[e] += x[idx[k]][e] / 4;
        const auto along = [&](double t) {
            P p;
            for (size_t e = 0; e < 4; ++e)
                p[e] = centre[e] + t * (x[worst][e] - centre[e]);
            return p;
        };
        const P r = along(-1);
        const double fr = eval(r);
        if (fr < fx[best]) {
            const P ex = along(-2);
            const double fe = eval(ex);
            if (fe < fr)
                x[worst] = ex, fx[worst] = fe;
            else
                x[worst] = r, fx[worst] = fr;
        } else if (fr < fx[second]) {
            x[worst] = r, fx[worst] = fr;
        } else {
            const P ct = fr < fx[worst] ? along(-0.5) : along(0.5);
            const double fc = eval(ct);
            if (fc < std::min(fr, fx[worst])) {
                x[worst] = ct, fx[worst] = fc;
            } else {
                for (size_t k = 1; k < 5; ++k) {
                    for (size_t e = 0; e < 4; ++e)
                        x[idx[k]][e] = (x[idx[k]][e] + x[best][e]) / 2;
                    fx[idx[k]] = eval(x[idx[k]]);
                }
            }
        }
    }
    const size_t best = size_t(std::min_element(fx.begin(), fx.end()) - fx.begin());
    out.a = x[best][0], out.b = x[best][1], out.c = x[best][2], out.phi = x[best][3];
    out.error = fx[best];
    return out;
}

std::array<float, kLtcSize * kLtcSize * kLtcFloats> fitTable(void (*progress)(int row)) {
    std::array<float, kLtcSize * kLtcSize * kLtcFloats> table{};
    Fit rowStart; // roughness 1, N·V = 1: close to the cosine itself
    for (int i = kLtcSize - 1; i >= 0; --i) {
        if (i < kLtcSize - 1) { // the lobe narrows with α: scale the previous row's first cell
            const double k = alphaOf(i) / alphaOf(i + 1);
            rowStart.a *= k, rowStart.c *= k;
        }
        Fit previous = rowStart;
        for (int j = 0; j < kLtcSize; ++j) {
            const Fit f = fitCell(i, j, previous);
            if (j == 0) rowStart = f;
            previous = f;
            const std::array<double, 4> inv = f.inverse();
            float* cell = &table[size_t((j * kLtcSize + i) * kLtcFloats)];
            for (int k = 0; k < 4; ++k)
                cell[k] = float(inv[size_t(k)]);
            cell[4] = float(f.scale);
            cell[5] = float(f.bias);
        }
        if (progress) progress(i);
    }
    return table;
}

} // namespace lr::ltc
