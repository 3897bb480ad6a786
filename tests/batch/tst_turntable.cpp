// render/turntable.h (issue 17): frame k of N at k·360/N degrees; the camera orbits the model's centre
// about +Y keeping its elevation and distance; the rig's lights (and environment) turn about the same axis,
// a model-space rig about its own origin; frame names replace the last run of # in the file name.
#include "render/turntable.h"

#include <QTest>
#include <cmath>
#include <glm/geometric.hpp>

using namespace lr;

namespace {
bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-9) {
    return glm::length(a - b) <= tolerance;
}
} // namespace

class TestTurntable : public QObject {
    Q_OBJECT
  private slots:
    void degrees() {
        QCOMPARE(turntableDegrees(0, 12), 0.0);
        QCOMPARE(turntableDegrees(3, 12), 90.0);
        QCOMPARE(turntableDegrees(11, 12), 330.0);
        QCOMPARE(turntableDegrees(1, 7), 360.0 / 7.0);
    }

    void cameraOrbitsKeepingElevationAndDistance() {
        const glm::dvec3 center(1.0, 2.0, 3.0);
        ViewCamera c;
        c.target = center;
        c.eye = center + glm::dvec3(0.0, 4.0, 3.0); // elevation atan(4/3), distance 5
        QVERIFY(orbitCamera(c, center, 0.0) == c);
        const ViewCamera q = orbitCamera(c, center, 90.0);
        // Counter-clockwise seen from above: +Z goes to +X.
        QVERIFY(near(q.eye, center + glm::dvec3(3.0, 4.0, 0.0)));
        QVERIFY(near(q.target, center));
        QVERIFY(near(q.up, glm::dvec3(0.0, 1.0, 0.0)));
        for (double deg : {17.0, 123.0, 301.0}) {
            const ViewCamera r = orbitCamera(c, center, deg);
            QVERIFY(std::abs(glm::length(r.eye - center) - 5.0) < 1e-9);
            QVERIFY(std::abs((r.eye - center).y - 4.0) < 1e-9);
        }
        QVERIFY(near(orbitCamera(c, center, 360.0).eye, c.eye));
    }

    void lightsTurnAboutTheCentre() {
        Rig rig;
        rig.environment.rotation = 10.0;
        Light spot = makeLight(LightType::Spot, QStringLiteral("S"));
        spot.position = {2.0, 1.0, 0.0};
        spot.direction = {0.0, 0.0, -1.0};
        rig.lights.push_back(spot);
        const glm::dvec3 center(1.0, 0.0, 0.0);
        QVERIFY(rotateRigLights(rig, center, 0.0) == rig);
        const Rig turned = rotateRigLights(rig, center, 90.0);
        QVERIFY(near(turned.lights[0].position, glm::dvec3(1.0, 1.0, -1.0)));
        QVERIFY(near(turned.lights[0].direction, glm::dvec3(-1.0, 0.0, 0.0)));
        QCOMPARE(turned.environment.rotation, 100.0);
        rig.space = RigSpace::Model; // about the rig's origin, which is the model's centre
        QVERIFY(near(rotateRigLights(rig, center, 90.0).lights[0].position, glm::dvec3(0.0, 1.0, -2.0)));
    }

    void frameNames() {
        QVERIFY(!hasFrameField(QStringLiteral("out.png")));
        QVERIFY(!hasFrameField(QStringLiteral("frames#/out.png"))); // the folder is not the name
        QVERIFY(hasFrameField(QStringLiteral("out_#.png")));
        QCOMPARE(framePath(QStringLiteral("out_####.png"), 7), QStringLiteral("out_0007.png"));
        QCOMPARE(framePath(QStringLiteral("a/#_##.png"), 3), QStringLiteral("a/#_03.png"));
        QCOMPARE(framePath(QStringLiteral("t#.png"), 12), QStringLiteral("t12.png"));
        QCOMPARE(framePath(QStringLiteral("out.png"), 2), QStringLiteral("out.png"));
    }
};

QTEST_APPLESS_MAIN(TestTurntable)
#include "tst_turntable.moc"
