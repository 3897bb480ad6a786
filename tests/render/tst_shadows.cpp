// Shadows (issue 14): the maps, their cache, the tiers' filters, the bias, the ground and the shadow
// catcher, on analytic scenes (shadowscenes.h) whose shadows are known in closed form. Probes are world
// points projected with the renderer's camera; visibility is the ratio of a render with the light's
// shadow on to the same render with it off (so the lighting itself cancels).
#include "glfixture.h"
#include "scenes.h"
#include "shadowscenes.h"

#include "render/offscreen.h"
#include "render/renderplan.h"
#include "render/shadergen.h"
#include "render/shadowmaps.h"
#include "scene/referencetrace.h"

#include <QTest>
#include <algorithm>
#include <cmath>

using namespace lr;
using namespace lr::render;
using namespace lr::test;

namespace {

const QSize kSize(400, 300);

Light castingSpot(glm::dvec3 position, glm::dvec3 target, double outer, double size) {
    Light l = makeLight(LightType::Spot, QStringLiteral("spot"));
    l.position = position;
    l.direction = glm::normalize(target - position);
    l.falloff.model = FalloffModel::None;
    l.falloff.range = -1.0;
    l.cone = {ConeModel::Smooth, outer - 2.0, outer, 1.0};
    l.shadow.enabled = true;
    l.shadow.size = size;
    return l;
}

// A rect light at `position` shining straight down, `width` × `width`, one- or two-sided.
Light castingRect(glm::dvec3 position, double width, bool twoSided = false) {
    Light l = makeLight(LightType::Rect, QStringLiteral("rect"));
    l.position = position;
    l.direction = {0.0, -1.0, 0.0};
    l.area.width = width;
    l.area.height = width;
    l.area.twoSided = twoSided;
    l.shadow.enabled = true;
    return l;
}

Rig withGround(std::vector<Light> lights, GroundMode mode, ShadingModel shading = ShadingModel::Classic) {
    Rig r = rigOf(std::move(lights));
    r.ground.mode = mode;
    r.shading.model = shading;
    return r;
}

Rig withoutShadows(Rig r) {
    for (Light& l : r.lights)
        l.shadow.enabled = false;
    return r;
}

RenderSettings settingsFor(Quality q, ShadingPath path = ShadingPath::Forward) {
    RenderSettings s;
    s.quality = q;
    s.msaaSamples = 0;
    s.shadingPath = path;
    return s;
}

// Lit ground compared with the same render without shadows: equal up to float rounding (the fast tier's
// program is another one: its reference is the exact tier's, see referenceFor).
double litTolerance(Quality q) {
    return q == Quality::Fast ? 1e-3 : 1e-4;
}

// The unshadowed render to compare a tier with: its own, except for the fast tier, whose casting lights are
// shaded per pixel exactly as the exact tier shades them (without its shadow a light would be Gouraud).
RenderSettings referenceFor(RenderSettings s) {
    if (s.quality == Quality::Fast) s.quality = Quality::Exact;
    return s;
}

// The radius of the shadow a sphere (centre c, radius a) casts from a point light at height h straight
// above it onto the plane y = 0: the tangent cone's half-angle asin(a / d), d = h − c.y.
double sphereShadowRadius(double h, double cy, double a) {
    const double half = std::asin(a / (h - cy));
    return h * std::tan(half);
}

} // namespace

class TestShadows : public QObject {
    Q_OBJECT
    std::unique_ptr<OffscreenRenderer> m_gl;

    bool startGl() {
        if (!haveDisplay()) return false;
        if (m_gl) return true;
        m_gl = std::make_unique<OffscreenRenderer>();
        QString error;
        if (!m_gl->initialize(&error)) qFatal("%s", qPrintable(error));
        return true;
    }

    FloatImage radiance(const Rig& rig, const ViewCamera& cam, const RenderSettings& s) {
        m_gl->setRig(rig);
        FloatImage out;
        QString error;
        if (!m_gl->renderRadiance(cam, kSize, s, &out, &error)) qWarning("%s", qPrintable(error));
        return out;
    }

    // Shadowed over unshadowed luminance at a world point (-1 where it is off the image or unlit).
    double visibilityAt(const FloatImage& on, const FloatImage& off, const ViewCamera& cam, glm::dvec3 p) {
        const auto px = projectToPixel(m_gl->renderer(), cam, kSize, p);
        if (!px) return -1.0;
        const double lit = luminance(off.at(px->x(), px->y()));
        return lit > 1e-6 ? luminance(on.at(px->x(), px->y())) / lit : -1.0;
    }

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

    // Without a casting light the programs are today's: no shadow define in any prelude, no shadow pass,
    // no map memory, and the image is the same byte for byte whatever the (disabled) shadow says.
    void withoutCastersNothingChanges() {
        FeatureKey key;
        key.rig = rigFeatures(rigOf({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.3)}));
        QVERIFY(key.rig.shadows);
        QVERIFY(shaderPrelude(key).contains("#define LR_SHADOWS 1"));
        // The six-face lookup only where a point light casts: a spot-only rig does not pay for it.
        QVERIFY(!key.rig.cubeShadows && !shaderPrelude(key).contains("LR_SHADOW_CUBE"));
        Light pointCaster = castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.3);
        pointCaster.type = LightType::Point;
        FeatureKey cube;
        cube.rig = rigFeatures(rigOf({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.3), pointCaster}));
        QVERIFY(cube.rig.cubeShadows && cube.bits() != key.bits());
        QVERIFY(shaderPrelude(cube).contains("#define LR_SHADOW_CUBE 1"));
        // The filters only where some emitter has an extent (this spot's size is 0.3; a size-0 rig has none).
        QVERIFY(key.rig.softShadows && shaderPrelude(key).contains("#define LR_SHADOW_SOFT 1"));
        FeatureKey hard;
        hard.rig = rigFeatures(rigOf({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.0)}));
        QVERIFY(hard.rig.shadows && !hard.rig.softShadows && !shaderPrelude(hard).contains("LR_SHADOW_SOFT"));
        for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast}) {
            for (ShadingModel m : {ShadingModel::Classic, ShadingModel::Pbr}) {
                Rig r = withoutShadows(rigOf({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.3)}));
                r.shading.model = m;
                FeatureKey k;
                k.rig = rigFeatures(r);
                k.quality = q;
                QVERIFY(!k.rig.shadows);
                QVERIFY(!shaderPrelude(k).contains("SHADOW"));
            }
        }
        // A rim light cannot cast: its shadow settings are ignored.
        Light rimLight = rim({0, 0, -1}, 1.3);
        rimLight.shadow.enabled = true;
        QVERIFY(!rigFeatures(rigOf({rimLight})).shadows);

        QVERIFY(m_gl->setModel(floatingSphere()));
        const ViewCamera cam = groundCamera();
        Rig plain = withoutShadows(withGround({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.0)}, GroundMode::Off));
        Rig odd = plain;
        odd.lights[0].shadow = {false, 2048, 5.0, 3.0, 0.7, 2.0}; // every field but `enabled` changed
        RenderSettings s = settingsFor(Quality::Exact);
        QString error;
        m_gl->setRig(plain);
        const QImage a = m_gl->renderImage(cam, kSize, s, 1, &error);
        m_gl->setRig(odd);
        const QImage b = m_gl->renderImage(cam, kSize, s, 1, &error);
        QVERIFY(!a.isNull());
        QVERIFY(a == b);
        const RenderStats& st = m_gl->renderer().stats();
        QCOMPARE(st.shadowCasters, 0);
        QCOMPARE(st.shadowMapBytes, qint64(0));
        QVERIFY(!m_gl->renderer().renderPlan().contains(QLatin1String("shadow")));
    }

    // The grid (an overlay under the model's bounds) gives way to a visible ground at the same height,
    // which it would z-fight; with the ground off or a catcher it is drawn.
    void visibleGroundReplacesTheGrid() {
        QVERIFY(m_gl->setModel(floatingSphere()));
        const ViewCamera cam = groundCamera();
        RenderSettings grid = settingsFor(Quality::Exact);
        grid.showGrid = true;
        RenderSettings none = grid;
        none.showGrid = false;
        QString error;
        for (GroundMode mode : {GroundMode::Off, GroundMode::Visible, GroundMode::Catcher}) {
            m_gl->setRig(withGround({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.0)}, mode));
            const QImage with = m_gl->renderImage(cam, kSize, grid, 1, &error);
            const QImage without = m_gl->renderImage(cam, kSize, none, 1, &error);
            QVERIFY2(!with.isNull() && !without.isNull(), qPrintable(error));
            QCOMPARE(with == without, mode == GroundMode::Visible);
        }
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

    // Orbiting re-renders no map; moving one of two lights re-renders that light's map only; a point light
    // renders six layers; without casters the array is freed.
    void mapsAreCachedUntilTheirLightMoves() {
        QVERIFY(m_gl->setModel(floatingSphere()));
        ViewCamera cam = groundCamera();
        Rig rig = withGround(
            {castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.0), castingSpot({2, 3, 0}, {0, 0, 0}, 40, 0.0)},
            GroundMode::Visible);
        const RenderSettings s = settingsFor(Quality::Exact);
        QString error;
        m_gl->setRig(rig);
        QVERIFY(m_gl->renderFrame(cam, kSize, s, &error));
        const RenderStats& st = m_gl->renderer().stats();
        QCOMPARE(st.shadowCasters, 2);
        QCOMPARE(st.shadowMapsRendered, 2);
        QCOMPARE(st.shadowMapBytes, qint64(2) * 1024 * 1024 * 4);
        QVERIFY(m_gl->renderer().renderPlan().startsWith(QLatin1String("shadow > ")));
        cam.orbit(30.0, 10.0);
        QVERIFY(m_gl->renderFrame(cam, kSize, s, &error));
        QCOMPARE(st.shadowMapsRendered, 0);
        rig.lights[1].position.x += 0.25;
        m_gl->setRig(rig);
        QVERIFY(m_gl->renderFrame(cam, kSize, s, &error));
        QCOMPARE(st.shadowMapsRendered, 1);
        QCOMPARE(st.shadowLayersRendered, 1);
        rig.lights[0].shadow.size = 0.5; // sampling only: the map stays
        rig.lights[0].color = {1.0, 0.5, 0.5};
        m_gl->setRig(rig);
        QVERIFY(m_gl->renderFrame(cam, kSize, s, &error));
        QCOMPARE(st.shadowMapsRendered, 0);
        Light bulb = makeLight(LightType::Point, QStringLiteral("bulb"));
        bulb.position = {1.0, 2.5, 1.0};
        bulb.shadow.enabled = true;
        rig.lights.push_back(bulb);
        m_gl->setRig(rig);
        QVERIFY(m_gl->renderFrame(cam, kSize, s, &error));
        QCOMPARE(st.shadowCasters, 3);
        QCOMPARE(st.shadowLayersRendered, 8); // the array grew: every layer again
        QCOMPARE(st.shadowMapBytes, qint64(8) * 1024 * 1024 * 4);
        QVERIFY(m_gl->setModel(floatingSphere())); // a new model: every map again
        QVERIFY(m_gl->renderFrame(cam, kSize, s, &error));
        QCOMPARE(st.shadowMapsRendered, 3);
        m_gl->setRig(withoutShadows(rig));
        QVERIFY(m_gl->renderFrame(cam, kSize, s, &error));
        QCOMPARE(st.shadowMapBytes, qint64(0));
        QCOMPARE(st.shadowCasters, 0);
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

    // The casters beyond kMaxShadowCasters are left out (in rig order); the maps of extreme lights stay
    // finite: a 179° spot maps only the model's cone, a 0.1° spot its own.
    void planLimitsAndExtremes() {
        Rig rig;
        for (int i = 0; i < kMaxShadowCasters + 4; ++i)
            rig.lights.push_back(castingSpot({double(i), 4, 0}, {0, 0, 0}, 40, 0.0));
        Bounds b;
        b.min = glm::dvec3(-1.0);
        b.max = glm::dvec3(1.0);
        const SceneFrame frame{b.center(), b.radius()};
        const auto views = planShadows(rig, frame, b);
        QCOMPARE(int(views.size()), kMaxShadowCasters);
        QCOMPARE(views.back().rigIndex, kMaxShadowCasters - 1);
        const double sphere = std::tan(std::asin(b.radius() * 1.02 / 4.0));
        const auto wide = planShadows(rigOf({castingSpot({0, 4, 0}, {0, 0, 0}, 89.5, 0.0)}), frame, b);
        QVERIFY(std::abs(wide.front().tanHalf - sphere) < 1e-9);
        const auto narrow = planShadows(rigOf({castingSpot({0, 4, 0}, {0, 0, 0}, 0.1, 0.0)}), frame, b);
        QVERIFY(std::abs(narrow.front().tanHalf - std::tan(0.1 * M_PI / 180.0)) < 1e-12);
        Light inside = castingSpot({0, 0, 0}, {0, -1, 0}, 89.5, 0.0);
        const auto in = planShadows(rigOf({inside}), frame, b);
        QVERIFY(in.front().tanHalf <= std::tan(85.0 * M_PI / 180.0) + 1e-9);
        QVERIFY(in.front().znear > 0.0 && in.front().znear < in.front().zfar);
    }

    // Area lights' maps: a rect far from the model gets one perspective map fitted to the model's sphere,
    // one close to it a cube in its own frame (face 4 along its direction) without the back face (5
    // layers; 6 when two-sided); PCSS sizes: the equal-area diameter and the diagonal; a point light's
    // map is as before.
    void areaLightMapsPlan() {
        const auto model = floatingSphere();
        const Rig far = rigOf({castingRect({0, 4, 0}, 0.5)});
        const SceneFrame frame{model->bounds.center(), model->bounds.radius()};
        std::vector<ShadowView> v = planShadows(far, frame, model->bounds);
        QCOMPARE(int(v.size()), 1);
        QCOMPARE(v[0].kind, ShadowKind::Perspective);
        QCOMPARE(v[0].layers(), 1);
        QCOMPARE(v[0].maxFilterTexels, kAreaMapFilterTexels);
        const double toWorld = 1.0 / distanceScale(far, frame);
        QVERIFY(std::abs(v[0].emitter - 2.0 * std::sqrt(0.25 / M_PI) * toWorld) < 1e-12);
        QVERIFY(std::abs(v[0].searchEmitter - std::sqrt(0.5) * toWorld) < 1e-12);
        const Rig near = rigOf({castingRect({0, 1.2, 0}, 0.5)});
        v = planShadows(near, frame, model->bounds);
        QCOMPARE(v[0].kind, ShadowKind::Cube);
        QCOMPARE(v[0].layers(), 5);
        QCOMPARE(v[0].maxFilterTexels, kAreaFilterTexels);
        QVERIFY(glm::length(v[0].axes[2] - glm::dvec3(0, -1, 0)) < 1e-12);
        QVERIFY(std::abs(glm::determinant(v[0].axes) - 1.0) < 1e-12);
        const Rig both = rigOf({castingRect({0, 1.2, 0}, 0.5, true)});
        QCOMPARE(planShadows(both, frame, model->bounds)[0].layers(), 6);
        Light bulb = makeLight(LightType::Point, QStringLiteral("bulb"));
        bulb.shadow.enabled = true;
        bulb.shadow.size = 0.2;
        v = planShadows(rigOf({bulb}), frame, model->bounds);
        QCOMPARE(v[0].layers(), 6);
        QCOMPARE(v[0].maxFilterTexels, kCubeMarginTexels);
        QCOMPARE(v[0].searchEmitter, v[0].emitter);
        QVERIFY(v[0].axes == glm::dmat3(1.0));
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

    // Extreme lights render finite in every tier: a 179° and a 0.1° spot, a directional light parallel to
    // the ground, a point light inside the model (every ground point is then in its shadow).
    void extremeLightsStayFinite() {
        QVERIFY(m_gl->setModel(floatingSphere()));
        const ViewCamera cam = groundCamera();
        Light parallel = directional({1.0, 0.0, 0.0}, DiffuseModel::Lambert);
        parallel.shadow.enabled = true;
        parallel.shadow.angle = 2.0;
        Light bulb = makeLight(LightType::Point, QStringLiteral("inside"));
        bulb.position = {0.0, 1.0, 0.0};
        bulb.falloff.model = FalloffModel::None;
        bulb.falloff.range = -1.0;
        bulb.shadow.enabled = true;
        bulb.shadow.size = 0.1;
        const Light lights[] = {castingSpot({0, 4, 0}, {0, 0, 0}, 89.5, 0.3),
                                castingSpot({0, 4, 0}, {0, 0, 0}, 0.1, 0.3), parallel, bulb};
        for (const Light& l : lights) {
            for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast}) {
                const Rig on = withGround({l}, GroundMode::Visible);
                const FloatImage a = radiance(on, cam, settingsFor(q));
                int nonFinite = 0;
                for (const glm::vec4& p : a.pixels)
                    nonFinite += std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) ? 0 : 1;
                QVERIFY2(nonFinite == 0, qPrintable(QStringLiteral("%1 %2").arg(l.name, toString(q))));
                if (l.type == LightType::Point) {
                    const FloatImage b = radiance(withoutShadows(on), cam, referenceFor(settingsFor(q)));
                    const double v = visibilityAt(a, b, cam, {1.5, 0.0, 0.5});
                    QVERIFY2(v >= 0 && v < 0.02,
                             qPrintable(QStringLiteral("%1: %2").arg(toString(q)).arg(v)));
                }
                if (l.type == LightType::Spot && l.cone.outer > 80) {
                    const FloatImage b = radiance(withoutShadows(on), cam, referenceFor(settingsFor(q)));
                    QVERIFY(visibilityAt(a, b, cam, {0.0, 0.0, 0.0}) < 0.02);
                    QVERIFY(std::abs(visibilityAt(a, b, cam, {2.0, 0.0, 0.0}) - 1.0) < litTolerance(q));
                }
            }
        }
    }

    // The shadow catcher in a transparent image: black with alpha only inside the shadow's closed-form
    // disc (plus its edge), alpha 0 on the rest of the invisible ground; over an opaque background the
    // background darkens there.
    void catcherWritesTheShadowAsAlpha() {
        QVERIFY(m_gl->setModel(floatingSphere()));
        const ViewCamera cam = groundCamera();
        const double radius = sphereShadowRadius(4.0, 1.0, 0.5);
        for (Quality q : {Quality::Exact, Quality::Fast}) {
            for (ShadingPath path : {ShadingPath::Forward, ShadingPath::Deferred, ShadingPath::Auto}) {
                RenderSettings s = settingsFor(q, path);
                s.hdrTarget = path == ShadingPath::Auto; // the tone-map pass composites the catcher's alpha
                s.transparentBackground = true;
                QString error;
                m_gl->setRig(withGround({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.0)}, GroundMode::Catcher));
                const QImage catcher = m_gl->renderImage(cam, kSize, s, 1, &error);
                m_gl->setRig(withGround({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.0)}, GroundMode::Off));
                const QImage bare = m_gl->renderImage(cam, kSize, s, 1, &error);
                QVERIFY2(!catcher.isNull() && !bare.isNull(), qPrintable(error));
                const QPoint centre = *projectToPixel(m_gl->renderer(), cam, kSize, {0.0, 0.0, 0.0});
                const QRgb c = catcher.pixel(centre);
                QVERIFY2(qAlpha(c) > 240 && qRed(c) == 0 && qGreen(c) == 0,
                         qPrintable(QString::number(qAlpha(c))));
                int shadowPixels = 0;
                for (int y = 0; y < kSize.height(); ++y) {
                    for (int x = 0; x < kSize.width(); ++x) {
                        if (qAlpha(bare.pixel(x, y)) != 0) {
                            QCOMPARE(qAlpha(catcher.pixel(x, y)), 255); // the model itself
                            continue;
                        }
                        if (qAlpha(catcher.pixel(x, y)) == 0) continue;
                        const auto g = pixelOnPlane(m_gl->renderer(), cam, kSize, x, y, 0.0);
                        QVERIFY(g.has_value());
                        const double r = glm::length(glm::dvec2(g->x, g->z));
                        QVERIFY2(r < radius + 0.05, qPrintable(QStringLiteral("alpha %1 at ground radius %2")
                                                                   .arg(qAlpha(catcher.pixel(x, y)))
                                                                   .arg(r)));
                        ++shadowPixels;
                    }
                }
                QVERIFY(shadowPixels > 500);
                // Opaque background: darkened inside the shadow, untouched outside it.
                s.transparentBackground = false;
                s.background = QColor(200, 200, 200);
                m_gl->setRig(withGround({castingSpot({0, 4, 0}, {0, 0, 0}, 40, 0.0)}, GroundMode::Catcher));
                const QImage over = m_gl->renderImage(cam, kSize, s, 1, &error);
                QVERIFY(qRed(over.pixel(centre)) < 20);
                const QPoint far = *projectToPixel(m_gl->renderer(), cam, kSize, {1.6 * radius, 0.0, 0.0});
                QCOMPARE(qRed(over.pixel(far)), 200);
            }
        }
    }
};

LR_GL_TEST_MAIN(TestShadows)
#include "tst_shadows.moc"
