#include "imagecompare.h"

#include <cmath>
#include <cstdlib>

namespace lr {

double psnrFromMse(double mse, double peak) {
    if (!(mse > 0.0)) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(peak * peak / mse);
}

ErrorFigures compareSrgb8(const std::uint8_t* a, const std::uint8_t* b, std::int64_t count, int stride,
                          const std::uint8_t* mask) {
    ErrorFigures f;
    std::int64_t sumAbs = 0, sumSquares = 0; // exact: at most 255² × 3 per pixel
    for (std::int64_t i = 0; i < count; ++i) {
        if (mask && !mask[i]) continue;
        const std::uint8_t* pa = a + i * stride;
        const std::uint8_t* pb = b + i * stride;
        int worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int d = std::abs(int(pa[c]) - int(pb[c]));
            sumAbs += d;
            sumSquares += std::int64_t(d) * d;
            if (d > worst) worst = d;
        }
        if (worst > f.maxLevels) f.maxLevels = worst;
        if (worst > 1) ++f.over1;
        ++f.pixels;
    }
    if (f.pixels > 0) {
        const double samples = 3.0 * double(f.pixels);
        f.meanLevels = double(sumAbs) / samples;
        f.psnrDb = psnrFromMse(double(sumSquares) / samples);
    }
    return f;
}

std::int64_t countNonFinite(const float* data, std::int64_t count, int components) {
    std::int64_t n = 0;
    for (std::int64_t i = 0; i < count; ++i) {
        const float* p = data + i * components;
        for (int c = 0; c < components; ++c) {
            if (!std::isfinite(p[c])) {
                ++n;
                break;
            }
        }
    }
    return n;
}

} // namespace lr
