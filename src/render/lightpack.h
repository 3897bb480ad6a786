// Packing prepared lights into the light buffer's RGBA32F texels (layout in shaders/shadetypes.glsl).
// No GL here.
#pragma once

#include "core/shade.h"
#include "shadergen.h"

#include <array>

namespace lr::render {

using LightTexels = std::array<float, 4 * kLightTexels>;

LightTexels packLight(const lighting::ShadeLight<float>& l);

} // namespace lr::render
