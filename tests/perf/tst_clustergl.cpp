// Clustered shading on the GPU gives the same radiance as shading every light: a sphere and a plane lit by
// 256 small-range lights (and a few unbounded ones) rendered with RenderSettings::clusteredShading on and
// off, compared in float (RGBA32F read-back) to 1e-5. Skips without a display.
#include "render/cluster.h"
#include "render/glfixture.h" // tests/render
#include "render/offscreen.h"
#include "render/scenes.h"

#include <QTest>
#include <random>

using namespace lr;
using namespace lr::test;

class TestClusterGl : public QObject {
    Q_OBJECT
  private:
    static Rig manyLights(int n, quint32 seed) {
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::vector<Light> lights;
        const FalloffModel models[] = {FalloffModel::RangePower, FalloffModel::RangeQuadratic,
                                       FalloffModel::InverseSquare, FalloffModel::InversePolynomial};
        for (int i = 0; i < n; ++i) {
            glm::dvec3 p(u(rng), u(rng), u(rng));
            p = glm::normalize(p) * (1.0 + 0.15 * std::abs(u(rng))); // just above the unit sphere
            Light l = point(p, models[i % 4], 0.25 + 0.2 * std::abs(u(rng)));
            l.color = {0.5 + 0.5 * u(rng), 0.6, 0.5 - 0.4 * u(rng)};
            l.intensity = 0.5;
            if (i % 5 == 0) { // some spots, bounded by their sphere
                l.type = LightType::Spot;
                l.direction = glm::normalize(-p);
                l.cone = {ConeModel::Smooth, 0.3, 0.7, 1.0};
            }
            lights.push_back(l);
        }
        lights.push_back(directional({-1, -1, -1}, DiffuseModel::Lambert)); // evaluated everywhere
        lights.back().intensity = 0.05;
        lights.push_back(point({0, 2, 2}, FalloffModel::InverseSquare, -1.0)); // range-less
        lights.back().intensity = 0.3;
        return rigOf(std::move(lights));
    }

    static void compare(OffscreenRenderer& gl, const ViewCamera& cam, QSize size, int expectedClusters) {
        for (ShadingPath path : {ShadingPath::Forward, ShadingPath::Deferred}) {
            compare(gl, cam, size, expectedClusters, path);
            if (QTest::currentTestFailed()) return;
        }
    }
    static void compare(OffscreenRenderer& gl, const ViewCamera& cam, QSize size, int expectedClusters,
                        ShadingPath path) {
        RenderSettings s;
        s.msaaSamples = 0;
        s.shadingPath = path;
        FloatImage on, off;
        QString error;
        s.clusteredShading = 1;
        QVERIFY2(gl.renderRadiance(cam, size, s, &on, &error), qPrintable(error));
        QVERIFY(gl.renderer().stats().clustered == (expectedClusters > 0));
        const qint64 refs = gl.renderer().stats().clusterLightRefs;
        s.clusteredShading = 0;
        QVERIFY2(gl.renderRadiance(cam, size, s, &off, &error), qPrintable(error));
        QVERIFY(!gl.renderer().stats().clustered);
        double maxDiff = 0.0, maxValue = 0.0;
        int lit = 0;
        for (size_t i = 0; i < on.pixels.size(); ++i)
            for (int c = 0; c < 4; ++c) {
                const double a = on.pixels[i][c], b = off.pixels[i][c];
                QVERIFY(std::isfinite(a));
                maxDiff = std::max(maxDiff, std::abs(a - b) / std::max(1.0, std::abs(b)));
                maxValue = std::max(maxValue, b);
                if (c == 0 && b > 0.01) ++lit;
            }
        QVERIFY2(maxDiff <= 1e-5, qPrintable(QStringLiteral("max difference %1").arg(maxDiff)));
        QVERIFY(lit > on.width * on.height / 20); // the comparison saw lit pixels
        QVERIFY(maxValue > 0.05);
        // The clusters hold far fewer entries than every light in every cluster (clusters × 258).
        const qint64 all = qint64(render::ClusterGrid{}.count()) * 258;
        QVERIFY2(refs > 0 && refs < all / 10, qPrintable(QStringLiteral("%1 of %2").arg(refs).arg(all)));
    }

  private slots:
    void clusteredEqualsUnclustered() {
        LR_REQUIRE_DISPLAY();
        OffscreenRenderer gl;
        QString error;
        QVERIFY2(gl.initialize(&error), qPrintable(error));
        gl.renderer().setModel(sphereScene());
        gl.renderer().setRig(manyLights(256, 7));
        compare(gl, sphereCamera(), QSize(320, 180), 1);
        ViewCamera close = sphereCamera(); // near the surface: lights around and behind the eye
        close.eye = {0.2, 0.3, 1.35};
        compare(gl, close, QSize(257, 143), 1);
        gl.renderer().setModel(planeScene());
        compare(gl, planeCamera(), QSize(200, 200), 1);
    }

    void automaticOnlyWithManyBoundedLights() {
        LR_REQUIRE_DISPLAY();
        OffscreenRenderer gl;
        QString error;
        QVERIFY2(gl.initialize(&error), qPrintable(error));
        gl.renderer().setModel(sphereScene());
        RenderSettings s;
        s.msaaSamples = 0;
        gl.renderer().setRig(manyLights(4, 1));
        QVERIFY(gl.renderFrame(sphereCamera(), QSize(64, 64), s, &error));
        QVERIFY(!gl.renderer().stats().clustered);
        gl.renderer().setRig(manyLights(64, 1));
        QVERIFY(gl.renderFrame(sphereCamera(), QSize(64, 64), s, &error));
        QVERIFY(gl.renderer().stats().clustered);
    }
};

LR_GL_TEST_MAIN(TestClusterGl)
#include "tst_clustergl.moc"
