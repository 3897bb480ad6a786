// Float read-backs of a frame: linear radiance (scene/floatimage.h's FloatImage) and the G-buffer of the
// shaded surfaces. Row 0 is the TOP row (image order, like QImage). No GL here.
#pragma once

#include "core/types.h"
#include "scene/floatimage.h"

#include <glm/vec4.hpp>
#include <vector>

namespace lr {

// What each pixel's surface was shaded with (view space). Background pixels have position.w = 0.
struct GBuffer {
    FloatImage position; // xyz, w = 1 where a surface was drawn
    FloatImage normal;   // unit normal as shaded (after normal map and double-sided flip), w = 1
    FloatImage albedo;   // linear rgb, w = alpha
    FloatImage specular; // ks rgb, w = shininess
    FloatImage emissive; // linear rgb
    // Physically based G-buffers (shading == Pbr; gbuffer.h): metallic, roughness, occlusion, w = 1.
    // Empty for classic ones, whose specular and shininess are above.
    ShadingModel shading = ShadingModel::Classic;
    FloatImage material;
};

} // namespace lr
