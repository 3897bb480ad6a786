// Colour, written once: the sRGB transfer functions, the tone-map operators, the exposure scale and the
// display transform (linear radiance -> ×2^EV -> tone map -> sRGB), templated on the scalar like
// lighting.h. The GLSL twins (same names, same guards) are toneMap, linearToSrgb and displayEncode in
// shaders/lighting.glsl; the renderer's uniforms (uExposureScale, uBackground) come from here, and so do
// the CPU reference (render/reference.h), the mip chains' sRGB tables and the editor's colour swatches.
// lighting.h re-exports toneMap, linearToSrgb and srgbToLinear as lighting::* for the formula tests.
#pragma once

#include "types.h"

#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>
#include <limits>

namespace lr::colour {

namespace detail {
template <typename T> T unit(T x) { // [0, 1]; NaN -> 0 (lighting::saturate)
    return x > T(0) ? (x < T(1) ? x : T(1)) : T(0);
}
} // namespace detail

// Exposure is clamped to ±kMaxExposureEV stops so that 2^EV stays finite in float.
constexpr double kMaxExposureEV = 60.0;

// The factor radiance is multiplied by before tone mapping: 2^EV, EV clamped to ±60.
inline double exposureScale(double exposureEV) {
    return std::exp2(std::clamp(exposureEV, -kMaxExposureEV, kMaxExposureEV));
}

// Tone mapping of one exposed channel into [0, 1]; <= 0 and NaN -> 0.
template <typename T> T toneMap(ToneMap op, T x) {
    if (!(x > T(0))) return T(0);
    switch (op) {
    case ToneMap::Clamp:
        return detail::unit(x);
    case ToneMap::Reinhard:
        return x < std::numeric_limits<T>::max() ? x / (T(1) + x) : T(1);
    case ToneMap::Aces: { // Narkowicz 2015 fit
        if (!(x < T(1e6))) return T(1);
        return detail::unit((x * (T(2.51) * x + T(0.03))) / (x * (T(2.43) * x + T(0.59)) + T(0.14)));
    }
    }
    return T(0);
}

// The sRGB transfer function (IEC 61966-2-1), its input clamped to [0, 1].
template <typename T> T linearToSrgb(T x) {
    x = detail::unit(x);
    return x <= T(0.0031308) ? T(12.92) * x : T(1.055) * std::pow(x, T(1) / T(2.4)) - T(0.055);
}

template <typename T> T srgbToLinear(T x) {
    x = detail::unit(x);
    return x <= T(0.04045) ? x / T(12.92) : std::pow((x + T(0.055)) / T(1.055), T(2.4));
}

template <typename T> glm::vec<3, T> srgbToLinear(const glm::vec<3, T>& c) {
    return {srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z)};
}

// The display colour of a linear radiance: ×scale (exposureScale()), tone map, sRGB; each channel in
// [0, 1]. What the display path writes per fragment and the tone-map pass per pixel.
template <typename T> glm::vec<3, T> displayColour(const glm::vec<3, T>& radiance, T scale, ToneMap op) {
    glm::vec<3, T> out;
    for (int c = 0; c < 3; ++c)
        out[c] = linearToSrgb(toneMap(op, radiance[c] * scale));
    return out;
}

} // namespace lr::colour
