// A float RGBA image: linear radiance before exposure and tone mapping (the raster's read-backs, the path
// tracer's accumulation). Row 0 is the TOP row (image order, like QImage). No GL here.
#pragma once

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

} // namespace lr
