#include "environmentmap.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lr::trace {

namespace {

// The first index i with cdf[i + 1] > u, over cdf of n + 1 non-decreasing entries from 0 to 1.
int pick(const double* cdf, int n, double u) {
    const double* it = std::upper_bound(cdf + 1, cdf + n + 1, u);
    return std::clamp(int(it - cdf) - 1, 0, n - 1);
}

} // namespace

EnvironmentMap::EnvironmentMap(const EnvironmentImage& image, double intensityEV, double rotationDegrees)
    : m_width(image.width), m_height(image.height), m_rotation(rotationDegrees) {
    if (image.isNull() || image.texels.size() < size_t(m_width) * size_t(m_height)) {
        m_width = m_height = 0;
        return;
    }
    const double scale = std::exp2(std::clamp(std::isfinite(intensityEV) ? intensityEV : 0.0, -60.0, 60.0));
    const size_t n = size_t(m_width) * size_t(m_height);
    m_radiance.resize(n);
    m_texelWeight.resize(n);
    m_rowCdf.assign(size_t(m_height) + 1, 0.0);
    m_columnCdf.assign(size_t(m_height) * size_t(m_width + 1), 0.0);
    for (int y = 0; y < m_height; ++y) {
        const double omega = environment::texelSolidAngle(y, m_width, m_height);
        double* cdf = m_columnCdf.data() + size_t(y) * size_t(m_width + 1);
        double row = 0.0;
        for (int x = 0; x < m_width; ++x) {
            const size_t i = size_t(y) * size_t(m_width) + size_t(x);
            glm::vec3 c = image.texels[i];
            for (int k = 0; k < 3; ++k)
                c[k] =
                    std::isfinite(c[k]) && c[k] > 0.0f ? float(std::min(double(c[k]) * scale, 3.0e37)) : 0.0f;
            m_radiance[i] = c;
            const double w = std::max(0.0, environment::luminance(c)) * omega;
            m_texelWeight[i] = std::isfinite(w) ? w : 0.0;
            row += m_texelWeight[i];
            cdf[x + 1] = row;
        }
        for (int x = 1; x <= m_width; ++x)
            cdf[x] = row > 0.0 ? cdf[x] / row : double(x) / m_width;
        m_rowCdf[size_t(y) + 1] = m_rowCdf[size_t(y)] + row;
    }
    m_total = m_rowCdf.back();
    for (double& c : m_rowCdf)
        c = m_total > 0.0 ? c / m_total : 0.0;
}

int EnvironmentMap::texelIndex(const glm::dvec3& direction, int* x, int* y) const {
    const glm::dvec2 uv = environment::equirectUv(direction, m_rotation);
    *x = std::clamp(int(std::floor(uv.x * m_width)), 0, m_width - 1);
    *y = std::clamp(int(std::floor(uv.y * m_height)), 0, m_height - 1);
    return *y * m_width + *x;
}

glm::dvec3 EnvironmentMap::radiance(const glm::dvec3& direction) const {
    if (m_width <= 0) return glm::dvec3(0.0);
    int x, y;
    return glm::dvec3(m_radiance[size_t(texelIndex(direction, &x, &y))]);
}

// The density per steradian of a direction in texel (x, y) at latitude cos: the texel's probability
// spread uniformly over its (u, v) cell, whose solid angle element is (2π/W)(π/H) cos(latitude) per unit
// of cell area.
double EnvironmentMap::densityOf(int x, int y, double cosLatitude) const {
    const double p = m_texelWeight[size_t(y) * size_t(m_width) + size_t(x)] / m_total;
    const double cellSolidAngle =
        (2.0 * std::numbers::pi / m_width) * (std::numbers::pi / m_height) * std::max(cosLatitude, 1e-12);
    return p / cellSolidAngle;
}

bool EnvironmentMap::sample(double u1, double u2, double u3, glm::dvec3* direction, double* pdf) const {
    if (isBlack()) return false;
    const int y = pick(m_rowCdf.data(), m_height, u1);
    const double* cdf = m_columnCdf.data() + size_t(y) * size_t(m_width + 1);
    const int x = pick(cdf, m_width, u2);
    const double u = (x + u3) / m_width;
    // Within the row, v uniform in the cell: reuse the row choice's remainder (stratified, cheap).
    const double lo = m_rowCdf[size_t(y)], hi = m_rowCdf[size_t(y) + 1];
    const double fv = hi > lo ? std::clamp((u1 - lo) / (hi - lo), 0.0, 0.999999) : 0.5;
    const double v = (y + fv) / m_height;
    *direction = environment::equirectDirection(u, v, m_rotation);
    const double latitude = (0.5 - v) * std::numbers::pi;
    *pdf = densityOf(x, y, std::cos(latitude));
    return *pdf > 0.0 && std::isfinite(*pdf);
}

double EnvironmentMap::pdf(const glm::dvec3& direction) const {
    if (isBlack()) return 0.0;
    int x, y;
    texelIndex(direction, &x, &y);
    const double cosLatitude = std::sqrt(std::max(0.0, 1.0 - direction.y * direction.y));
    return densityOf(x, y, cosLatitude);
}

std::size_t EnvironmentMap::bytes() const {
    return m_radiance.size() * sizeof(glm::vec3) +
           (m_rowCdf.size() + m_columnCdf.size() + m_texelWeight.size()) * sizeof(double);
}

} // namespace lr::trace
