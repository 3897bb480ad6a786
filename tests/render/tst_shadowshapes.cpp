// Shadows (issue 14): where they fall and how soft they are, on analytic scenes (shadowscenes.h) whose
// shadows are known in closed form or traced: a spot, rect and point light over spheres and a cube, the
// penumbra's width against the emitter's size, and no acne at grazing light, in every tier (probes and
// visibility: shadowfixture.h). Programs, maps, plans and the catcher: tst_shadows.
#include "glfixture.h"
#include "scenes.h"
#include "shadowfixture.h"
#include "shadowscenes.h"

#include "render/offscreen.h"
#include "render/shadowmaps.h"
#include "scene/referencetrace.h"

#include <QTest>
#include <algorithm>
#include <cmath>

using namespace lr;
using namespace lr::render;
using namespace lr::test;

class TestShadowShapes : public QObject, protected ShadowFixture {
    Q_OBJECT
    // Where the visibility along the ground from `from` to `to` first reaches 0.1, 0.5 and 0.9.
    struct Edge {
        double at10 = -1, at50 = -1, at90 = -1;
        double width() const { return at90 - at10; }
    };
    Edge edgeAlong(const FloatImage& on, const FloatImage& off, const ViewCamera& cam, glm::dvec3 from,
                   glm::dvec3 to) {
        Edge e;
        const int steps = 400;
        for (int i = 0; i <= steps; ++i) {
            const glm::dvec3 p = from + (to - from) * (double(i) / steps);
            const double v = visibilityAt(on, off, cam, p), t = glm::length(p - from);
            if (v < 0) continue;
            if (e.at10 < 0 && v >= 0.1) e.at10 = t;
            if (e.at50 < 0 && v >= 0.5) e.at50 = t;
            if (e.at90 < 0 && v >= 0.9) e.at90 = t;
        }
        return e;
    }

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QVERIFY(startGl());
    }

    // A spot straight above a sphere floating over a visible ground: the ground under the sphere is in
    // shadow, a ground point outside the shadow's closed-form radius is lit exactly as without shadows,
    // in every tier, both shading models and the forward, deferred and clustered paths.
    void spotShadowsTheGroundUnderASphere() {
        QVERIFY(m_gl->setModel(floatingSphere()));
        const ViewCamera cam = groundCamera();
        const double radius = sphereShadowRadius(4.0, 1.0, 0.5);
        for (ShadingModel model : {ShadingModel::Classic, ShadingModel::Pbr}) {
            const Rig on =
                withGround({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.0)}, GroundMode::Visible, model);
            const Rig off = withoutShadows(on);
            for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast}) {
                for (ShadingPath path : {ShadingPath::Forward, ShadingPath::Deferred}) {
                    for (int clustered : {0, 1}) {
                        if (clustered && (path == ShadingPath::Deferred || q == Quality::Fast)) continue;
                        RenderSettings s = settingsFor(q, path);
                        s.clusteredShading = clustered;
                        const FloatImage a = radiance(on, cam, s);
                        QCOMPARE(m_gl->renderer().stats().deferred,
                                 path == ShadingPath::Deferred && q != Quality::Fast);
                        const FloatImage b = radiance(off, cam, referenceFor(s));
                        const QString where = QStringLiteral("%1 %2 %3%4")
                                                  .arg(toString(model), toString(q))
                                                  .arg(path == ShadingPath::Deferred ? "deferred" : "forward")
                                                  .arg(clustered ? " clustered" : "");
                        const double under = visibilityAt(a, b, cam, {0.0, 0.0, 0.0});
                        const double inside = visibilityAt(a, b, cam, {0.0, 0.0, 0.7 * radius});
                        const double outside = visibilityAt(a, b, cam, {1.6 * radius, 0.0, 0.0});
                        QVERIFY2(under >= 0 && under < 0.02,
                                 qPrintable(where + QStringLiteral(": %1").arg(under)));
                        QVERIFY2(inside >= 0 && inside < 0.02,
                                 qPrintable(where + QStringLiteral(": %1").arg(inside)));
                        QVERIFY2(std::abs(outside - 1.0) < litTolerance(q),
                                 qPrintable(where + QStringLiteral(": %1").arg(outside)));
                    }
                }
            }
        }
    }

    // Size 0: the outline sits at the closed-form radius and is hard (a pixel or two wide) in every tier.
    // A larger emitter widens the exact tier's penumbra, by about the similar-triangles width.
    void penumbraWidthFollowsTheEmitter() {
        QVERIFY(m_gl->setModel(floatingSphere()));
        const ViewCamera cam = groundCamera();
        const double radius = sphereShadowRadius(4.0, 1.0, 0.5);
        const glm::dvec3 from(0.3, 0.0, 0.0), to(1.3, 0.0, 0.0);
        double hardWidth = 0.0;
        for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast}) {
            const Rig on = withGround({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.0)}, GroundMode::Visible);
            const FloatImage a = radiance(on, cam, settingsFor(q)),
                             b = radiance(withoutShadows(on), cam, referenceFor(settingsFor(q)));
            const Edge e = edgeAlong(a, b, cam, from, to);
            QVERIFY2(e.at10 >= 0 && e.at90 >= 0, toString(q).toLatin1());
            QVERIFY2(std::abs(0.3 + e.at50 - radius) < 0.03,
                     qPrintable(QStringLiteral("%1: edge at %2, expected %3")
                                    .arg(toString(q))
                                    .arg(0.3 + e.at50)
                                    .arg(radius)));
            QVERIFY2(e.width() < 0.06,
                     qPrintable(QStringLiteral("%1: hard edge %2 wide").arg(toString(q)).arg(e.width())));
            if (q == Quality::Exact) hardWidth = e.width();
        }
        // Emitter 0.8 wide at height 4, the sphere's silhouette about 3 below it: a penumbra about
        // 0.8 · (4 − 3) / 3 ≈ 0.27 wide on the ground.
        const Rig soft = withGround({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.8)}, GroundMode::Visible);
        const FloatImage a = radiance(soft, cam, settingsFor(Quality::Exact)),
                         b = radiance(withoutShadows(soft), cam, settingsFor(Quality::Exact));
        const Edge e = edgeAlong(a, b, cam, from, to);
        QVERIFY2(e.width() > 0.12 && e.width() > 3.0 * hardWidth && e.width() < 0.6,
                 qPrintable(QStringLiteral("soft penumbra %1 wide (hard %2)").arg(e.width()).arg(hardWidth)));
        QVERIFY2(std::abs(0.3 + e.at50 - radius) < 0.06,
                 qPrintable(QStringLiteral("soft edge at %1").arg(0.3 + e.at50)));
    }

    // A plane lit at a grazing angle, nothing above it: no texel may shadow it (no acne), in any tier,
    // from a directional light and from a spot.
    void grazingLightCausesNoAcne() {
        auto plane = std::make_shared<Model>(horizontalQuad(1.0, glm::dvec3(0.0)));
        QVERIFY(m_gl->setModel(plane));
        ViewCamera cam;
        cam.eye = {0.0, 2.0, 2.0};
        cam.target = {0.0, 0.0, 0.0};
        Light sun = directional({std::cos(0.087), -std::sin(0.087), 0.2}, DiffuseModel::Lambert); // ~5°
        sun.shadow.enabled = true;
        Light spotLight = castingSpot({-3.0, 0.25, 0.0}, {0.0, 0.0, 0.0}, 30, 0.0);
        for (const Light& l : {sun, spotLight}) {
            for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast}) {
                for (double size : {0.0, 0.2}) {
                    Light lit = l;
                    lit.shadow.size = size;
                    lit.shadow.angle = size * 10.0;
                    const Rig on = rigOf({lit});
                    const FloatImage a = radiance(on, cam, settingsFor(q)),
                                     b = radiance(withoutShadows(on), cam, referenceFor(settingsFor(q)));
                    int covered = 0, dark = 0;
                    double worst = 1.0;
                    for (int y = 0; y < kSize.height(); ++y) {
                        for (int x = 0; x < kSize.width(); ++x) {
                            const double ref = luminance(b.at(x, y));
                            if (b.at(x, y).w < 0.5f || !(ref > 1e-4)) continue;
                            ++covered;
                            const double v = luminance(a.at(x, y)) / ref;
                            worst = std::min(worst, v);
                            if (v < 0.999) ++dark;
                        }
                    }
                    QVERIFY(covered > 1000);
                    QVERIFY2(dark == 0,
                             qPrintable(QStringLiteral("%1 %2 size %3: %4 of %5 pixels shadowed, worst %6")
                                            .arg(toString(l.type), toString(q))
                                            .arg(size)
                                            .arg(dark)
                                            .arg(covered)
                                            .arg(worst)));
                }
            }
        }
    }

    // A cube resting on the ground, lit at 45°: the shadow starts at the contact edge (no peter-panning)
    // and ends one cube height beyond it; the ground on the lit side stays lit.
    void cubeShadowTouchesItsContactEdge() {
        QVERIFY(m_gl->setModel(std::make_shared<Model>(restingCube(0.5))));
        ViewCamera cam;
        cam.eye = {1.6, 2.5, 3.5};
        cam.target = {0.6, 0.0, 0.0};
        Light sun = directional({1.0, -1.0, 0.0}, DiffuseModel::Lambert);
        sun.shadow.enabled = true;
        for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast}) {
            const Rig on = withGround({sun}, GroundMode::Visible);
            const FloatImage a = radiance(on, cam, settingsFor(q)),
                             b = radiance(withoutShadows(on), cam, referenceFor(settingsFor(q)));
            for (double x : {0.51, 0.53, 1.0, 1.45}) {
                const double v = visibilityAt(a, b, cam, {x, 0.0, 0.0});
                QVERIFY2(v >= 0 && v < 0.05,
                         qPrintable(QStringLiteral("%1: x %2 visibility %3").arg(toString(q)).arg(x).arg(v)));
            }
            for (double x : {1.56, 2.0}) {
                const double v = visibilityAt(a, b, cam, {x, 0.0, 0.0});
                QVERIFY2(std::abs(v - 1.0) < litTolerance(q),
                         qPrintable(QStringLiteral("%1: x %2 visibility %3").arg(toString(q)).arg(x).arg(v)));
            }
            const double side = visibilityAt(a, b, cam, {0.0, 0.0, 0.6});
            QVERIFY2(std::abs(side - 1.0) < litTolerance(q),
                     qPrintable(QStringLiteral("%1: beside %2").arg(toString(q)).arg(side)));
        }
    }

    // A point light among five small spheres (four around it, one below): each throws its shadow outward
    // through its own cube face; the ground between the shadows stays lit.
    void pointLightCastsToAllSides() {
        auto m = std::make_shared<Model>(makeSphere(0.15, 32, 16, {0.0, 0.6, 0.0}));
        for (glm::dvec3 c : {glm::dvec3(0.6, 0.9, 0), glm::dvec3(-0.6, 0.9, 0), glm::dvec3(0, 0.9, 0.6),
                             glm::dvec3(0, 0.9, -0.6)})
            appendMeshes(*m, makeSphere(0.15, 32, 16, c));
        appendMeshes(*m, horizontalQuad(0.02, {0.8, 0.0, 0.8}));
        recomputeBounds(*m);
        QVERIFY(m_gl->setModel(m));
        ViewCamera cam;
        cam.eye = {0.0, 9.0, 3.0};
        cam.target = {0.0, 0.0, 0.0};
        Light bulb = makeLight(LightType::Point, QStringLiteral("bulb"));
        bulb.position = {0.0, 1.2, 0.0};
        bulb.falloff.model = FalloffModel::None;
        bulb.falloff.range = -1.0;
        bulb.shadow.enabled = true;
        const Rig on = withGround({bulb}, GroundMode::Visible);
        for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast}) {
            const FloatImage a = radiance(on, cam, settingsFor(q)),
                             b = radiance(withoutShadows(on), cam, referenceFor(settingsFor(q)));
            // From the light through each sphere's centre to y = 0: 4× the horizontal offset for the ring.
            for (glm::dvec3 p : {glm::dvec3(2.4, 0, 0), glm::dvec3(-2.4, 0, 0), glm::dvec3(0, 0, 2.4),
                                 glm::dvec3(0, 0, -2.4), glm::dvec3(0.05, 0, 0.05)}) {
                const double v = visibilityAt(a, b, cam, p);
                QVERIFY2(v >= 0 && v < 0.05, qPrintable(QStringLiteral("%1: (%2, %3) visibility %4")
                                                            .arg(toString(q))
                                                            .arg(p.x)
                                                            .arg(p.z)
                                                            .arg(v)));
            }
            for (glm::dvec3 p : {glm::dvec3(1.7, 0, 1.7), glm::dvec3(-1.7, 0, 1.7), glm::dvec3(1.7, 0, -1.7),
                                 glm::dvec3(-1.7, 0, -1.7)}) {
                const double v = visibilityAt(a, b, cam, p);
                QVERIFY2(std::abs(v - 1.0) < litTolerance(q),
                         qPrintable(QStringLiteral("%1: (%2, %3) visibility %4")
                                        .arg(toString(q))
                                        .arg(p.x)
                                        .arg(p.z)
                                        .arg(v)));
            }
        }
        radiance(on, cam, settingsFor(Quality::Exact));
        QCOMPARE(m_gl->renderer().stats().shadowMapBytes, qint64(6) * 1024 * 1024 * 4);
    }

    // A rect light over the floating sphere shadows the ground: the GPU visibility (exact tier) agrees
    // with the traced reference's wherever the traced one is 0 or 1, away from its penumbra band; a rect
    // ten times as wide gives a wider measured band (10 % to 90 %); a one-sided rect close under the
    // sphere (a 5-face cube) shadows nothing in front of it, as the two-sided one (6 faces).
    void rectShadowFollowsItsSize() {
        const auto model = floatingSphere();
        QVERIFY(m_gl->setModel(model));
        const ViewCamera cam = groundCamera();
        const ShadowTracer tracer(*model, false);
        QVERIFY2(tracer.ok(), qPrintable(tracer.error()));
        const glm::dvec3 from(0.0, 0.0, 0.0), to(1.8, 0.0, 0.0);
        double widths[2] = {0.0, 0.0};
        int k = 0;
        for (double width : {0.2, 2.0}) {
            const Rig on = withGround({castingRect({0, 4, 0}, width)}, GroundMode::Visible);
            const FloatImage a = radiance(on, cam, settingsFor(Quality::Exact)),
                             b = radiance(withoutShadows(on), cam, settingsFor(Quality::Exact));
            QVERIFY2(visibilityAt(a, b, cam, {1.5, 0.0, 0.0}) >= 0,
                     "the rect light lights nothing on the ground beside the shadow (GPU area shading)");
            const ShadowEmitter e = shadowEmitter(on, m_gl->renderer().sceneFrame(), on.lights.front());
            // The traced profile along the ground through the shadow's centre, and its penumbra band
            // [lo, hi] (0 < traced < 1), widened by half its width each side: PCSS widens a penumbra
            // about the centre's hard edge, so its kernel reaches that far into the umbra.
            const int steps = 240;
            std::vector<double> traced(steps + 1);
            double lo = 1e9, hi = -1e9;
            for (int i = 0; i <= steps; ++i) {
                const glm::dvec3 p(-1.8 + 3.6 * i / steps, 0.0, 0.0);
                traced[size_t(i)] = tracer.visibility(p, {0, 1, 0}, e, std::uint32_t(i), 1024);
                if (traced[size_t(i)] > 0.0 && traced[size_t(i)] < 1.0 && p.x > 0.0) {
                    lo = std::min(lo, p.x);
                    hi = std::max(hi, p.x);
                }
            }
            const double margin = 0.5 * (hi - lo) + 0.02;
            int compared = 0, wrong = 0;
            for (int i = 0; i <= steps; ++i) {
                const glm::dvec3 p(-1.8 + 3.6 * i / steps, 0.0, 0.0);
                const double t = traced[size_t(i)], d = std::abs(p.x);
                if (!(d < lo - margin || d > hi + margin)) continue;
                const double v = visibilityAt(a, b, cam, p);
                if (v < 0) continue;
                ++compared;
                const bool ok =
                    t == 0.0 ? v < 0.02 : t == 1.0 && std::abs(v - 1.0) < litTolerance(Quality::Exact);
                if (!ok && ++wrong <= 5)
                    qWarning() << "rect" << width << "at x" << p.x << "traced" << t << "GPU" << v;
            }
            const Edge t = edgeAlong(a, b, cam, from, to);
            double traced10 = -1, traced90 = -1;
            for (int i = steps / 2; i <= steps; ++i) {
                const double x = -1.8 + 3.6 * i / steps;
                if (traced10 < 0 && traced[size_t(i)] >= 0.1) traced10 = x;
                if (traced90 < 0 && traced[size_t(i)] >= 0.9) traced90 = x;
            }
            const Edge& g = t;
            widths[k++] = g.width();
            qInfo() << "rect" << width << "penumbra 10-90 %: GPU" << g.at10 << "to" << g.at90 << "="
                    << g.width() << ", traced" << traced10 << "to" << traced90 << "=" << traced90 - traced10
                    << "; compared" << compared << "points outside the band";
            QCOMPARE(wrong, 0);
            QVERIFY(compared > 30);
            QVERIFY(g.at10 >= 0 && g.at90 >= 0);
        }
        QVERIFY2(widths[1] > 3.0 * widths[0],
                 qPrintable(QStringLiteral("bands %1 and %2").arg(widths[0]).arg(widths[1])));
        // One- and two-sided under the sphere: the same ground, no shadow on it.
        RenderStats stats[2];
        FloatImage images[2];
        for (int two : {0, 1}) {
            const Rig on = withGround({castingRect({0, 0.45, 0}, 0.3, two)}, GroundMode::Visible);
            images[two] = radiance(on, cam, settingsFor(Quality::Exact));
            stats[two] = m_gl->renderer().stats();
            const FloatImage b = radiance(withoutShadows(on), cam, settingsFor(Quality::Exact));
            for (double x : {0.0, 0.3, 0.8})
                QVERIFY2(std::abs(visibilityAt(images[two], b, cam, {x, 0.0, 0.1}) - 1.0) < 1e-4,
                         qPrintable(QStringLiteral("%1-sided at %2").arg(two + 1).arg(x)));
        }
        QCOMPARE(stats[0].shadowLayersRendered, 5);
        QCOMPARE(stats[1].shadowLayersRendered, 6);
    }
};

LR_GL_TEST_MAIN(TestShadowShapes)
#include "tst_shadowshapes.moc"
