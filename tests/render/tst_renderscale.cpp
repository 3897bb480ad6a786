// Issue 40: the editor's moving frames drawn smaller and stretched to the viewport (RenderSettings::
// renderScale, render/scaledoutput.h), and the controller that picks their scale from each frame's time
// (render/dynamicresolution.h).
#include "glfixture.h"
#include "scenes.h"

#include "render/dynamicresolution.h"
#include "render/imageerrors.h"
#include "render/offscreen.h"
#include "render/scaledoutput.h"

#include <QTest>
#include <limits>

using namespace lr;
using namespace lr::test;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

} // namespace

class TestRenderScale : public QObject {
    Q_OBJECT
  private slots:
    void drawSizeRoundsAndClamps() {
        using render::scaledDrawSize;
        QCOMPARE(scaledDrawSize({1280, 720}, 1.0), QSize(1280, 720));
        QCOMPARE(scaledDrawSize({1280, 720}, 0.5), QSize(640, 360));
        QCOMPARE(scaledDrawSize({1281, 721}, 0.5), QSize(641, 361)); // rounded half up
        QCOMPARE(scaledDrawSize({1280, 720}, 2.0), QSize(1280, 720));
        QCOMPARE(scaledDrawSize({1280, 720}, kNaN), QSize(1280, 720));
        QCOMPARE(scaledDrawSize({1280, 720}, kInf), QSize(1280, 720));
        QCOMPARE(scaledDrawSize({1280, 720}, 0.0), QSize(160, 90)); // kMinRenderScale
        QCOMPARE(scaledDrawSize({1280, 720}, -1.0), QSize(160, 90));
        QCOMPARE(scaledDrawSize({3, 1}, 0.125), QSize(1, 1)); // never empty
    }

    // A frame at half scale is drawn at half the size and stretched over the whole output: the same picture,
    // softer. Tiles and the HDR path ignore the scale: files are rendered at their size.
    void halfScaleDrawsAQuarterOfThePixels() {
        LR_REQUIRE_DISPLAY();
        OffscreenRenderer gl;
        QString error;
        QVERIFY2(gl.initialize(&error), qPrintable(error));
        QVERIFY(gl.setModel(sphereScene(), &error));
        gl.setRig(rigOf({point({2.0, 2.0, 3.0}, FalloffModel::None)}));
        RenderSettings full;
        full.msaaSamples = 0;
        RenderSettings half = full;
        half.renderScale = 0.5;
        const QSize size(160, 120);
        const QImage a = gl.renderImage(sphereCamera(), size, full, 1, &error);
        QVERIFY2(!a.isNull(), qPrintable(error));
        QCOMPARE(gl.renderer().stats().drawnSize, size);
        const QImage b = gl.renderImage(sphereCamera(), size, half, 1, &error);
        QVERIFY2(!b.isNull(), qPrintable(error));
        QCOMPARE(b.size(), size);
        QCOMPARE(gl.renderer().stats().drawnSize, QSize(80, 60));
        const ErrorFigures d = imageErrors(a, b);
        QVERIFY2(d.maxLevels > 0, "the stretched frame is the full frame: nothing was scaled");
        QVERIFY2(d.psnrDb > 24.0 && d.meanLevels < 3.0,
                 qPrintable(QStringLiteral("PSNR %1 dB, mean %2 levels").arg(d.psnrDb).arg(d.meanLevels)));
        const QImage c = gl.renderImage(sphereCamera(), size, full, 1, &error);
        QCOMPARE(c, a); // and back at full size, nothing of the scaled frame is left
        FloatImage radiance;
        QVERIFY2(gl.renderRadiance(sphereCamera(), size, half, &radiance, &error), qPrintable(error));
        QCOMPARE(QSize(radiance.width, radiance.height), size);
        QCOMPARE(gl.renderer().stats().drawnSize, size);
    }

    void controllerKeepsTheBudget() {
        DynamicResolution d(40.0);
        QCOMPARE(d.scale(), 1.0);
        QCOMPARE(d.fullFrameMs(), -1.0);
        // 160 ms at full size: a quarter of the pixels is ~40 ms, so one step below that.
        d.frameDrawn(160.0, 1.0);
        QCOMPARE(d.fullFrameMs(), 160.0);
        QVERIFY2(d.scale() <= 0.5 && d.scale() >= DynamicResolution::kMinScale,
                 qPrintable(QString::number(d.scale())));
        const double settled = d.scale();
        QVERIFY(160.0 * settled * settled <= DynamicResolution::kHeadroom * 40.0);
        // Frames that fit keep it: no flicker between sizes.
        for (int i = 0; i < 10; ++i)
            d.frameDrawn(160.0 * settled * settled, settled);
        QCOMPARE(d.scale(), settled);
        // The scene got cheap (a light switched off): one step up per fast frame, to full size.
        d.frameDrawn(2.0, settled);
        QCOMPARE(d.scale(), settled + DynamicResolution::kStep);
        for (int i = 0; i < 20; ++i)
            d.frameDrawn(2.0, d.scale());
        QCOMPARE(d.scale(), 1.0);
        // A frame far dearer than the estimate counts at once.
        d.frameDrawn(400.0, 1.0);
        QVERIFY2(d.scale() <= 0.375, qPrintable(QString::number(d.scale())));
        // Nothing fits: the smallest scale, never less.
        d.frameDrawn(1e6, d.scale());
        QCOMPARE(d.scale(), DynamicResolution::kMinScale);
        // Scales are whole steps.
        const double steps = d.scale() / DynamicResolution::kStep;
        QCOMPARE(steps, std::round(steps));
    }

    void controllerIgnoresNonsense() {
        DynamicResolution d(33.0);
        for (double ms : {kNaN, kInf, -1.0, 0.0})
            d.frameDrawn(ms, 1.0);
        for (double s : {kNaN, kInf, -1.0, 0.0})
            d.frameDrawn(100.0, s);
        QCOMPARE(d.scale(), 1.0);
        QCOMPARE(d.fullFrameMs(), -1.0);
        // Off: every frame at full size, whatever they cost.
        for (double budget : {0.0, -5.0, kNaN, kInf}) {
            DynamicResolution off(budget);
            QVERIFY(!off.enabled());
            off.frameDrawn(1000.0, 1.0);
            QCOMPARE(off.scale(), 1.0);
        }
        d.frameDrawn(1000.0, 1.0);
        QVERIFY(d.scale() < 1.0);
        d.reset();
        QCOMPARE(d.scale(), 1.0);
    }
};

LR_GL_TEST_MAIN(TestRenderScale)
#include "tst_renderscale.moc"
