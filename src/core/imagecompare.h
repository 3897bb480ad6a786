// Error figures of an 8-bit sRGB image against a reference of the same size: the accuracy side of the
// quality tiers (docs/quality.md, `lightrig bench`, the editor's Quality panel). Pure arithmetic on
// pixel arrays, no Qt Gui: the callers hand in RGBA8 rows (QImage::Format_RGBA8888 bits) and masks.
//
// Figures over the compared pixels (every pixel, or those a mask selects) and their r, g, b channels
// (alpha is ignored):
//   maxLevels     largest |a − b| of one channel, in 8-bit levels (0..255)
//   meanLevels    mean of |a − b| over pixels × 3 channels
//   psnrDb        10·log10(255² / MSE), MSE over pixels × 3 channels; +infinity for identical images
//   over1         pixels with some channel off by more than one level (share: over1 / pixels)
//   nonFinite     NaN or ±Inf pixels of a float buffer (countNonFinite), filled in by the caller
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

namespace lr {

struct ErrorFigures {
    std::int64_t pixels = 0; // compared
    int maxLevels = 0;
    double meanLevels = 0.0;
    double psnrDb = std::numeric_limits<double>::infinity();
    std::int64_t over1 = 0;
    std::int64_t nonFinite = 0;

    double shareOver1() const { return pixels > 0 ? double(over1) / double(pixels) : 0.0; }
    bool identical() const { return maxLevels == 0; }
};

// PSNR in dB of a mean squared error in levels² against a peak of `peak` levels; +inf for mse <= 0.
double psnrFromMse(double mse, double peak = 255.0);

// Compares `count` pixels of a and b (each pixel `stride` bytes, r g b first). mask (optional, one byte
// per pixel): compare only where it is non-zero. Rows of a QImage with padding are the caller's business
// (Format_RGBA8888 has none).
ErrorFigures compareSrgb8(const std::uint8_t* a, const std::uint8_t* b, std::int64_t count, int stride = 4,
                          const std::uint8_t* mask = nullptr);

// Pixels of a float buffer (`components` floats each) with any NaN or infinite component.
std::int64_t countNonFinite(const float* data, std::int64_t count, int components = 4);

} // namespace lr
