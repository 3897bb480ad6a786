#include "lights.h"

#include "core/barndoors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lr::trace {

bool areaLightSees(const TraceLight& light, const glm::dvec3& from, const glm::dvec3& onEmitter) {
    const lighting::ShadeLight<double>& l = light.shade;
    if (!barndoors::hasBarnDoors(l)) return true;
    const barndoors::Window<double> w = barndoors::visibleWindow(l, from);
    const glm::dvec3 q = onEmitter - l.position;
    const double x = glm::dot(q, l.axisX), y = glm::dot(q, l.axisY);
    return !w.empty() && x >= w.x0 && x <= w.x1 && y >= w.y0 && y <= w.y1;
}

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
    if (barndoors::hasBarnDoors(l)) { // a flap hides the point from the origin outside the window
        const barndoors::Window<double> w = barndoors::visibleWindow(l, origin);
        if (w.empty() || x < w.x0 || x > w.x1 || y < w.y0 || y > w.y1) return false;
    }
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

namespace {

constexpr double kMinSolidAngle = 1e-4; // below this a rect is sampled by area (the mapping loses precision)

// The angle between unit vectors, accurate near 0 and π.
double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::dot(a, b) < 0.0 ? std::numbers::pi - 2.0 * std::asin(std::min(1.0, glm::length(a + b) / 2.0))
                                : 2.0 * std::asin(std::min(1.0, glm::length(b - a) / 2.0));
}

// A rect as seen from a point, in the frame (axisX, axisY, z) at the point, z turned so that the rect's
// plane lies at z0 < 0: its corners' coordinates, the spherical rectangle's solid angle and the constants
// of the sampling (b0, b1, k: Ureña et al.'s names).
struct SphericalRect {
    glm::dvec3 z;
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0, z0 = 0;
    double b0 = 0, b1 = 0, k = 0, solidAngle = 0;
};

SphericalRect sphericalRect(const lighting::ShadeLight<double>& l, const glm::dvec3& from) {
    SphericalRect r;
    r.z = glm::cross(l.axisX, l.axisY);
    const glm::dvec3 d = l.position - l.halfWidth * l.axisX - l.halfHeight * l.axisY - from;
    r.x0 = glm::dot(d, l.axisX), r.y0 = glm::dot(d, l.axisY), r.z0 = glm::dot(d, r.z);
    if (r.z0 > 0.0) r.z = -r.z, r.z0 = -r.z0;
    r.x1 = r.x0 + 2.0 * l.halfWidth, r.y1 = r.y0 + 2.0 * l.halfHeight;
    if (!(r.z0 < 0.0)) return r; // in the rect's plane: it subtends nothing
    const glm::dvec3 v00(r.x0, r.y0, r.z0), v01(r.x0, r.y1, r.z0), v10(r.x1, r.y0, r.z0),
        v11(r.x1, r.y1, r.z0);
    const glm::dvec3 n0 = glm::normalize(glm::cross(v00, v10)), n1 = glm::normalize(glm::cross(v10, v11)),
                     n2 = glm::normalize(glm::cross(v11, v01)), n3 = glm::normalize(glm::cross(v01, v00));
    const double g0 = angleBetween(-n0, n1), g1 = angleBetween(-n1, n2), g2 = angleBetween(-n2, n3),
                 g3 = angleBetween(-n3, n0);
    r.b0 = n0.z, r.b1 = n2.z;
    r.k = 2.0 * std::numbers::pi - g2 - g3;
    r.solidAngle = g0 + g1 + g2 + g3 - 2.0 * std::numbers::pi;
    if (!std::isfinite(r.solidAngle)) r.solidAngle = 0.0;
    return r;
}

} // namespace

AreaLightSample sampleAreaLightFrom(const TraceLight& light, const glm::dvec3& from, double u1, double u2) {
    // Barn doors (core/barndoors.h): the part of the rect `from` sees, sampled as the emitter.
    const lighting::ShadeLight<double> l = barndoors::visiblePart(light.shade, from);
    const double area = barndoors::hasBarnDoors(light.shade) ? 4.0 * l.halfWidth * l.halfHeight : light.area;
    AreaLightSample out;
    if (!(area > 0.0)) return out;
    if (l.type == LightType::Rect) {
        const SphericalRect r = sphericalRect(l, from);
        if (r.solidAngle >= kMinSolidAngle) {
            // Ureña et al. 2013, section 4: the x coordinate from the area u1 of the solid angle, then y.
            const double au = u1 * r.solidAngle + r.k;
            const double fu = (std::cos(au) * r.b0 - r.b1) / std::sin(au);
            double cu = std::copysign(1.0, fu) / std::sqrt(fu * fu + r.b0 * r.b0);
            cu = std::clamp(cu, -1.0 + 1e-12, 1.0 - 1e-12);
            double xu = -(cu * r.z0) / std::sqrt(std::max(0.0, 1.0 - cu * cu));
            xu = std::clamp(std::isfinite(xu) ? xu : r.x0, r.x0, r.x1);
            const double dd = std::sqrt(xu * xu + r.z0 * r.z0);
            const double h0 = r.y0 / std::sqrt(dd * dd + r.y0 * r.y0),
                         h1 = r.y1 / std::sqrt(dd * dd + r.y1 * r.y1);
            const double hv = h0 + u2 * (h1 - h0), hv2 = hv * hv;
            const double yv = hv2 < 1.0 - 1e-12 ? hv * dd / std::sqrt(1.0 - hv2) : r.y1;
            out.point = from + xu * l.axisX + std::clamp(yv, r.y0, r.y1) * l.axisY + r.z0 * r.z;
            out.pdf = 1.0 / r.solidAngle;
            return out;
        }
    }
    out.point = l.type == LightType::Rect ? l.position + (2.0 * u1 - 1.0) * l.halfWidth * l.axisX +
                                                (2.0 * u2 - 1.0) * l.halfHeight * l.axisY
                                          : sampleAreaLight(light, u1, u2);
    const glm::dvec3 d = out.point - from;
    const double dist2 = glm::dot(d, d), cosL = std::abs(glm::dot(d, l.direction)) / std::sqrt(dist2);
    out.pdf = dist2 / (area * cosL);
    if (!std::isfinite(out.pdf) || !(cosL > 0.0)) out.pdf = 0.0;
    return out;
}

double areaLightPdf(const TraceLight& light, const glm::dvec3& from, const glm::dvec3& dir, double t) {
    const lighting::ShadeLight<double> l = barndoors::visiblePart(light.shade, from);
    const double area = barndoors::hasBarnDoors(light.shade) ? 4.0 * l.halfWidth * l.halfHeight : light.area;
    if (!(area > 0.0)) return 0.0;
    if (l.type == LightType::Rect) {
        const SphericalRect r = sphericalRect(l, from);
        if (r.solidAngle >= kMinSolidAngle) return 1.0 / r.solidAngle;
    }
    const double cosL = std::abs(glm::dot(dir, l.direction));
    const double pdf = t * t / (area * cosL);
    return std::isfinite(pdf) && cosL > 0.0 ? pdf : 0.0;
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
