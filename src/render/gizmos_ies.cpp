// The IES gizmo (issue 39): the distribution's shape around the light, as a photometric diagram draws it.
#include "gizmos.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace lr::render {

std::vector<std::vector<glm::dvec3>> iesOutline(const Light& light, const IesProfile& profile,
                                                const glm::dvec3& at, double length, int steps) {
    std::vector<std::vector<glm::dvec3>> out;
    if (!(profile.peak > 0.0) || !(length > 0.0) || steps < 2 || !light.ies) return out;
    const glm::dvec3 nadir = lighting::safeNormalize(light.direction, glm::dvec3(0.0, -1.0, 0.0));
    const AreaAxes axes = areaAxes(nadir, light.ies->rotation);
    for (const double plane : {0.0, 90.0}) { // C0-C180, then C90-C270: down one side and up the other
        std::vector<glm::dvec3> curve;
        for (const double phi : {plane, plane + 180.0}) {
            const double p = glm::radians(phi);
            const glm::dvec3 side = axes.x * std::cos(p) + axes.y * std::sin(p);
            for (int k = 0; k <= steps; ++k) {
                const double theta = 180.0 * (phi == plane ? k : steps - k) / steps;
                const double t = glm::radians(theta);
                const glm::dvec3 w = nadir * std::cos(t) + side * std::sin(t);
                curve.push_back(at + w * (length * iesCandela(profile, theta, phi) / profile.peak));
            }
        }
        out.push_back(std::move(curve));
    }
    return out;
}

} // namespace lr::render
