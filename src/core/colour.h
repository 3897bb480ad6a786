// Colour, written once: the sRGB transfer functions, the tone-map operators, the exposure scale and the
// display transform (linear radiance -> ×2^EV -> tone map -> sRGB), templated on the scalar like
// lighting.h. The GLSL twins (same names, same guards) are toneMap, linearToSrgb and displayEncode in
// shaders/colour.glsl; the renderer's uniforms (uExposureScale, uBackground) come from here, and so do
// the CPU reference (render/reference.h), the mip chains' sRGB tables and the editor's colour swatches.
// lighting.h re-exports toneMap, linearToSrgb and srgbToLinear as lighting::* for the formula tests.
#pragma once

#include "types.h"

#include <algorithm>
#include <cmath>
#include <glm/mat3x3.hpp>
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

// Exposed radiance above this is treated as this by every operator (finite arithmetic; all of them are at
// or within 1e-6 of white long before).
constexpr double kMaxToneMapInput = 1e6;

// Khronos PBR Neutral (github.com/KhronosGroup/ToneMapping, its published constants; three.js's
// NeutralToneMapping): linear sRGB in, linear sRGB in [0, 1] out. Hue-preserving: one curve on the peak.
template <typename T> glm::vec<3, T> toneMapNeutral(glm::vec<3, T> c) {
    const T startCompression = T(0.8) - T(0.04);
    const T desaturation = T(0.15);
    const T x = std::min({c.r, c.g, c.b});
    const T offset = x < T(0.08) ? x - T(6.25) * x * x : T(0.04);
    c -= offset;
    const T peak = std::max({c.r, c.g, c.b});
    if (peak < startCompression) return c;
    const T d = T(1) - startCompression;
    const T newPeak = T(1) - d * d / (peak + d - startCompression);
    c *= newPeak / peak;
    const T g = T(1) - T(1) / (desaturation * (peak - newPeak) + T(1));
    return c * (T(1) - g) + glm::vec<3, T>(newPeak) * g;
}

// AgX (Troy Sobotka), as three.js r187 and Filament evaluate it: Rec. 2020 inset, log2 encoding over
// [-12.47393, 4.026069] EV, the 6th-order sigmoid fit, outset, 2.2 power, back to sRGB primaries, clamp.
template <typename T> glm::vec<3, T> toneMapAgx(glm::vec<3, T> c) {
    using V = glm::vec<3, T>;
    using M = glm::mat<3, 3, T>;
    // Column-major, as the GLSL twins write them.
    const M srgbToRec2020(V(0.6274, 0.0691, 0.0164), V(0.3293, 0.9195, 0.0880), V(0.0433, 0.0113, 0.8956));
    const M rec2020ToSrgb(V(1.6605, -0.1246, -0.0182), V(-0.5876, 1.1329, -0.1006),
                          V(-0.0728, -0.0083, 1.1187));
    const M inset(V(0.856627153315983, 0.137318972929847, 0.11189821299995),
                  V(0.0951212405381588, 0.761241990602591, 0.0767994186031903),
                  V(0.0482516061458583, 0.101439036467562, 0.811302368396859));
    const M outset(V(1.1271005818144368, -0.1413297634984383, -0.14132976349843826),
                   V(-0.11060664309660323, 1.157823702216272, -0.11060664309660294),
                   V(-0.016493938717834573, -0.016493938717834257, 1.2519364065950405));
    const T minEv = T(-12.47393), maxEv = T(4.026069);
    c = inset * (srgbToRec2020 * c);
    for (int i = 0; i < 3; ++i) {
        const T v = std::log2(std::max(c[i], T(1e-10)));
        const T x = std::clamp((v - minEv) / (maxEv - minEv), T(0), T(1));
        const T x2 = x * x, x4 = x2 * x2;
        c[i] = T(15.5) * x4 * x2 - T(40.14) * x4 * x + T(31.96) * x4 - T(6.868) * x2 * x + T(0.4298) * x2 +
               T(0.1191) * x - T(0.00232);
    }
    c = outset * c;
    for (int i = 0; i < 3; ++i)
        c[i] = std::pow(std::max(c[i], T(0)), T(2.2));
    c = rec2020ToSrgb * c;
    return {detail::unit(c.r), detail::unit(c.g), detail::unit(c.b)};
}

// Tone mapping of one exposed channel into [0, 1]; <= 0 and NaN -> 0. Neutral and AgX act on colours
// (toneMapRgb); here on a grey of value x.
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
    case ToneMap::Neutral:
    case ToneMap::Agx:
        break;
    }
    const T g = std::min(x, T(kMaxToneMapInput));
    const glm::vec<3, T> c =
        op == ToneMap::Neutral ? toneMapNeutral(glm::vec<3, T>(g)) : toneMapAgx(glm::vec<3, T>(g));
    return detail::unit(c.g);
}

// An exposed colour into [0, 1]³: per channel (clamp, Reinhard, ACES) or on the colour (Neutral, AgX).
// Negative and NaN channels count as 0, channels above kMaxToneMapInput as kMaxToneMapInput.
template <typename T> glm::vec<3, T> toneMapRgb(ToneMap op, const glm::vec<3, T>& x) {
    if (op != ToneMap::Neutral && op != ToneMap::Agx)
        return {toneMap(op, x.r), toneMap(op, x.g), toneMap(op, x.b)};
    glm::vec<3, T> c;
    for (int i = 0; i < 3; ++i)
        c[i] = x[i] > T(0) ? std::min(x[i], T(kMaxToneMapInput)) : T(0);
    c = op == ToneMap::Neutral ? toneMapNeutral(c) : toneMapAgx(c);
    return {detail::unit(c.r), detail::unit(c.g), detail::unit(c.b)};
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
    const glm::vec<3, T> m = toneMapRgb(op, radiance * scale);
    return {linearToSrgb(m.r), linearToSrgb(m.g), linearToSrgb(m.b)};
}

} // namespace lr::colour
