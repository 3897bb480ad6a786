// Barn doors (issue 39; core/barndoors.h): UE5's flap shape, the visible window against the definition (a
// segment from the emitter to the point that crosses a flap is blocked), the window's closed form at a
// hand-worked point, the light prepared from a rig, and the irradiance of the cut emitter against a direct
// integration over the emitter with the segment test.
#include "common.h"
#include "core/barndoors.h"
#include "core/lighting_area.h"
#include "core/prepare.h"

#include <QObject>
#include <QTest>
#include <random>

using namespace lr;
using namespace lr::test;
using lighting::ShadeLight;

namespace {

// A rect facing +z at the origin, axes x and y (the window reads the axes by dot product, so the
// handedness of the prepared frame does not matter here).
ShadeLight<double> rect(double hw, double hh, double angleDeg, double length) {
    ShadeLight<double> l;
    l.type = LightType::Rect;
    l.position = Vec3d(0);
    l.direction = Vec3d(0, 0, 1);
    l.axisX = Vec3d(1, 0, 0);
    l.axisY = Vec3d(0, 1, 0);
    l.halfWidth = hw;
    l.halfHeight = hh;
    const barndoors::FlapShape f = barndoors::flapShape({angleDeg, length});
    l.barnDepth = f.depth;
    l.barnExtent = f.extent;
    l.color = Vec3d(1);
    l.specular = Vec3d(0);
    return l;
}

} // namespace

class TestBarnDoors : public QObject {
    Q_OBJECT
  private slots:
    void flapShapeIsUnreals() {
        // UE: depth = cos(angle)·length along the normal, extent = sin(angle)·length outwards.
        const auto a0 = barndoors::flapShape({0.0, 0.2});
        QCOMPARE(a0.depth, 0.2);
        QCOMPARE(a0.extent, 0.0);
        const auto a88 = barndoors::flapShape({88.0, 0.2});
        QVERIFY(std::abs(a88.depth - 0.2 * std::cos(radians(88))) < 1e-15);
        QVERIFY(std::abs(a88.extent - 0.2 * std::sin(radians(88))) < 1e-15);
        // 90° lies in the emitter's plane and length 0 has no flap: exactly nothing cut.
        QCOMPARE(barndoors::flapShape({90.0, 0.5}).depth, 0.0);
        QVERIFY(!barndoors::cuts({90.0, 0.5}));
        QVERIFY(!barndoors::cuts({30.0, 0.0}));
        QVERIFY(barndoors::cuts({30.0, 0.1}));
        // The rig's default is UE's angle.
        QCOMPARE(BarnDoors{}.angle, 88.0);
    }

    void noCutWithoutDepth() {
        const ShadeLight<double> l = rect(0.5, 0.3, 90.0, 1.0);
        const auto w = barndoors::visibleWindow(l, Vec3d(3, 1, 0.2));
        QCOMPARE(w.x0, -0.5);
        QCOMPARE(w.x1, 0.5);
        QCOMPARE(w.y0, -0.3);
        QCOMPARE(w.y1, 0.3);
        // Behind the emitter (a two-sided rect's back): not cut either.
        const auto back = barndoors::visibleWindow(rect(0.5, 0.3, 0.0, 1.0), Vec3d(3, 1, -2));
        QCOMPARE(back.x1, 0.5);
    }

    void windowByHand() {
        // A tube (angle 0) of depth 1 on a 1 × 1 emitter; from (1, 0, 2) the ray past the far edge x = 0.5,
        // z = 1 meets the plane at x = 1 + (0.5 − 1)·2/(2 − 1) = 0.
        const auto w = barndoors::visibleWindow(rect(0.5, 0.5, 0.0, 1.0), Vec3d(1, 0, 2));
        QVERIFY(std::abs(w.x1 - 0.0) < 1e-15);
        QCOMPARE(w.x0, -0.5);
        // y: on the axis, the far edge at 0.5 projects to 0.5·2/1 = 1 > 0.5: the whole height.
        QCOMPARE(w.y0, -0.5);
        QCOMPARE(w.y1, 0.5);
        // Outside the tube's walls below its far edge: nothing; inside: everything.
        QVERIFY(barndoors::visibleWindow(rect(0.5, 0.5, 0.0, 1.0), Vec3d(0.7, 0, 0.5)).empty());
        QVERIFY(!barndoors::visibleWindow(rect(0.5, 0.5, 0.0, 1.0), Vec3d(0.3, 0, 0.5)).empty());
        // Far outside the beam: nothing.
        QVERIFY(barndoors::visibleWindow(rect(0.5, 0.5, 0.0, 1.0), Vec3d(5, 0, 2)).empty());
    }

    // The window is the definition: for random lights, points and emitter samples, a sample is inside the
    // window exactly when the segment to it misses the four flaps (samples within 1e-9 of the window's
    // edge skipped: there the two differ by rounding only).
    void windowMatchesSegments() {
        std::mt19937_64 rng(39);
        std::uniform_real_distribution<double> u(0.0, 1.0);
        int checked = 0, cut = 0, mismatches = 0;
        for (int i = 0; i < 400; ++i) {
            const ShadeLight<double> l = rect(0.05 + u(rng), 0.05 + u(rng), 90.0 * u(rng), 1.5 * u(rng));
            const Vec3d P((u(rng) - 0.5) * 8.0, (u(rng) - 0.5) * 8.0, 0.01 + u(rng) * 4.0);
            const auto w = barndoors::visibleWindow(l, P);
            for (int j = 0; j < 50; ++j) {
                const double x = (2 * u(rng) - 1) * l.halfWidth, y = (2 * u(rng) - 1) * l.halfHeight;
                const double margin = std::min(
                    {std::abs(x - w.x0), std::abs(x - w.x1), std::abs(y - w.y0), std::abs(y - w.y1)});
                if (margin < 1e-9) continue;
                const bool inWindow = !w.empty() && x > w.x0 && x < w.x1 && y > w.y0 && y < w.y1;
                const bool hit = barndoors::segmentHitsFlaps(l, l.position + x * l.axisX + y * l.axisY, P);
                if (inWindow == hit) ++mismatches;
                ++checked;
                cut += hit ? 1 : 0;
            }
        }
        qInfo("%d samples, %d cut by a flap, %d where the window and the segments disagree", checked, cut,
              mismatches);
        QVERIFY(cut > checked / 10); // the sample set exercises the flaps
        QVERIFY(cut < checked);
        QCOMPARE(mismatches, 0);
    }

    // The prepared light carries the flaps in view units: a model-space rig scales them with the model.
    void preparedFromRig() {
        Rig rig;
        rig.space = RigSpace::Model;
        Light light = makeLight(LightType::Rect, QStringLiteral("Softbox"));
        light.barnDoors = BarnDoors{30.0, 0.4};
        rig.lights.push_back(light);
        SceneFrame frame{glm::dvec3(0), 2.5};
        const auto l = prepareLight(rig, frame, glm::dmat4(1.0), rig.lights[0]);
        QVERIFY(std::abs(l.barnDepth - 0.4 * std::cos(radians(30)) * 2.5) < 1e-12);
        QVERIFY(std::abs(l.barnExtent - 0.4 * std::sin(radians(30)) * 2.5) < 1e-12);
        // A disk has no barn doors, nor a rect without them.
        light.type = LightType::Disk;
        QCOMPARE(prepareLight(rig, frame, glm::dmat4(1.0), light).barnDepth, 0.0);
        rig.lights[0].barnDoors.reset();
        QCOMPARE(prepareLight(rig, frame, glm::dmat4(1.0), rig.lights[0]).barnDepth, 0.0);
    }

    // The irradiance on a plane under the cut emitter: the exact form factor of the visible window
    // (shadeAreaLight on visiblePart, what every tier integrates) against a midpoint sum over the whole
    // emitter with each cell's centre cut by the segment test.
    void irradianceOfTheWindow() {
        const ShadeLight<double> l = rect(0.4, 0.25, 45.0, 0.3);
        lighting::ShadeSettings<double> st;
        st.model = ShadingModel::Classic;
        lighting::Surface<double> s;
        s.albedo = Vec3d(1);
        s.specular = Vec3d(0);
        s.normal = Vec3d(0, 0, 1);
        double worst = 0.0;
        for (const Vec3d P : {Vec3d(0.2, 0.1, -1.5), Vec3d(0.9, -0.3, -1.0), Vec3d(1.6, 0.4, -0.8)}) {
            // The light shines down onto P: mirror the point to the emitting side (z > 0) by turning the
            // light.
            ShadeLight<double> down = l;
            down.direction = Vec3d(0, 0, -1);
            down.axisY = Vec3d(0, -1, 0);
            const Vec3d at(P.x, -P.y, P.z);
            s.position = at;
            const ShadeLight<double> seen = barndoors::visiblePart(down, at);
            const double exact =
                seen.halfWidth > 0.0
                    ? lighting::shadeAreaLight(seen, s, st, Vec3d(0, 0, 1)).x * kPi // E = π·(D/π)
                    : 0.0;
            const int n = 400;
            double sum = 0.0;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    const double x = (2.0 * (i + 0.5) / n - 1.0) * down.halfWidth;
                    const double y = (2.0 * (j + 0.5) / n - 1.0) * down.halfHeight;
                    const Vec3d Q = down.position + x * down.axisX + y * down.axisY;
                    if (barndoors::segmentHitsFlaps(down, Q, at)) continue;
                    const Vec3d d = Q - at;
                    const double r2 = glm::dot(d, d);
                    sum += d.z * d.z / (r2 * r2); // cosθ·cosθe/r² with both normals along z
                }
            const double numeric = sum * (4.0 * down.halfWidth * down.halfHeight) / (double(n) * n);
            qInfo("P (%g, %g, %g): window %g, segments %g", P.x, P.y, P.z, exact, numeric);
            QVERIFY(numeric > 0.0);
            worst = std::max(worst, std::abs(exact - numeric) / numeric);
        }
        QVERIFY2(worst < 0.01, qPrintable(QStringLiteral("relative error %1").arg(worst)));
    }
};

QTEST_GUILESS_MAIN(TestBarnDoors)
#include "tst_barndoors.moc"
