// Parity with three.js (issue 13): our image against three.js's image of the same glTF file, compared
// over the pixels three.js covers (those that differ from its background, 0.2 in sRGB = level 51), with
// core/imagecompare's figures. Used by tst_parity (the small scene in tests/data/parity, every run) and by
// parity_compare (scripts/perf/parity.sh: the helmet scenes against a fresh three.js run).
#pragma once

#include "core/imagecompare.h"

#include <QImage>
#include <vector>

namespace lrtest {

constexpr int kThreeBackgroundLevel = 51; // bench.html: scene.background = 0.2 (sRGB)

// Figures of `ours` against `three` over three.js's covered pixels; pixels = 0 when the sizes differ.
inline lr::ErrorFigures compareWithThree(const QImage& ours, const QImage& three) {
    if (ours.size() != three.size() || ours.isNull()) return {};
    const QImage a = ours.convertToFormat(QImage::Format_RGBA8888);
    const QImage b = three.convertToFormat(QImage::Format_RGBA8888);
    std::vector<std::uint8_t> mask(size_t(b.width()) * size_t(b.height()));
    for (int y = 0; y < b.height(); ++y) {
        const uchar* p = b.constScanLine(y);
        for (int x = 0; x < b.width(); ++x, p += 4)
            mask[size_t(y) * size_t(b.width()) + size_t(x)] = p[0] != kThreeBackgroundLevel ||
                                                              p[1] != kThreeBackgroundLevel ||
                                                              p[2] != kThreeBackgroundLevel;
    }
    return lr::compareSrgb8(a.constBits(), b.constBits(), qint64(a.width()) * a.height(), 4, mask.data());
}

} // namespace lrtest
