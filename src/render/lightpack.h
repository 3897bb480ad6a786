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

// The texels an IES frame appends (RigFeatures::ies, kIesTexels; shaders/shaping.glsl lrIes reads them):
//   0: the photometric nadir (view space, unit), the profile's layer in the IES array (-1: none)
//   1: horizontal angle 0's axis (view space, unit), the scale: iesScale × the layer's normalisation
// `layer` -1 (no profile, or it did not load) leaves the light unshaped, as core does without one.
std::array<float, 4 * kIesTexels> packIesTexels(const lighting::ShadeLight<float>& l, int layer, float norm);

// The texels a gobo frame appends (RigFeatures::gobo, kGoboTexels; shaders/shaping.glsl lrGoboTint):
//   0: the gobo's X axis (view space), its layer in the gobo array (-1: none)
//   1: its Y axis, the half extent h (core/gobo.h)
//   2: the image's width and height in texels, 1 / the array's width and height (the image fills a corner)
std::array<float, 4 * kGoboTexels> packGoboTexels(const lighting::ShadeLight<float>& l, int layer, int width,
                                                  int height, int arrayWidth, int arrayHeight);

} // namespace lr::render
