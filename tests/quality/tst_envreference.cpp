// The double-precision reference with an environment (issue 15): the procedural studio loaded as the
// renderer would shade with it, integrated at every covered pixel of the G-buffer (reference.h): the
// image differs from the one without it, stays finite, adds exactly what EnvironmentField::integrate
// gives for the pixel's surface (seeded by the pixel), which agrees with the definition's sum over the
// texels; the integration converges below half an 8-bit level on most pixels; runQualityBench reports the
// environment and the reference's convergence, and prints nothing of it without an environment.
#include "qualityscenes.h"

#include "render/benchreport.h"
#include "render/gbuffer.h"
#include "render/qualitybench.h"
#include "scene/environmentloader.h"

#include <QJsonArray>
#include <QTest>

using namespace lr;
using namespace lr::test;

namespace {

// LIGHTRIG_ENVREF_SIZE=WxH measures the reference at another size (docs/quality.md's figures).
const QSize kSize = [] {
    const QStringList wh = qEnvironmentVariable("LIGHTRIG_ENVREF_SIZE").split(QLatin1Char('x'));
    return wh.size() == 2 && wh[0].toInt() >= 16 && wh[1].toInt() >= 16 ? QSize(wh[0].toInt(), wh[1].toInt())
                                                                        : QSize(96, 72);
}();

Environment studioEnvironment() {
    Environment e;
    e.source = EnvironmentSource::Studio;
    Softbox key;
    key.azimuth = 40.0, key.elevation = 35.0, key.width = 50.0, key.height = 35.0, key.intensity = 6.0;
    Softbox rim;
    rim.azimuth = 200.0, rim.elevation = 15.0, rim.width = 20.0, rim.height = 60.0, rim.intensity = 10.0;
    rim.color = {0.6, 0.8, 1.0};
    e.studio.softboxes = {key, rim};
    e.intensity = -1.0;
    e.rotation = 30.0;
    return e;
}

Rig rigWith(ShadingModel model, bool environment) {
    Rig rig;
    rig.shading.model = model;
    Light sun = makeLight(LightType::Directional, QStringLiteral("sun"));
    sun.direction = glm::normalize(glm::dvec3(-0.3, -1.0, -0.5));
    sun.intensity = model == ShadingModel::Pbr ? 1.5 : 0.6;
    rig.lights = {sun};
    if (environment) rig.environment = studioEnvironment();
    return rig;
}

struct Frame {
    GBuffer g;
    glm::dmat4 view{1.0};
    SceneFrame frame;
};

} // namespace

class TestEnvReference : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;
    std::shared_ptr<const LoadedEnvironment> m_studio;

    Frame gbuffer(std::shared_ptr<Model> model, const Rig& rig, const ViewCamera& cam) {
        Frame f;
        QString error;
        if (!m_gl.setModel(model, &error)) qFatal("%s", qPrintable(error));
        m_gl.setRig(rig);
        RenderSettings settings;
        settings.msaaSamples = 0;
        settings.hdrFloat32 = true;
        if (!m_gl.renderGBuffer(cam, kSize, settings, &f.g, &error)) qFatal("%s", qPrintable(error));
        f.view = m_gl.renderer().effectiveCamera(cam).view();
        f.frame = m_gl.renderer().sceneFrame();
        return f;
    }

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
        const EnvironmentLoadResult loaded = loadEnvironment(studioEnvironment(), QString());
        QVERIFY2(loaded.environment, qPrintable(loaded.error));
        m_studio = loaded.environment;
    }

    void referenceWithEnvironment_data() {
        QTest::addColumn<bool>("pbr");
        QTest::addRow("classic sphere") << false;
        QTest::addRow("pbr spheres") << true;
    }

    void referenceWithEnvironment() {
        QFETCH(bool, pbr);
        const ShadingModel model = pbr ? ShadingModel::Pbr : ShadingModel::Classic;
        const auto scene = pbr ? pbrSpheresScene() : sphereScene();
        const ViewCamera cam = pbr ? pbrSpheresCamera() : sphereCamera();
        const Rig with = rigWith(model, true), without = rigWith(model, false);
        const Frame f = gbuffer(scene, with, cam);
        RenderSettings settings;
        QString error;
        const auto plain = makeReferenceScene(*scene, without, f.frame, f.view, settings, &error, m_studio);
        const auto lit = makeReferenceScene(*scene, with, f.frame, f.view, settings, &error, m_studio);
        QVERIFY2(plain && lit, qPrintable(error));
        QVERIFY(!plain->environment); // the rig says none: the loaded environment is not used
        QVERIFY(lit->environment);
        QCOMPARE(lit->environmentSource, QStringLiteral("studio"));
        // Nor without a loaded one.
        QVERIFY(!makeReferenceScene(*scene, with, f.frame, f.view, settings, &error)->environment);

        QElapsedTimer clock;
        clock.start();
        const ReferenceImage a = computeReference(f.g, *plain);
        const double plainMs = clock.restart();
        const ReferenceImage b = computeReference(f.g, *lit);
        const double litMs = clock.elapsed();
        QVERIFY(!a.environment && b.environment);
        const EnvironmentConvergence c = environmentConvergence(b);
        qInfo(
            "%s: reference %.0f ms without the environment, %.0f ms with; %lld covered pixels, %.2f%% above "
            "half a level (worst %.2f, mean %.3f levels), %.0f sample pairs per pixel",
            pbr ? "pbr" : "classic", plainMs, litMs, static_cast<long long>(c.pixels), 100.0 * c.shareOver(),
            c.maxErrorLevels, c.meanErrorLevels, c.meanSamples);
        QVERIFY(c.pixels > kSize.width() * kSize.height() / 8);
        // Converged: at most 0.5 % of pixels above half a level (0 % of either scene on 2026-11-26, the
        // mirror-like metal 2 % before the lobe window; the rest only where the stopping rule's last step
        // lands a hair above the target).
        QVERIFY2(c.shareOver() <= 0.005, qPrintable(QString::number(c.shareOver())));
        QVERIFY2(c.maxErrorLevels <= 1.0, qPrintable(QString::number(c.maxErrorLevels)));
        int brighter = 0;
        for (size_t i = 0; i < b.radiance.size(); ++i) {
            QCOMPARE(a.covered[i], b.covered[i]);
            const glm::dvec3 d = b.radiance[i] - a.radiance[i];
            QVERIFY(std::isfinite(b.radiance[i].x) && std::isfinite(b.radiance[i].y) &&
                    std::isfinite(b.radiance[i].z));
            if (!b.covered[i]) {
                QCOMPARE(b.radiance[i], glm::dvec3(0.0));
                continue;
            }
            // The studio's radiance is positive everywhere: every covered pixel gains light (the
            // estimate's own noise is far below what it adds).
            if (d.x > 0.0 && d.y > 0.0 && d.z > 0.0) ++brighter;
        }
        QCOMPARE(brighter, int(c.pixels));
        QVERIFY(compareWithReference(a.srgb, b).maxLevels > 10); // visibly different images

        // Pixel by pixel: exactly the field's integral for the pixel's surface with the pixel's seed, and
        // that agrees with the definition (one light per texel) within its error.
        const glm::dmat3 toWorld(lit->viewToWorld);
        int checked = 0;
        for (int y = 3; y < kSize.height(); y += 7)
            for (int x = 5; x < kSize.width(); x += 9) {
                const size_t i = size_t(y) * size_t(kSize.width()) + size_t(x);
                if (!b.covered[i]) continue;
                const lighting::Surface<double> s = render::surfaceAt(f.g, x, y);
                const envintegrate::Estimate e = lit->environment->integrate(
                    s, lit->settings, toWorld, std::uint64_t(i), lit->environmentConvergence, a.radiance[i]);
                QVERIFY2(glm::length(b.radiance[i] - a.radiance[i] - e.radiance) <=
                             1e-12 * glm::length(e.radiance),
                         qPrintable(QStringLiteral("pixel %1,%2").arg(x).arg(y)));
                if (checked < 6) {
                    const glm::dvec3 sum =
                        envintegrate::environmentRadianceBySum(*lit->environment, s, lit->settings, toWorld);
                    for (int ch = 0; ch < 3; ++ch)
                        QVERIFY2(std::abs(e.radiance[ch] - sum[ch]) <=
                                     5.0 * e.standardError[ch] + e.bound[ch] + 2e-3 * sum[ch],
                                 qPrintable(QStringLiteral("pixel %1,%2 channel %3: %4 vs the sum %5 (se %6)")
                                                .arg(x)
                                                .arg(y)
                                                .arg(ch)
                                                .arg(e.radiance[ch])
                                                .arg(sum[ch])
                                                .arg(e.standardError[ch])));
                }
                ++checked;
            }
        QVERIFY(checked > 10);
    }

    // Bench: the environment is integrated and reported; without one nothing is said about it.
    void benchReportsEnvironment() {
        BenchScene scene;
        scene.name = QStringLiteral("sphere");
        scene.model = sphereScene();
        scene.rig = rigWith(ShadingModel::Classic, true);
        scene.camera = sphereCamera();
        scene.environment = m_studio;
        BenchOptions o;
        o.size = QSize(64, 48);
        o.frames = 2;
        o.warmupFrames = 1;
        o.uberShader = false;
        o.tiers = {Quality::Exact};
        BenchReport report;
        QString error;
        QVERIFY2(runQualityBench({scene}, o, &report, &error) == BenchStatus::Ok, qPrintable(error));
        QCOMPARE(int(report.results.size()), 1);
        const BenchResult& r = report.results[0];
        QVERIFY(r.hasErrors && r.hasEnvironment);
        QCOMPARE(r.environmentSource, QStringLiteral("studio"));
        QVERIFY(r.environment.pixels == r.errors.pixels && r.referenceMs > 0.0);
        const QString table = benchTable(report);
        QVERIFY2(table.contains(QStringLiteral("Environment integrated in the double-precision reference")) &&
                     table.contains(QStringLiteral("sphere: studio, reference")),
                 qPrintable(table));
        const QJsonObject json = benchJson(report);
        QVERIFY(json.contains(QStringLiteral("environment_reference")));
        const QJsonObject first = json.value(QStringLiteral("results")).toArray().first().toObject();
        QCOMPARE(first.value(QStringLiteral("environment_source")).toString(), QStringLiteral("studio"));
        QVERIFY(first.value(QStringLiteral("environment_over_half_level_share")).toDouble(-1.0) >= 0.0);

        scene.rig.environment = Environment{}; // none: the loaded one is ignored, nothing reported
        BenchReport none;
        QVERIFY2(runQualityBench({scene}, o, &none, &error) == BenchStatus::Ok, qPrintable(error));
        QVERIFY(!none.results[0].hasEnvironment);
        QVERIFY(!benchTable(none).contains(QStringLiteral("Environment")));
        QVERIFY(!benchJson(none).contains(QStringLiteral("environment_reference")));
        QVERIFY(!benchJson(none)
                     .value(QStringLiteral("results"))
                     .toArray()
                     .first()
                     .toObject()
                     .contains(QStringLiteral("environment_source")));
    }
};

LR_GL_TEST_MAIN(TestEnvReference)

#include "tst_envreference.moc"
