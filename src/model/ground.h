// The ground plane's geometry (issue 14): one definition for the renderer, which draws it, and the
// double-precision reference, which traces shadow rays against it. Rig::ground says whether it is there
// and how it looks; this says where: horizontal (normal +Y, the world's up after import's up-axis
// correction), at the model's lowest point, a square kGroundExtent model radii wide about the model's
// centre, so it never moves while lights or the camera do.
#pragma once

#include "model.h"

#include <array>
#include <glm/vec3.hpp>

namespace lr {

struct GroundPlane {
    std::array<glm::dvec3, 4> corners; // world, counter-clockwise seen from above (+Y)
    glm::dvec3 normal{0.0, 1.0, 0.0};
    double height = 0.0; // world y of the plane
};

// The plane under `bounds` (Model::bounds). An empty model (radius 1 at the origin) gets a plane at y = 0.
GroundPlane groundPlane(const Bounds& bounds);

} // namespace lr
