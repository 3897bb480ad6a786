// Shadows (issue 14): the programs and plans they change, the maps and their cache, the grid giving way to
// the ground, extreme lights and the shadow catcher's alpha, on the analytic scenes of shadowscenes.h
// (probes and visibility: shadowfixture.h). Where the shadows fall and how soft they are: tst_shadowshapes.
#include "glfixture.h"
#include "scenes.h"
#include "shadowfixture.h"
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

class TestShadows : public QObject, protected ShadowFixture {
    Q_OBJECT
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
