// Resampling and the mip pyramid of equirectangular images (envprefilter_detail.h).
#include "envprefilter_detail.h"

#include <QtConcurrent/QtConcurrentMap>
#include <algorithm>
#include <cmath>
#include <numeric>

namespace lr::envfilter {

namespace {

struct Tap {
    int index;
    double weight;
};

// For each of `out` texels along an axis of `in` texels, the source texels and weights: a box over the
// output texel's footprint (fractional coverage, times rowWeight) when shrinking, a tent when growing.
// `wrap`: indices wrap around (azimuth), else they clamp (latitude).
std::vector<std::vector<Tap>> taps(int in, int out, bool wrap, const std::vector<double>& rowWeight) {
    std::vector<std::vector<Tap>> result(static_cast<size_t>(out));
    const double scale = double(in) / out;
    const auto index = [&](int i) { return wrap ? ((i % in) + in) % in : std::clamp(i, 0, in - 1); };
    for (int o = 0; o < out; ++o) {
        std::vector<Tap>& t = result[size_t(o)];
        if (scale > 1.0) {
            const double a = o * scale, b = (o + 1) * scale;
            for (int i = int(std::floor(a)); i < int(std::ceil(b)); ++i) {
                const double cover = std::min(b, i + 1.0) - std::max(a, double(i));
                if (cover > 0.0) t.push_back({index(i), cover * rowWeight[size_t(index(i))]});
            }
        } else {
            const double p = (o + 0.5) * scale - 0.5;
            const int i0 = int(std::floor(p));
            const double f = p - i0;
            t.push_back({index(i0), 1.0 - f});
            t.push_back({index(i0 + 1), f});
        }
        const double sum =
            std::accumulate(t.begin(), t.end(), 0.0, [](double s, const Tap& x) { return s + x.weight; });
        for (Tap& x : t)
            x.weight = sum > 0.0 ? x.weight / sum : 1.0 / double(t.size());
    }
    return result;
}

} // namespace

void forEachRow(int count, const std::function<void(int)>& fn) {
    std::vector<int> rows(size_t(std::max(count, 0)));
    std::iota(rows.begin(), rows.end(), 0);
    QtConcurrent::blockingMap(rows, [&fn](int row) { fn(row); });
}

EnvironmentImage resample(const EnvironmentImage& src, int width) {
    const int height = std::max(width / 2, 1);
    if (src.width == width && src.height == height) return src;
    std::vector<double> ones(size_t(src.width), 1.0), rowOmega(size_t(src.height));
    for (int y = 0; y < src.height; ++y)
        rowOmega[size_t(y)] = environment::texelSolidAngle(y, src.width, src.height);
    const auto tx = taps(src.width, width, true, ones);
    const auto ty = taps(src.height, height, false, rowOmega);
    EnvironmentImage across; // width × src.height
    across.width = width;
    across.height = src.height;
    across.texels.resize(size_t(width) * size_t(src.height));
    forEachRow(src.height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            glm::dvec3 s(0.0);
            for (const Tap& t : tx[size_t(x)])
                s += glm::dvec3(src.at(t.index, y)) * t.weight;
            across.at(x, y) = glm::vec3(s);
        }
    });
    EnvironmentImage out;
    out.width = width;
    out.height = height;
    out.texels.resize(size_t(width) * size_t(height));
    forEachRow(height, [&](int y) {
        for (int x = 0; x < width; ++x) {
            glm::dvec3 s(0.0);
            for (const Tap& t : ty[size_t(y)])
                s += glm::dvec3(across.at(x, t.index)) * t.weight;
            out.at(x, y) = glm::vec3(s);
        }
    });
    return out;
}

EnvironmentImage halve(const EnvironmentImage& src) {
    EnvironmentImage out;
    out.width = src.width / 2;
    out.height = src.height / 2;
    out.texels.resize(size_t(out.width) * size_t(out.height));
    for (int y = 0; y < out.height; ++y) {
        const float w0 = float(environment::texelSolidAngle(2 * y, src.width, src.height));
        const float w1 = float(environment::texelSolidAngle(2 * y + 1, src.width, src.height));
        const float a = w0 / (2.0f * (w0 + w1)), b = w1 / (2.0f * (w0 + w1));
        for (int x = 0; x < out.width; ++x)
            out.at(x, y) = (src.at(2 * x, 2 * y) + src.at(2 * x + 1, 2 * y)) * a +
                           (src.at(2 * x, 2 * y + 1) + src.at(2 * x + 1, 2 * y + 1)) * b;
    }
    return out;
}

std::vector<EnvironmentImage> pyramid(const EnvironmentImage& base, int minWidth) {
    std::vector<EnvironmentImage> mips{base};
    while (mips.back().width / 2 >= minWidth && mips.back().height % 2 == 0 && mips.back().width % 2 == 0)
        mips.push_back(halve(mips.back()));
    return mips;
}

namespace {
glm::vec3 bilinear(const EnvironmentImage& img, float u, float v) {
    const float x = u * float(img.width) - 0.5f, y = v * float(img.height) - 0.5f;
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    int x0 = int(fx) % img.width;
    if (x0 < 0) x0 += img.width;
    const int x1 = x0 + 1 == img.width ? 0 : x0 + 1;
    const int y0 = std::clamp(int(fy), 0, img.height - 1), y1 = std::clamp(int(fy) + 1, 0, img.height - 1);
    return (img.at(x0, y0) * (1.0f - ax) + img.at(x1, y0) * ax) * (1.0f - ay) +
           (img.at(x0, y1) * (1.0f - ax) + img.at(x1, y1) * ax) * ay;
}
} // namespace

glm::vec3 sampleLevel(const std::vector<EnvironmentImage>& mips, float u, float v, float lod) {
    lod = std::clamp(lod, 0.0f, float(mips.size() - 1));
    const int l0 = int(lod);
    const float f = lod - float(l0);
    const glm::vec3 a = bilinear(mips[size_t(l0)], u, v);
    if (f <= 0.0f || l0 + 1 >= int(mips.size())) return a;
    return a * (1.0f - f) + bilinear(mips[size_t(l0 + 1)], u, v) * f;
}

} // namespace lr::envfilter
