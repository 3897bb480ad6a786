// GL-free parts of the renderer: camera math (orbit, pan, dolly, framing, standard views, tiles, clip
// planes), the shader feature key (what compiles and what does not) and the light texel packing.
#include "core/prepare.h"
#include "render/lightpack.h"
#include "render/shadergen.h"
#include "scene/camera.h"

#include <QTest>
#include <glm/ext/matrix_transform.hpp>

using namespace lr;
using namespace lr::render;

namespace {

Bounds box(glm::dvec3 lo, glm::dvec3 hi) {
    Bounds b;
    b.min = lo;
    b.max = hi;
    return b;
}

// NDC of a world point; w <= 0 gives NaN coordinates.
glm::dvec3 ndc(const ViewCamera& c, double aspect, const glm::dvec3& p) {
    const glm::dvec4 q = c.projection(aspect) * c.view() * glm::dvec4(p, 1.0);
    return q.w > 0 ? glm::dvec3(q) / q.w : glm::dvec3(std::nan(""));
}

bool inside(const glm::dvec3& n) {
    return std::abs(n.x) <= 1.0 && std::abs(n.y) <= 1.0 && std::abs(n.z) <= 1.0;
}

} // namespace

class TestRenderCamera : public QObject {
    Q_OBJECT
  private slots:
    void viewMatrixConventions() {
        ViewCamera c;
        c.eye = {1, 2, 3};
        c.target = {1, 2, -7};
        const glm::dvec4 t = c.view() * glm::dvec4(c.target, 1.0);
        QVERIFY(std::abs(t.x) < 1e-12 && std::abs(t.y) < 1e-12 &&
                std::abs(t.z + 10.0) < 1e-12); // looks down -Z
        const glm::dvec4 up = c.view() * glm::dvec4(1, 3, 3, 1.0);
        QVERIFY(up.y > 0.99); // world up stays up
    }

    void orbitPanDolly() {
        ViewCamera c;
        c.eye = {0, 0, 5};
        c.orbit(90.0, 0.0);
        QVERIFY(std::abs(c.distance() - 5.0) < 1e-9);
        QVERIFY(std::abs(c.eye.x - 5.0) < 1e-9); // a quarter turn about +Y
        c.orbit(0.0, 500.0);                     // pitch clamps short of the pole
        QVERIFY(std::abs(c.distance() - 5.0) < 1e-9);
        QVERIFY(glm::dot(glm::normalize(c.eye - c.target), glm::dvec3(0, 1, 0)) < 1.0 - 1e-6);
        QVERIFY(std::isfinite(c.view()[0][0]));
        const glm::dvec3 before = c.target;
        c.pan(0.1, 0.0);
        QVERIFY(glm::length(c.target - before) > 0.0 && std::abs(c.distance() - 5.0) < 1e-9);
        c.dolly(0.5);
        QVERIFY(std::abs(c.distance() - 2.5) < 1e-9);
        c.dolly(0.0); // ignored
        c.dolly(std::nan(""));
        QVERIFY(std::abs(c.distance() - 2.5) < 1e-9);
    }

    void frameAllAndStandardViews_data() {
        QTest::addColumn<QString>("view");
        for (const QString& v : standardViewNames())
            QTest::newRow(qPrintable(v)) << v;
    }

    void frameAllAndStandardViews() {
        QFETCH(QString, view);
        const Bounds b = box({1e6 - 2, -1, 3}, {1e6 + 2, 5, 4}); // far from the origin, elongated
        for (double aspect : {16.0 / 9.0, 0.5}) {
            const auto c = standardView(view, b, aspect);
            QVERIFY(c.has_value());
            const ViewCamera clipped = c->withClipPlanes(b.center(), b.radius());
            for (int i = 0; i < 8; ++i) {
                const glm::dvec3 corner((i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y,
                                        (i & 4) ? b.max.z : b.min.z);
                QVERIFY2(inside(ndc(clipped, aspect, corner)), qPrintable(view));
            }
        }
        QVERIFY(!standardView(QStringLiteral("diagonal"), b, 1.0).has_value());
    }

    void tilesCropTheFullProjection() {
        ViewCamera c;
        c.eye = {0.3, 0.2, 4};
        c.znear = 0.1;
        c.zfar = 100;
        const double aspect = 1.5;
        const glm::dvec4 p = c.view() * glm::dvec4(0.4, -0.3, 0.5, 1);
        const glm::dvec4 full = c.projection(aspect) * p;
        const glm::dvec4 tile = c.projection(aspect, 0.0, -1.0, 1.0, 0.0) * p; // the lower-right quarter
        QVERIFY(std::abs(tile.x / tile.w - (2.0 * full.x / full.w - 1.0)) < 1e-12);
        QVERIFY(std::abs(tile.y / tile.w - (2.0 * full.y / full.w + 1.0)) < 1e-12);
        QVERIFY(std::abs(tile.z / tile.w - full.z / full.w) < 1e-12);
    }

    void modelCameras() {
        Camera cam;
        cam.position = {0, 1, 10};
        cam.forward = {0, 0, -2}; // not unit
        cam.yfovDegrees = 30;
        cam.znear = 0.5;
        cam.zfar = 0.0; // infinite
        const ViewCamera v = fromModelCamera(cam, 10.0);
        QVERIFY(glm::length(v.target - glm::dvec3(0, 1, 0)) < 1e-12);
        QCOMPARE(v.yfovDeg, 30.0);
        const glm::dmat4 p = v.projection(1.0);
        QVERIFY(std::isfinite(p[2][2]) && std::abs(p[2][3] + 1.0) < 1e-12);
    }

    void featureKeys() {
        Rig rig;
        rig.lights.push_back(makeLight(LightType::Point, QStringLiteral("a")));
        const RigFeatures one = rigFeatures(rig);
        Rig moved = rig;
        moved.lights[0].position = {9, 9, 9};
        moved.lights[0].color = {0.1, 0.2, 0.3};
        moved.lights[0].intensity = 7;
        moved.lights[0].falloff.range = 100;
        QVERIFY(rigFeatures(moved) == one); // values never change the key
        Rig more = rig;
        more.lights.push_back(makeLight(LightType::Point, QStringLiteral("b")));
        QVERIFY(rigFeatures(more) == one); // nor does the count
        Rig spot = rig;
        spot.lights.push_back(makeLight(LightType::Spot, QStringLiteral("s")));
        QVERIFY(!(rigFeatures(spot) == one));
        spot.lights[1].enabled = false;
        QVERIFY(rigFeatures(spot) == one); // disabled lights are not compiled in

        FeatureKey a, b;
        a.rig = one;
        b.rig = rigFeatures(more);
        QVERIFY(a.bits() == b.bits());
        b.material.normalMap = true;
        QVERIFY(a.bits() != b.bits());
        const QByteArray prelude = shaderPrelude(a);
        QVERIFY(prelude.startsWith("#version 330 core\n"));
        QVERIFY(prelude.contains("#define LR_HAS_LIGHT_POINT 1"));
        QVERIFY(prelude.contains("#define LR_ONLY_LIGHT 0"));
        QVERIFY(!prelude.contains("LR_HAS_LIGHT_SPOT"));
        QVERIFY(prelude.contains("#define LR_FALLOFF_RANGE_POWER 1")); // enum values from types.h
        QVERIFY(!prelude.contains("LR_NORMAL_MAP"));
    }

    void lightTexels() {
        lighting::ShadeLight<float> l;
        l.type = LightType::Spot;
        l.position = {1, 2, 3};
        l.range = 4;
        l.color = {5, 6, 7};
        l.cone = ConeModel::Hard;
        l.rimExponent = 9;
        const LightTexels t = packLight(l);
        QCOMPARE(t.size(), size_t(4 * kLightTexels));
        QCOMPARE(t[0], 1.0f);
        QCOMPARE(t[3], 4.0f);                        // range beside the position
        QCOMPARE(t[7], float(int(LightType::Spot))); // type beside the colour
        QCOMPARE(t[5 * 4 + 3], float(int(ConeModel::Hard)));
        QCOMPARE(t[7 * 4 + 0], 9.0f);
    }
};

QTEST_GUILESS_MAIN(TestRenderCamera)
#include "tst_rendercamera.moc"
