#include "envbrdf.h"

#include "lighting.h"
#include "lowdiscrepancy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lr::envbrdf {

namespace {

using lighting::kPi;

double ggx(double nh, double a) {
    if (!(nh > 0.0)) return 0.0;
    const double a2 = a * a, k = nh * nh * (a2 - 1.0) + 1.0;
    return a2 / (kPi * k * k);
}

double schlickWeight(double vh) {
    const double m = 1.0 - std::clamp(vh, 0.0, 1.0);
    return m * m * m * m * m;
}

} // namespace

double alphaOf(double roughness) {
    return lighting::pbrAlpha(roughness);
}

Dfg integrate(double nDotV, double roughness, int samples) {
    const double nv = std::clamp(nDotV, 1e-5, 1.0);
    const double a = alphaOf(roughness), a2 = a * a;
    // n = +z, v in the xz plane.
    const double vx = std::sqrt(std::max(0.0, 1.0 - nv * nv)), vz = nv;
    // Smith's G1(v) for GGX: 2 n·v / (n·v + √(α² + (1 − α²) n·v²)).
    const double g1v = 2.0 * nv / (nv + std::sqrt(a2 + (1.0 - a2) * nv * nv));
    // The visible-normal sampling frame (Heitz 2018): v stretched by α; T1 ⟂ to it in the xy plane.
    const double shx = a * vx, shz = vz, shn = std::sqrt(shx * shx + shz * shz);
    const double wx = shx / shn, wz = shz / shn; // Vh (y = 0)
    // T1 = (−Vh.y, Vh.x, 0)/|..| = (0, 1, 0) when Vh.x > 0, else (1, 0, 0); T2 = Vh × T1.
    const bool tilted = wx > 1e-12;
    const double t1x = tilted ? 0.0 : 1.0, t1y = tilted ? 1.0 : 0.0;
    const double t2x = tilted ? -wz : 0.0, t2y = tilted ? 0.0 : wz, t2z = tilted ? wx : 0.0;
    Dfg out;
    for (int i = 0; i < samples; ++i) {
        const double u1 = (i + 0.5) / samples, u2 = radicalInverse2(std::uint32_t(i));
        const double phi = 2.0 * kPi * u2, r = std::sqrt(u1);
        // GGX visible normals: pdf(l) = G1(v) D(h) / (4 n·v), so f·cos/pdf = 4 V (n·l)(n·v) / G1(v) (the
        // distribution's own variance is gone: converges at grazing angles too, unlike sampling D).
        const double p1 = r * std::cos(phi), s = 0.5 * (1.0 + wz);
        const double p2 = (1.0 - s) * std::sqrt(std::max(0.0, 1.0 - p1 * p1)) + s * r * std::sin(phi);
        const double p3 = std::sqrt(std::max(0.0, 1.0 - p1 * p1 - p2 * p2));
        double hx = p1 * t1x + p2 * t2x + p3 * wx, hy = p1 * t1y + p2 * t2y, hz = p2 * t2z + p3 * wz;
        hx *= a, hy *= a, hz = std::max(0.0, hz);
        const double hn = std::sqrt(hx * hx + hy * hy + hz * hz);
        if (hn > 0.0) {
            hx /= hn, hz /= hn;
            const double vh = vx * hx + vz * hz;
            const double lz = 2.0 * vh * hz - vz; // l = 2(v·h)h − v
            if (lz > 0.0 && vh > 0.0) {
                const double g = 4.0 * lighting::smithVisibility(std::min(lz, 1.0), nv, a) * lz * nv / g1v;
                const double w = schlickWeight(vh);
                out.scale += (1.0 - w) * g;
                out.bias += w * g;
            }
        }
        // Cosine-weighted l for W: (1/π)∫ (1 − w) cos dω = E[1 − w].
        const double lx = r * std::cos(phi), ly = r * std::sin(phi), lz2 = std::sqrt(std::max(0.0, 1.0 - u1));
        const double hx2 = lx + vx, hz2 = lz2 + vz;
        const double hn2 = std::sqrt(hx2 * hx2 + ly * ly + hz2 * hz2);
        const double vh2 = hn2 > 0.0 ? (vx * hx2 + vz * hz2) / hn2 : 1.0;
        out.diffuse += 1.0 - schlickWeight(vh2);
    }
    out.scale /= samples;
    out.bias /= samples;
    out.diffuse /= samples;
    return out;
}

Dfg quadrature(double nDotV, double roughness, int steps) {
    const double nv = std::clamp(nDotV, 1e-5, 1.0);
    const double a = alphaOf(roughness);
    const double vx = std::sqrt(std::max(0.0, 1.0 - nv * nv)), vz = nv;
    const int nt = steps, np = 4 * steps;
    const double dt = 0.5 * kPi / nt, dp = 2.0 * kPi / np;
    Dfg out;
    for (int i = 0; i < nt; ++i) {
        const double t = (i + 0.5) * dt, st = std::sin(t), ct = std::cos(t);
        for (int j = 0; j < np; ++j) {
            const double p = (j + 0.5) * dp;
            const double lx = st * std::cos(p), ly = st * std::sin(p), lz = ct;
            double hx = lx + vx, hy = ly, hz = lz + vz;
            const double hn = std::sqrt(hx * hx + hy * hy + hz * hz);
            if (!(hn > 0.0)) continue;
            hx /= hn, hy /= hn, hz /= hn;
            const double vh = vx * hx + vz * hz;
            const double w = schlickWeight(vh);
            const double dw = st * dt * dp;
            const double spec = ggx(hz, a) * lighting::smithVisibility(lz, nv, a) * lz * dw;
            out.scale += (1.0 - w) * spec;
            out.bias += w * spec;
            out.diffuse += (1.0 - w) * lz * dw / kPi;
        }
    }
    return out;
}

std::vector<glm::vec3> dfgLut(int size, int samples) {
    std::vector<glm::vec3> out(size_t(size) * size_t(size));
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const Dfg d = integrate((i + 0.5) / size, (j + 0.5) / size, samples);
            out[size_t(j) * size_t(size) + size_t(i)] =
                glm::vec3(float(d.scale), float(d.bias), float(d.diffuse));
        }
    return out;
}

} // namespace lr::envbrdf
