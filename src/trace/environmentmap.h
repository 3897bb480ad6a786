// The environment as the path tracer sees it: the rig's image (or the rendered procedural studio, with its
// softboxes) × 2^intensity, turned by its rotation, piecewise constant per texel exactly as the reference
// defines it (core/envintegrate.h radianceAt: the texel a direction's cell lies in). Importance sampled by
// luminance × solid angle: a marginal CDF over the rows and a conditional CDF within each row, a uniform
// point in the chosen texel's (u, v) cell; pdf() is the exact density of that choice per steradian.
// Non-finite or negative texels count as black.
#pragma once

#include "core/environment.h"

#include <glm/vec3.hpp>
#include <vector>

namespace lr::trace {

class EnvironmentMap {
  public:
    EnvironmentMap() = default;
    EnvironmentMap(const EnvironmentImage& image, double intensityEV, double rotationDegrees);

    bool isBlack() const { return !(m_total > 0.0); }
    // The radiance arriving from a world direction (unit), linear.
    glm::dvec3 radiance(const glm::dvec3& direction) const;
    // A direction drawn by luminance (u1, u2, u3 uniform in [0, 1)) and its density per steradian; false
    // for a black environment.
    bool sample(double u1, double u2, double u3, glm::dvec3* direction, double* pdf) const;
    double pdf(const glm::dvec3& direction) const;
    std::size_t bytes() const;

  private:
    int texelIndex(const glm::dvec3& direction, int* x, int* y) const;
    double densityOf(int x, int y, double cosLatitude) const;

    int m_width = 0, m_height = 0;
    double m_rotation = 0.0;
    std::vector<glm::vec3> m_radiance; // scaled, sanitised
    std::vector<double> m_rowCdf;      // m_height + 1 entries, 0 ... 1
    std::vector<double> m_columnCdf;   // per row, m_width + 1 entries each
    std::vector<double> m_texelWeight; // luminance × solid angle, per texel
    double m_total = 0.0;              // sum of m_texelWeight
};

} // namespace lr::trace
