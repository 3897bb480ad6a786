// Issue 12 item 4: a selected light's gizmo is clearly distinct from the others (its lines in the selection
// colour, its icon larger), whatever the lights' own colours.
#include "render/gizmos.h"

#include <QTest>
#include <glm/ext/matrix_transform.hpp>

using namespace lr;
using namespace lr::render;

class TestGizmos : public QObject {
    Q_OBJECT
  private slots:
    void selectedGizmosStandOut() {
        Rig rig;
        Light a = makeLight(LightType::Spot, QStringLiteral("a"));
        a.color = glm::dvec3(0.2, 0.9, 0.3);
        rig.lights = {a, a};
        rig.lights[1].position = glm::dvec3(-2.0, 2.0, 2.0);
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 10), glm::dvec3(0), glm::dvec3(0, 1, 0));
        GizmoOptions options;
        options.selected = {1};
        const Bounds bounds{glm::dvec3(-1), glm::dvec3(1)};
        const GizmoGeometry g = buildGizmos(rig, SceneFrame{}, bounds, view, options);
        QCOMPARE(int(g.points.size()), 2);
        const float plain = g.points[0].point.x, chosen = g.points[1].point.x;
        QVERIFY2(chosen >= 1.6f * plain, qPrintable(QStringLiteral("%1 vs %2").arg(chosen).arg(plain)));
        // Lines: the unselected light's in its own colour, below full strength; the selected one's opaque in
        // the selection colour. Both lights draw the same number of vertices, unselected first.
        QVERIFY(!g.lines.empty() && g.lines.size() % 2 == 0);
        const GizmoVertex& first = g.lines.front();
        const GizmoVertex& last = g.lines.back();
        QVERIFY(first.color.a < 0.9f);
        QVERIFY(glm::vec3(first.color) != glm::vec3(kSelectedColor));
        QVERIFY(glm::vec3(last.color) == glm::vec3(kSelectedColor));
        int selectedLines = 0;
        for (const GizmoVertex& v : g.lines)
            if (glm::vec3(v.color) == glm::vec3(kSelectedColor)) {
                ++selectedLines;
                QVERIFY(v.color.a >= 0.75f);
            }
        QVERIFY(selectedLines > 0 && selectedLines < int(g.lines.size()));
    }

    // Issue 39: a rect's barn doors add each corner's slanted edge and the four far edges (8 lines), and
    // flaps in the emitter's plane (90°) draw none.
    void barnDoorsDrawTheirEdges() {
        Rig rig;
        rig.lights = {makeLight(LightType::Rect, QStringLiteral("box"))};
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 10), glm::dvec3(0), glm::dvec3(0, 1, 0));
        const Bounds bounds{glm::dvec3(-1), glm::dvec3(1)};
        const auto lines = [&] { return buildGizmos(rig, SceneFrame{}, bounds, view, {}).lines.size(); };
        const size_t plain = lines();
        rig.lights[0].barnDoors = BarnDoors{45.0, 0.3};
        QCOMPARE(lines(), plain + 16);
        rig.lights[0].barnDoors = BarnDoors{90.0, 0.3};
        QCOMPARE(lines(), plain);
    }

    // Issue 39: an IES light draws its photometric diagram: the C0-C180 and C90-C270 planes, each point
    // at I(θ, φ) / peak of the gizmo's length along the direction the profile's angles name (full.ies: the
    // peak 1500 cd at the nadir of C0, 750 cd at 90° of C0, 500 cd at the nadir of C90). Turning the
    // profile turns the diagram; a light without a loaded profile draws none.
    void iesLightDrawsItsDistribution() {
        QString error;
        const auto profile = readIesFile(QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies"), &error);
        QVERIFY2(profile, qPrintable(error));
        Light l = makeLight(LightType::Point, QStringLiteral("downlight"));
        l.direction = glm::dvec3(0, -1, 0);
        l.ies = IesSpec{};
        const glm::dvec3 at(1.0, 2.0, 3.0);
        const auto curves = iesOutline(l, *profile, at, 2.0, 36);
        QCOMPARE(int(curves.size()), 2);
        const AreaAxes axes = areaAxes(l.direction, 0.0);
        const auto near = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < 1e-9; };
        QVERIFY(near(curves[0].front(), at + glm::dvec3(0, -2, 0)));                    // C0, θ 0: the peak
        QVERIFY(near(curves[0][18], at + axes.x * (2.0 * 750.0 / 1500.0)));             // C0, θ 90
        QVERIFY(near(curves[1].front(), at + glm::dvec3(0, -2.0 * 500.0 / 1500.0, 0))); // C90, θ 0
        l.ies->rotation = 90.0;
        const auto turned = iesOutline(l, *profile, at, 2.0, 36);
        QVERIFY(near(turned[0][18], at + areaAxes(l.direction, 90.0).x * 1.0));
        QVERIFY(!near(turned[0][18], curves[0][18]));

        Rig rig;
        rig.lights = {l};
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 10), glm::dvec3(0), glm::dvec3(0, 1, 0));
        const Bounds bounds{glm::dvec3(-1), glm::dvec3(1)};
        GizmoOptions options;
        const size_t plain = buildGizmos(rig, SceneFrame{}, bounds, view, options).lines.size();
        const std::vector<std::shared_ptr<const IesProfile>> loaded{profile}, none{nullptr};
        options.ies = &loaded;
        QCOMPARE(buildGizmos(rig, SceneFrame{}, bounds, view, options).lines.size(), plain + 2 * 2 * 73);
        options.ies = &none;
        QCOMPARE(buildGizmos(rig, SceneFrame{}, bounds, view, options).lines.size(), plain);
    }
};

QTEST_GUILESS_MAIN(TestGizmos)
#include "tst_gizmos.moc"
