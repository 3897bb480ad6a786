#include "texture.h"

#include "core/colour.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lr::trace {

namespace {

const std::array<float, 256>& srgbTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i)
            t[size_t(i)] = float(colour::srgbToLinear(double(i) / 255.0));
        return t;
    }();
    return table;
}

} // namespace

glm::vec2 transformUv(const TextureTransform& t, const glm::vec2& uv) {
    if (t.isIdentity()) return uv;
    const float c = std::cos(t.rotation), s = std::sin(t.rotation);
    const glm::vec2 q = t.scale * uv;
    return t.offset + glm::vec2(c * q.x + s * q.y, -s * q.x + c * q.y);
}

float TextureSampler::reduce(float t, TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::ClampToEdge:
        return std::clamp(t, 0.0f, 1.0f);
    case TextureWrap::MirroredRepeat:
        return t - 2.0f * std::floor(0.5f * t);
    case TextureWrap::Repeat:
        break;
    }
    return t - std::floor(t);
}

int TextureSampler::wrapIndex(int i, int n, TextureWrap wrap) {
    switch (wrap) {
    case TextureWrap::ClampToEdge:
        return std::clamp(i, 0, n - 1);
    case TextureWrap::MirroredRepeat: {
        const int m = i % (2 * n);
        const int r = m < 0 ? m + 2 * n : m;
        return r < n ? r : 2 * n - 1 - r;
    }
    case TextureWrap::Repeat:
        break;
    }
    const int m = i % n;
    return m < 0 ? m + n : m;
}

TextureSampler::TextureSampler(const QImage& image, bool srgb, const TextureSampling& sampling)
    : m_srgb(srgb), m_sampling(sampling) {
    if (image.isNull()) return;
    const QImage* source = &image;
    if (image.format() != QImage::Format_RGBA8888) {
        m_converted = image.convertToFormat(QImage::Format_RGBA8888);
        source = &m_converted;
    }
    m_bits = source->constBits();
    m_stride = source->bytesPerLine();
    m_width = source->width();
    m_height = source->height();
}

glm::vec4 TextureSampler::texel(int x, int y) const {
    const uchar* p = m_bits + qsizetype(wrapIndex(y, m_height, m_sampling.wrapT)) * m_stride +
                     qsizetype(wrapIndex(x, m_width, m_sampling.wrapS)) * 4;
    if (m_srgb) {
        const auto& t = srgbTable();
        return {t[p[0]], t[p[1]], t[p[2]], float(p[3]) * (1.0f / 255.0f)};
    }
    return glm::vec4(p[0], p[1], p[2], p[3]) * (1.0f / 255.0f);
}

glm::vec4 TextureSampler::sample(const glm::vec2& uv) const {
    if (isNull()) return glm::vec4(1.0f);
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return texel(0, 0);
    // Texel centres at (i + 0.5) / size; keep the coordinate small before the float -> int conversion.
    const float fx = reduce(uv.x, m_sampling.wrapS) * float(m_width) - 0.5f;
    const float fy = reduce(uv.y, m_sampling.wrapT) * float(m_height) - 0.5f;
    if (m_sampling.nearestMagnification) // the pixel's many samples average what minification would
        return texel(int(std::floor(fx + 0.5f)), int(std::floor(fy + 0.5f)));
    const float x0 = std::floor(fx), y0 = std::floor(fy);
    const float ax = fx - x0, ay = fy - y0;
    const int ix = int(x0), iy = int(y0);
    const glm::vec4 top = texel(ix, iy) * (1.0f - ax) + texel(ix + 1, iy) * ax;
    const glm::vec4 bottom = texel(ix, iy + 1) * (1.0f - ax) + texel(ix + 1, iy + 1) * ax;
    return top * (1.0f - ay) + bottom * ay;
}

} // namespace lr::trace
