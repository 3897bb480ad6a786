// Two 8-bit images of one size compared as core/imagecompare.h does (r, g, b: levels and PSNR), converted to
// RGBA8888 first; with `mask` (one byte per pixel, the image's size) only the pixels it marks. The bench's
// traced errors (tracebench.cpp) and the render tests compare images with it.
#pragma once

#include "core/imagecompare.h"

#include <QImage>
#include <cstdint>
#include <vector>

namespace lr {

inline ErrorFigures imageErrors(const QImage& a, const QImage& b,
                                const std::vector<std::uint8_t>* mask = nullptr) {
    const QImage x = a.convertToFormat(QImage::Format_RGBA8888),
                 y = b.convertToFormat(QImage::Format_RGBA8888);
    const std::int64_t count = std::int64_t(x.width()) * x.height();
    const bool masked = mask && std::int64_t(mask->size()) == count;
    return compareSrgb8(x.constBits(), y.constBits(), count, 4, masked ? mask->data() : nullptr);
}

} // namespace lr
