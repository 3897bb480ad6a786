// The lobe window of EnvironmentField::integrate() (envintegrate.h, "Window"): the texels whose centres lie
// within a cone about the lobe's axis, enumerated row by row over the rows and azimuths the cone can reach,
// and summed cell by cell.
#include "envintegrate.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lr::envintegrate {

namespace {
using V = glm::dvec3;
constexpr double kPi = environment::kPi;
} // namespace

bool EnvironmentField::inWindow(const Window& w, int texelIndex) const {
    const size_t y = size_t(texelIndex / m_width), x = size_t(texelIndex % m_width);
    const V centre(m_rowCosLat[y] * m_colCos[x], m_rowSinLat[y], m_rowCosLat[y] * m_colSin[x]);
    return glm::dot(centre, w.axis) >= w.cosHalfAngle;
}

V EnvironmentField::windowSum(const Window& w, const Integrand& f, int subdivide) const {
    const int s = std::max(1, subdivide);
    const double latA = std::asin(std::clamp(w.axis.y, -1.0, 1.0));
    const double phiA = std::atan2(w.axis.z, w.axis.x);
    const bool pole = latA + w.halfAngle >= kPi / 2 || latA - w.halfAngle <= -kPi / 2;
    const double column = 2.0 * kPi / m_width;
    V sum(0.0);
    for (int y = 0; y < m_height; ++y) {
        const double lat = (0.5 - (double(y) + 0.5) / m_height) * kPi;
        if (std::abs(lat - latA) > w.halfAngle * (1.0 + 1e-9) + 1e-12) continue;
        // The azimuths within the cone at this latitude: cos Δ ≥ (cos θ − sin lat sin latA)/(cos lat cos
        // latA).
        int x0 = 0, count = m_width;
        if (!pole) {
            const double c =
                (w.cosHalfAngle - std::sin(lat) * std::sin(latA)) / (std::cos(lat) * std::cos(latA));
            if (c > 1.0 + 1e-9) continue;
            const double delta = std::acos(std::clamp(c, -1.0, 1.0)) + column;
            if (2.0 * delta < 2.0 * kPi) {
                x0 = int(std::floor(((phiA - delta) / (2.0 * kPi) + 0.5) * m_width));
                count = std::min(m_width, int(std::ceil(2.0 * delta / column)) + 2);
            }
        }
        const double latLo = (0.5 - double(y + 1) / m_height) * kPi,
                     latHi = (0.5 - double(y) / m_height) * kPi;
        const double s0 = std::sin(latLo), ds = (std::sin(latHi) - s0) / s;
        for (int i = 0; i < count; ++i) {
            const int x = ((x0 + i) % m_width + m_width) % m_width;
            const int t = y * m_width + x;
            if (!inWindow(w, t)) continue;
            const V L = texel(x, y);
            if (!(luminance(L) > 0.0)) continue;
            const double phi0 = (double(x) / m_width - 0.5) * 2.0 * kPi, dphi = column / s;
            const double omega = dphi * ds;
            for (int j = 0; j < s; ++j) {
                const double sl = s0 + (j + 0.5) * ds;
                const double cl = std::sqrt(std::max(0.0, 1.0 - sl * sl));
                for (int k = 0; k < s; ++k) {
                    const double phi = phi0 + (k + 0.5) * dphi;
                    sum += f(V(cl * std::cos(phi), sl, cl * std::sin(phi)), L) * omega;
                }
            }
        }
    }
    return sum;
}

} // namespace lr::envintegrate
