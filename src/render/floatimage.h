// Float read-backs of a frame: linear radiance before exposure and tone mapping, and the G-buffer of the
// shaded surfaces. Row 0 is the TOP row (image order, like QImage). No GL here.
#pragma once

#include "core/types.h"

#include <glm/vec4.hpp>
#include <vector>

namespace lr {

struct FloatImage {
    int width = 0, height = 0;
    std::vector<glm::vec4> pixels; // row-major, top row first

    bool isNull() const { return width <= 0 || height <= 0; }
    const glm::vec4& at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    glm::vec4& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

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
