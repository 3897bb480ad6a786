// The hand-built camera the picking and area-gizmo tests share: at (0, 0, 10) looking at the origin, 90°
// vertical field of view, 200×100 pixels (at depth 10 one world unit is 5 pixels), and a point comparison.
#pragma once

#include "app/picking.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lr::test {

inline ScreenProjector frontCamera() {
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 10), glm::dvec3(0), glm::dvec3(0, 1, 0));
    const glm::dmat4 proj = glm::perspective(glm::radians(90.0), 2.0, 0.1, 100.0);
    return ScreenProjector(view, proj, QSizeF(200, 100));
}

inline bool near(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-9) {
    return glm::length(a - b) <= tol;
}

} // namespace lr::test
