// The path tracer's random numbers: a hash of (pixel, sample index, seed) starts a PCG stream (Jarzynski &
// Olano 2020), so that sample k of pixel p is the same whichever thread, tile or pass draws it: the image
// does not depend on the thread count.
#pragma once

#include <cstdint>

namespace lr::trace {

inline std::uint32_t pcgHash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

class Sampler {
  public:
    Sampler(std::uint32_t pixel, std::uint32_t sample, std::uint32_t seed = 0)
        : m_state(pcgHash(pixel ^ pcgHash(sample + pcgHash(seed)))) {}
    // Uniform in [0, 1), 24 bits.
    double next() {
        m_state = m_state * 747796405u + 2891336453u;
        std::uint32_t word = ((m_state >> ((m_state >> 28u) + 4u)) ^ m_state) * 277803737u;
        word = (word >> 22u) ^ word;
        return double(word >> 8) * (1.0 / 16777216.0);
    }

  private:
    std::uint32_t m_state;
};

} // namespace lr::trace
