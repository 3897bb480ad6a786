#include "lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lr::trace {

bool areaLightFaces(const TraceLight& light, const glm::dvec3& point) {
    const double side = glm::dot(point - light.shade.position, light.shade.direction);
    return light.shade.twoSided ? side != 0.0 : side > 0.0;
}

bool hitAreaLight(const TraceLight& light, const glm::dvec3& origin, const glm::dvec3& dir, double* t) {
    const lighting::ShadeLight<double>& l = light.shade;
    if (!(light.area > 0.0) || !areaLightFaces(light, origin)) return false;
    const double denom = glm::dot(dir, l.direction);
    if (denom == 0.0 || !std::isfinite(denom)) return false;
    const double d = glm::dot(l.position - origin, l.direction) / denom;
    if (!(d > 0.0) || !std::isfinite(d)) return false;
    const glm::dvec3 q = origin + d * dir - l.position;
    const double x = glm::dot(q, l.axisX), y = glm::dot(q, l.axisY);
    const bool inside = l.type == LightType::Disk ? x * x + y * y <= l.halfWidth * l.halfWidth
                                                  : std::abs(x) <= l.halfWidth && std::abs(y) <= l.halfHeight;
    if (!inside) return false;
    *t = d;
    return true;
}

glm::dvec3 sampleAreaLight(const TraceLight& light, double u1, double u2) {
    const lighting::ShadeLight<double>& l = light.shade;
    if (l.type == LightType::Disk) {
        const double r = l.halfWidth * std::sqrt(u1), phi = 2.0 * std::numbers::pi * u2;
        return l.position + r * std::cos(phi) * l.axisX + r * std::sin(phi) * l.axisY;
    }
    return l.position + (2.0 * u1 - 1.0) * l.halfWidth * l.axisX + (2.0 * u2 - 1.0) * l.halfHeight * l.axisY;
}

glm::dvec2 sampleTriangle(double u1, double u2) {
    const double s = std::sqrt(u1);
    return {s * (1.0 - u2), s * u2};
}

void EmissiveTriangles::add(std::uint32_t part, std::vector<Triangle> triangles, double luminance) {
    for (Triangle& t : triangles) {
        const double w = t.area * luminance;
        m_weight.push_back(std::isfinite(w) && w > 0.0 ? w : 0.0);
        m_triangles.push_back(t);
    }
    (void)part;
}

void EmissiveTriangles::finish(std::size_t parts) {
    m_first.assign(parts, -1);
    m_cdf.assign(m_weight.size() + 1, 0.0);
    for (size_t i = 0; i < m_weight.size(); ++i) {
        m_cdf[i + 1] = m_cdf[i] + m_weight[i];
        const Triangle& t = m_triangles[i];
        if (t.part < parts && m_first[t.part] < 0) m_first[t.part] = long(i) - long(t.triangle);
    }
    m_total = m_cdf.back();
}

const EmissiveTriangles::Triangle& EmissiveTriangles::pick(double u, double* probability) const {
    const double target = u * m_total;
    auto it = std::upper_bound(m_cdf.begin() + 1, m_cdf.end(), target);
    size_t i = std::min(size_t(it - m_cdf.begin()) - 1, m_triangles.size() - 1);
    while (i > 0 && !(m_weight[i] > 0.0)) // a zero-weight triangle at the very end of the range
        --i;
    *probability = m_weight[i] / m_total;
    return m_triangles[i];
}

double EmissiveTriangles::areaDensity(std::uint32_t part, std::uint32_t triangle) const {
    if (empty() || part >= m_first.size() || m_first[part] < 0) return 0.0;
    const size_t i = size_t(m_first[part] + long(triangle));
    if (i >= m_weight.size() || !(m_triangles[i].area > 0.0)) return 0.0;
    return m_weight[i] / m_total / m_triangles[i].area;
}

} // namespace lr::trace
