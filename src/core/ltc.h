// Linearly Transformed Cosines (Heitz, Dupuy, Hill and Neubelt 2016) fitted to LightRig's own GGX BRDF
// (lighting.h pbrLobes: GGX D × height-correlated Smith visibility × N·L, glTF Appendix B), Fresnel
// split off as Hill's two scalars so that the table does not depend on F0:
//   ∫Ω F D V (N·L) dω ≈ (F0·scale + bias) · ∫Ω D_ltc(ω) dω,   scale = ∫ (1 − w) D V N·L,  bias = ∫ w D V N·L
// over the hemisphere, w = (1 − V·H)^5 (Schlick's weight). D_ltc is the clamped cosine transformed by
//   M = | m00  0  m02 |
//       |  0  m11  0  |      in the frame (T1, T2, N), V = (sin θv, 0, cos θv),
//       | m20  0  m22 |
// and the polygon integral is the clipped-cosine integral of the polygon, clipped to the horizon, transformed
// by M⁻¹. The fit writes M = R(φ)·S, R turning about y to the BRDF's mean direction φ, S = [[a, 0, b],
// [0, c, 0], [0, 0, 1]]. Clipping to the horizon first leaves h < 1 of the LTC's mass (at grazing views a
// lobe about the mirror direction reaches below it): the table's scale and bias are the integrals above
// divided by h, so that the whole hemisphere gives the BRDF's norm.
//
// The table: kLtcSize × kLtcSize cells, cell (i, j) at perceptual roughness
// r = kMinRoughness + (1 − kMinRoughness)·i/(kLtcSize − 1) and N·V = 1 − (j/(kLtcSize − 1))² (x: roughness,
// y: sqrt(1 − N·V)); each cell holds M⁻¹ up to scale as (m00, m02, m20, m22) with m11 = 1 (m01 = m10 =
// m12 = m21 = 0), then (scale, bias). Sampled with bilinear interpolation of those six numbers (as the GPU's
// linear filtering). tools/ltcfit writes ltc_table.cpp (docs/lighting-models.md "Area lights").
#pragma once

#include "lighting.h"

#include <array>
#include <cmath>

namespace lr::ltc {

constexpr int kLtcSize = 64;
constexpr int kLtcFloats = 6; // m00, m02, m20, m22 of M⁻¹ (m11 = 1), scale, bias

// The cell's parameters.
double cellRoughness(int i);
double cellNDotV(int j);

// One fitted cell: S's entries, the mean direction's angle φ (from N towards +x), the Fresnel integrals
// and the fit's residual (the L³ error).
struct Fit {
    double a = 1, b = 0, c = 1, phi = 0;
    double scale = 0, bias = 0;
    double horizon = 1; // the share of the LTC's mass above the horizon (Matrix::aboveHorizon)
    double error = 0;
    std::array<double, 4> inverse() const; // (m00, m02, m20, m22) of M⁻¹ / m11(M⁻¹)
};

// Fits cell (i, j) by Nelder-Mead from `start` (the neighbour's fit; the identity for the first cell).
// `samples`² stratified samples of each of the two sampling strategies (the BRDF's and the LTC's).
Fit fitCell(int i, int j, const Fit& start, int samples = 24);

// The whole table in the order tools/ltcfit fits it (roughness 1 to the floor, each row from N·V = 1,
// each cell warm-started from its neighbour): kLtcSize² × kLtcFloats floats, row-major (j, i).
std::array<float, kLtcSize * kLtcSize * kLtcFloats> fitTable(void (*progress)(int row) = nullptr);

// The generated table (ltc_table.cpp).
const float* ltcTable();

// The share h of the LTC's mass above the horizon for M⁻¹'s (m00, m20) (any positive scale): the
// clamped cosine's mass on the positive side of the plane whose normal is M's last row, ∝ (−m20, 0, m00),
// at β from the pole: (1 + cos β)/2. The table's scale and bias are the BRDF's integrals divided by it.
inline double horizonShare(double m00, double m20) {
    const double l = std::hypot(m00, m20);
    return l > 0 ? 0.5 * (1 + m00 / l) : 0.5;
}

// The six numbers at (alpha, nDotV), bilinear between cells, the coordinates clamped to the table.
template <typename T> struct Lookup { T m00, m02, m20, m22, scale, bias; };

template <typename T> Lookup<T> lookup(T alpha, T nDotV) {
    const T r = std::sqrt(lighting::positive(alpha));
    const T u = lighting::saturate((r - T(lighting::kMinRoughness)) / T(1 - lighting::kMinRoughness));
    const T v = std::sqrt(lighting::saturate(T(1) - nDotV));
    const T x = u * T(kLtcSize - 1), y = v * T(kLtcSize - 1);
    const int i0 = std::min(int(x), kLtcSize - 2), j0 = std::min(int(y), kLtcSize - 2);
    const T fx = x - T(i0), fy = y - T(j0);
    const float* t = ltcTable();
    T o[kLtcFloats];
    for (int k = 0; k < kLtcFloats; ++k) {
        const auto at = [&](int i, int j) { return T(t[(j * kLtcSize + i) * kLtcFloats + k]); };
        const T top = at(i0, j0) + (at(i0 + 1, j0) - at(i0, j0)) * fx;
        const T bottom = at(i0, j0 + 1) + (at(i0 + 1, j0 + 1) - at(i0, j0 + 1)) * fx;
        o[k] = top + (bottom - top) * fy;
    }
    return {o[0], o[1], o[2], o[3], o[4], o[5]};
}

} // namespace lr::ltc
