// The raster's IES profiles and gobo images, without GL (issue 39, docs/light-shaping.md): every
// distinct profile and image of the rig's lights (scene/lightassets.h) in one texture array each, and per rig
// light its layer, which the light buffer packs (lightpack.h packIesTexels, packGoboTexels;
// shaders/shaping.glsl reads them).
//
// IES: each profile resampled, I(θ, φ) / peak as core's bilinear iesCandela gives it, on a grid of
// kIesGridVertical vertical angles (0 ... 180°, every 0.5°) by kIesGridHorizontal horizontal ones (0 ...
// 357.5°, every 2.5°, wrapping), R32F, sampled bilinear: exactly core's value wherever the file's angles
// are multiples of the grid's (most files: 0.5°, 1°, 2.5°, 5°, 10° vertical; 0°, 2.5°, 5°, 22.5°, 45°
// horizontal), the linear interpolation of it between grid angles elsewhere.
// Gobos: each image as it is (RGB16F, no resampling), in the corner of a layer as large as the largest one;
// the shader clamps to the image's own edge texels, so GL_LINEAR gives core's bilinear (gobo::sample).
#pragma once

#include "core/gobo.h"
#include "core/ies.h"
#include "core/rig.h"

#include <memory>
#include <vector>

namespace lr {
struct LightAssets;
}

namespace lr::render {

constexpr int kIesGridVertical = 361, kIesGridHorizontal = 144;
constexpr double kIesGridVerticalStep = 0.5, kIesGridHorizontalStep = 2.5; // degrees

// The profile on the grid, I / peak (0 for a profile without light): row j is vertical angle
// j × kIesGridVerticalStep, column i horizontal angle i × kIesGridHorizontalStep.
std::vector<float> resampleIes(const IesProfile& profile);

// Which layer each rig light reads (no GL).
struct ShapingLayers {
    std::vector<int> iesLayer;  // per rig light: -1 none (no profile, it did not load, or not point/spot)
    std::vector<float> iesNorm; // per rig light: the profile's peak (the array holds I / peak)
    std::vector<int> goboLayer; // per rig light: -1 none (a spot's only)
    // Per layer, shared with the scene description: held, so that an address is never reused for another
    // profile or image while LightShapingGl compares them.
    std::vector<std::shared_ptr<const IesProfile>> profiles;
    std::vector<std::shared_ptr<const GoboImage>> gobos;
    int goboWidth = 0, goboHeight = 0; // the gobo array's layer size
};
ShapingLayers shapingLayers(const Rig& rig, const LightAssets& assets);

} // namespace lr::render
