// The pieces of the bench that need no OpenGL: the error metrics (known differences give known figures,
// identical images an infinite PSNR), the reference's tone-map encoding against lighting.h, the procedural
// rigs (valid rig files, constant total intensity) and the report (JSON keys, table, chart).
#include "core/imagecompare.h"
#include "core/lighting.h"
#include "core/proceduralrig.h"
#include "core/rigjson.h"
#include "render/benchoffers.h"
#include "render/benchreport.h"
#include "render/reference.h"

#include <QGuiApplication>
#include <QJsonArray>
#include <QTest>
#include <cmath>
#include <limits>
#include <vector>

using namespace lr;

namespace {

std::vector<std::uint8_t> image(int pixels, std::uint8_t value) {
    std::vector<std::uint8_t> v(size_t(pixels) * 4, value);
    for (int i = 0; i < pixels; ++i)
        v[size_t(i) * 4 + 3] = 255;
    return v;
}

BenchResult result(const QString& scene, Quality q, double ms, double meanError, bool uber = false) {
    BenchResult r;
    r.scene = scene;
    r.quality = q;
    r.uberShader = uber;
    r.size = QSize(64, 32);
    r.msMedian = r.msMin = r.msMax = ms;
    r.lightsInRig = r.lightsUploaded = 8;
    r.hasErrors = true;
    r.errors.pixels = 100;
    r.errors.meanLevels = meanError;
    r.errors.maxLevels = int(std::ceil(meanError * 3));
    r.errors.psnrDb = meanError > 0 ? 40.0 : std::numeric_limits<double>::infinity();
    return r;
}

} // namespace

class TestImageCompare : public QObject {
    Q_OBJECT
  private slots:
    void identicalImages() {
        const auto a = image(1000, 77);
        const ErrorFigures f = compareSrgb8(a.data(), a.data(), 1000);
        QCOMPARE(f.pixels, 1000);
        QCOMPARE(f.maxLevels, 0);
        QCOMPARE(f.meanLevels, 0.0);
        QVERIFY(std::isinf(f.psnrDb) && f.psnrDb > 0);
        QCOMPARE(f.over1, 0);
        QVERIFY(f.identical());
        QVERIFY(std::isinf(psnrFromMse(0.0)));
    }

    void oneChannelOfOnePixel() {
        const int n = 500;
        auto a = image(n, 100), b = image(n, 100);
        b[4 * 17 + 1] = 103; // pixel 17, green, +3 levels
        const ErrorFigures f = compareSrgb8(a.data(), b.data(), n);
        QCOMPARE(f.maxLevels, 3);
        QCOMPARE(f.over1, 1);
        QVERIFY(std::abs(f.meanLevels - 3.0 / (3.0 * n)) < 1e-12);
        const double mse = 9.0 / (3.0 * n);
        QVERIFY(std::abs(f.psnrDb - 10.0 * std::log10(255.0 * 255.0 / mse)) < 1e-9);
        QVERIFY(std::abs(f.shareOver1() - 1.0 / n) < 1e-12);
    }

    void everyChannelOffByOne() {
        // MSE = 1 level²: PSNR = 20·log10(255) = 48.13 dB; no pixel is off by more than one level.
        auto a = image(64, 10), b = image(64, 11);
        const ErrorFigures f = compareSrgb8(a.data(), b.data(), 64);
        QCOMPARE(f.maxLevels, 1);
        QCOMPARE(f.meanLevels, 1.0);
        QCOMPARE(f.over1, 0);
        QVERIFY(std::abs(f.psnrDb - 48.1308036) < 1e-6);
        QVERIFY(std::abs(psnrFromMse(255.0 * 255.0)) < 1e-12); // error as large as the peak: 0 dB
    }

    void alphaIgnoredAndSymmetric() {
        auto a = image(8, 50), b = image(8, 50);
        b[3] = 0;          // alpha of pixel 0
        b[4 * 5 + 2] = 40; // blue of pixel 5: -10
        a[4 * 6 + 0] = 60; // red of pixel 6 in a: +10
        const ErrorFigures ab = compareSrgb8(a.data(), b.data(), 8), ba = compareSrgb8(b.data(), a.data(), 8);
        QCOMPARE(ab.maxLevels, 10);
        QCOMPARE(ab.over1, 2);
        QCOMPARE(ba.maxLevels, ab.maxLevels);
        QCOMPARE(ba.meanLevels, ab.meanLevels);
        QCOMPARE(ba.psnrDb, ab.psnrDb);
    }

    void maskAndStride() {
        // RGB with stride 3; the mask leaves out the one pixel that differs.
        std::vector<std::uint8_t> a(30, 5), b(30, 5);
        b[3 * 4 + 0] = 255;
        std::vector<std::uint8_t> mask(10, 1);
        QCOMPARE(compareSrgb8(a.data(), b.data(), 10, 3).maxLevels, 250);
        mask[4] = 0;
        const ErrorFigures f = compareSrgb8(a.data(), b.data(), 10, 3, mask.data());
        QCOMPARE(f.pixels, 9);
        QCOMPARE(f.maxLevels, 0);
        std::vector<std::uint8_t> none(10, 0);
        const ErrorFigures empty = compareSrgb8(a.data(), b.data(), 10, 3, none.data());
        QCOMPARE(empty.pixels, 0);
        QCOMPARE(empty.shareOver1(), 0.0);
    }

    void countsNonFinitePixels() {
        const float inf = std::numeric_limits<float>::infinity(),
                    nan = std::numeric_limits<float>::quiet_NaN();
        const float data[] = {0,
                              1,
                              2,
                              1, // fine
                              nan,
                              0,
                              0,
                              1, // NaN
                              0,
                              0,
                              inf,
                              1, // +Inf
                              0,
                              -inf,
                              0,
                              1, // -Inf
                              std::numeric_limits<float>::max(),
                              1e-45f,
                              0,
                              1, // largest and denormal: finite
                              nan,
                              inf,
                              -inf,
                              nan}; // one pixel, counted once
        QCOMPARE(countNonFinite(data, 6, 4), 4);
        QCOMPARE(countNonFinite(data, 1, 4), 0);
    }

    // The reference's encoding is lighting.h's tone map and sRGB curve, rounded to the nearest level.
    void referenceEncoding() {
        QCOMPARE(toLevel(0.0), std::uint8_t(0));
        QCOMPARE(toLevel(1.0), std::uint8_t(255));
        QCOMPARE(toLevel(-3.0), std::uint8_t(0));
        QCOMPARE(toLevel(std::numeric_limits<double>::quiet_NaN()), std::uint8_t(0));
        QCOMPARE(toLevel(127.49 / 255.0), std::uint8_t(127));
        QCOMPARE(toLevel(127.51 / 255.0), std::uint8_t(128));
        for (int i = 0; i < enumCount<ToneMap>(); ++i) {
            const ToneMap op = ToneMap(i);
            for (double x : {0.0, 1e-4, 0.01, 0.18, 0.5, 1.0, 4.0, 1e6}) {
                const glm::dvec3 rgb(x, 2 * x, 0.5 * x);
                const glm::dvec3 e = encodeSrgb(rgb, 0.0, op);
                const glm::dvec3 m = colour::toneMapRgb(op, rgb);
                QCOMPARE(e.x, lighting::linearToSrgb(m.x));
                QCOMPARE(e.y, lighting::linearToSrgb(m.y));
                // One EV more is twice the radiance.
                QCOMPARE(encodeSrgb(rgb, 1.0, op).x,
                         lighting::linearToSrgb(colour::toneMapRgb(op, 2.0 * rgb).x));
            }
        }
        const glm::dvec3 nan =
            encodeSrgb(glm::dvec3(std::numeric_limits<double>::quiet_NaN()), 0.0, ToneMap::Aces);
        QCOMPARE(nan.x, 0.0);
    }

    void proceduralRigs_data() {
        QTest::addColumn<int>("type");
        QTest::addColumn<int>("count");
        for (int t = 0; t < enumCount<LightType>(); ++t)
            for (int n : {1, 8, 64, 256})
                QTest::addRow("%s-%d", EnumNames<LightType>::names[size_t(t)], n) << t << n;
    }

    void proceduralRigs() {
        QFETCH(int, type);
        QFETCH(int, count);
        ProceduralRigOptions o;
        o.type = LightType(type);
        o.count = count;
        const Rig rig = proceduralRig(o);
        QCOMPARE(int(rig.lights.size()), count);
        QVERIFY(rig.space == RigSpace::Model);
        double total = 0.0;
        for (const Light& l : rig.lights) {
            QVERIFY(l.type == o.type);
            total += l.intensity;
            QVERIFY(std::abs(glm::length(l.direction) - 1.0) < 1e-12);
            if (l.usesPosition()) {
                // On the ring of radius 2.5 (in bounding radii), shining towards the centre.
                QVERIFY(std::abs(std::hypot(l.position.x, l.position.z) - 2.5) < 1e-9 || count == 1);
                QVERIFY(glm::dot(l.direction, -l.position) > 0.0);
            }
            if (l.isArea()) {
                // Softboxes (issue 16) facing the model's centre head on, sized to it and outside its
                // bounding sphere (radius 1 in a model-space rig): the whole model on their emitting side.
                QVERIFY(glm::length(l.direction + glm::normalize(l.position)) < 1e-12);
                QVERIFY(glm::length(l.position) > 1.0);
                QVERIFY(l.area.width > 0.1 && l.area.width < 2.0 && l.area.height > 0.1 &&
                        l.area.height < 2.0);
                QVERIFY(l.area.radius > 0.1 && l.area.radius < 1.0);
                QVERIFY(!l.area.twoSided);
            }
        }
        ProceduralRigOptions one = o;
        one.count = 1;
        QVERIFY(std::abs(total - proceduralRig(one).lights[0].intensity) < 1e-9); // constant total intensity
        // A valid rig file: it survives the strict reader.
        const RigReadResult back = readRigJson(writeRigJson(rig), QStringLiteral("procedural.json"));
        QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));
        QCOMPARE(back.rig->lights.size(), rig.lights.size());
        QVERIFY(proceduralRigName(o).contains(toString(o.type)));
    }

    void reportJsonTableAndChart() {
        BenchReport report;
        report.glDescription = QStringLiteral("test GL");
        report.options.size = QSize(64, 32);
        report.results = {result(QStringLiteral("a"), Quality::Exact, 10.0, 0.01),
                          result(QStringLiteral("a"), Quality::Balanced, 8.0, 0.05),
                          result(QStringLiteral("a"), Quality::Fast, 2.0, 1.5),
                          result(QStringLiteral("a"), Quality::Exact, 12.5, 0.0, true)};
        report.results[0].speedUp = 1.0;
        report.results[2].speedUp = 5.0;
        const QJsonObject json = benchJson(report);
        const QJsonArray results = json.value(QStringLiteral("results")).toArray();
        QCOMPARE(results.size(), 4);
        for (const char* key :
             {"scene", "lights", "quality", "width", "height", "ms_median", "ms_min", "ms_max",
              "first_frame_ms", "max_error_levels", "mean_error_levels", "psnr_db", "nonfinite_pixels",
              "gpu_ms_median", "cpu_ms_median", "variants", "lights_uploaded", "triangles", "shader"})
            QVERIFY2(results[0].toObject().contains(QLatin1String(key)), key);
        QCOMPARE(results[2].toObject().value(QStringLiteral("quality")).toString(), QStringLiteral("fast"));
        QCOMPARE(results[2].toObject().value(QStringLiteral("width")).toInt(), 64);
        QVERIFY(results[3].toObject().value(QStringLiteral("psnr_db")).isNull()); // identical: infinite PSNR
        QCOMPARE(results[3].toObject().value(QStringLiteral("shader")).toString(), QStringLiteral("uber"));
        const QJsonArray uber = json.value(QStringLiteral("uber_shader")).toArray();
        QCOMPARE(uber.size(), 1);
        QVERIFY(std::abs(uber[0].toObject().value(QStringLiteral("saving")).toDouble() - 0.2) < 1e-9);

        const QString table = benchTable(report);
        QCOMPARE(table.count(QLatin1Char('\n')) >= 5, true);
        QVERIFY(table.contains(QStringLiteral("balanced")));
        QVERIFY(table.contains(QStringLiteral("(20.0% saved)")));

        const QImage chart = benchChart(report, QSize(500, 300));
        QCOMPARE(chart.size(), QSize(500, 300));
        // Points in the tier colours were drawn inside the plot: exact blue, fast green.
        bool blue = false, green = false;
        for (int y = 0; y < chart.height(); ++y)
            for (int x = 0; x < chart.width() - 175; ++x) { // the plot, not the legend
                const QColor c = chart.pixelColor(x, y);
                blue |= c == QColor(40, 100, 200);
                green |= c == QColor(40, 160, 70);
            }
        QVERIFY(blue && green);
    }

    // The tiers' promise under the table and in the JSON (render/benchoffers.h): the run's interaction,
    // each cheaper tier against exact of its own scene; the über-shader's run and a scene without exact are
    // not judged.
    void reportSaysWhichTiersAreOffered() {
        BenchReport report;
        report.options.dragLight = true;
        report.results = {result(QStringLiteral("a"), Quality::Exact, 10.0, 0.01),
                          result(QStringLiteral("a"), Quality::Balanced, 9.0, 0.05),
                          result(QStringLiteral("a"), Quality::Fast, 12.0, 1.5),
                          result(QStringLiteral("a"), Quality::Exact, 30.0, 0.0, true),
                          result(QStringLiteral("b"), Quality::Exact, 10.0, 0.01),
                          result(QStringLiteral("b"), Quality::Fast, 4.0, 1.5),
                          result(QStringLiteral("c"), Quality::Fast, 40.0, 1.5)};
        QVERIFY(benchInteraction(report.options) == Interaction::Drag);
        const QJsonObject json = benchJson(report);
        QCOMPARE(
            json.value(QStringLiteral("options")).toObject().value(QStringLiteral("interaction")).toString(),
            QStringLiteral("drag"));
        const QJsonArray results = json.value(QStringLiteral("results")).toArray();
        const std::vector<bool> offered{true, true, false, true, true, true, true};
        for (int i = 0; i < results.size(); ++i) {
            const QJsonObject o = results[i].toObject();
            QCOMPARE(o.value(QStringLiteral("offered")).toBool(), bool(offered[size_t(i)]));
            QCOMPARE(o.value(QStringLiteral("not_offered_why")).isNull(), bool(offered[size_t(i)]));
        }
        const QString why = results[2].toObject().value(QStringLiteral("not_offered_why")).toString();
        QVERIFY2(why.contains(QStringLiteral("1.20×")) && why.contains(interactionPhrase(Interaction::Drag)),
                 qPrintable(why));
        const QString table = benchTable(report);
        QVERIFY2(table.contains(QStringLiteral("a: balanced 0.90× exact (at most 1×): offered; fast 1.20× "
                                               "exact (at most 0.5×): not offered")),
                 qPrintable(table));
        QVERIFY2(table.contains(QStringLiteral("b: fast 0.40× exact (at most 0.5×): offered")),
                 qPrintable(table));
        QVERIFY2(!table.contains(QStringLiteral("c: ")), qPrintable(table));
        report.options.orbitDegrees = 1.0;
        QVERIFY(benchInteraction(report.options) == Interaction::Orbit);
        QVERIFY(benchTable(report).contains(interactionPhrase(Interaction::Orbit)));
    }
};

int main(int argc, char** argv) {
    if (!qEnvironmentVariableIsSet("DISPLAY")) qputenv("QT_QPA_PLATFORM", "offscreen");
    QGuiApplication app(argc, argv);
    TestImageCompare tc;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&tc, argc, argv);
}

#include "tst_imagecompare.moc"
