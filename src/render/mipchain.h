// Texture mipmap chains built on the CPU, so that a model's textures are prepared on worker threads in
// parallel (QtConcurrent) instead of one after the other by glGenerateMipmap on the GL thread: on Mesa
// llvmpipe that took ~100 ms per 2048² sRGB texture of the first frame (DamagedHelmet: 3 of them).
//
// Each level halves the previous one (floor, at least 1) with a 2×2 box filter, the last row/column
// repeated where a dimension is odd. sRGB textures are filtered in linear light (decoded through a table,
// averaged, re-encoded exactly rounded), as GL requires of sRGB mipmaps; alpha and linear textures
// average their 8-bit values (rounded to nearest).
#pragma once

#include <QImage>
#include <vector>

namespace lr::render {

struct MipChain {
    std::vector<QImage> levels; // RGBA8888; levels[0] the full-size image, down to 1×1
};

MipChain buildMipChain(const QImage& image, bool srgb);

// One 2×2 box-filtered level of an RGBA8888 image (exposed for tests).
QImage downsampleLevel(const QImage& source, bool srgb);

// The 8-bit sRGB encoding of a linear value in [0, 1], rounded to nearest (exposed for tests).
unsigned char encodeSrgb8(float linear);

} // namespace lr::render
