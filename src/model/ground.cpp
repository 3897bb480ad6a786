#include "ground.h"

#include "core/rig.h"

namespace lr {

GroundPlane groundPlane(const Bounds& bounds) {
    GroundPlane g;
    const double half = 0.5 * kGroundExtent * bounds.radius();
    const glm::dvec3 c = bounds.center();
    g.height = bounds.min.y;
    g.corners = {glm::dvec3(c.x - half, g.height, c.z + half), glm::dvec3(c.x + half, g.height, c.z + half),
                 glm::dvec3(c.x + half, g.height, c.z - half), glm::dvec3(c.x - half, g.height, c.z - half)};
    return g;
}

} // namespace lr
