// The traced visibility of the double-precision reference (src/scene/referencetrace.h, issue 14) on
// analytic scenes built in code: a sphere above a plane against the closed-form shadow outline (point and
// directional light), a cube resting on the ground (no peter-panning), a light inside the model, a
// directional light parallel to the ground, and the penumbra of a disk light behind a straight edge
// against the exact visible fraction of the disk; area lights (issue 16): a rect's penumbra behind an edge
// against its exact (linear) visible share, wider for a wider rect, and a one-sided rect, which shadows
// nothing behind its plane. No OpenGL: the tracer takes world points directly.
#include "shadowscenes.h"

#include "scene/referencetrace.h"

#include <QTest>
#include <cmath>
#include <numbers>

using namespace lr;
using namespace lr::test;

namespace {

ShadowEmitter pointEmitter(glm::dvec3 position, double size = 0.0) {
    ShadowEmitter e;
    e.casts = true;
    e.position = position;
    e.radius = 0.5 * size;
    return e;
}

ShadowEmitter sunEmitter(glm::dvec3 toLight, double angleDegrees = 0.0) {
    ShadowEmitter e;
    e.casts = true;
    e.directional = true;
    e.toLight = glm::normalize(toLight);
    e.halfAngle = 0.5 * angleDegrees * std::numbers::pi / 180.0;
    return e;
}

// A rect light at `position` shining down (-Y), width along X, height along Z (or a disk of radius w/2).
ShadowEmitter rectEmitter(glm::dvec3 position, double width, double height, bool twoSided = false,
                          ShadowEmitter::Area shape = ShadowEmitter::Area::Rect) {
    ShadowEmitter e;
    e.casts = true;
    e.position = position;
    e.area = shape;
    e.normal = {0.0, -1.0, 0.0};
    e.axisX = {1.0, 0.0, 0.0};
    e.axisY = {0.0, 0.0, 1.0};
    e.halfWidth = 0.5 * width;
    e.halfHeight = 0.5 * height;
    e.twoSided = twoSided;
    return e;
}

constexpr glm::dvec3 kUp(0.0, 1.0, 0.0);

} // namespace

class TestShadowReference : public QObject {
    Q_OBJECT

    // A unit sphere centred 2 above the plane y = 0: a plane point is shadowed iff its ray to the light
    // passes within the radius of the centre. The mesh is inscribed in the sphere, so only points whose
    // ray passes within the tessellation's depth of the surface may disagree; they are left out.
    void sphereAbovePlane(const ShadowEmitter& light) {
        constexpr int kSegments = 96, kRings = 48;
        const glm::dvec3 c(0.0, 2.0, 0.0);
        constexpr double radius = 1.0;
        const ShadowTracer tracer(
            ShadowSceneBuilder().floor(0.0, 8.0).sphere(c, radius, kSegments, kRings).build(), false);
        QVERIFY2(tracer.ok(), qPrintable(tracer.error()));
        const double depth =
            radius * (1.0 - std::cos(std::numbers::pi / kSegments) * std::cos(std::numbers::pi / kRings));
        int shadowed = 0, lit = 0, skipped = 0, wrong = 0;
        for (int j = 0; j <= 120; ++j)
            for (int i = 0; i <= 120; ++i) {
                const glm::dvec3 p(-6.0 + 0.1 * i, 0.0, -6.0 + 0.1 * j);
                const double d = light.directional ? distanceToSegment(c, p, light.toLight, true)
                                                   : distanceToSegment(c, p, light.position);
                if (d > radius - depth - 1e-6 && d < radius + 1e-6) {
                    ++skipped;
                    continue;
                }
                const double v = tracer.visibility(p, kUp, light, std::uint32_t(i * 131 + j));
                const bool expectShadow = d < radius;
                (expectShadow ? shadowed : lit) += 1;
                if (v != (expectShadow ? 0.0 : 1.0)) {
                    if (++wrong <= 5)
                        qWarning() << "at" << p.x << p.z << "distance" << d << "visibility" << v;
                }
            }
        qInfo() << "shadowed" << shadowed << "lit" << lit << "left out (tessellation)" << skipped;
        QCOMPARE(wrong, 0);
        QVERIFY(shadowed > 300 && lit > 3000); // both sides are well represented
        QVERIFY(skipped < (shadowed + lit) / 50);
    }

  private slots:
    void sphereAbovePlanePointLight() { sphereAbovePlane(pointEmitter({0.7, 5.0, 0.3})); }
    void sphereAbovePlaneDirectional() { sphereAbovePlane(sunEmitter({0.5, 1.0, -0.3})); }

    // A unit cube resting on the ground (the ground from groundPlane(), so at the cube's bottom): the
    // shadow meets the contact edge, and ends where similar triangles say.
    void cubeOnGroundHasNoPeterPanning() {
        const ShadowTracer tracer(ShadowSceneBuilder().box({-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}).build(), true);
        QVERIFY2(tracer.ok(), qPrintable(tracer.error()));
        QCOMPARE(tracer.triangles(), std::int64_t(14));           // 12 of the cube, 2 of the ground
        const ShadowEmitter sun = sunEmitter({1.0, 1.0, 0.0});    // 45°: a shadow 1 long on the -x side
        const ShadowEmitter lamp = pointEmitter({3.0, 4.0, 0.0}); // a shadow to x = -5/3
        for (double gap : {1e-3, 3e-3, 0.01, 0.1, 0.5, 0.9}) {
            const glm::dvec3 p(-0.5 - gap, 0.0, 0.0);
            QCOMPARE(tracer.visibility(p, kUp, sun, 1), 0.0);
            QCOMPARE(tracer.visibility(p, kUp, lamp, 1), 0.0);
        }
        QCOMPARE(tracer.visibility({-1.6, 0.0, 0.0}, kUp, sun, 1), 1.0);
        QCOMPARE(tracer.visibility({-2.1, 0.0, 0.0}, kUp, lamp, 1), 1.0);
        // The lit side right at the contact edge, and the top face (its own acne would show here).
        QCOMPARE(tracer.visibility({0.5 + 1e-3, 0.0, 0.0}, kUp, sun, 1), 1.0);
        QCOMPARE(tracer.visibility({0.0, 1.0, 0.0}, kUp, lamp, 1), 1.0);
    }

    // A light inside a closed model: every point outside is shadowed, every point inside sees it.
    void lightInsideTheModel() {
        const ShadowTracer tracer(ShadowSceneBuilder().sphere({0.0, 0.0, 0.0}, 1.0, 48, 24).build(), false);
        QVERIFY2(tracer.ok(), qPrintable(tracer.error()));
        for (double size : {0.0, 0.5}) {
            const ShadowEmitter inside = pointEmitter({0.1, 0.2, -0.1}, size);
            for (int k = 0; k < 200; ++k) {
                const double z = -1.0 + 2.0 * (k + 0.5) / 200.0, phi = 2.3999632 * k; // Fibonacci sphere
                const glm::dvec3 n(std::sqrt(1.0 - z * z) * std::cos(phi), z,
                                   std::sqrt(1.0 - z * z) * std::sin(phi));
                QCOMPARE(tracer.visibility(2.0 * n, n, inside, std::uint32_t(k)), 0.0);
                QCOMPARE(tracer.visibility(0.9 * n, -n, inside, std::uint32_t(k)), 1.0);
            }
        }
    }

    // A directional light parallel to the ground: the ground behind the cube is shadowed, the rest lit,
    // and nothing is undefined.
    void directionalParallelToGround() {
        const ShadowTracer tracer(ShadowSceneBuilder().box({-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}).build(), true);
        QVERIFY2(tracer.ok(), qPrintable(tracer.error()));
        const ShadowEmitter grazing = sunEmitter({1.0, 0.0, 0.0}); // travels along -x
        for (double z : {-0.4, 0.0, 0.4}) {
            QCOMPARE(tracer.visibility({-0.6, 0.0, z}, kUp, grazing, 1), 0.0);
            QCOMPARE(tracer.visibility({-4.0, 0.0, z}, kUp, grazing, 1), 0.0);
            QCOMPARE(tracer.visibility({0.6, 0.0, z}, kUp, grazing, 1), 1.0);
        }
        for (double z : {-0.6, 0.6, 3.0})
            QCOMPARE(tracer.visibility({-1.0, 0.0, z}, kUp, grazing, 1), 1.0);
        const double soft = tracer.visibility({-1.0, 0.0, 0.5}, kUp, sunEmitter({1.0, 0.0, 0.0}, 10.0), 7);
        QVERIFY(std::isfinite(soft) && soft >= 0.0 && soft <= 1.0);
    }

    // A disk light of diameter 0.5 at height 3 behind the straight edge x = 0 of a half-plane at height 1:
    // on the ground the penumbra is 0.5 · 1 / (3 − 1) = 0.25 wide (similar triangles) about x = 0, and
    // visibility rises monotonically across it.
    void penumbraWidthFollowsSimilarTriangles() {
        constexpr double H = 3.0, h = 1.0, size = 0.5;
        const ShadowTracer tracer(
            ShadowSceneBuilder().quad({-10, h, -10}, {-10, h, 10}, {0, h, 10}, {0, h, -10}).build(), false);
        QVERIFY2(tracer.ok(), qPrintable(tracer.error()));
        const ShadowEmitter lamp = pointEmitter({0.0, H, 0.0}, size);
        const double width = size * h / (H - h);
        double previous = 0.0;
        for (int i = 0; i <= 120; ++i) {
            const double x = -0.3 + 0.005 * i;
            const double v = tracer.visibility({x, 0.0, 0.0}, kUp, lamp, std::uint32_t(i));
            if (std::abs(x) > 0.5 * width * 1.1) QCOMPARE(v, x < 0.0 ? 0.0 : 1.0);
            if (std::abs(x) < 0.5 * width * 0.9) QVERIFY2(v > 0.0 && v < 1.0, qPrintable(QString::number(x)));
            QVERIFY2(v >= previous - 0.03,
                     qPrintable(QStringLiteral("x %1: %2 after %3").arg(x).arg(v).arg(previous)));
            previous = std::max(previous, v);
        }
    }

    // The same edge with the light straight above each point (so the disk lies flat): the visible share of
    // the disk is the circular segment beyond the edge's shadow line, in closed form. This measures the
    // error kShadowSamples jittered strata leave (docs/quality.md quotes it).
    void penumbraMatchesTheVisibleShareOfTheDisk() {
        constexpr double H = 3.0, h = 1.0, size = 0.5, R = 0.5 * size;
        const ShadowTracer tracer(
            ShadowSceneBuilder().quad({-10, h, -10}, {-10, h, 10}, {0, h, 10}, {0, h, -10}).build(), false);
        QVERIFY2(tracer.ok(), qPrintable(tracer.error()));
        double worst = 0.0, sumSq = 0.0;
        int n = 0;
        for (int i = 1; i < 100; ++i) {
            const double x = R * h / H * (-1.0 + 2.0 * i / 100.0); // across the whole penumbra
            // Disk points (x + u, H, v) are hidden where the ray crosses y = h at x + u·h/H < 0.
            const double d = std::clamp(-x * H / (h * R), -1.0, 1.0);
            const double exact = (std::acos(d) - d * std::sqrt(1.0 - d * d)) / std::numbers::pi;
            for (std::uint32_t seed = 0; seed < 8; ++seed) {
                const double v =
                    tracer.visibility({x, 0.0, 0.0}, kUp, pointEmitter({x, H, 0.0}, size), seed + 100u * i);
                worst = std::max(worst, std::abs(v - exact));
                sumSq += (v - exact) * (v - exact);
                ++n;
            }
        }
        const double rms = std::sqrt(sumSq / n);
        qInfo() << "visibility error with" << kShadowSamples << "rays: rms" << rms << "worst" << worst;
        QVERIFY(rms < 0.01);
        QVERIFY(worst < 0.04);
        // More rays converge: the same with 16× as many is closer still.
        double worstFine = 0.0;
        for (int i = 1; i < 100; i += 7) {
            const double x = R * h / H * (-1.0 + 2.0 * i / 100.0);
            const double d = std::clamp(-x * H / (h * R), -1.0, 1.0);
            const double exact = (std::acos(d) - d * std::sqrt(1.0 - d * d)) / std::numbers::pi;
            const double v = tracer.visibility({x, 0.0, 0.0}, kUp, pointEmitter({x, H, 0.0}, size), 5u,
                                               16 * kShadowSamples);
            worstFine = std::max(worstFine, std::abs(v - exact));
        }
        qInfo() << "worst with" << 16 * kShadowSamples << "rays:" << worstFine;
        QVERIFY(worstFine < 0.01);
    }

    // A rect of width w at height H over the straight edge x = 0 of a half-plane (x < 0) at height h: the
    // emitter point x_e is seen from ground point x iff x_e ≥ −x·(H − h)/h, so the visible share of the
    // rect, uniform in x_e over [−w/2, w/2], is linear across a penumbra w·h/(H − h) wide. Both a narrow
    // and a wide rect match it, and the wide one's band is ten times the narrow one's.
    void rectPenumbraIsItsVisibleShare() {
        constexpr double H = 3.0, h = 1.0;
        const ShadowTracer tracer(
            ShadowSceneBuilder().quad({-10, h, -10}, {-10, h, 10}, {0, h, 10}, {0, h, -10}).build(), false);
        QVERIFY2(tracer.ok(), qPrintable(tracer.error()));
        double bands[2] = {0.0, 0.0};
        int k = 0;
        for (double width : {0.2, 2.0}) {
            const ShadowEmitter rect = rectEmitter({0.0, H, 0.0}, width, 0.5);
            const double band = width * h / (H - h);
            double worst = 0.0, at10 = 1e9, at90 = -1e9;
            for (int i = 0; i <= 200; ++i) {
                const double x = band * (-1.0 + 2.0 * i / 200.0);
                const double exact = std::clamp((0.5 * width + x * (H - h) / h) / width, 0.0, 1.0);
                const double v = tracer.visibility({x, 0.0, 0.3}, kUp, rect, std::uint32_t(i + 7));
                worst = std::max(worst, std::abs(v - exact));
                if (v >= 0.1) at10 = std::min(at10, x);
                if (v < 0.9) at90 = std::max(at90, x);
            }
            bands[k++] = at90 - at10;
            qInfo() << "rect" << width << "wide: 10-90 % band" << at90 - at10 << "(exact" << 0.8 * band
                    << ") worst error" << worst;
            QVERIFY2(worst < 0.05, qPrintable(QString::number(worst)));
            QVERIFY(std::abs((at90 - at10) - 0.8 * band) < 0.1 * band);
        }
        QVERIFY(bands[1] > 8.0 * bands[0]);
        // A disk: the same edge, a penumbra as wide as its diameter's similar triangles, about x = 0.
        const ShadowEmitter disk = rectEmitter({0.0, H, 0.0}, 1.0, 1.0, false, ShadowEmitter::Area::Disk);
        QCOMPARE(tracer.visibility({-0.26, 0.0, 0.0}, kUp, disk, 1u), 0.0);
        QCOMPARE(tracer.visibility({0.26, 0.0, 0.0}, kUp, disk, 2u), 1.0);
        QVERIFY(std::abs(tracer.visibility({0.0, 0.0, 0.0}, kUp, disk, 3u, 4096) - 0.5) < 0.02);
    }

    // A one-sided rect at height 2 shining down, a slab at height 3 above it (behind its plane): the
    // ground below is fully lit (a blocker behind the emitter cannot come between it and its front), and a
    // point on the slab's far side, behind the plane, gets 1 (the light does not reach it). Two-sided, the
    // same point above the rect sees the slab in the way: shadowed.
    void oneSidedRectShadowsNothingBehindIt() {
        const ShadowTracer tracer(ShadowSceneBuilder().box({-3, 3.0, -3}, {3, 3.2, 3}).build(), false);
        QVERIFY2(tracer.ok(), qPrintable(tracer.error()));
        const ShadowEmitter one = rectEmitter({0.0, 2.0, 0.0}, 1.0, 1.0);
        for (double x : {-1.0, 0.0, 0.4, 2.0})
            QCOMPARE(tracer.visibility({x, 0.0, 0.0}, kUp, one, std::uint32_t(x * 10 + 20)), 1.0);
        const glm::dvec3 above(0.0, 3.5, 0.0);
        QCOMPARE(tracer.visibility(above, kUp, one, 5u), 1.0);
        const ShadowEmitter two = rectEmitter({0.0, 2.0, 0.0}, 1.0, 1.0, true);
        QCOMPARE(tracer.visibility(above, kUp, two, 5u), 0.0);
        QCOMPARE(tracer.visibility({0.0, 0.0, 0.0}, kUp, two, 6u), 1.0);
        // Zero size: one ray to the centre, a hard shadow.
        const ShadowEmitter dot = rectEmitter({0.0, 2.0, 0.0}, 0.0, 0.0, true);
        QCOMPARE(tracer.visibility(above, kUp, dot, 5u), 0.0);
    }

    // The emitter from a rig light: size in rig units scaled like positions, angle a full angle.
    void emitterFromRigLight() {
        Rig rig;
        rig.space = RigSpace::Model;
        const SceneFrame frame{{1.0, 2.0, 3.0}, 4.0};
        Light spot = makeLight(LightType::Spot, QStringLiteral("s"));
        spot.position = {0.0, 1.0, 0.0};
        spot.shadow.enabled = true;
        spot.shadow.size = 0.25;
        ShadowEmitter e = shadowEmitter(rig, frame, spot);
        QVERIFY(e.casts && !e.directional);
        QVERIFY(e.position == glm::dvec3(1.0, 6.0, 3.0));
        QCOMPARE(e.radius, 0.5 * 0.25 * 4.0);
        Light sun = makeLight(LightType::Directional, QStringLiteral("d"));
        sun.direction = {0.0, -1.0, 0.0};
        sun.shadow.enabled = true;
        sun.shadow.angle = 2.0;
        e = shadowEmitter(rig, frame, sun);
        QVERIFY(e.casts && e.directional);
        QVERIFY(e.toLight == glm::dvec3(0.0, 1.0, 0.0));
        QVERIFY(std::abs(e.halfAngle - std::numbers::pi / 180.0) < 1e-15);
        sun.shadow.enabled = false;
        QVERIFY(!shadowEmitter(rig, frame, sun).casts);
        QVERIFY(!shadowEmitter(rig, frame, makeLight(LightType::Rim, QStringLiteral("r"))).casts);
        // Area lights: their own shape and axes (areaAxes), half extents in world units, the side.
        Light rect = makeLight(LightType::Rect, QStringLiteral("rect"));
        rect.position = {0.0, 1.0, 0.0};
        rect.direction = {0.0, -1.0, 0.0};
        rect.area.width = 0.5;
        rect.area.height = 0.25;
        rect.area.twoSided = true;
        rect.shadow.enabled = true;
        e = shadowEmitter(rig, frame, rect);
        QVERIFY(e.casts && !e.directional && e.area == ShadowEmitter::Area::Rect && e.twoSided);
        QVERIFY(e.position == glm::dvec3(1.0, 6.0, 3.0));
        QCOMPARE(e.halfWidth, 0.25 * 4.0);
        QCOMPARE(e.halfHeight, 0.125 * 4.0);
        const AreaAxes axes = areaAxes(rect.direction, 0.0);
        QVERIFY(e.axisX == axes.x && e.axisY == axes.y && e.normal == rect.direction);
        Light disk = makeLight(LightType::Disk, QStringLiteral("disk"));
        disk.area.radius = 0.3;
        disk.shadow.enabled = true;
        e = shadowEmitter(rig, frame, disk);
        QVERIFY(e.area == ShadowEmitter::Area::Disk && !e.twoSided);
        QCOMPARE(e.halfWidth, 0.3 * 4.0);
        QCOMPARE(e.halfHeight, 0.3 * 4.0);
    }
};

QTEST_GUILESS_MAIN(TestShadowReference)
#include "tst_shadowreference.moc"
