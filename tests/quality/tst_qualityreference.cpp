// The bench's measurement itself: the double reference agrees with the exact tier to within the 8-bit
// rounding, detects a known difference (half an EV of exposure), and ranks the tiers' errors as their
// approximations imply; runQualityBench produces complete, plausible results for a small scene.
//
// Stated bounds (8-bit sRGB levels over the covered pixels; linear: glfixture's relative per channel):
//   exact     linear 1e-4 (as tests/render); 8-bit: share of pixels off by > 1 level <= 0.1 %
//   balanced  linear 2e-3;                   8-bit: share off by > 1 level <= 1 %, mean <= exact's + 0.1
// (One level is the 8-bit rounding: a flat area whose exact value sits near a rounding boundary may be
// off by one level everywhere, so the mean of even the exact tier can reach 1/3 or more.)
//   fast      finite and no better than exact; mean <= 64 levels only as a sanity bound (per-vertex lighting
//             on these coarse meshes loses highlights, cone and range edges: several levels are normal).
//             Where Gouraud is exact (a plane, directional lights, the infinite viewer) it must equal exact
//             within one level.
#include "qualityscenes.h"

#include "render/qualitybench.h"

#include <QTest>

using namespace lr;
using namespace lr::test;

namespace {

const QSize kSize(120, 90);
// B5 + B6 (balanced, physically based): relative per-channel tolerance in linear radiance and the mean
// 8-bit levels above exact's, set from their measured error (docs/quality.md).
constexpr double kPbrBalancedTolerance = 0.05;
constexpr double kPbrBalancedMeanLevels = 0.5;

Rig mixedRig() {
    for (const RigCase& c : rigCases())
        if (QLatin1String(c.name) == QLatin1String("mixed-all-types")) return c.make();
    return {};
}

} // namespace

class TestQualityReference : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
    }

    void tiersAgainstReference_data() {
        QTest::addColumn<bool>("sphere");
        QTest::addColumn<int>("rigIndex");
        const auto cases = rigCases();
        for (int i = 0; i < int(cases.size()); ++i) {
            QTest::addRow("sphere/%s", cases[size_t(i)].name) << true << i;
            QTest::addRow("grid/%s", cases[size_t(i)].name) << false << i;
        }
    }

    void tiersAgainstReference() {
        QFETCH(bool, sphere);
        QFETCH(int, rigIndex);
        const Rig rig = rigCases()[size_t(rigIndex)].make();
        auto model = sphere ? sphereScene() : gridPlane(2.0, 48);
        const ViewCamera cam = sphere ? sphereCamera() : planeCamera();
        const TierFrame exact = renderTier(m_gl, model, rig, cam, kSize, Quality::Exact, 1e-4);
        const TierFrame balanced = renderTier(m_gl, model, rig, cam, kSize, Quality::Balanced, 2e-3);
        const TierFrame fast = renderTier(m_gl, model, rig, cam, kSize, Quality::Fast, 1.0);
        qInfo().noquote() << "exact:   " << exact.summary();
        qInfo().noquote() << "balanced:" << balanced.summary();
        qInfo().noquote() << "fast:    " << fast.summary();
        for (const TierFrame* f : {&exact, &balanced, &fast}) {
            QVERIFY2(f->error.isEmpty(), qPrintable(f->error));
            QCOMPARE(f->levels.nonFinite, 0);
            QVERIFY2(f->levels.pixels > kSize.width() * kSize.height() / 5, qPrintable(f->summary()));
        }
        QVERIFY2(exact.linear.failures == 0 && exact.linear.skipped <= exact.linear.covered / 50,
                 qPrintable(exact.summary()));
        QVERIFY2(exact.levels.shareOver1() <= 0.001, qPrintable(exact.summary()));
        QVERIFY2(balanced.linear.failures == 0, qPrintable(balanced.summary()));
        QVERIFY2(balanced.levels.meanLevels <= exact.levels.meanLevels + 0.1 &&
                     balanced.levels.shareOver1() <= 0.01,
                 qPrintable(balanced.summary()));
        QVERIFY2(fast.levels.meanLevels <= 64.0, qPrintable(fast.summary()));
        QVERIFY2(fast.levels.meanLevels >= exact.levels.meanLevels, qPrintable(fast.summary()));
    }

    // Physically based shading (issue 13): every tier against the same double reference, on the spheres
    // of metallic 0/1 × roughness 0/0.4/1. Balanced with B5 (Schlick as a spherical Gaussian) and B6
    // (Filament's visibility) on as well as with the shipped set; fast is the per-vertex split of
    // shadevertex.glsl (shadeVertexPbr), bounded as the classic fast tier is.
    void pbrTiersAgainstReference_data() {
        QTest::addColumn<int>("rigIndex");
        const auto cases = pbrRigCases();
        for (int i = 0; i < int(cases.size()); ++i)
            QTest::addRow("%s", cases[size_t(i)].name) << i;
    }

    void pbrTiersAgainstReference() {
        QFETCH(int, rigIndex);
        const Rig rig = pbrRigCases()[size_t(rigIndex)].make();
        const auto model = pbrSpheresScene();
        const ViewCamera cam = pbrSpheresCamera();
        RenderSettings brdf;
        brdf.approximations = render::approx::kDefault | render::approx::kB5 | render::approx::kB6;
        const TierFrame exact = renderTier(m_gl, model, rig, cam, kSize, Quality::Exact, 1e-4);
        const TierFrame balanced = renderTier(m_gl, model, rig, cam, kSize, Quality::Balanced, 2e-3);
        const TierFrame approximated =
            renderTier(m_gl, model, rig, cam, kSize, Quality::Balanced, kPbrBalancedTolerance, brdf);
        const TierFrame fast = renderTier(m_gl, model, rig, cam, kSize, Quality::Fast, 1.0);
        qInfo().noquote() << "exact:      " << exact.summary();
        qInfo().noquote() << "balanced:   " << balanced.summary();
        qInfo().noquote() << "b5+b6:      " << approximated.summary();
        qInfo().noquote() << "fast:       " << fast.summary();
        for (const TierFrame* f : {&exact, &balanced, &approximated, &fast}) {
            QVERIFY2(f->error.isEmpty(), qPrintable(f->error));
            QCOMPARE(f->levels.nonFinite, 0);
            QVERIFY2(f->levels.pixels > kSize.width() * kSize.height() / 8, qPrintable(f->summary()));
        }
        QVERIFY2(exact.linear.failures == 0 && exact.linear.skipped <= exact.linear.covered / 50,
                 qPrintable(exact.summary()));
        QVERIFY2(exact.levels.shareOver1() <= 0.001, qPrintable(exact.summary()));
        QVERIFY2(balanced.linear.failures == 0, qPrintable(balanced.summary()));
        QVERIFY2(balanced.levels.meanLevels <= exact.levels.meanLevels + 0.1 &&
                     balanced.levels.shareOver1() <= 0.01,
                 qPrintable(balanced.summary()));
        QVERIFY2(approximated.linear.failures == 0, qPrintable(approximated.summary()));
        QVERIFY2(approximated.levels.meanLevels <= exact.levels.meanLevels + kPbrBalancedMeanLevels,
                 qPrintable(approximated.summary()));
        QVERIFY2(fast.levels.meanLevels <= 64.0, qPrintable(fast.summary()));
        QVERIFY2(fast.levels.meanLevels >= exact.levels.meanLevels, qPrintable(fast.summary()));
    }

    // Gouraud shading is measurably worse than per-pixel on a curved, specular scene.
    void fastIsAnApproximation() {
        const TierFrame exact =
            renderTier(m_gl, sphereScene(), mixedRig(), sphereCamera(), kSize, Quality::Exact, 1e-4);
        const TierFrame fast =
            renderTier(m_gl, sphereScene(), mixedRig(), sphereCamera(), kSize, Quality::Fast, 1.0);
        qInfo().noquote() << "exact:" << exact.summary() << "\nfast: " << fast.summary();
        QVERIFY2(fast.levels.meanLevels > exact.levels.meanLevels + 0.05, qPrintable(fast.summary()));
        QVERIFY2(fast.levels.maxLevels > 2, qPrintable(fast.summary()));
    }

    // Per-vertex lighting is exact where the lighting is constant over each triangle: directional lights on
    // a plane seen by the infinite viewer (diffuse, specular and rim terms are then the same everywhere).
    void fastExactWhereLinear() {
        Rig rig =
            rigOf({directional({-0.3, -0.4, -1.0}, DiffuseModel::Lambert),
                   directional({0.5, -0.2, -1.0}, DiffuseModel::HalfLambert), rim({1.0, -0.5, -0.3}, 2.0)});
        rig.shading.viewer = ViewerModel::Infinite;
        rig.shading.shininess = 12.0;
        rig.ambient = {0.05, 0.05, 0.05};
        const TierFrame exact =
            renderTier(m_gl, gridPlane(2.0, 8), rig, planeCamera(), kSize, Quality::Exact, 1e-4);
        const TierFrame fast =
            renderTier(m_gl, gridPlane(2.0, 8), rig, planeCamera(), kSize, Quality::Fast, 1e-3);
        qInfo().noquote() << "exact:" << exact.summary() << "\nfast: " << fast.summary();
        QVERIFY2(fast.levels.maxLevels <= 1 && fast.linear.failures == 0, qPrintable(fast.summary()));
        QVERIFY2(fast.levels.pixels == exact.levels.pixels && fast.levels.pixels > 1000,
                 qPrintable(fast.summary()));
    }

    // F1-PBR's split (shadevertex.glsl shadeVertexPbr / shadePixelPbr) is exact algebra: where the lights'
    // D·Vis and Schlick weight are the same at every vertex — directional lights on a plane seen from
    // far away through a narrow lens (V varies by < 0.002 rad) — fast must equal exact, with F0, c_diff,
    // occlusion, the light's and the scene's ambient, rim and emissive applied per pixel.
    void pbrFastSplitExactWhereLightingIsConstant() {
        auto model = gridPlane(2.0, 8);
        Material& m = model->materials[0];
        m.pbr = true, m.metallic = 0.5f, m.roughness = 0.7f, m.emissive = {0.02f, 0.01f, 0.0f};
        Light half = directional({0.5, -0.2, -1.0}, DiffuseModel::HalfLambert);
        half.ambient = glm::dvec3(0.2, 0.1, 0.05);
        Rig rig = pbrRig(
            {directional({-0.3, -0.4, -1.0}, DiffuseModel::Lambert), half, rim({1.0, -0.5, -0.3}, 2.0)},
            glm::dvec3(0.1, 0.1, 0.12));
        ViewCamera far;
        far.eye = {0.0, 0.0, 1000.0};
        far.target = {0.0, 0.0, 0.0};
        far.yfovDeg = 0.25;
        const TierFrame exact = renderTier(m_gl, model, rig, far, kSize, Quality::Exact, 1e-4);
        const TierFrame fast = renderTier(m_gl, model, rig, far, kSize, Quality::Fast, 1e-3);
        qInfo().noquote() << "exact:" << exact.summary() << "\nfast: " << fast.summary();
        QVERIFY2(exact.error.isEmpty() && fast.error.isEmpty(), qPrintable(exact.error + fast.error));
        QVERIFY2(fast.linear.failures == 0 && fast.levels.maxLevels <= 1, qPrintable(fast.summary()));
        QVERIFY2(fast.levels.pixels == exact.levels.pixels && fast.levels.pixels > 1000,
                 qPrintable(fast.summary()));
        QVERIFY2(fast.linear.maxReference > 0.05, "the plane should be lit");
    }

    // A known difference: the frame rendered at +0.5 EV against the reference at 0 EV.
    void detectsAKnownDifference() {
        const Rig rig = mixedRig();
        QString error;
        const auto model = sphereScene();
        QVERIFY(m_gl.setModel(model, &error));
        m_gl.setRig(rig);
        RenderSettings s;
        s.msaaSamples = 0;
        s.toneMap = ToneMap::Reinhard;
        GBuffer g;
        QVERIFY2(m_gl.renderGBuffer(sphereCamera(), kSize, s, &g, &error), qPrintable(error));
        const glm::dmat4 view = m_gl.renderer().effectiveCamera(sphereCamera()).view();
        const auto scene = makeReferenceScene(*model, rig, m_gl.renderer().sceneFrame(), view, s, &error);
        QVERIFY2(scene, qPrintable(error));
        const ReferenceImage ref = computeReference(g, *scene);
        const QImage same = m_gl.renderImage(sphereCamera(), kSize, s, 1, &error);
        s.exposureEV = 0.5;
        const QImage brighter = m_gl.renderImage(sphereCamera(), kSize, s, 1, &error);
        const ErrorFigures a = compareWithReference(same, ref), b = compareWithReference(brighter, ref);
        qInfo() << "same: mean" << a.meanLevels << "PSNR" << a.psnrDb << "| +0.5 EV: mean" << b.meanLevels
                << "PSNR" << b.psnrDb;
        QVERIFY(a.maxLevels <= 2 && a.psnrDb > 50.0);
        QVERIFY(b.meanLevels > 5.0 && b.psnrDb < 35.0 && b.shareOver1() > 0.5);
        // Background pixels are not compared: the covered count is the G-buffer's.
        std::int64_t covered = 0;
        for (std::uint8_t c : ref.covered)
            covered += c;
        QCOMPARE(a.pixels, covered);
    }

    // The über-shader is a variant of its own (every light model compiled in) that draws the same pixels.
    void uberShaderIsAnotherVariantWithTheSamePixels() {
        QString error;
        QVERIFY(m_gl.setModel(sphereScene(), &error));
        m_gl.setRig(rigOf({point({0.5, 0.5, 1.5}, FalloffModel::InverseSquare)}));
        RenderSettings s;
        s.msaaSamples = 0;
        const QImage specialised = m_gl.renderImage(sphereCamera(), kSize, s, 1, &error);
        const int variants = m_gl.renderer().stats().shaderVariantsCached;
        s.forceAllFeatures = true;
        const QImage uber = m_gl.renderImage(sphereCamera(), kSize, s, 1, &error);
        QCOMPARE(m_gl.renderer().stats().shaderVariantsCached, variants + 1);
        QVERIFY(!m_gl.renderImage(sphereCamera(), kSize, s, 1, &error).isNull());
        QCOMPARE(m_gl.renderer().stats().shaderVariantsCached, variants + 1); // compiled once
        const ErrorFigures f = compareSrgb8(specialised.constBits(), uber.constBits(),
                                            std::int64_t(kSize.width()) * kSize.height());
        QVERIFY2(f.maxLevels <= 1, qPrintable(QString::number(f.maxLevels)));
    }

    void benchRunsEveryTier() {
        BenchScene scene;
        scene.name = QStringLiteral("sphere");
        scene.model = sphereScene();
        scene.rig = mixedRig();
        scene.camera = sphereCamera();
        BenchOptions o;
        o.size = QSize(80, 60);
        o.frames = 3;
        o.warmupFrames = 1;
        BenchReport report;
        QString error;
        int calls = 0;
        double last = -1.0;
        bool monotonic = true;
        const BenchStatus status =
            runQualityBench({scene}, o, &report, &error, [&](double f, const QString&) {
                ++calls;
                monotonic = monotonic && f >= last - 1e-9;
                last = f;
                return true;
            });
        QVERIFY2(status == BenchStatus::Ok, qPrintable(error));
        QVERIFY(calls > 4 && monotonic && last == 1.0);
        QCOMPARE(int(report.results.size()), 4); // exact, balanced, fast, über
        QVERIFY(!report.glDescription.isEmpty());
        for (const BenchResult& r : report.results) {
            QVERIFY(r.msMin > 0.0 && r.msMin <= r.msMedian && r.msMedian <= r.msMax);
            QVERIFY(r.firstFrameMs >= r.firstDrawMs && r.firstDrawMs > 0.0);
            QVERIFY(r.variants >= 1);
            QCOMPARE(r.lightsInRig, int(scene.rig.lights.size()));
            QVERIFY(r.lightsUploaded >= 1 &&
                    r.lightsUploaded < r.lightsInRig); // the disabled light is not uploaded
            QCOMPARE(r.triangles, qint64(scene.model->triangleCount()));
            QVERIFY(r.hasErrors && r.errors.pixels > 0);
            QCOMPARE(r.errors.nonFinite, 0);
            QCOMPARE(r.msaaSamples, r.quality == Quality::Fast ? 0 : 4);
        }
        QVERIFY(report.results[0].quality == Quality::Exact);
        QCOMPARE(report.results[0].speedUp, 1.0);
        QVERIFY(report.results[3].uberShader);
        QVERIFY(report.results[0].errors.meanLevels <= 0.05);
        // The über-shader evaluates the same lights: the same pixels within rounding.
        QVERIFY(std::abs(report.results[3].errors.meanLevels - report.results[0].errors.meanLevels) < 0.02);

        // Cancelling stops the run.
        BenchReport cancelled;
        const BenchStatus stopped =
            runQualityBench({scene}, o, &cancelled, &error, [](double f, const QString&) { return f < 0.3; });
        QVERIFY(stopped == BenchStatus::Cancelled);
        QVERIFY(cancelled.results.size() < 4);
    }
};

LR_GL_TEST_MAIN(TestQualityReference)

#include "tst_qualityreference.moc"
