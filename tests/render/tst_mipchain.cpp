// CPU mipmap chains (render/mipchain.h): sRGB rounding, the box filter, odd sizes, and agreement with the
// driver's own glGenerateMipmap, which they replace.
#include "glfixture.h"
#include "render/mipchain.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions_3_3_Core>
#include <QOpenGLVersionFunctionsFactory>
#include <QRandomGenerator>
#include <QtTest>
#include <cmath>

using namespace lr::render;

namespace {

double srgbToLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
double linearToSrgb(double l) {
    return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

QImage randomImage(int w, int h, quint32 seed) {
    QImage image(w, h, QImage::Format_RGBA8888);
    QRandomGenerator rng(seed);
    for (int y = 0; y < h; ++y) {
        uchar* row = image.scanLine(y);
        for (int x = 0; x < 4 * w; ++x)
            row[x] = uchar(rng.bounded(256));
    }
    return image;
}

int maxDifference(const QImage& a, const QImage& b) {
    int worst = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < 4 * a.width(); ++x)
            worst = std::max(worst, std::abs(int(a.constScanLine(y)[x]) - int(b.constScanLine(y)[x])));
    return worst;
}

} // namespace

class TestMipChain : public QObject {
    Q_OBJECT
  private slots:
    void srgbEncodingRoundsToNearest() {
        for (int k = 0; k < 256; ++k)
            QCOMPARE(int(encodeSrgb8(float(srgbToLinear(k / 255.0)))), k);
        for (int i = 0; i <= 1000; ++i) {
            const double linear = i / 1000.0;
            const int expected = int(std::lround(linearToSrgb(linear) * 255.0));
            QVERIFY2(std::abs(int(encodeSrgb8(float(linear))) - expected) <= 0,
                     qPrintable(QStringLiteral("linear %1").arg(linear)));
        }
        QCOMPARE(int(encodeSrgb8(-1.0f)), 0);
        QCOMPARE(int(encodeSrgb8(2.0f)), 255);
    }

    void boxFilterInLinearLightForSrgb() {
        QImage image(2, 2, QImage::Format_RGBA8888);
        image.setPixelColor(0, 0, QColor(0, 0, 0, 0));
        image.setPixelColor(1, 0, QColor(255, 255, 255, 255));
        image.setPixelColor(0, 1, QColor(0, 0, 0, 0));
        image.setPixelColor(1, 1, QColor(255, 255, 255, 255));
        const QImage srgb = downsampleLevel(image, true), linear = downsampleLevel(image, false);
        QCOMPARE(srgb.size(), QSize(1, 1));
        // Half black, half white: linear 0.5 is sRGB 187.5/255 -> 188; a plain average gives 128.
        QCOMPARE(srgb.pixelColor(0, 0).red(), 188);
        QCOMPARE(srgb.pixelColor(0, 0).alpha(), 128); // alpha is never sRGB-encoded
        QCOMPARE(linear.pixelColor(0, 0).red(), 128);
    }

    void oddSizesHalveDownToOnePixel() {
        const MipChain chain = buildMipChain(randomImage(5, 3, 1), false);
        QCOMPARE(int(chain.levels.size()), 3); // 5×3, 2×1, 1×1
        QCOMPARE(chain.levels[1].size(), QSize(2, 1));
        QCOMPARE(chain.levels[2].size(), QSize(1, 1));
        QCOMPARE(int(buildMipChain(randomImage(1, 1, 2), true).levels.size()), 1);
        QCOMPARE(int(buildMipChain(randomImage(64, 1, 3), true).levels.size()), 7);
        // An ARGB image is converted, not misread.
        QImage argb(2, 2, QImage::Format_ARGB32);
        argb.fill(QColor(10, 20, 30, 255));
        const MipChain converted = buildMipChain(argb, false);
        QCOMPARE(converted.levels[1].pixelColor(0, 0), QColor(10, 20, 30, 255));
    }

    // The chain matches what the driver's glGenerateMipmap makes of the same texture (the driver filters
    // in float and may round differently by one 8-bit level per step).
    void agreesWithTheDriver_data() {
        QTest::addColumn<bool>("srgb");
        QTest::addRow("linear") << false;
        QTest::addRow("sRGB") << true;
    }
    void agreesWithTheDriver() {
        LR_REQUIRE_DISPLAY();
        QFETCH(bool, srgb);
        QOpenGLContext context;
        QSurfaceFormat format;
        format.setVersion(3, 3);
        format.setProfile(QSurfaceFormat::CoreProfile);
        context.setFormat(format);
        QVERIFY(context.create());
        QOffscreenSurface surface;
        surface.setFormat(context.format());
        surface.create();
        QVERIFY(context.makeCurrent(&surface));
        auto* gl = QOpenGLVersionFunctionsFactory::get<QOpenGLFunctions_3_3_Core>(&context);
        QVERIFY(gl);
        const QImage image = randomImage(64, 32, 7);
        const MipChain chain = buildMipChain(image, srgb);
        GLuint texture = 0;
        gl->glGenTextures(1, &texture);
        gl->glBindTexture(GL_TEXTURE_2D, texture);
        gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        gl->glPixelStorei(GL_PACK_ALIGNMENT, 4);
        gl->glTexImage2D(GL_TEXTURE_2D, 0, srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8, image.width(), image.height(),
                         0, GL_RGBA, GL_UNSIGNED_BYTE, image.constBits());
        gl->glGenerateMipmap(GL_TEXTURE_2D);
        // Each level from the driver's previous one (rounding differences would otherwise accumulate), and
        // the whole chain within two levels of the driver's.
        QImage previous = image;
        for (int level = 1; level < int(chain.levels.size()); ++level) {
            QImage driver(chain.levels[size_t(level)].size(), QImage::Format_RGBA8888);
            gl->glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_UNSIGNED_BYTE, driver.bits());
            const int step = maxDifference(downsampleLevel(previous, srgb), driver);
            const int whole = maxDifference(chain.levels[size_t(level)], driver);
            QVERIFY2(
                step <= 1 && whole <= 2,
                qPrintable(QStringLiteral("level %1: %2 / %3 levels apart").arg(level).arg(step).arg(whole)));
            previous = driver;
        }
        gl->glDeleteTextures(1, &texture);
        QCOMPARE(gl->glGetError(), GLenum(GL_NO_ERROR));
        context.doneCurrent();
    }
};

LR_GL_TEST_MAIN(TestMipChain)
#include "tst_mipchain.moc"
