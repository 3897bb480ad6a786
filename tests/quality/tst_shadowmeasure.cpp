// The shadow error measure (src/render/reference.h: markShadowBand, compareShadows) on synthetic images,
// its place in `lightrig bench`'s table and JSON (only with casters), and the traced reference end to end
// on a G-buffer built by hand: a caster's direct light is multiplied by its visibility, its ambient is not.
#include "shadowscenes.h"

#include "core/lighting.h"
#include "render/benchreport.h"
#include "render/gbuffer.h"
#include "render/reference.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTest>
#include <functional>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

using namespace lr;
using namespace lr::test;

namespace {

// A w × h reference with one caster, every pixel covered and compared, visibility from `code(x, y)`.
ReferenceImage syntheticReference(int w, int h, const std::function<std::uint8_t(int, int)>& code) {
    ReferenceImage r;
    r.width = w, r.height = h;
    r.casters = 1;
    r.covered.assign(size_t(w * h), 1);
    r.shadowClass.assign(size_t(w * h), 1);
    r.visibility.resize(size_t(w * h));
    r.srgb = QImage(w, h, QImage::Format_RGBA8888);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t v = code(x, y);
            r.visibility[size_t(y * w + x)] = v;
            const int level = 50 + 150 * v / 255; // shadowed 50, lit 200
            r.srgb.setPixel(x, y, qRgba(level, level, level, 255));
        }
    return r;
}

// A one-row G-buffer of points on the ground y = 0 (world x, z), seen through `view`.
GBuffer groundRow(const glm::dmat4& view, const std::vector<double>& xs, const std::vector<double>& zs = {}) {
    GBuffer g;
    for (FloatImage* f : {&g.position, &g.normal, &g.albedo, &g.specular, &g.emissive}) {
        f->width = int(xs.size()), f->height = 1;
        f->pixels.assign(xs.size(), glm::vec4(0.0f));
    }
    for (size_t i = 0; i < xs.size(); ++i) {
        const glm::dvec4 p(xs[i], 0.0, i < zs.size() ? zs[i] : 0.0, 1.0);
        g.position.pixels[i] = glm::vec4(glm::vec3(view * p), 1.0f);
        g.normal.pixels[i] = glm::vec4(glm::vec3(view * glm::dvec4(0.0, 1.0, 0.0, 0.0)), 1.0f);
        g.albedo.pixels[i] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
        g.specular.pixels[i] = glm::vec4(0.0f, 0.0f, 0.0f, 16.0f);
    }
    return g;
}

QImage shifted(const QImage& image, const std::function<int(int x, int level)>& f) {
    QImage out = image.copy();
    for (int y = 0; y < out.height(); ++y)
        for (int x = 0; x < out.width(); ++x) {
            const int l = std::clamp(f(x, qRed(out.pixel(x, y))), 0, 255);
            out.setPixel(x, y, qRgba(l, l, l, 255));
        }
    return out;
}

} // namespace

class TestShadowMeasure : public QObject {
    Q_OBJECT

  private slots:
    // The band: a partial pixel and every pixel within kShadowBandRadius of a change; uncovered pixels
    // neither belong to it nor widen it.
    void bandFromEdgesAndPartialPixels() {
        ReferenceImage r = syntheticReference(24, 5, [](int x, int y) {
            if (x == 3 && y == 2) return std::uint8_t(128);
            return std::uint8_t(x < 10 || (x == 18 && y == 2) ? 0 : 255);
        });
        const size_t uncovered = size_t(2 * 24 + 18); // its code differs from its neighbours'
        r.covered[uncovered] = 0, r.shadowClass[uncovered] = 0;
        markShadowBand(&r);
        for (int y = 0; y < 5; ++y)
            for (int x = 0; x < 24; ++x) {
                const size_t i = size_t(y * 24 + x);
                // The edge between columns 9 and 10, and the 5 × 5 pixels about the partial one.
                const bool expected = r.covered[i] && ((x >= 8 && x <= 11) || (x >= 1 && x <= 5));
                QVERIFY2((r.shadowClass[i] == 2) == expected,
                         qPrintable(QStringLiteral("pixel %1, %2").arg(x).arg(y)));
            }
    }

    // Outside the band a pixel differs when some channel is more than kShadowThresholdLevels off.
    void measureCountsOutsideTheBand() {
        ReferenceImage r =
            syntheticReference(20, 6, [](int x, int) { return std::uint8_t(x < 10 ? 0 : 255); });
        for (int x = 0; x < 20; ++x)
            r.shadowClass[size_t(5 * 20 + x)] = 0; // the last row: the casters' light does not matter there
        markShadowBand(&r);
        const std::int64_t compared = 5 * (20 - 4), shadowed = 5 * 8; // columns 8..11 are the band
        ShadowFigures f = compareShadows(r.srgb, r);
        QCOMPARE(f.compared, compared);
        QCOMPARE(f.band, std::int64_t(6 * 4));
        QCOMPARE(f.differing, std::int64_t(0));
        QCOMPARE(f.meanLevels, 0.0);
        // No shadow at all: every compared shadowed pixel is 150 levels too bright.
        f = compareShadows(shifted(r.srgb, [](int, int) { return 200; }), r);
        QCOMPARE(f.differing, shadowed);
        QCOMPARE(f.shareDiffering(), double(shadowed) / double(compared));
        QCOMPARE(f.meanLevels, 150.0 * double(shadowed) / double(compared));
        // Off by exactly the threshold: not a difference; one level more: every compared pixel.
        f = compareShadows(shifted(r.srgb, [](int, int l) { return l + kShadowThresholdLevels; }), r);
        QCOMPARE(f.differing, std::int64_t(0));
        QCOMPARE(f.meanLevels, double(kShadowThresholdLevels));
        f = compareShadows(shifted(r.srgb, [](int, int l) { return l - kShadowThresholdLevels - 1; }), r);
        QCOMPARE(f.differing, compared);
        // A frame of another size, or a reference without casters, gives nothing.
        QCOMPARE(compareShadows(r.srgb.copy(0, 0, 10, 6), r).compared, std::int64_t(0));
        r.casters = 0;
        QCOMPARE(compareShadows(r.srgb, r).compared, std::int64_t(0));
    }

    // The table and the JSON show the measure only when some result has it.
    void reportShowsShadowsOnlyWithCasters() {
        BenchReport report;
        BenchResult plain;
        plain.scene = QStringLiteral("s");
        plain.hasErrors = true;
        report.results = {plain};
        QVERIFY(!benchTable(report).contains(QStringLiteral("shadow off")));
        QJsonObject json = benchJson(report);
        QVERIFY(!json.contains(QStringLiteral("shadow_measure")));
        QVERIFY(!json[QStringLiteral("results")][0].toObject().contains(
            QStringLiteral("shadow_differing_share")));
        QCOMPARE(benchTableHeaders().size(), benchTableRow(plain).size());

        BenchResult shadowed = plain;
        shadowed.hasShadowErrors = true;
        shadowed.shadow.compared = 400;
        shadowed.shadow.differing = 100;
        shadowed.shadow.meanLevels = 12.5;
        shadowed.shadow.band = 7;
        report.results.push_back(shadowed);
        const QString table = benchTable(report);
        QVERIFY(table.contains(QStringLiteral("shadow off")) && table.contains(QStringLiteral("shadow err")));
        QVERIFY(table.contains(QStringLiteral("25.00%")) && table.contains(QStringLiteral("12.500")));
        QCOMPARE(benchTableHeaders(true).size(), benchTableRow(plain, true).size());
        json = benchJson(report);
        QCOMPARE(json[QStringLiteral("shadow_measure")][QStringLiteral("threshold_levels")].toInt(),
                 kShadowThresholdLevels);
        const QJsonObject o = json[QStringLiteral("results")][1].toObject();
        QCOMPARE(o[QStringLiteral("shadow_differing_share")].toDouble(), 0.25);
        QCOMPARE(o[QStringLiteral("shadow_mean_error_levels")].toDouble(), 12.5);
        QCOMPARE(o[QStringLiteral("shadow_compared_pixels")].toDouble(), 400.0);
        QCOMPARE(o[QStringLiteral("shadow_band_pixels")].toDouble(), 7.0);
        QVERIFY(
            !json[QStringLiteral("results")][0].toObject().contains(QStringLiteral("shadow_band_pixels")));
    }

    // The reference end to end on a hand-made G-buffer: points on the ground around a unit cube under a
    // 45° sun that casts (shadow on x in (-1.5, -0.5)) and a point light that does not.
    void referenceShadowsDirectLightOnly() {
        const Model model = ShadowSceneBuilder().box({-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}).build();
        Rig rig;
        rig.ambient = glm::dvec3(0.05);
        rig.ground.mode = GroundMode::Visible;
        Light sun = makeLight(LightType::Directional, QStringLiteral("sun"));
        sun.direction = glm::normalize(glm::dvec3(-1.0, -1.0, 0.0));
        sun.ambient = glm::dvec3(0.2);
        sun.shadow.enabled = true;
        Light fill = makeLight(LightType::Point, QStringLiteral("fill"));
        fill.position = {0.0, 5.0, 3.0};
        fill.falloff = {};
        fill.intensity = 0.3;
        rig.lights = {sun, fill};
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 3, 6), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
        const std::vector<double> xs{-3.0, -2.0, -1.4, -1.0, -0.7, 1.0, 2.0};
        const std::vector<bool> inShadow{false, false, true, true, true, false, false};
        const GBuffer g = groundRow(view, xs);
        QString error;
        const auto scene = makeReferenceScene(model, rig, SceneFrame{}, view, RenderSettings(), &error);
        QVERIFY2(scene, qPrintable(error));
        QCOMPARE(scene->casters(), 1);
        QVERIFY(scene->tracer && scene->tracer->triangles() == 14); // the cube and the ground
        const ReferenceImage r = computeReference(g, *scene);
        QCOMPARE(r.casters, 1);
        for (size_t i = 0; i < xs.size(); ++i) {
            const lighting::Surface<double> s = render::surfaceAt(g, int(i), 0);
            const std::vector<double> vis{inShadow[i] ? 0.0 : 1.0, 1.0};
            const glm::dvec3 expected =
                lighting::shadeSurface<double>(s, scene->lights, scene->settings, vis);
            const glm::dvec3 unshadowed = lighting::shadeSurface<double>(s, scene->lights, scene->settings);
            QVERIFY2(r.radiance[i] == expected, qPrintable(QStringLiteral("x = %1").arg(xs[i])));
            QCOMPARE(r.visibility[i], std::uint8_t(inShadow[i] ? 0 : 255));
            if (inShadow[i]) {
                // Darker by the sun's direct light only: its ambient (0.2 · 0.5) and the fill stay.
                QVERIFY(expected.x < unshadowed.x - 0.1);
                QVERIFY(expected.x > 0.05 * 0.5 + 0.2 * 0.5);
            } else {
                QVERIFY(expected == unshadowed);
            }
        }
        // Without a caster the reference traces nothing and keeps no shadow data.
        rig.lights[0].shadow.enabled = false;
        const auto plain = makeReferenceScene(model, rig, SceneFrame{}, view, RenderSettings(), &error);
        QVERIFY(plain && !plain->tracer && plain->casters() == 0);
        const ReferenceImage p = computeReference(g, *plain);
        QVERIFY(p.casters == 0 && p.visibility.empty() && p.shadowClass.empty());
        QVERIFY(p.radiance[3].x > r.radiance[3].x);
    }

    // Spots of 179° and 0.1° (full angles) behind and beside a unit cube on the ground: where the cone
    // reaches a point its shadow is traced (0 behind the cube, 1 in front), elsewhere nothing is traced and
    // the light adds nothing either; every value finite.
    void extremeSpotCones_data() {
        QTest::addColumn<double>("outer");
        QTest::addColumn<double>("aimX");
        QTest::addColumn<std::vector<int>>("expected"); // visibility code per point; -1: not traced (255)
        // Points: behind the cube (-0.7, 0, 0), between the spot and the cube (1, 0, 0), beside (-1, 0, 2).
        QTest::newRow("179° down") << 89.5 << 2.0 << std::vector<int>{0, 255, 255};
        QTest::newRow("0.1° behind") << 0.05 << -0.7 << std::vector<int>{0, -1, -1};
        QTest::newRow("0.1° in front") << 0.05 << 1.0 << std::vector<int>{-1, 255, -1};
    }
    void extremeSpotCones() {
        QFETCH(double, outer);
        QFETCH(double, aimX);
        QFETCH(std::vector<int>, expected);
        const Model model = ShadowSceneBuilder().box({-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}).build();
        Rig rig;
        rig.ground.mode = GroundMode::Visible;
        Light spot = makeLight(LightType::Spot, QStringLiteral("spot"));
        spot.position = {2.0, 1.5, 0.0};
        spot.direction = glm::normalize(outer > 45.0 ? glm::dvec3(0.0, -1.0, 0.0)
                                                     : glm::dvec3(aimX, 0.0, 0.0) - spot.position);
        spot.cone = {ConeModel::Smooth, 0.8 * outer, outer, 1.0};
        spot.falloff = {};
        spot.shadow.enabled = true;
        spot.shadow.size = 0.1;
        rig.lights = {spot};
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 3, 6), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
        const GBuffer g = groundRow(view, {-0.7, 1.0, -1.0}, {0.0, 0.0, 2.0});
        QString error;
        const auto scene = makeReferenceScene(model, rig, SceneFrame{}, view, RenderSettings(), &error);
        QVERIFY2(scene, qPrintable(error));
        const ReferenceImage r = computeReference(g, *scene);
        for (size_t i = 0; i < expected.size(); ++i) {
            const glm::dvec3 c = r.radiance[i];
            QVERIFY(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z));
            QCOMPARE(int(r.visibility[i]), expected[i] < 0 ? 255 : expected[i]);
            if (expected[i] < 0) QCOMPARE(c.x, 0.0); // outside the cone: no light, nothing traced
            if (expected[i] == 255) QVERIFY(c.x > 0.0);
        }
    }
};

QTEST_GUILESS_MAIN(TestShadowMeasure)
#include "tst_shadowmeasure.moc"
