// Issue 39: a spot with a checkerboard gobo in the double reference (render/reference.h), end to end:
// the PNG decoded in the import worker (scene/lightassets.h), attached to the spot by makeReferenceScene,
// and the ground under it lit exactly on the squares geometry puts white (x / (H tan(outer) scale) picks
// the square) and not at all on the black ones; the same rig without its gobo lights every point of the
// cone. Runs against LIGHTRIG_EXECUTABLE (the worker).
#include "core/prepare.h"
#include "model/isolatedimport.h"
#include "render/gbuffer.h"
#include "render/reference.h"
#include "scene/scenedescription.h"

#include <QImage>
#include <QTemporaryDir>
#include <QTest>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

using namespace lr;
using V = glm::dvec3;

namespace {

constexpr int kSquares = 4;
constexpr double kHeight = 2.0, kOuter = 40.0;

// A one-row G-buffer of ground points (normal +Y), seen through `view`.
GBuffer groundRow(const glm::dmat4& view, const std::vector<V>& points) {
    GBuffer g;
    for (FloatImage* f : {&g.position, &g.normal, &g.albedo, &g.specular, &g.emissive}) {
        f->width = int(points.size()), f->height = 1;
        f->pixels.assign(points.size(), glm::vec4(0.0f));
    }
    for (size_t i = 0; i < points.size(); ++i) {
        g.position.pixels[i] = glm::vec4(glm::vec3(view * glm::dvec4(points[i], 1.0)), 1.0f);
        g.normal.pixels[i] = glm::vec4(glm::vec3(view * glm::dvec4(0.0, 1.0, 0.0, 0.0)), 1.0f);
        g.albedo.pixels[i] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
        g.specular.pixels[i] = glm::vec4(0.0f, 0.0f, 0.0f, 16.0f);
    }
    return g;
}

} // namespace

class TestReferenceGobo : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE)); }
    void checkerboardLandsWhereGeometrySays_data() {
        QTest::addColumn<double>("rotation");
        QTest::addColumn<double>("scale");
        QTest::newRow("plain") << 0.0 << 1.0;
        QTest::newRow("turned 30, scale 0.7") << 30.0 << 0.7;
    }
    void checkerboardLandsWhereGeometrySays() {
        QFETCH(double, rotation);
        QFETCH(double, scale);
        QTemporaryDir dir;
        QImage board(kSquares * 16, kSquares * 16, QImage::Format_RGB888);
        for (int y = 0; y < board.height(); ++y)
            for (int x = 0; x < board.width(); ++x)
                board.setPixelColor(x, y, (x / 16 + y / 16) % 2 == 0 ? Qt::white : Qt::black);
        QVERIFY(board.save(dir.filePath("board.png")));

        Rig rig;
        Light spot = makeLight(LightType::Spot, QStringLiteral("Gobo"));
        spot.position = V(0.0, kHeight, 0.0);
        spot.direction = V(0.0, -1.0, 0.0);
        spot.falloff = {};
        spot.cone.model = ConeModel::Hard;
        spot.cone.outer = kOuter;
        spot.gobo = GoboSpec{QStringLiteral("board.png"), {}, scale, rotation};
        rig.lights = {spot};
        resolveLightFiles(rig, dir.path());
        SceneDescription scene;
        scene.setRig(rig);
        QVERIFY2(scene.lightAssets().errors.isEmpty(), qPrintable(scene.lightAssets().errors.join('\n')));

        const double h = std::tan(glm::radians(kOuter)) * scale, reach = kHeight * h;
        const AreaAxes axes = areaAxes(spot.direction, rotation);
        std::vector<V> points;
        std::vector<int> expect; // 1 white, 0 black; points near a square's edge are left out
        for (int i = 0; i < 30; ++i)
            for (int j = 0; j < 30; ++j) {
                const V p((i + 0.5) / 30.0 * 2.4 * reach - 1.2 * reach, 0.0,
                          (j + 0.5) / 30.0 * 2.4 * reach - 1.2 * reach);
                const double gx = glm::dot(p, axes.x) / reach, gy = glm::dot(p, axes.y) / reach;
                const double col = (gx + 1.0) / 2.0 * kSquares, row = (1.0 - gy) / 2.0 * kSquares;
                if (std::min(std::abs(col - std::round(col)), std::abs(row - std::round(row))) < 0.1)
                    continue;
                const bool inCone = std::hypot(p.x, p.z) < kHeight * std::tan(glm::radians(kOuter)) * 0.98;
                if (std::hypot(p.x, p.z) > kHeight * std::tan(glm::radians(kOuter)) * 0.98 &&
                    std::hypot(p.x, p.z) < kHeight * std::tan(glm::radians(kOuter)) * 1.02)
                    continue;
                const bool inside = std::abs(gx) < 1.0 && std::abs(gy) < 1.0;
                points.push_back(p);
                expect.push_back(inCone && inside && (int(std::floor(col)) + int(std::floor(row))) % 2 == 0);
            }
        const glm::dmat4 view = glm::lookAt(V(0.0, 5.0, 3.0), V(0.0), V(0.0, 1.0, 0.0));
        QString error;
        auto rs = makeReferenceScene(scene, view, RenderSettings(), &error);
        QVERIFY2(rs, qPrintable(error));
        QVERIFY(rs->lights.at(0).gobo != nullptr);
        const ReferenceImage img = computeReference(groundRow(view, points), *rs);
        int lit = 0, dark = 0;
        for (size_t i = 0; i < points.size(); ++i) {
            const double r = img.radiance[i].x;
            if (expect[i]) {
                QVERIFY2(
                    r > 0.0,
                    qPrintable(QStringLiteral("(%1, %2) should be lit").arg(points[i].x).arg(points[i].z)));
                ++lit;
            } else {
                QVERIFY2(r == 0.0, qPrintable(QStringLiteral("(%1, %2) should be dark: %3")
                                                  .arg(points[i].x)
                                                  .arg(points[i].z)
                                                  .arg(r)));
                ++dark;
            }
        }
        QVERIFY(lit > 50 && dark > 50);

        // Without its gobo the same spot lights every point of its cone.
        rig.lights[0].gobo.reset();
        scene.setRig(rig);
        auto plain = makeReferenceScene(scene, view, RenderSettings(), &error);
        QVERIFY2(plain, qPrintable(error));
        const ReferenceImage open = computeReference(groundRow(view, points), *plain);
        for (size_t i = 0; i < points.size(); ++i)
            if (std::hypot(points[i].x, points[i].z) < kHeight * std::tan(glm::radians(kOuter)) * 0.98)
                QVERIFY(open.radiance[i].x > 0.0);
    }
    void aMissingImageRendersUnshapedAndSaysWhy() {
        Rig rig;
        Light spot = makeLight(LightType::Spot, QStringLiteral("Gobo"));
        spot.gobo = GoboSpec{QStringLiteral("/nonexistent/board.png"), {}, 1.0, 0.0};
        rig.lights = {spot};
        SceneDescription scene;
        scene.setRig(rig);
        QCOMPARE(scene.lightAssets().errors.size(), 1);
        QVERIFY2(scene.lightAssets().errors[0].startsWith(
                     QStringLiteral("lights[0].gobo.file: /nonexistent/board.png: no such file")),
                 qPrintable(scene.lightAssets().errors[0]));
        QString error;
        auto rs = makeReferenceScene(scene, glm::dmat4(1.0), RenderSettings(), &error);
        QVERIFY2(rs, qPrintable(error));
        QVERIFY(rs->lights.at(0).gobo == nullptr);
    }
};

QTEST_GUILESS_MAIN(TestReferenceGobo)
#include "tst_referencegobo.moc"
