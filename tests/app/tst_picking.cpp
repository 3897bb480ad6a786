// Viewport picking geometry (src/app/picking.h) and gizmo anchors, checked against hand-built cameras.
#include "app/gizmointeraction.h"
#include "app/picking.h"
#include "model/model.h"

#include "pickingcamera.h"

#include <QTest>

using namespace lr;
using namespace lr::test;

class TestPicking : public QObject {
    Q_OBJECT
  private slots:
    void projectsTheCentreAndEdges() {
        const ScreenProjector p = frontCamera();
        const auto c = p.project(glm::dvec3(0));
        QVERIFY(c);
        QCOMPARE(c->x(), 100.0);
        QCOMPARE(c->y(), 50.0);
        // tan(45°) = 1: at distance 10 the top edge is y = 10 (screen y 0), the right edge x = 20 (aspect 2).
        const auto top = p.project(glm::dvec3(0, 10, 0));
        QVERIFY(top && std::abs(top->y()) < 1e-9);
        const auto right = p.project(glm::dvec3(20, 0, 0));
        QVERIFY(right && std::abs(right->x() - 200.0) < 1e-9);
        QVERIFY(!p.project(glm::dvec3(0, 0, 20))); // behind the camera
    }

    void raysRoundTrip() {
        const ScreenProjector p = frontCamera();
        for (const QPointF s : {QPointF(100, 50), QPointF(10, 90), QPointF(190, 5)}) {
            const Ray r = p.ray(s);
            const auto back = p.project(r.at(7.0));
            QVERIFY(back);
            QVERIFY(std::abs(back->x() - s.x()) < 1e-6 && std::abs(back->y() - s.y()) < 1e-6);
        }
        QVERIFY(near(p.viewDirection(), glm::dvec3(0, 0, -1)));
        QVERIFY(near(p.eye(), glm::dvec3(0, 0, 10)));
        QCOMPARE(p.depth(glm::dvec3(0, 0, 4)), 6.0);
        // 100 px span 2 * depth * tan(45°) world units.
        QVERIFY(std::abs(p.worldPerPixel(10.0) - 0.2) < 1e-12);
    }

    void picksTheNearestWithinRadius() {
        const ScreenProjector p = frontCamera();
        // Screen x = 100 + 10 * X / depth * ... : at depth 10 one world unit is 5 px.
        const std::vector<glm::dvec3> anchors{{0, 0, 0}, {2, 0, 0}, {0, 0, 5}};
        QCOMPARE(pickNearest(p, anchors, QPointF(110, 50), 3.0), 1); // (2,0,0) projects to x = 110
        QCOMPARE(pickNearest(p, anchors, QPointF(130, 50), 3.0), -1);
        // (0,0,0) and (0,0,5) project to the same pixel: the one nearer the camera wins.
        QCOMPARE(pickNearest(p, anchors, QPointF(100, 50), 3.0), 2);
    }

    void dragsInTheViewPlaneAndAlongTheAxis() {
        const ScreenProjector p = frontCamera();
        const glm::dvec3 start(1, 1, 0);
        // 10 px right at depth 10 is 2 world units (0.2 per pixel); the depth stays.
        const glm::dvec3 moved = dragInViewPlane(p, start, QPointF(105, 45), QPointF(115, 45));
        QVERIFY2(near(moved, glm::dvec3(3, 1, 0), 1e-9), qPrintable(QString::number(moved.x)));
        const glm::dvec3 pushed = dragAlongViewAxis(p, start, QPointF(0, 50), QPointF(0, 40), 0.5);
        // Up = away from the camera, 10 px * 0.5 = 5 units along the line of sight from the eye (0,0,10).
        QVERIFY(near(pushed, start + glm::normalize(start - glm::dvec3(0, 0, 10)) * 5.0));
        const auto s0 = p.project(start), s1 = p.project(pushed);
        QVERIFY(s0 && s1 && QLineF(*s0, *s1).length() < 1e-9); // still under the cursor
    }

    void hitsTheModelsNearestTriangle() {
        const Model sphere = makeSphere(1.0, 32, 16, glm::dvec3(0.0, 0.0, 0.0));
        const ScreenProjector p = frontCamera();
        const auto hit = intersectModel(sphere, p.ray(QPointF(100, 50)));
        QVERIFY(hit);
        QVERIFY2(std::abs(hit->z - 1.0) < 0.01 && std::abs(hit->x) < 1e-6, "front of the sphere");
        QVERIFY(!intersectModel(sphere, p.ray(QPointF(5, 5))));
    }

    void coneEdgeAngle() {
        // A spot at the origin pointing down -Y, seen from the front: the cursor at 45° below-right.
        const ScreenProjector p = frontCamera();
        const glm::dvec3 apex(0), axis(0, -1, 0);
        const auto s = p.project(glm::dvec3(3, -3, 0));
        QVERIFY(s);
        const auto angle = coneAngleUnderCursor(p, apex, axis, *s, 3.0);
        QVERIFY(angle);
        QVERIFY2(std::abs(*angle - 45.0) < 1e-6, qPrintable(QString::number(*angle)));
        // Seen along the axis (the spot points away from the camera): the disc 4 units down the axis.
        const glm::dvec3 away(0, 0, -1);
        const auto s2 = p.project(glm::dvec3(4, 0, -4)); // 45° off the axis, 4 units along it
        QVERIFY(s2);
        const auto angle2 = coneAngleUnderCursor(p, apex, away, *s2, 4.0);
        QVERIFY(angle2);
        QVERIFY2(std::abs(*angle2 - 45.0) < 1e-6, qPrintable(QString::number(*angle2)));
        // The rim of a 30° cone of slant length 2 is at distance 2 from the apex, 30° from the axis.
        for (const glm::dvec3& q : coneRim(apex, axis, 30.0, 2.0, 12)) {
            QVERIFY(std::abs(glm::length(q) - 2.0) < 1e-9);
            QVERIFY(std::abs(glm::degrees(std::acos(glm::dot(glm::normalize(q), axis))) - 30.0) < 1e-9);
        }
        const auto rim = coneRim(apex, axis, 30.0, 2.0, 64);
        const auto onRim = p.project(rim[0]);
        QVERIFY(distanceToConeRim(p, rim, *onRim) < 1e-6);
    }

    void anchors() {
        Rig rig;
        rig.space = RigSpace::Model;
        const SceneFrame frame{glm::dvec3(10, 0, 0), 2.0};
        Light point = makeLight(LightType::Point, "p");
        point.position = glm::dvec3(1, 0, 0);
        QVERIFY(near(lightAnchor(rig, frame, point), glm::dvec3(12, 0, 0)));
        Light sun = makeLight(LightType::Directional, "s");
        sun.direction = glm::dvec3(0, -1, 0);
        const glm::dvec3 a = lightAnchor(rig, frame, sun);
        QVERIFY(a.y > frame.radius); // above the scene, against the light's direction
        QVERIFY(std::abs(a.x - 10.0) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestPicking)
#include "tst_picking.moc"
