// Camera rays of the path tracer through the raster's own camera (scene/camera.h ViewCamera: its view and
// projection matrices, the field of view clamped as the raster clamps it), so a traced image lines up
// with the raster's pixel for pixel. Pinhole: every ray leaves the eye.
#pragma once

#include "scene/camera.h"

#include <QSize>
#include <glm/mat4x4.hpp>

namespace lr::trace {

class CameraRays {
  public:
    CameraRays(const ViewCamera& camera, QSize size);
    const glm::dvec3& origin() const { return m_eye; }
    // The unit direction through image point (x, y) in pixels, (0, 0) the top-left corner of the image.
    glm::dvec3 direction(double x, double y) const;

  private:
    glm::dvec3 m_eye;
    glm::dmat4 m_inverse; // (projection · view)⁻¹
    double m_width, m_height;
};

} // namespace lr::trace
