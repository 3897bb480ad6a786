// Scene-linear images out as OpenEXR (issue 37, HDR output): float RGBA, premultiplied alpha (the EXR
// convention), ZIP compressed, top row first, with string attributes in the header (what the image is:
// its exposure and tone map, which are not applied to the pixels). Encoded in memory, so that the caller
// writes the bytes atomically (core/atomicwrite.h) like every other output.
#pragma once

#include <QByteArray>
#include <QString>

#include <utility>
#include <vector>

namespace lr {

// `rgba`: width × height × 4 floats, row-major. Empty bytes and *error on failure.
QByteArray encodeExrRgba(int width, int height, const float* rgba,
                         const std::vector<std::pair<QString, QString>>& attributes, QString* error);

} // namespace lr
