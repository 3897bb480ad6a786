// Low-discrepancy points and the hash that scrambles them, shared by the environment's integrators
// (core/envbrdf, scene/envprefilter_ggx), the traced shadow reference (scene/referencetrace) and the path
// tracer (trace/sampler.h).
#pragma once

#include <cstdint>

namespace lr {

inline std::uint32_t reverseBits(std::uint32_t x) {
    x = (x << 16u) | (x >> 16u);
    x = ((x & 0x55555555u) << 1u) | ((x & 0xAAAAAAAAu) >> 1u);
    x = ((x & 0x33333333u) << 2u) | ((x & 0xCCCCCCCCu) >> 2u);
    x = ((x & 0x0F0F0F0Fu) << 4u) | ((x & 0xF0F0F0F0u) >> 4u);
    x = ((x & 0x00FF00FFu) << 8u) | ((x & 0xFF00FF00u) >> 8u);
    return x;
}

// The radical inverse of i in base 2 (van der Corput): the second coordinate of Hammersley point i.
inline double radicalInverse2(std::uint32_t bits) {
    return double(reverseBits(bits)) * 2.3283064365386963e-10;
}

// PCG hash (Jarzynski & Olano 2020): a well-mixed 32-bit value from a 32-bit state.
inline std::uint32_t pcgHash(std::uint32_t v) {
    const std::uint32_t state = v * 747796405u + 2891336453u;
    const std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

// Owen scrambling by hashing (Burley 2020, "Practical Hash-based Owen Scrambling", JCGT 9(4)): the
// path tracer's sampler (trace/sampler.h).
namespace sobol {

// A hash-based Laine-Karras permutation: a random permutation of the low bits in which each bit depends
// on the lower ones only, i.e. (on the reversed bits) an Owen scramble of the high ones.
inline std::uint32_t laineKarras(std::uint32_t x, std::uint32_t seed) {
    x ^= x * 0x3d20adeau;
    x += seed;
    x *= (seed >> 16) | 1u;
    x ^= x * 0x05526c56u;
    x ^= x * 0x53a22864u;
    return x;
}

// Owen scrambling of a 32-bit fixed-point coordinate (or, on an index, a shuffle that keeps every
// power-of-two block of indices together).
inline std::uint32_t nestedUniformScramble(std::uint32_t x, std::uint32_t seed) {
    return reverseBits(laineKarras(reverseBits(x), seed));
}

// The first two Sobol dimensions as 32-bit fixed point: van der Corput and the Pascal-matrix one.
inline std::uint32_t dimension0(std::uint32_t i) {
    return reverseBits(i);
}
constexpr std::uint32_t dimension1Bits(std::uint32_t i) {
    std::uint32_t r = 0, v = 1u << 31;
    for (; i; i >>= 1, v ^= v >> 1)
        if (i & 1u) r ^= v;
    return r;
}
// The generator matrix is linear over GF(2): one table per byte of the index, four lookups a point.
struct Dimension1Tables {
    std::uint32_t byte[4][256] = {};
    constexpr Dimension1Tables() {
        for (int k = 0; k < 4; ++k)
            for (std::uint32_t b = 0; b < 256; ++b)
                byte[k][b] = dimension1Bits(b << (8 * k));
    }
};
inline constexpr Dimension1Tables kDimension1Tables{};
inline std::uint32_t dimension1(std::uint32_t i) {
    const Dimension1Tables& t = kDimension1Tables;
    return t.byte[0][i & 0xffu] ^ t.byte[1][(i >> 8) & 0xffu] ^ t.byte[2][(i >> 16) & 0xffu] ^
           t.byte[3][i >> 24];
}

} // namespace sobol

} // namespace lr
