#include "camerarays.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace lr::trace {

CameraRays::CameraRays(const ViewCamera& camera, QSize size)
    : m_eye(camera.eye), m_width(std::max(1, size.width())), m_height(std::max(1, size.height())) {
    ViewCamera c = camera;
    if (!(c.znear > 0.0)) c.znear = 1e-3 * std::max(1e-9, c.distance()); // only the directions matter
    c.zfar = 0.0;                                                        // infinite
    m_inverse = glm::inverse(c.projection(m_width / m_height) * c.view());
}

glm::dvec3 CameraRays::direction(double x, double y) const {
    const double nx = 2.0 * x / m_width - 1.0, ny = 1.0 - 2.0 * y / m_height;
    const glm::dvec4 p = m_inverse * glm::dvec4(nx, ny, 0.0, 1.0);
    const glm::dvec3 d = glm::dvec3(p) / p.w - m_eye;
    const double len = glm::length(d);
    return len > 0.0 ? d / len : glm::dvec3(0.0, 0.0, -1.0);
}

} // namespace lr::trace
