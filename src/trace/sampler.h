// The path tracer's random numbers: Owen-scrambled Sobol points, shuffled per dimension (Burley 2020,
// "Practical Hash-based Owen Scrambling", JCGT 9(4)), so that the samples of one pixel are stratified in
// every dimension (and in pairs: the pixel position, a light's point, a BSDF direction) while the
// dimensions stay independent of each other. Sample k of pixel p with seed s is a pure function of (p, k, s,
// dimension): the image does not depend on the thread count, the tiles or the passes, and another seed
// gives an independent image.
//
// Dimensions are numbered per bounce (startBounce) and then counted by each draw, so a path whose
// bounces draw different numbers of values never reuses a dimension (a reuse would correlate two
// decisions of one path). Each draw is uniform in [0, 1) on its own.
#pragma once

#include "core/lowdiscrepancy.h"

#include <glm/vec2.hpp>

#include <cstdint>

namespace lr::trace {

class Sampler {
  public:
    Sampler(std::uint32_t pixel, std::uint32_t sample, std::uint32_t seed = 0)
        : m_index(sample), m_key(pcgHash(pixel ^ pcgHash(seed ^ 0x6a09e667u))) {}

    // Dimensions of bounce `depth` (0: the first surface the camera ray meets); the camera's own draws
    // come before any startBounce.
    void startBounce(int depth) { m_dimension = (std::uint32_t(depth) + 1u) << 16; }

    // One uniform number in [0, 1) from a dimension of its own.
    double next() { return next2().x; }

    // Two uniform numbers in [0, 1), stratified together (a 2-D Sobol point), from a dimension of their own.
    glm::dvec2 next2() {
        const std::uint32_t d = pcgHash(m_key ^ pcgHash(m_dimension++));
        const std::uint32_t i = sobol::nestedUniformScramble(m_index, d);
        const std::uint32_t x = sobol::nestedUniformScramble(sobol::dimension0(i), pcgHash(d ^ 0x85ebca6bu));
        const std::uint32_t y = sobol::nestedUniformScramble(sobol::dimension1(i), pcgHash(d ^ 0xc2b2ae35u));
        constexpr double kScale = 1.0 / 4294967296.0;
        return {double(x) * kScale, double(y) * kScale};
    }

  private:
    std::uint32_t m_index;
    std::uint32_t m_key;
    std::uint32_t m_dimension = 0;
};

} // namespace lr::trace
