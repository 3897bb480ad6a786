// The path tracer's texture lookups (src/trace/texture.h) follow the glTF sampler as OpenGL defines it
// (glTF 2.0 "samplers"; OpenGL 3.3 §3.8.8): REPEAT takes the fractional part, CLAMP_TO_EDGE clamps to the
// edge texels' centres, MIRRORED_REPEAT reflects every other image, and a NEAREST magnification filter
// takes the texel under the point instead of blending four. The raster binds the same wrap modes as GL
// sampler objects (tests/render/tst_materials.cpp: wrapModesFollowTheSampler).
#include "trace/texture.h"

#include <QTest>

using namespace lr;
using lr::trace::TextureSampler;

namespace {

constexpr int kSize = 4;

// A linear 4×4 texture: red = 60·column, green = 60·row (levels), blue 0.
QImage ramp() {
    QImage img(kSize, kSize, QImage::Format_RGBA8888);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            img.setPixelColor(x, y, QColor(60 * x, 60 * y, 0));
    return img;
}

// The level a column (or row) holds, as the sampler returns it.
float level(int texel) {
    return float(60 * texel) / 255.0f;
}

// The centre of texel i along an axis.
float centre(int i) {
    return (float(i) + 0.5f) / float(kSize);
}

bool near(float a, float b) {
    return std::abs(a - b) <= 1e-5f;
}

} // namespace

class TraceTexture : public QObject {
    Q_OBJECT
    QImage m_image = ramp();

    glm::vec4 at(TextureWrap s, TextureWrap t, float u, float v, bool nearest = false) const {
        const TextureSampler sampler(m_image, false, TextureSampling{s, t, nearest});
        return sampler.sample({u, v});
    }

  private slots:
    void repeatTakesTheFractionalPart() {
        for (float u : {centre(0), centre(2)})
            for (float shift : {1.0f, -1.0f, 3.0f})
                QVERIFY(near(at(TextureWrap::Repeat, TextureWrap::Repeat, u + shift, centre(1)).r,
                             at(TextureWrap::Repeat, TextureWrap::Repeat, u, centre(1)).r));
        // Halfway between the last texel and the first of the next image: their mean.
        QVERIFY(near(at(TextureWrap::Repeat, TextureWrap::Repeat, 1.0f, centre(1)).r,
                     0.5f * (level(3) + level(0))));
    }

    void clampHoldsTheEdgeTexels() {
        for (float u : {1.0f, 1.5f, 7.25f})
            QVERIFY2(near(at(TextureWrap::ClampToEdge, TextureWrap::Repeat, u, centre(1)).r, level(3)),
                     qPrintable(QString::number(u)));
        for (float u : {0.0f, -0.5f, -9.0f})
            QVERIFY2(near(at(TextureWrap::ClampToEdge, TextureWrap::Repeat, u, centre(1)).r, level(0)),
                     qPrintable(QString::number(u)));
        // Inside the image clamping changes nothing.
        QVERIFY(near(at(TextureWrap::ClampToEdge, TextureWrap::Repeat, 0.3f, centre(1)).r,
                     at(TextureWrap::Repeat, TextureWrap::Repeat, 0.3f, centre(1)).r));
    }

    void mirroredRepeatReflectsEveryOtherImage() {
        // u = 1 + centre(0) reads as 1 - centre(0): the last texel; u = -centre(1) as centre(1).
        QVERIFY(near(at(TextureWrap::MirroredRepeat, TextureWrap::Repeat, 1.0f + centre(0), centre(1)).r,
                     level(3)));
        QVERIFY(
            near(at(TextureWrap::MirroredRepeat, TextureWrap::Repeat, -centre(1), centre(1)).r, level(1)));
        QVERIFY(near(at(TextureWrap::MirroredRepeat, TextureWrap::Repeat, 2.0f + centre(2), centre(1)).r,
                     level(2)));
        // Continuous across the reflection: at u = 1 the last texel on both sides.
        QVERIFY(near(at(TextureWrap::MirroredRepeat, TextureWrap::Repeat, 1.0f, centre(1)).r, level(3)));
        QVERIFY(near(at(TextureWrap::MirroredRepeat, TextureWrap::Repeat, 1.0f + 1e-3f, centre(1)).r,
                     at(TextureWrap::MirroredRepeat, TextureWrap::Repeat, 1.0f - 1e-3f, centre(1)).r));
    }

    void theAxesWrapIndependently() {
        // S clamps (red: the last column), T repeats (green: the first row again).
        const glm::vec4 c = at(TextureWrap::ClampToEdge, TextureWrap::Repeat, 1.5f, 1.0f + centre(0));
        QVERIFY(near(c.r, level(3)));
        QVERIFY(near(c.g, level(0)));
        const glm::vec4 d =
            at(TextureWrap::Repeat, TextureWrap::MirroredRepeat, 1.0f + centre(0), 1.0f + centre(0));
        QVERIFY(near(d.r, level(0)));
        QVERIFY(near(d.g, level(3)));
    }

    void nearestTakesTheTexelUnderThePoint() {
        // u = 0.3: 1.2 texels in, between the centres of texels 0 and 1 (0.7 of the way): bilinear blends,
        // nearest is texel 1.
        const float u = 0.3f;
        QVERIFY(near(at(TextureWrap::Repeat, TextureWrap::Repeat, u, centre(2)).r,
                     0.3f * level(0) + 0.7f * level(1)));
        QVERIFY(near(at(TextureWrap::Repeat, TextureWrap::Repeat, u, centre(2), true).r, level(1)));
        QVERIFY(near(at(TextureWrap::ClampToEdge, TextureWrap::Repeat, 3.0f, centre(2), true).r, level(3)));
        QVERIFY(
            near(at(TextureWrap::MirroredRepeat, TextureWrap::Repeat, 1.1f, centre(2), true).r, level(3)));
    }

    void nonFiniteCoordinatesStayFinite() {
        for (TextureWrap w : {TextureWrap::Repeat, TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat})
            for (float u : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                            1e30f, -1e30f}) {
                const glm::vec4 c = at(w, w, u, 0.5f);
                QVERIFY(std::isfinite(c.r) && std::isfinite(c.g) && c.r >= 0.0f && c.r <= 1.0f);
            }
    }
};

QTEST_APPLESS_MAIN(TraceTexture)
#include "tst_trace_texture.moc"
