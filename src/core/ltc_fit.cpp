// The LTC fit (ltc.h): our own implementation from the paper's description (Heitz, Dupuy, Hill and
// Neubelt 2016, section 4): per cell, the BRDF's norm and Fresnel integrals by importance sampling, then
// M's shape (a, b, c; its pole fixed at the BRDF's mean direction) by Nelder-Mead minimising the L¹ distance
// between the lobe as shaded (the LTC above the horizon, renormalised: Matrix::aboveHorizon) and the
// normalised BRDF × cosine, estimated with fixed stratified samples of both distributions (balance
// heuristic), so that the objective is a smooth function of M. No published table is used.
// The L¹ distance, not the paper's L³: it bounds the error of the integral over any polygon, which is what
// the shading computes (|∫P D_ltc − ∫P D| ≤ ∫ |D_ltc − D|); the L³ fit matched the peak and lost the tails:
// caps 30–60° above a grazing view's mirror direction came out at a third to a half of the BRDF's.
#include "ltc.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>
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
    // The share of the LTC's mass above the surface's horizon: the clamped cosine's mass on the side of
    // the plane M⁻¹ makes of z = 0, (1 + cos β)/2 for the plane's normal at β from the pole. The shading
    // clips the polygon to the horizon before M⁻¹, so the lobe it integrates is the LTC above the horizon,
    // divided by this share to keep the BRDF's norm.
    double aboveHorizon() const {
        const double nx = -a * std::sin(phi), nz = std::cos(phi) - b * std::sin(phi);
        const double l = std::sqrt(nx * nx + nz * nz);
        return l > 0 ? 0.5 * (1 + nz / l) : 0.5;
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

// ∫ |lobe − f/norm| dω by the balance heuristic over both sample sets.
double objective(const Cell& cell, const Matrix& m, const std::vector<Sample>& brdfSamples, int s,
                 double norm) {
    if (!(m.a > 1e-7) || !(m.c > 1e-7)) return 1e300;
    const double share = m.aboveHorizon();
    if (!(share > 1e-3)) return 1e300;
    // The lobe as shaded: the LTC above the horizon, renormalised (its density is also the LTC samples' pdf).
    const auto lobe = [&](const V3& w, double density) { return w.z > 0 ? density / share : 0.0; };
    double sum = 0;
    for (const Sample& x : brdfSamples) {
        const double dl = m.density(x.w);
        const double e = std::abs(lobe(x.w, dl) - x.f / norm);
        sum += e / (x.pdf + dl);
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
            const double e = std::abs(lobe(w, dl) - f / norm);
            if (pdf + dl > 0) sum += e / (pdf + dl);
        }
    return sum / double(s * s);
}

// Nelder-Mead from x0 with the simplex's first steps along each axis; stops when the simplex's values agree
// to 1e-9 relative or after 500 iterations.
template <size_t N> struct Minimum {
    std::array<double, N> x;
    double f;
};

template <size_t N, typename F>
Minimum<N> nelderMead(const std::array<double, N>& x0, const std::array<double, N>& steps, const F& eval) {
    using P = std::array<double, N>;
    std::array<P, N + 1> x;
    std::array<double, N + 1> fx;
    x[0] = x0;
    for (size_t k = 0; k < N; ++k) {
        x[k + 1] = x0;
        x[k + 1][k] += steps[k];
    }
    for (size_t k = 0; k <= N; ++k)
        fx[k] = eval(x[k]);
    for (int iter = 0; iter < 500; ++iter) {
        std::array<size_t, N + 1> idx;
        for (size_t k = 0; k <= N; ++k)
            idx[k] = k;
        std::sort(idx.begin(), idx.end(), [&](size_t l, size_t r) { return fx[l] < fx[r]; });
        const size_t best = idx[0], worst = idx[N], second = idx[N - 1];
        if (fx[worst] - fx[best] <= 1e-9 * std::abs(fx[best])) break;
        P centre{};
        for (size_t k = 0; k < N; ++k)
            for (size_t e = 0; e < N; ++e)
                centre[e] += x[idx[k]][e] / double(N);
        const auto along = [&](double t) {
            P p;
            for (size_t e = 0; e < N; ++e)
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
                for (size_t k = 1; k <= N; ++k) {
                    for (size_t e = 0; e < N; ++e)
                        x[idx[k]][e] = (x[idx[k]][e] + x[best][e]) / 2;
                    fx[idx[k]] = eval(x[idx[k]]);
                }
            }
        }
    }
    const size_t best = size_t(std::min_element(fx.begin(), fx.end()) - fx.begin());
    return {x[best], fx[best]};
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
    // Nelder-Mead over (a, b, c) from the neighbour's shape; φ stays the BRDF's mean direction (fitting it
    // too let the pole drift at grazing views into local minima: at roughness 0.2, 30° from the horizon,
    // a cap's integral came out 6 to 25 times the BRDF's).
    const double minStep = 0.05 * std::min(start.a, start.c);
    const auto step = [&](double v) { return std::max(0.1 * std::abs(v), minStep); };
    const auto best = nelderMead<3>(
        {start.a, start.b, start.c}, {step(start.a), step(start.b), step(start.c)}, [&](const auto& p) {
            return objective(cell, Matrix{p[0], p[1], p[2], out.phi}, set, samples, norm);
        });
    out.a = best.x[0], out.b = best.x[1], out.c = best.x[2];
    out.error = best.f;
    out.horizon = Matrix{out.a, out.b, out.c, out.phi}.aboveHorizon();
    return out;
}

std::array<float, kLtcSize * kLtcSize * kLtcFloats> fitTable(void (*progress)(int row)) {
    std::array<float, kLtcSize * kLtcSize * kLtcFloats> table{};
    // First the cells at N·V = 1, roughness 1 down to the floor, each from the one before (the lobe
    // narrows with α: its shape scaled); then each roughness's column from its N·V = 1 cell, the columns
    // on as many threads as there are cores. The same warm starts in the same order as one thread.
    std::array<Fit, kLtcSize> heads;
    Fit start; // roughness 1, N·V = 1: close to the cosine itself
    for (int i = kLtcSize - 1; i >= 0; --i) {
        if (i < kLtcSize - 1) {
            const double k = alphaOf(i) / alphaOf(i + 1);
            start.a *= k, start.c *= k;
        }
        heads[size_t(i)] = fitCell(i, 0, start);
        start = heads[size_t(i)];
    }
    const auto store = [&](int i, int j, const Fit& f) {
        const std::array<double, 4> inv = f.inverse();
        float* cell = &table[size_t((j * kLtcSize + i) * kLtcFloats)];
        for (int k = 0; k < 4; ++k)
            cell[k] = float(inv[size_t(k)]);
        cell[4] = float(f.scale / f.horizon);
        cell[5] = float(f.bias / f.horizon);
    };
    std::atomic<int> next{kLtcSize - 1};
    std::mutex report;
    const auto work = [&] {
        for (int i = next--; i >= 0; i = next--) {
            Fit previous = heads[size_t(i)];
            store(i, 0, previous);
            for (int j = 1; j < kLtcSize; ++j) {
                previous = fitCell(i, j, previous);
                store(i, j, previous);
            }
            const std::lock_guard lock(report);
            if (progress) progress(i);
        }
    };
    std::vector<std::thread> threads(std::max(1u, std::thread::hardware_concurrency()));
    for (std::thread& t : threads)
        t = std::thread(work);
    for (std::thread& t : threads)
        t.join();
    return table;
}

} // namespace lr::ltc
