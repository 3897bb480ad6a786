// Issue 39: a spot's gobo in the path tracer. A plane lit by a spot with a checkerboard gobo (decoded in
// the import worker, LIGHTRIG_EXECUTABLE), one bounce: the traced image equals core's shade term with the
// same image at every pixel (no noise: a point light's next-event estimate is exact), so its squares land
// where the reference and geometry put them; dark squares stay exactly black.
#include "tracescenes.h"

#include "core/prepare.h"
#include "core/shade.h"
#include "model/isolatedimport.h"
#include "trace/camerarays.h"

#include <QImage>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;
using namespace tracetest;

class TestTraceGobo : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE)); }
    void checkerboardMatchesTheShadeTerm() {
        QTemporaryDir dir;
        QImage board(64, 64, QImage::Format_RGB888);
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x)
                board.setPixelColor(x, y, (x / 16 + y / 16) % 2 == 0 ? Qt::white : Qt::black);
        QVERIFY(board.save(dir.filePath("board.png")));
        Model plane = quadsModel(
            {{glm::dvec3(-5, 0, 5), glm::dvec3(5, 0, 5), glm::dvec3(5, 0, -5), glm::dvec3(-5, 0, -5)}},
            pbrMaterial(glm::vec3(0.8f), 0.0f, 1.0f));
        Rig rig = pbrRig(false);
        Light spot;
        spot.type = LightType::Spot;
        spot.position = {0.0, 2.0, 0.0};
        spot.direction = {0.0, -1.0, 0.0};
        spot.intensity = 5.0;
        spot.falloff.model = FalloffModel::InverseSquare;
        spot.cone.model = ConeModel::Hard;
        spot.cone.outer = 40.0;
        spot.gobo = GoboSpec{QStringLiteral("board.png"), {}, 1.0, 20.0};
        rig.lights = {spot};
        resolveLightFiles(rig, dir.path());
        auto scene = describe(plane, rig);
        QVERIFY2(scene->lightAssets().gobos.at(0), qPrintable(scene->lightAssets().errors.join('\n')));
        QString error;
        const auto traced = trace::TraceScene::build(*scene, &error);
        QVERIFY2(traced, qPrintable(error));
        const ViewCamera camera = lookAt({0.0, 6.0, 0.01}, glm::dvec3(0.0), 40.0);
        const QSize size(48, 48);
        trace::TraceSettings settings;
        settings.bounces = 1;
        settings.jitter = false;
        trace::PathTracer tracer(traced, camera, size, settings, 2);
        tracer.render(1);
        const FloatImage image = tracer.image();
        const trace::CameraRays rays(camera, size);
        const glm::dmat4 view = camera.view();
        auto lights = scene->lights(view);
        lights.at(0).gobo = scene->lightAssets().gobos[0].get();
        const auto st = scene->shadeSettings();
        int covered = 0, matching = 0, dark = 0, lit = 0;
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x) {
                const auto s = tracetest::viewSurfaceAt(*traced, rays, view, x, y);
                if (!s) continue;
                const glm::dvec3 expected = lighting::shadeSurface<double>(*s, lights, st);
                const glm::dvec3 got(image.at(x, y));
                ++covered;
                if (expected.x == 0.0) {
                    ++dark;
                    matching += got.x == 0.0 ? 1 : 0;
                } else {
                    ++lit;
                    matching += glm::length(got - expected) / glm::length(expected) < 1e-3 ? 1 : 0;
                }
            }
        QVERIFY(covered > 1000);
        QVERIFY(dark > 200 && lit > 200);
        QVERIFY2(matching == covered, qPrintable(QStringLiteral("%1 of %2").arg(matching).arg(covered)));
    }
};

QTEST_GUILESS_MAIN(TestTraceGobo)
#include "tst_trace_gobo.moc"
