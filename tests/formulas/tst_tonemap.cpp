// The colour tone maps (core/colour.h): Khronos PBR Neutral and AgX against values worked by hand from
// their published definitions, and the properties that make them what they are (Neutral keeps hue and
// passes dark colours through; AgX maps greys to greys, monotonically, black to black). The GLSL twins are
// compared with these in tests/render/tst_renderaccuracy.cpp (toneMappedOutput).
#include "common.h"

#include <QtTest>

using namespace lr;
using namespace lr::test;
using colour::toneMapAgx;
using colour::toneMapNeutral;
using colour::toneMapRgb;

class TestToneMap : public QObject {
    Q_OBJECT

  private slots:
    void neutralByHand() {
        // x = min channel >= 0.08: offset 0.04; peak 0.46 < 0.76 (start of compression): passed through.
        QCOMPARE(toneMapNeutral(Vec3d(0.5)).x, 0.46);
        // x < 0.08: offset x - 6.25 x² (the toe): 0.05 - 0.015625 = 0.034375.
        QVERIFY(std::abs(toneMapNeutral(Vec3d(0.05)).x - 0.015625) < 1e-15);
        // Peak 2 - 0.04 = 1.96 above 0.76: new peak 1 - 0.24² / (1.96 + 0.24 - 0.76) = 0.96; grey stays grey.
        const Vec3d g = toneMapNeutral(Vec3d(2.0));
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(g[c] - 0.96) < 1e-12, qPrintable(QString::number(g[c], 'g', 17)));
    }

    void neutralKeepsHueBelowCompression() {
        const Vec3d in(0.3, 0.2, 0.1), out = toneMapNeutral(in);
        const Vec3d shifted = in - 0.04; // min 0.1 >= 0.08: a constant offset, no scaling
        for (int c = 0; c < 3; ++c)
            QVERIFY(std::abs(out[c] - shifted[c]) < 1e-15);
        // Above compression the channel ratios after the offset move towards the peak (desaturation), but
        // their order is kept.
        const Vec3d hot = toneMapNeutral(Vec3d(8.0, 4.0, 1.0));
        QVERIFY(hot.x > hot.y && hot.y > hot.z);
        QVERIFY(hot.x < 1.0);
    }

    void agxGreysStayGreyAndRiseMonotonically() {
        double previous = -1.0;
        for (int e = -40; e <= 40; ++e) {
            const double x = 0.18 * std::exp2(e / 4.0);
            const Vec3d y = toneMapAgx(Vec3d(x));
            QVERIFY2(std::abs(y.x - y.y) < 2e-3 && std::abs(y.y - y.z) < 2e-3,
                     qPrintable(QStringLiteral("grey %1 -> %2 %3 %4").arg(x).arg(y.x).arg(y.y).arg(y.z)));
            QVERIFY2(y.y >= previous, qPrintable(QStringLiteral("not monotonic at %1").arg(x)));
            previous = y.y;
        }
        QCOMPARE(toneMapAgx(Vec3d(0.0)), Vec3d(0.0)); // the sigmoid's -0.00232 at 0 is clamped away
        QVERIFY(toneMapAgx(Vec3d(1e6)).y > 0.95);
        // Middle grey lands in the middle of the display range (AgX's design: 0.18 -> about 0.5 encoded).
        const double mid = colour::linearToSrgb(toneMapAgx(Vec3d(0.18)).y);
        QVERIFY2(mid > 0.4 && mid < 0.6, qPrintable(QString::number(mid)));
    }

    void colourOperatorsNeedColours() {
        // The scalar entry point applies Neutral/AgX to a grey; toneMapRgb to the colour itself.
        QCOMPARE(colour::toneMap(ToneMap::Neutral, 0.5), 0.46);
        const Vec3d c = toneMapRgb(ToneMap::Neutral, Vec3d(0.5, 0.3, 0.2));
        QVERIFY(std::abs(c.x - 0.46) < 1e-15 && std::abs(c.y - 0.26) < 1e-15 && std::abs(c.z - 0.16) < 1e-15);
        // The per-channel operators are unchanged by the colour entry point.
        for (ToneMap op : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
            const Vec3d rgb(0.1, 0.9, 3.0), m = toneMapRgb(op, rgb);
            for (int k = 0; k < 3; ++k)
                QCOMPARE(m[k], colour::toneMap(op, rgb[k]));
        }
    }

    void floatFollowsDouble() {
        // The float evaluation (the GPU's precision) stays within 1e-4 of double over 1e-4 .. 1e4.
        double worst = 0.0;
        for (int e = -40; e <= 40; ++e) {
            for (const Vec3d& tint : {Vec3d(1.0), Vec3d(1.0, 0.5, 0.25), Vec3d(0.1, 0.4, 1.0)}) {
                const Vec3d x = tint * std::pow(10.0, e / 10.0);
                for (ToneMap op : {ToneMap::Neutral, ToneMap::Agx}) {
                    const Vec3d d = toneMapRgb(op, x);
                    const Vec3f f = toneMapRgb(op, Vec3f(x));
                    for (int k = 0; k < 3; ++k)
                        worst = std::max(worst, std::abs(double(f[k]) - d[k]));
                }
            }
        }
        QVERIFY2(worst < 1e-4, qPrintable(QString::number(worst)));
    }

    void hostileInputsStayInRange() {
        const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
        for (ToneMap op : {ToneMap::Neutral, ToneMap::Agx})
            for (const Vec3d& x : {Vec3d(nan, 0.5, 1.0), Vec3d(inf, 0.5, 1.0), Vec3d(-inf, -1.0, 0.0),
                                   Vec3d(1e300), Vec3d(1e-300)}) {
                const Vec3d y = toneMapRgb(op, x);
                for (int k = 0; k < 3; ++k)
                    QVERIFY2(std::isfinite(y[k]) && y[k] >= 0.0 && y[k] <= 1.0,
                             qPrintable(QStringLiteral("%1 -> %2").arg(toString(op)).arg(y[k])));
            }
    }
};

QTEST_APPLESS_MAIN(TestToneMap)
#include "tst_tonemap.moc"
