// A linear float image for the eye: × 2^exposureEV, tone map, sRGB, 8 bits (core/colour.h displayColour,
// as the raster's tone-map pass does it). RGBA8888, straight alpha. With `transparent`, alpha is the
// image's coverage and each pixel's colour that of its covered share (the image's rgb is premultiplied);
// otherwise alpha is 255. What the path tracer's display, the Mixer dock and `lightrig mix` share.
#pragma once

#include "core/types.h"
#include "floatimage.h"

#include <QImage>

namespace lr {

QImage displayImage(const FloatImage& image, double exposureEV, ToneMap toneMap, bool transparent);

} // namespace lr
