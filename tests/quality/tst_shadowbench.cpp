// The shadow measure in the bench (issue 14): runQualityBench reports it per tier when the rig has casters
// and not otherwise, and its reference holds the traced shadow of a sphere on the floor (full shadow, lit
// floor and a penumbra). With the shared models present, the helmet with every spot casting measures what
// the traced reference costs (docs/quality.md quotes the figures; the GPU tiers' own shadows are measured
// where the renderer draws them).
#include "shadowscenes.h"

#include "render/benchreport.h"
#include "render/glfixture.h"
#include "render/offscreen.h"
#include "render/qualitybench.h"
#include "render/reference.h"

#include "model/modelloader.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTest>
#include <glm/geometric.hpp>

using namespace lr;
using namespace lr::test;

namespace {

BenchScene sphereOnFloor(bool shadows) {
    BenchScene scene;
    scene.name = QStringLiteral("sphere over floor");
    auto model = std::make_shared<Model>(
        ShadowSceneBuilder().floor(0.0, 3.0).sphere({0.0, 1.2, 0.0}, 0.8, 48, 24).build());
    model->materials[0].baseColor = {0.7f, 0.7f, 0.7f, 1.0f};
    model->materials[0].specular = {0.0f, 0.0f, 0.0f};
    scene.model = model;
    Light spot = makeLight(LightType::Spot, QStringLiteral("key"));
    spot.position = {1.0, 4.0, 0.5};
    spot.direction = glm::normalize(glm::dvec3(0.0, 0.0, 0.0) - spot.position);
    spot.cone.inner = 35.0, spot.cone.outer = 50.0;
    spot.falloff = {};
    spot.shadow.enabled = shadows;
    spot.shadow.size = 0.3;
    Light fill = makeLight(LightType::Directional, QStringLiteral("fill")); // never casts here
    fill.intensity = 0.2;
    scene.rig.lights = {spot, fill};
    scene.rig.ambient = glm::dvec3(0.03);
    scene.camera.eye = {0.0, 3.5, 5.0};
    scene.camera.target = {0.0, 0.4, 0.0};
    scene.camera.yfovDeg = 45.0;
    return scene;
}

BenchOptions quickOptions(QSize size) {
    BenchOptions o;
    o.size = size;
    o.warmupFrames = 1;
    o.frames = 2;
    o.tiers = {Quality::Exact, Quality::Fast};
    o.uberShader = false;
    o.keepImages = true;
    return o;
}

} // namespace

class TestShadowBench : public QObject {
    Q_OBJECT

  private slots:
    void initTestCase() { LR_REQUIRE_DISPLAY(); }

    void benchReportsShadowsOnlyWithCasters() {
        for (bool shadows : {false, true}) {
            BenchReport report;
            QString error;
            QVERIFY2(runQualityBench({sphereOnFloor(shadows)}, quickOptions({96, 72}), &report, &error) ==
                         BenchStatus::Ok,
                     qPrintable(error));
            QCOMPARE(int(report.results.size()), 2);
            QCOMPARE(benchHasShadows(report), shadows);
            QCOMPARE(benchTable(report).contains(QStringLiteral("shadow off")), shadows);
            for (const BenchResult& r : report.results) {
                QCOMPARE(r.hasShadowErrors, shadows);
                if (!shadows) continue;
                const ShadowFigures& f = r.shadow;
                qInfo() << toString(r.quality) << "shadow: compared" << f.compared << "band" << f.band
                        << "differing" << f.differing << "mean" << f.meanLevels;
                QVERIFY(f.compared > 0 && f.band > 0 && f.compared + f.band <= r.errors.pixels);
                QVERIFY(f.differing <= f.compared && std::isfinite(f.meanLevels) && f.meanLevels >= 0.0);
            }
        }
    }

    // The reference itself: the floor under the sphere is in full shadow, around it lit, with a band.
    void referenceHasTheSphereShadow() {
        const BenchScene scene = sphereOnFloor(true);
        OffscreenRenderer gl;
        QString error;
        QVERIFY2(gl.initialize(&error) && gl.setModel(scene.model, &error), qPrintable(error));
        gl.setRig(scene.rig);
        RenderSettings s;
        s.msaaSamples = 0;
        GBuffer g;
        QVERIFY2(gl.renderGBuffer(scene.camera, {96, 72}, s, &g, &error), qPrintable(error));
        const glm::dmat4 view = gl.renderer().effectiveCamera(scene.camera).view();
        const auto rs =
            makeReferenceScene(*scene.model, scene.rig, gl.renderer().sceneFrame(), view, s, &error);
        QVERIFY2(rs, qPrintable(error));
        const ReferenceImage r = computeReference(g, *rs);
        QCOMPARE(r.casters, 1);
        int unlit = 0, lit = 0, partial = 0, band = 0;
        for (size_t i = 0; i < r.covered.size(); ++i) {
            if (!r.covered[i]) continue;
            const std::uint8_t v = r.visibility[i];
            (v == 0 ? unlit : v == 255 ? lit : partial) += 1;
            band += r.shadowClass[i] == 2;
        }
        qInfo() << "covered pixels: unlit" << unlit << "lit" << lit << "partial" << partial << "band" << band;
        QVERIFY(unlit > 100 && lit > 100 && partial > 10 && band >= partial);
    }

    // What the traced reference costs on the bench's helmet with its 8 spots all casting and a ground.
    void helmetWithEveryLightCasting() {
        const QString path = QStringLiteral(LIGHTRIG_SHARED_MODELS "/bench/helmet_8spot.glb");
        if (!QFile::exists(path)) QSKIP("needs ../shared/models/bench/helmet_8spot.glb (the shared models)");
        const ModelLoadResult loaded = loadModel(path);
        QVERIFY2(loaded.ok(), qPrintable(loaded.error));
        BenchScene scene;
        scene.name = QStringLiteral("helmet_8spot, all cast");
        scene.model = loaded.model;
        scene.rig = loaded.model->lights;
        scene.rig.ground.mode = GroundMode::Visible;
        int casters = 0;
        for (Light& l : scene.rig.lights) {
            l.shadow.enabled = true;
            l.shadow.size = 0.05;
            casters += l.hasShadow();
        }
        QCOMPARE(casters, 8);
        const QSize size =
            qEnvironmentVariableIsSet("LIGHTRIG_SHADOW_BENCH_FULL") ? QSize(1280, 720) : QSize(320, 180);
        const auto view = standardView(standardViewNames().front(), loaded.model->bounds,
                                       double(size.width()) / size.height());
        QVERIFY(view);
        scene.camera = *view;
        BenchReport report;
        QString error;
        QVERIFY2(runQualityBench({scene}, quickOptions(size), &report, &error) == BenchStatus::Ok,
                 qPrintable(error));
        qInfo().noquote() << QStringLiteral("%1×%2: reference %3 ms (%4 triangles)")
                                 .arg(size.width())
                                 .arg(size.height())
                                 .arg(report.referenceMs, 0, 'f', 0)
                                 .arg(loaded.model->triangleCount());
        qInfo().noquote() << benchTable(report);
        for (const BenchResult& r : report.results)
            QVERIFY(r.hasShadowErrors && r.shadow.compared + r.shadow.band > 0);
        if (const QString out = qEnvironmentVariable("LIGHTRIG_SHADOW_BENCH_OUT"); !out.isEmpty()) {
            report.results[0].reference.save(out + QStringLiteral("/reference.png"));
            report.results[0].image.save(out + QStringLiteral("/exact.png"));
            benchDifferenceImage(report.results[0].image, report.results[0].reference)
                .save(out + QStringLiteral("/difference.png"));
        }
        // The same reference without shadows, for what tracing costs.
        for (Light& l : scene.rig.lights)
            l.shadow.enabled = false;
        BenchOptions once = quickOptions(size);
        once.tiers = {Quality::Exact};
        once.frames = 1;
        BenchReport plain;
        QVERIFY2(runQualityBench({scene}, once, &plain, &error) == BenchStatus::Ok, qPrintable(error));
        qInfo().noquote()
            << QStringLiteral("the same reference without shadows: %1 ms").arg(plain.referenceMs, 0, 'f', 0);
        QVERIFY(!benchHasShadows(plain));
    }
};

LR_GL_TEST_MAIN(TestShadowBench)

#include "tst_shadowbench.moc"
