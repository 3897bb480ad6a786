// Multi-layer OpenEXR test files (model/exrencode.h, exrdecode.h): the layers `lightrig render --aovs`
// writes, with values that differ by layer, channel, column and row, some negative, some above 1.
#pragma once

#include "model/exrdecode.h"

#include <QTest>
#include <cmath>

namespace exrtest {

inline float value(int layer, int channel, int x, int y) {
    return 0.37f * float(layer + 1) - 0.11f * float(channel) + 0.013f * float(x) - 0.05f * float(y) +
           (x == 3 && y == 2 ? 17.5f : 0.0f);
}

inline lr::ExrLayer makeLayer(const QString& name, const QStringList& channels, int w, int h, int index) {
    lr::ExrLayer l{name, channels, {}};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < int(channels.size()); ++c)
                l.pixels.push_back(value(index, c, x, y));
    return l;
}

// Beauty, two light groups, albedo, normal and depth; depth far beyond half's 65504.
inline std::vector<lr::ExrLayer> aovLayers(int w, int h) {
    std::vector<lr::ExrLayer> layers{
        makeLayer("", {"R", "G", "B", "A"}, w, h, 0),  makeLayer("key", {"R", "G", "B"}, w, h, 1),
        makeLayer("rim_2", {"R", "G", "B"}, w, h, 2),  makeLayer("albedo", {"R", "G", "B"}, w, h, 3),
        makeLayer("normal", {"X", "Y", "Z"}, w, h, 4), makeLayer("depth", {"Z"}, w, h, 5)};
    for (float& z : layers.back().pixels)
        z = 1000.25f + 997.5f * z * z;
    if (layers.back().pixels.size() > 1) layers.back().pixels[1] = 123456.78f;
    return layers;
}

inline std::vector<std::pair<QString, QString>> aovAttributes() {
    return {
        {"lightrig/toneMap", "agx"}, {"lightrig/exposureEV", "1.5"}, {"lightrig/note", "Schlüssel, 主光"}};
}

inline const lr::ExrLayer* find(const std::vector<lr::ExrLayer>& layers, const QString& name) {
    for (const lr::ExrLayer& l : layers)
        if (l.name == name) return &l;
    return nullptr;
}

inline QByteArray encodeOrFail(int w, int h, const std::vector<lr::ExrLayer>& layers, lr::ExrPixel pixel) {
    QString error;
    const QByteArray bytes = lr::encodeExrLayers(w, h, layers, aovAttributes(), pixel, &error);
    if (bytes.isEmpty()) qFatal("encodeExrLayers: %s", qPrintable(error));
    return bytes;
}

} // namespace exrtest
