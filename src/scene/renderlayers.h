// The layers of one render (issue 37; docs/light-mixing.md): the beauty image, one image per light group
// (core/lightgroups.h) that sum to it, and the auxiliary images a compositor or a denoiser wants (albedo,
// normal, depth). Every renderer that splits its output fills one: the path tracer (trace/pathtracer.h),
// the raster tiers and the reference. Mixing (core/lightmix.h) re-balances it with no render.
#pragma once

#include "core/lightgroups.h"
#include "core/lightmix.h"
#include "floatimage.h"

#include <vector>

namespace lr {

// What an empty pixel holds in the depth layer (Blender's convention: far, finite, so half-less tools cope).
inline constexpr float kBackgroundDepth = 1e10f;

struct RenderLayers {
    FloatImage beauty;                   // linear radiance, rgb; alpha: coverage
    std::vector<LightGroup> groups;      // what each group image is
    std::vector<FloatImage> groupImages; // one per group, beauty's size; rgb (alpha: beauty's)
    // Of the first surface each pixel sees, averaged over its samples; null when not rendered.
    FloatImage albedo; // linear base colour, rgb
    FloatImage normal; // world-space shading normal, xyz (0 where nothing is)
    FloatImage depth;  // x: distance along the view axis, kBackgroundDepth where nothing is
};

// rgb: Σ over groups of mix.of(name).factor() × group image; alpha: the beauty's. With an identity mix,
// the sum of the groups (equal to the beauty to rounding). Null when there are no group images.
FloatImage mixGroupImages(const RenderLayers& layers, const LightMix& mix);

// The largest |Σ groups − beauty| over pixels and channels, relative to the beauty's largest channel
// (at least 1e-30): what a renderer's split is checked against.
double groupSumError(const RenderLayers& layers);

} // namespace lr
