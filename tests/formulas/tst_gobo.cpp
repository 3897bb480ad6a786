// Issue 39: a gobo's projection (core/gobo.h) and its tint in the shade term (core/shade.h): the image
// lands where the cone's geometry says, turned by its rotation, scaled by its scale, black outside.
#include "core/gobo.h"
#include "core/prepare.h"
#include "core/rig.h"
#include "core/shade.h"

#include <QtTest>
#include <glm/trigonometric.hpp>

using namespace lr;

namespace {

// A checkerboard of n × n squares, white where (column + row) is even.
GoboImage checkerboard(int n, int texelsPerSquare) {
    GoboImage g;
    g.width = g.height = n * texelsPerSquare;
    g.rgb.resize(size_t(g.width) * size_t(g.height) * 3);
    for (int y = 0; y < g.height; ++y)
        for (int x = 0; x < g.width; ++x) {
            const float v = ((x / texelsPerSquare + y / texelsPerSquare) % 2 == 0) ? 1.0f : 0.0f;
            for (int c = 0; c < 3; ++c)
                g.rgb[(size_t(y) * size_t(g.width) + size_t(x)) * 3 + size_t(c)] = v;
        }
    return g;
}

} // namespace

class GoboTest : public QObject {
    Q_OBJECT
  private slots:
    void axisHitsTheCentre() {
        glm::dvec2 uv;
        const glm::dvec3 d(0, 0, -1), X(1, 0, 0), Y(0, 1, 0);
        QVERIFY(gobo::project(d, d, X, Y, 0.5, &uv));
        QCOMPARE(uv.x, 0.5);
        QCOMPARE(uv.y, 0.5);
    }
    void edgesOfTheSquare() {
        // h = tan(30°): the direction at 30° towards +X lands on the right edge, towards +Y on the top.
        const double h = gobo::halfExtent(glm::radians(30.0), 1.0);
        const glm::dvec3 d(0, 0, -1), X(1, 0, 0), Y(0, 1, 0);
        const double a = glm::radians(29.9);
        glm::dvec2 uv;
        QVERIFY(gobo::project(glm::dvec3(std::sin(a), 0, -std::cos(a)), d, X, Y, h, &uv));
        QVERIFY(uv.x > 0.99 && uv.x <= 1.0);
        QCOMPARE(uv.y, 0.5);
        QVERIFY(gobo::project(glm::dvec3(0, std::sin(a), -std::cos(a)), d, X, Y, h, &uv));
        QVERIFY(uv.y < 0.01 && uv.y >= 0.0); // up is row 0
        const double b = glm::radians(30.1);
        QVERIFY(!gobo::project(glm::dvec3(std::sin(b), 0, -std::cos(b)), d, X, Y, h, &uv));
        QVERIFY(!gobo::project(-d, d, X, Y, h, &uv)); // behind the light
        // Scale 2: the same direction lands halfway to the edge.
        QVERIFY(gobo::project(glm::dvec3(std::sin(a), 0, -std::cos(a)), d, X, Y, 2.0 * h, &uv));
        QVERIFY(std::abs(uv.x - 0.75) < 0.01);
    }
    void bilinearBetweenCentres() {
        GoboImage g;
        g.width = 2;
        g.height = 1;
        g.rgb = {0, 0, 0, 1, 1, 1};
        QCOMPARE(gobo::sample(g, 0.25, 0.5).x, 0.0); // the first texel's centre
        QCOMPARE(gobo::sample(g, 0.5, 0.5).x, 0.5);  // halfway
        QCOMPARE(gobo::sample(g, 1.0, 0.5).x, 1.0);  // clamped beyond the last centre
        QCOMPARE(gobo::sample(g, 0.0, 0.5).x, 0.0);
    }
    // A spot straight down from height H over the plane y = 0, a 4 × 4 checkerboard gobo: each point of the
    // plane is lit exactly where geometry puts a white square (x/(H h), z/(H h) picks the square), black
    // on the others and outside the square; rotating the gobo 90° swaps the squares' colours (n even).
    void checkerboardOnAPlane_data() {
        QTest::addColumn<double>("rotation");
        QTest::addColumn<double>("scale");
        QTest::newRow("plain") << 0.0 << 1.0;
        QTest::newRow("turned 90") << 90.0 << 1.0;
        QTest::newRow("scale 0.5") << 0.0 << 0.5;
    }
    void checkerboardOnAPlane() {
        QFETCH(double, rotation);
        QFETCH(double, scale);
        const int n = 4;
        const GoboImage board = checkerboard(n, 8);
        Rig rig;
        Light spot;
        spot.type = LightType::Spot;
        spot.position = glm::dvec3(0, 2, 0);
        spot.direction = glm::dvec3(0, -1, 0);
        spot.cone.model = ConeModel::Hard;
        spot.cone.outer = 60.0;
        spot.gobo = GoboSpec{{}, {}, scale, rotation};
        rig.lights.push_back(spot);
        const SceneFrame frame;
        const glm::dmat4 view(1.0); // world = view
        lighting::ShadeLight<double> l = prepareLight(rig, frame, view, rig.lights[0]);
        l.gobo = &board;
        const double H = 2.0, h = std::tan(glm::radians(60.0)) * scale;
        const AreaAxes axes = areaAxes(spot.direction, rotation);
        lighting::ShadeSettings<double> st = prepareSettings(rig, frame);
        int lit = 0, dark = 0;
        for (int i = 0; i < 400; ++i) {
            // Points on the plane, away from the squares' edges (a texel's bilinear blend).
            const double x = (double(i % 20) + 0.5) / 20.0 * 2.4 * H * h - 1.2 * H * h;
            const double z = (double(i / 20) + 0.5) / 20.0 * 2.4 * H * h - 1.2 * H * h;
            const glm::dvec3 p(x, 0, z);
            // Where geometry says: the plane point in the gobo's frame, over H h, onto the n × n squares.
            const double gx = glm::dot(p, axes.x) / (H * h), gy = glm::dot(p, axes.y) / (H * h);
            const double col = (gx + 1.0) / 2.0 * n, row = (1.0 - gy) / 2.0 * n;
            const double edge = std::min(std::abs(col - std::round(col)), std::abs(row - std::round(row)));
            if (edge < 0.1) continue;
            const bool inside = std::abs(gx) < 1.0 && std::abs(gy) < 1.0;
            const bool inCone = glm::length(glm::dvec2(x, z)) / H < std::tan(glm::radians(60.0));
            const bool white = inside && inCone && (int(std::floor(col)) + int(std::floor(row))) % 2 == 0;
            lighting::Surface<double> s;
            s.position = p;
            s.normal = glm::dvec3(0, 1, 0);
            const glm::dvec3 c = lighting::shadeLight(l, s, st, glm::dvec3(0, 1, 0));
            if (white) {
                QVERIFY2(c.x > 0.0, qPrintable(QStringLiteral("(%1, %2) should be lit").arg(x).arg(z)));
                ++lit;
            } else {
                QVERIFY2(c.x == 0.0, qPrintable(QStringLiteral("(%1, %2) should be dark").arg(x).arg(z)));
                ++dark;
            }
        }
        QVERIFY(lit > 20);
        QVERIFY(dark > 20);
        // Without the image the same spot lights every point in its cone: the gobo did the darkening.
        l.gobo = nullptr;
        lighting::Surface<double> s;
        s.position = glm::dvec3(0.01, 0, 0.01);
        s.normal = glm::dvec3(0, 1, 0);
        QVERIFY(lighting::shadeLight(l, s, st, glm::dvec3(0, 1, 0)).x > 0.0);
    }
    // The 90° turn moves the square that was at the image's top left to its top right: the plane's colours
    // under (+x, +z) swap for an even board.
    void rotationTurnsTheImage() {
        const GoboImage board = checkerboard(2, 4);
        const glm::dvec3 d(0, -1, 0);
        const AreaAxes a0 = areaAxes(d, 0.0), a90 = areaAxes(d, 90.0);
        const glm::dvec3 w = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
        const glm::dvec3 t0 = gobo::tint(board, w, d, a0.x, a0.y, 1.0);
        const glm::dvec3 t90 = gobo::tint(board, w, d, a90.x, a90.y, 1.0);
        QCOMPARE(t0.x + t90.x, 1.0); // one white, one black
    }
};

QTEST_APPLESS_MAIN(GoboTest)
#include "tst_gobo.moc"
