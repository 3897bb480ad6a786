// The measured approximations of the balanced and fast tiers (docs/quality.md) as named shader-variant
// bits. RenderSettings::approximations picks them (`lightrig bench --approximations` for measuring each);
// FeatureKey::approximations carries those of a variant's own tier, and shaderPrelude turns them into
// defines. No environment variable changes what a shader compiles.
#pragma once

#include "core/quality.h"

#include <QString>
#include <cstdint>

namespace lr::render {

namespace approx {
constexpr std::uint8_t kB1 = 1 << 0; // angle-power cone: acos as Abramowitz & Stegun 4.4.45
constexpr std::uint8_t kB2 = 1 << 1; // integer shininess as a chain of products
constexpr std::uint8_t kB3 = 1 << 2; // early-outs beyond a bounded range / outside the cone (off: slower)
constexpr std::uint8_t kB4 = 1 << 3; // L and d from one inversesqrt, branch-free
constexpr std::uint8_t kF2 = 1 << 4; // fast tier: Direct3D's infinite viewer (off: doubled the error)
// Physically based shading only (compiled into LR_PBR programs; classic programs never see them):
constexpr std::uint8_t kB5 = 1 << 5; // Schlick's (1 - x)^5 as three.js's spherical Gaussian exp2(...)
constexpr std::uint8_t kB6 = 1 << 6; // Filament's fast Smith visibility 0.5 / mix(2 NL NV, NL + NV, α)
constexpr std::uint8_t kBalancedMask = kB1 | kB2 | kB3 | kB4 | kB5 | kB6, kFastMask = kF2;
constexpr std::uint8_t kDefault = kB1 | kB2 | kB4; // what the tiers ship with
constexpr int kCount = 7;
// The bits of `set` that apply to `quality`'s shaders (none for exact).
std::uint8_t forTier(std::uint8_t set, Quality quality);
// "b1,b2,b4" (case-insensitive; "none" for no approximation); false and *error naming the bad word.
bool parseApproximations(const QString& text, std::uint8_t* out, QString* error);
QString approximationNames(std::uint8_t set); // "b1,b2,b4", or "none"
} // namespace approx

} // namespace lr::render
