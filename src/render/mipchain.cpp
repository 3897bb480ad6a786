#include "mipchain.h"

#include "core/colour.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lr::render {

namespace {

using colour::srgbToLinear;

constexpr int kGuessBuckets = 4096;

struct SrgbTables {
    std::array<float, 256> decode{};     // 8-bit sRGB -> linear
    std::array<float, 256> thresholds{}; // [k]: linear value at the midpoint between code k and k + 1
    std::array<unsigned char, kGuessBuckets + 1> guess{}; // the code at linear i / kGuessBuckets
    SrgbTables() {
        for (int i = 0; i < 256; ++i)
            decode[size_t(i)] = float(srgbToLinear(i / 255.0));
        for (int k = 0; k < 255; ++k)
            thresholds[size_t(k)] = float(srgbToLinear((k + 0.5) / 255.0));
        thresholds[255] = std::numeric_limits<float>::infinity();
        for (int i = 0; i <= kGuessBuckets; ++i) {
            const float linear = float(i) / kGuessBuckets;
            guess[size_t(i)] = static_cast<unsigned char>(
                std::upper_bound(thresholds.begin(), thresholds.end() - 1, linear) - thresholds.begin());
        }
    }
    // The code whose interval [thresholds[k-1], thresholds[k]) holds the value (rounding in sRGB space):
    // a table guess, then at most a step or two to the exact interval.
    unsigned char encode(float linear) const {
        if (!(linear > 0.0f)) return 0;
        if (linear >= 1.0f) return 255;
        int k = guess[size_t(linear * kGuessBuckets)];
        while (linear >= thresholds[size_t(k)])
            ++k;
        while (k > 0 && linear < thresholds[size_t(k - 1)])
            --k;
        return static_cast<unsigned char>(k);
    }
};

const SrgbTables& tables() {
    static const SrgbTables t;
    return t;
}

} // namespace

unsigned char encodeSrgb8(float linear) {
    return tables().encode(linear);
}

QImage downsampleLevel(const QImage& source, bool srgb) {
    const int sw = source.width(), sh = source.height();
    const int w = std::max(1, sw / 2), h = std::max(1, sh / 2);
    QImage out(w, h, QImage::Format_RGBA8888);
    if (out.isNull()) return out;
    const SrgbTables& t = tables();
    const auto& decode = t.decode;
    for (int y = 0; y < h; ++y) {
        const uchar* r0 = source.constScanLine(std::min(2 * y, sh - 1));
        const uchar* r1 = source.constScanLine(std::min(2 * y + 1, sh - 1));
        uchar* dst = out.scanLine(y);
        for (int x = 0; x < w; ++x) {
            const int a = 4 * std::min(2 * x, sw - 1), b = 4 * std::min(2 * x + 1, sw - 1);
            for (int c = 0; c < 4; ++c) {
                if (srgb && c < 3) {
                    const float sum =
                        decode[r0[a + c]] + decode[r0[b + c]] + decode[r1[a + c]] + decode[r1[b + c]];
                    dst[4 * x + c] = t.encode(0.25f * sum);
                } else {
                    dst[4 * x + c] = uchar((r0[a + c] + r0[b + c] + r1[a + c] + r1[b + c] + 2) / 4);
                }
            }
        }
    }
    return out;
}

MipChain buildMipChain(const QImage& image, bool srgb) {
    MipChain chain;
    QImage level =
        image.format() == QImage::Format_RGBA8888 ? image : image.convertToFormat(QImage::Format_RGBA8888);
    if (level.isNull()) return chain;
    chain.levels.push_back(level);
    while (level.width() > 1 || level.height() > 1) {
        level = downsampleLevel(level, srgb);
        if (level.isNull()) break; // out of memory: the levels so far still make a valid texture
        chain.levels.push_back(level);
    }
    return chain;
}

} // namespace lr::render
