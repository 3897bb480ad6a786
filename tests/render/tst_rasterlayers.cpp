// The raster tiers' light-group split (issue 37; render/rasterlayers.h): the groups sum to the beauty at
// every tier, with and without MSAA, under classic and physically based shading; a group scaled, switched
// off, or a whole mix, equals a fresh render of the rig with the mix applied (core/lightmix.h
// applyLightMix, the editor's "Apply to rig"); a shadow catcher's composite goes to "background"; the
// renderer's rig comes back; sizes beyond one tile are refused; albedo, normal and depth on an analytic
// plane and on the bundled Avocado.
#include "glfixture.h"
#include "layerscenes.h"

#include "model/modelloader.h"
#include "render/offscreen.h"
#include "render/rasterlayers.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace lr::test;

namespace {

// The tolerance of Σ groups = beauty: each group is one float pass minus the emission pass, and the sum
// runs over 8 groups in float (mixGroupImages): a few float ulps of the brightest pixel.
constexpr double kSumTolerance = 1e-5;
// A mix against a fresh render of the mixed rig: the same passes with scaled light data, so float
// rounding only (the bound is 0.5 %).
constexpr double kMixTolerance = 1e-4;

class TestRasterLayers : public QObject {
    Q_OBJECT

    std::unique_ptr<OffscreenRenderer> m_gl;

    bool setScene(std::shared_ptr<Model> model, const Rig& rig) {
        QString error;
        if (!m_gl->setModel(std::move(model), &error)) return qWarning("%s", qPrintable(error)), false;
        m_gl->renderer().setEnvironment(layerEnvironment());
        m_gl->setRig(rig);
        return true;
    }

    std::optional<RenderLayers> layers(const RenderSettings& s, const ViewCamera& cam = groundCamera(),
                                       QSize size = kLayerSize) {
        QString error;
        std::optional<RenderLayers> out = renderRasterLayers(*m_gl, cam, size, s, &error);
        if (!out) qWarning("%s", qPrintable(error));
        return out;
    }

    FloatImage beautyOf(const Rig& rig, const RenderSettings& s) {
        const Rig before = m_gl->renderer().rig();
        m_gl->setRig(rig);
        FloatImage out;
        QString error;
        if (!m_gl->renderRadiance(groundCamera(), kLayerSize, s, &out, &error))
            qWarning("%s", qPrintable(error));
        m_gl->setRig(before);
        return out;
    }

    void addTiers() {
        QTest::addColumn<int>("quality");
        QTest::addColumn<int>("msaa");
        QTest::addColumn<int>("shading");
        for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast})
            for (int msaa : {0, 4})
                for (ShadingModel m : {ShadingModel::Classic, ShadingModel::Pbr}) {
                    if (q == Quality::Fast && msaa > 0) continue; // fast never uses MSAA
                    QTest::addRow("%s-msaa%d-%s", qPrintable(toString(q)), msaa, qPrintable(toString(m)))
                        << int(q) << msaa << int(m);
                }
    }

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        m_gl = std::make_unique<OffscreenRenderer>();
        QString error;
        QVERIFY2(m_gl->initialize(&error), qPrintable(error));
    }

    void groupsSumToBeauty_data() { addTiers(); }
    void groupsSumToBeauty() {
        QFETCH(int, quality);
        QFETCH(int, msaa);
        QFETCH(int, shading);
        const Rig rig = layerRig(ShadingModel(shading));
        QVERIFY(setScene(emittingSphere(), rig));
        const std::optional<RenderLayers> l = layers(layerSettings(Quality(quality), msaa));
        QVERIFY(l);
        QCOMPARE(groupNames(l->groups), QStringList({"key", "fill", "sun", "rim", "environment", "emissive",
                                                     "ambient", "background"}));
        QCOMPARE(l->groupImages.size(), l->groups.size());
        QVERIFY(m_gl->renderer().rig() == rig); // restored
        const double error = groupSumError(*l);
        qInfo("Σ groups − beauty: %.3g of the brightest channel", error);
        QVERIFY2(error <= kSumTolerance, qPrintable(QStringLiteral("Σ groups − beauty: %1").arg(error)));
        // Every group but the background adds light somewhere; nothing else is in the radiance.
        for (size_t g = 0; g < l->groups.size(); ++g) {
            double peak = 0.0, low = 0.0;
            for (const glm::vec4& p : l->groupImages[g].pixels)
                peak = std::max(peak, double(std::max({p.r, p.g, p.b}))),
                low = std::min(low, double(std::min({p.r, p.g, p.b})));
            const bool background = l->groups[g].kind == LightGroupKind::Background;
            QVERIFY2(background ? peak == 0.0 : peak > 1e-3, qPrintable(l->groups[g].name));
            QVERIFY2(low >= -kSumTolerance, qPrintable(l->groups[g].name)); // no negative light
        }
        // The beauty is the renderer's own radiance for these settings.
        const FloatImage beauty = beautyOf(rig, layerSettings(Quality(quality), msaa));
        QCOMPARE(maxRelativeDifference(beauty, l->beauty), 0.0);
    }

    void scaledGroupEqualsScaledLights_data() { addTiers(); }
    void scaledGroupEqualsScaledLights() {
        QFETCH(int, quality);
        QFETCH(int, msaa);
        QFETCH(int, shading);
        const Rig rig = layerRig(ShadingModel(shading));
        QVERIFY(setScene(emittingSphere(), rig));
        const RenderSettings s = layerSettings(Quality(quality), msaa);
        const std::optional<RenderLayers> l = layers(s);
        QVERIFY(l);
        for (const char* group : {"key", "fill", "sun"}) {
            const double k = 2.7;
            LightMix mix;
            mix.groups[QString::fromLatin1(group)].ev = std::log2(k);
            const FloatImage mixed = mixGroupImages(*l, mix);
            Rig scaled = rig;
            for (int i : l->groups[size_t(groupIndex(l->groups, QString::fromLatin1(group)))].lights)
                scaled.lights[size_t(i)].intensity *= k;
            const Relative d = relativeDifference(mixed, beautyOf(scaled, s));
            QVERIFY2(d.bright > 100, group);
            QVERIFY2(d.mean <= kMixTolerance && d.max <= kMixTolerance,
                     qPrintable(
                         QStringLiteral("%1 ×%2: mean %3, max %4").arg(group).arg(k).arg(d.mean).arg(d.max)));
        }
    }

    void switchedOffGroupEqualsDisabledLights() {
        const Rig rig = layerRig(ShadingModel::Pbr);
        QVERIFY(setScene(emittingSphere(), rig));
        const RenderSettings s = layerSettings(Quality::Exact, 4);
        const std::optional<RenderLayers> l = layers(s);
        QVERIFY(l);
        for (const char* group : {"key", "fill", "rim"}) {
            LightMix mix;
            mix.groups[QString::fromLatin1(group)].enabled = false;
            Rig off = rig;
            for (int i : l->groups[size_t(groupIndex(l->groups, QString::fromLatin1(group)))].lights)
                off.lights[size_t(i)].enabled = false;
            const Relative d = relativeDifference(mixGroupImages(*l, mix), beautyOf(off, s));
            QVERIFY2(d.mean <= kMixTolerance && d.max <= kMixTolerance,
                     qPrintable(QStringLiteral("%1 off: mean %2, max %3").arg(group).arg(d.mean).arg(d.max)));
        }
    }

    // The editor's "Apply to rig": the mix written into the rig renders the mixed image.
    void appliedMixEqualsMixedImage_data() { addTiers(); }
    void appliedMixEqualsMixedImage() {
        QFETCH(int, quality);
        QFETCH(int, msaa);
        QFETCH(int, shading);
        const Rig rig = layerRig(ShadingModel(shading));
        QVERIFY(setScene(emittingSphere(), rig));
        const RenderSettings s = layerSettings(Quality(quality), msaa);
        const std::optional<RenderLayers> l = layers(s);
        QVERIFY(l);
        LightMix mix;
        mix.groups["key"] = {true, 0.8, {1.0, 0.85, 0.6}};
        mix.groups["fill"] = {true, -1.5, {0.7, 0.8, 1.0}};
        mix.groups["sun"] = {true, -1.0, {1.0, 1.0, 1.0}};
        mix.groups["rim"] = {false, 1.0, {2.0, 1.0, 0.5}};
        mix.groups["ambient"] = {true, 1.0, {1.0, 1.0, 1.0}};
        mix.groups["environment"] = {true, -0.5, {1.0, 1.0, 1.0}};
        QStringList notApplied;
        const Rig applied = applyLightMix(rig, l->groups, mix, &notApplied);
        QVERIFY2(notApplied.isEmpty(), qPrintable(notApplied.join('\n')));
        const Relative d = relativeDifference(mixGroupImages(*l, mix), beautyOf(applied, s));
        qInfo("mixed image against the applied rig's render: mean %.3g, max %.3g", d.mean, d.max);
        QVERIFY2(d.mean <= kMixTolerance && d.max <= kMixTolerance,
                 qPrintable(QStringLiteral("mean %1, max %2").arg(d.mean).arg(d.max)));
    }

    // The one departure from "Apply to rig" renders the mixed image: the shadow array holds one resolution,
    // the largest any caster asks for, so switching off that caster lowers the others' in a fresh render,
    // while their group images keep the beauty's. Exact again when they asked for the same resolution.
    void switchingOffTheSharpestCasterChangesTheOthersMaps() {
        for (int keyResolution : {512, 1024}) {
            Rig rig = layerRig(ShadingModel::Classic, false);
            rig.lights[0].shadow.resolution = keyResolution; // the sun's is 1024
            QVERIFY(setScene(emittingSphere(), rig));
            const RenderSettings s = layerSettings(Quality::Exact, 0);
            const std::optional<RenderLayers> l = layers(s);
            QVERIFY(l);
            LightMix mix;
            mix.groups["sun"].enabled = false;
            const Rig applied = applyLightMix(rig, l->groups, mix, nullptr);
            const Relative d = relativeDifference(mixGroupImages(*l, mix), beautyOf(applied, s));
            const QByteArray what = QStringLiteral("key at %1: mean %2, max %3")
                                        .arg(keyResolution)
                                        .arg(d.mean)
                                        .arg(d.max)
                                        .toUtf8();
            if (keyResolution < 1024)
                QVERIFY2(d.max > 1e-2, what.constData());
            else
                QVERIFY2(d.mean <= kMixTolerance && d.max <= kMixTolerance, what.constData());
        }
    }

    // With several casters the shadow array takes the largest resolution asked for: the key's own pass
    // keeps the sun's 1024, so its shadow edge is the beauty's. Rendered at its own 512 it would differ.
    void groupPassKeepsTheBeautysShadowMaps() {
        const Rig rig = layerRig(ShadingModel::Classic, false);
        QVERIFY(setScene(emittingSphere(), rig));
        const RenderSettings s = layerSettings(Quality::Exact, 0);
        const std::optional<RenderLayers> l = layers(s);
        QVERIFY(l);
        const int key = groupIndex(l->groups, "key"), emissive = groupIndex(l->groups, "emissive");
        QVERIFY(key >= 0 && emissive >= 0);
        Rig alone = groupPassRig(rig, l->groups[size_t(key)], 0, {}); // its own resolution
        FloatImage own = beautyOf(alone, s);
        for (size_t i = 0; i < own.pixels.size(); ++i)
            own.pixels[i] -= glm::vec4(glm::vec3(l->groupImages[size_t(emissive)].pixels[i]), 0.0f);
        const Relative naive = relativeDifference(own, l->groupImages[size_t(key)]);
        QVERIFY2(naive.max > 1e-3, qPrintable(QStringLiteral("max %1").arg(naive.max))); // the test can fail
        QVERIFY(groupSumError(*l) <= kSumTolerance);
    }

    // A shadow catcher's composite (1 − shadowed/unshadowed over the environment behind it) is not a sum
    // of lights: it goes to "background" as the darkening of the environment group's unshadowed pixels.
    void catcherGoesToBackground() {
        Rig rig = layerRig(ShadingModel::Pbr);
        rig.ground.mode = GroundMode::Catcher;
        QVERIFY(setScene(emittingSphere(), rig));
        const std::optional<RenderLayers> l = layers(layerSettings(Quality::Exact, 0));
        QVERIFY(l);
        QVERIFY(groupSumError(*l) <= kSumTolerance);
        const int background = groupIndex(l->groups, "background");
        double darkest = 0.0, brightest = 0.0;
        for (const glm::vec4& p : l->groupImages[size_t(background)].pixels)
            darkest = std::min(darkest, double(p.g)), brightest = std::max(brightest, double(p.g));
        QVERIFY2(darkest < -0.01, qPrintable(QString::number(darkest))); // the shadows on the catcher
        QVERIFY2(brightest <= kSumTolerance, qPrintable(QString::number(brightest)));
    }

    // The editor's Mixer dock shows progress and can cancel: one call per pass (the G-buffer, the beauty,
    // the emission's and the six lit groups' here), and a cancel leaves the rig as it was.
    void progressAndCancel() {
        const Rig rig = layerRig(ShadingModel::Classic);
        QVERIFY(setScene(emittingSphere(), rig));
        std::vector<std::pair<int, int>> calls;
        QString error;
        RasterLayersStats stats;
        const auto l = renderRasterLayers(*m_gl, groundCamera(), kLayerSize, layerSettings(Quality::Fast, 0),
                                          &error, &stats, [&](int done, int total) {
                                              calls.emplace_back(done, total);
                                              return true;
                                          });
        QVERIFY2(l, qPrintable(error));
        QCOMPARE(int(calls.size()), 10); // before each of 9 passes, and once at the end
        for (size_t i = 0; i < calls.size(); ++i)
            QCOMPARE(calls[i], std::make_pair(int(i), 9));
        QCOMPARE(stats.passes, 8); // the G-buffer is no radiance pass
        QCOMPARE(stats.groups, 8);
        const auto cancelled =
            renderRasterLayers(*m_gl, groundCamera(), kLayerSize, layerSettings(Quality::Fast, 0), &error,
                               nullptr, [&](int done, int) { return done < 4; });
        QVERIFY(!cancelled);
        QCOMPARE(error, QStringLiteral("cancelled"));
        QVERIFY(m_gl->renderer().rig() == rig);
    }

    void refusesMoreThanOneTile() {
        const Rig rig = layerRig(ShadingModel::Classic);
        QVERIFY(setScene(emittingSphere(), rig));
        m_gl->setMaxTileSize(64);
        QString error;
        const auto l =
            renderRasterLayers(*m_gl, groundCamera(), kLayerSize, layerSettings(Quality::Exact, 0), &error);
        m_gl->setMaxTileSize(4096);
        QVERIFY(!l);
        QVERIFY2(error.contains("one tile") && error.contains("64x64") && error.contains("96x72"),
                 qPrintable(error));
        QVERIFY(m_gl->renderer().rig() == rig);
    }

    // A plane facing +Z seen straight on from z = 3: depth 3, normal +Z, the material's base colour.
    void auxiliaryLayersOnAPlane() {
        const auto plane = planeScene();
        Rig rig = layerRig(ShadingModel::Classic, false);
        rig.ground.mode = GroundMode::Off;
        QVERIFY(setScene(plane, rig));
        ViewCamera cam;
        cam.eye = {0.0, 0.0, 3.0};
        cam.yfovDeg = 30.0; // the plane (half size 2) fills the image
        const std::optional<RenderLayers> l = layers(layerSettings(Quality::Exact, 0), cam);
        QVERIFY(l);
        QCOMPARE(l->depth.width, kLayerSize.width());
        const glm::vec3 base(plane->materials[0].baseColor);
        for (size_t i = 0; i < l->depth.pixels.size(); ++i) {
            QCOMPARE(l->depth.pixels[i].w, 1.0f);
            QVERIFY2(std::abs(l->depth.pixels[i].x - 3.0f) < 1e-4f,
                     qPrintable(QString::number(l->depth.pixels[i].x)));
            QVERIFY(glm::length(glm::vec3(l->normal.pixels[i]) - glm::vec3(0, 0, 1)) < 1e-5f);
            QVERIFY(glm::length(glm::vec3(l->albedo.pixels[i]) - base) < 1e-6f);
        }
    }

    // The bundled Avocado (normal map, textures): covered pixels have a unit normal facing the camera, a
    // depth within the model's bounding sphere along the view axis and a base colour in [0, 1]; empty
    // pixels hold kBackgroundDepth; coverage is the beauty's.
    void auxiliaryLayersOnTheAvocado() {
        const QString path = QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/avocado/Avocado.gltf");
        ModelLoadResult loaded = loadModel(path);
        QVERIFY2(loaded.model, qPrintable(loaded.error));
        const std::shared_ptr<Model> model = loaded.model;
        const Bounds b = model->bounds;
        Rig rig = layerRig(ShadingModel::Pbr, false);
        rig.ground.mode = GroundMode::Off;
        QVERIFY(setScene(model, rig));
        ViewCamera cam;
        cam.eye = b.center() + glm::dvec3(0.3, 0.2, 1.0) * b.radius() * 3.0;
        cam.target = b.center();
        const std::optional<RenderLayers> l = layers(layerSettings(Quality::Exact, 0), cam);
        QVERIFY(l);
        const glm::dvec3 forward = cam.forward();
        const double centre = glm::dot(b.center() - cam.eye, forward);
        int covered = 0, facing = 0, agree = 0;
        for (size_t i = 0; i < l->depth.pixels.size(); ++i) {
            const bool surface = l->depth.pixels[i].w > 0.0f;
            agree += surface == (l->beauty.pixels[i].a > 0.5f);
            if (!surface) {
                QCOMPARE(l->depth.pixels[i].x, kBackgroundDepth);
                QCOMPARE(glm::vec3(l->normal.pixels[i]), glm::vec3(0.0f));
                continue;
            }
            ++covered;
            const double depth = l->depth.pixels[i].x;
            QVERIFY2(depth >= centre - b.radius() && depth <= centre + b.radius(),
                     qPrintable(QString::number(depth)));
            const glm::dvec3 n(glm::vec3(l->normal.pixels[i]));
            QVERIFY(std::abs(glm::length(n) - 1.0) < 1e-4);
            facing += glm::dot(n, -forward) > 0.0;
            const glm::vec3 a(l->albedo.pixels[i]);
            QVERIFY(a.r >= 0.0f && a.g >= 0.0f && a.b >= 0.0f && a.r <= 1.0f && a.g <= 1.0f && a.b <= 1.0f);
        }
        QVERIFY2(covered > 500, qPrintable(QString::number(covered)));
        QVERIFY2(facing >= 0.95 * covered, qPrintable(QStringLiteral("%1 of %2").arg(facing).arg(covered)));
        QVERIFY2(agree >= 0.98 * double(l->depth.pixels.size()), qPrintable(QString::number(agree)));
    }
};

} // namespace

LR_GL_TEST_MAIN(TestRasterLayers)
#include "tst_rasterlayers.moc"
