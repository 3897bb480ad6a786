// Packing prepared lights into the light buffer's RGBA32F texels (layout in shaders/shadetypes.glsl).
// No GL here.
#pragma once

#include "core/shade.h"
#include "shadergen.h"

#include <array>
#include <cstdint>

namespace lr::render {

using LightTexels = std::array<float, 4 * kLightTexels>;

LightTexels packLight(const lighting::ShadeLight<float>& l);

// The texel a linking frame appends to each light (RigFeatures::linking, kLinkedLightTexels): its lit-class
// mask (LinkResolution::litMask) as its low and high 16 bits, each an exact float, so no bit pattern is
// bent by a float conversion; shadetypes.glsl loadLight joins them.
std::array<float, 4> packLinkTexel(std::uint32_t litMask);

} // namespace lr::render
