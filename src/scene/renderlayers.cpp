#include "renderlayers.h"

#include <algorithm>
#include <cmath>

namespace lr {

FloatImage mixGroupImages(const RenderLayers& layers, const LightMix& mix) {
    FloatImage out;
    if (layers.groupImages.empty()) return out;
    const FloatImage& first = layers.groupImages.front();
    out.width = first.width;
    out.height = first.height;
    out.pixels.assign(first.pixels.size(), glm::vec4(0.0f));
    for (size_t g = 0; g < layers.groupImages.size() && g < layers.groups.size(); ++g) {
        const glm::dvec3 f = mix.of(layers.groups[g].name).factor();
        if (f == glm::dvec3(0.0)) continue;
        const glm::vec3 k(f);
        const std::vector<glm::vec4>& src = layers.groupImages[g].pixels;
        const size_t n = std::min(src.size(), out.pixels.size());
        for (size_t i = 0; i < n; ++i)
            out.pixels[i] += glm::vec4(k * glm::vec3(src[i]), 0.0f);
    }
    const bool alpha = layers.beauty.pixels.size() == out.pixels.size();
    for (size_t i = 0; i < out.pixels.size(); ++i)
        out.pixels[i].w = alpha ? layers.beauty.pixels[i].w : 1.0f;
    return out;
}

double groupSumError(const RenderLayers& layers) {
    const FloatImage sum = mixGroupImages(layers, LightMix{});
    if (sum.pixels.size() != layers.beauty.pixels.size()) return INFINITY;
    double worst = 0.0, peak = 1e-30;
    for (size_t i = 0; i < sum.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const double b = layers.beauty.pixels[i][c];
            peak = std::max(peak, std::abs(b));
            worst = std::max(worst, std::abs(double(sum.pixels[i][c]) - b));
        }
    return worst / peak;
}

} // namespace lr
