#include "displayimage.h"

#include "core/colour.h"
#include "core/lighting.h"

#include <cmath>

namespace lr {

QImage displayImage(const FloatImage& image, double exposureEV, ToneMap toneMap, bool transparent) {
    if (image.isNull() || image.pixels.size() != size_t(image.width) * size_t(image.height)) return {};
    QImage out(image.width, image.height, QImage::Format_RGBA8888);
    if (out.isNull()) return out;
    const double scale = colour::exposureScale(exposureEV);
    for (int y = 0; y < image.height; ++y) {
        uchar* row = out.scanLine(y);
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4& p = image.at(x, y);
            const double alpha = transparent ? lighting::saturate(double(p.a)) : 1.0;
            glm::dvec3 rgb(p);
            if (transparent && alpha > 0.0) rgb /= alpha; // the covered share's own colour
            const glm::dvec3 c = colour::displayColour(rgb, scale, toneMap);
            for (int k = 0; k < 3; ++k)
                row[4 * x + k] = uchar(std::lround(lighting::saturate(c[k]) * 255.0));
            row[4 * x + 3] = uchar(std::lround(alpha * 255.0));
        }
    }
    return out;
}

} // namespace lr
