// The traced visibility of the double-precision reference (src/render/referencetrace.h, issue 14) on
// analytic scenes built in code: a sphere above a plane against the closed-form shadow outline (point and
// directional light), a cube resting on the ground (no peter-panning), a light inside the model, a
// directional light parallel to the ground, and the penumbra of a disk light behind a straight edge
// against the exact visible fraction of the disk. No OpenGL: the tracer takes world points directly.
#include "shadowscenes.h"

#include "render/referencetrace.h"

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
    }
};

QTEST_GUILESS_MAIN(TestShadowReference)
#include "tst_shadowreference.moc"
