// `lightrig render --quality path -o OUT.exr` (issue 37, HDR output, on the traced tier): scene-linear
// float RGBA with the exposure, tone map and samples in the header and not in the pixels: the PNG of the
// same render (same seed) is the EXR's pixels through exposure, clamp and sRGB; a raster quality is refused.
#include "support/cli.h"

#include <ImfArray.h>
#include <ImfHeader.h>
#include <ImfRgbaFile.h>
#include <ImfStringAttribute.h>

#include <QImage>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace lrtest;

namespace {

QStringList traced(const QString& out) {
    return {QStringLiteral("render"),
            QStringLiteral(LIGHTRIG_TEST_DATA "/model/pbr.gltf"),
            QStringLiteral("--quality"),
            QStringLiteral("path"),
            QStringLiteral("--samples"),
            QStringLiteral("8"),
            QStringLiteral("--size"),
            QStringLiteral("48x32"),
            QStringLiteral("--environment"),
            QStringLiteral("studio"),
            QStringLiteral("--exposure"),
            QStringLiteral("1"),
            QStringLiteral("--tonemap"),
            QStringLiteral("clamp"),
            QStringLiteral("-o"),
            out};
}

double srgb(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

} // namespace

class TraceExr : public QObject {
    Q_OBJECT
  private slots:
    void sceneLinearWithTheDisplayInTheHeader() {
        QTemporaryDir dir;
        const QString exr = dir.filePath(QStringLiteral("t.exr")),
                      png = dir.filePath(QStringLiteral("t.png"));
        const QProcessEnvironment env = environmentWithoutDisplay();
        for (const QString& out : {exr, png}) {
            const CliRun run = runLightrig(traced(out), &env);
            QVERIFY2(run.code == 0, qPrintable(run.show()));
        }
        Imf::RgbaInputFile file(exr.toStdString().c_str());
        const Imath::Box2i dw = file.dataWindow();
        const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
        QCOMPARE(w, 48);
        QCOMPARE(h, 32);
        const auto* tone = file.header().findTypedAttribute<Imf::StringAttribute>("lightrig/toneMap");
        const auto* ev = file.header().findTypedAttribute<Imf::StringAttribute>("lightrig/exposureEV");
        const auto* samples = file.header().findTypedAttribute<Imf::StringAttribute>("lightrig/samples");
        QVERIFY(tone && ev && samples);
        QCOMPARE(QString::fromStdString(tone->value()), QStringLiteral("clamp"));
        QCOMPARE(QString::fromStdString(ev->value()), QStringLiteral("1"));
        QCOMPARE(QString::fromStdString(samples->value()), QStringLiteral("8"));
        Imf::Array2D<Imf::Rgba> pixels(h, w);
        file.setFrameBuffer(&pixels[0][0] - dw.min.x - dw.min.y * w, 1, size_t(w));
        file.readPixels(dw.min.y, dw.max.y);
        const QImage image = QImage(png).convertToFormat(QImage::Format_RGBA8888);
        QCOMPARE(image.size(), QSize(w, h));
        int over = 0; // channels brighter than 1 after the exposure: the EXR keeps what the PNG clips
        double worst = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const Imf::Rgba& p = pixels[y][x];
                const QRgb q = image.pixel(x, y);
                const double rgb[3] = {p.r, p.g, p.b},
                             shown[3] = {double(qRed(q)), double(qGreen(q)), double(qBlue(q))};
                for (int c = 0; c < 3; ++c) {
                    QVERIFY(std::isfinite(rgb[c]) && rgb[c] >= 0.0);
                    over += rgb[c] * 2.0 > 1.0;
                    worst = std::max(worst, std::abs(255.0 * srgb(rgb[c] * 2.0) - shown[c]));
                }
            }
        QVERIFY2(worst <= 1.5, qPrintable(QString::number(worst))); // half-float read, 8-bit rounding
        QVERIFY(over > 0);
    }

    // Every quality writes an .exr now (tst_aovsrender renders the raster's); what an .exr cannot hold is a
    // usage error before anything renders: supersampling (its pixels are the render's own), and --aovs or
    // --half without an .exr.
    void exrUsageErrors() {
        QTemporaryDir dir;
        const QString model = QStringLiteral(LIGHTRIG_TEST_DATA "/model/pbr.gltf");
        const QString out = dir.filePath(QStringLiteral("r.exr"));
        CliRun run = runLightrig({QStringLiteral("render"), model, QStringLiteral("--supersample"),
                                  QStringLiteral("2"), QStringLiteral("-o"), out});
        QCOMPARE(run.code, 2);
        QVERIFY2(run.err.contains(QLatin1String("--supersample does not apply to an .exr")),
                 qPrintable(run.show()));
        QVERIFY(!QFile::exists(out));
        const QString png = dir.filePath(QStringLiteral("r.png"));
        run = runLightrig(
            {QStringLiteral("render"), model, QStringLiteral("--aovs"), QStringLiteral("-o"), png});
        QCOMPARE(run.code, 2);
        QVERIFY2(run.err.contains(QLatin1String("--aovs writes OpenEXR")), qPrintable(run.show()));
        QVERIFY(!QFile::exists(png));
    }
};

QTEST_MAIN(TraceExr)
#include "tst_trace_exr.moc"
