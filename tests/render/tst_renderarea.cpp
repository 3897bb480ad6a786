// Area lights on the GPU (issue 16): a rect and a disk light on the test plane and the PBR spheres, under
// classic and physically based shading, forward, deferred and clustered, each quality tier, against
// lighting::shadeSurface<double> (core/lighting_area.h: the same LTC and form factors in double). This
// checks shaders/area.glsl, the area twin; the LTC's own error against the definition is tests/formulas'
// formulas_area (and the Monte Carlo reference's).
//
// Tolerance (per channel, linear radiance): exact |gpu − ref| <= 2e-4 · max(1, |ref|) (float polygon
// integrals: atan2 and cross products of nearly parallel vertex directions lose a few more bits than the
// point lights' formulas; measured on llvmpipe: <= 5e-6); balanced is held to the same bound (its
// approximations do not touch the area code); fast evaluates the area integrals at the vertices (F1) and is
// only checked finite (on the test plane's few vertices the highlight falls between them).
#include "glfixture.h"
#include "scenes.h"

#include "render/offscreen.h"

#include <QTest>

using namespace lr;
using namespace lr::test;

namespace {
constexpr double kExactTolerance = 2e-4;
const QSize kSize(64, 48);

RenderSettings floatSettings() {
    RenderSettings s;
    s.msaaSamples = 0;
    s.hdrFloat32 = true;
    return s;
}

Light areaLight(LightType type, glm::dvec3 p, glm::dvec3 target, double intensity) {
    Light l = makeLight(type, type == LightType::Rect ? QStringLiteral("softbox") : QStringLiteral("disk"));
    l.position = p;
    l.direction = glm::normalize(target - p);
    l.area.width = 1.2, l.area.height = 0.6, l.area.radius = 0.5, l.area.roll = 20.0;
    l.intensity = intensity;
    l.color = {1.0, 0.9, 0.8};
    return l;
}

Rig areaRig(ShadingModel model, SpecularModel spec, DiffuseModel diffuse) {
    Light rect = areaLight(LightType::Rect, {0.6, 0.9, 1.3}, {0, 0, 0}, 3.0);
    Light disk = areaLight(LightType::Disk, {-1.0, -0.4, 1.0}, {0, 0.2, 0}, 2.0);
    disk.area.twoSided = true;
    rect.diffuse = disk.diffuse = diffuse;
    Rig r = model == ShadingModel::Pbr ? pbrRig({rect, disk}) : rigOf({rect, disk});
    r.shading.specular = spec;
    return r;
}

// The extremes on the test plane (z = 0, normal +z): a rect standing across the plane (half of it below the
// surface), a rect lying 1e-4 above the plane facing it (its edges nearly in every point's horizon), a disk
// 1e4× the plane's size far above it, and a rect of zero width.
Rig extremeRig(ShadingModel model, SpecularModel spec) {
    Light across = areaLight(LightType::Rect, {0.5, 0.3, 0.0}, {-1.0, 0.3, 0.0}, 2.0);
    Light touching = areaLight(LightType::Rect, {-0.6, -0.5, 1e-4}, {-0.6, -0.5, -1.0}, 1.0);
    Light huge = areaLight(LightType::Disk, {0.0, 0.0, 5e4}, {0.0, 0.0, 0.0}, 1e-8);
    huge.area.radius = 2e4;
    Light zero = areaLight(LightType::Rect, {0.0, 0.5, 0.8}, {0.0, 0.0, 0.0}, 3.0);
    zero.area.width = 0.0;
    Rig r = model == ShadingModel::Pbr ? pbrRig({across, touching, huge, zero})
                                       : rigOf({across, touching, huge, zero});
    r.shading.specular = spec;
    return r;
}
} // namespace

class TestRenderArea : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
    }

    void matchesDoubleReference_data() {
        QTest::addColumn<int>("model");
        QTest::addColumn<int>("spec");
        QTest::addColumn<int>("diffuse");
        QTest::addColumn<int>("path");
        QTest::addColumn<int>("quality");
        const char* paths[] = {"forward", "deferred", "clustered"};
        for (int q = 0; q < 3; ++q)
            for (int path = 0; path < 3; ++path) {
                if (q != int(Quality::Exact) && path > 0) continue; // fast is forward only; balanced: once
                const char* tier = EnumNames<Quality>::names[size_t(q)];
                QTest::addRow("pbr/%s/%s", paths[path], tier)
                    << int(ShadingModel::Pbr) << 0 << 0 << path << q;
                QTest::addRow("pbr-halflambert/%s/%s", paths[path], tier)
                    << int(ShadingModel::Pbr) << 0 << int(DiffuseModel::HalfLambert) << path << q;
                QTest::addRow("phong/%s/%s", paths[path], tier)
                    << int(ShadingModel::Classic) << int(SpecularModel::Phong) << 0 << path << q;
                QTest::addRow("blinn/%s/%s", paths[path], tier)
                    << int(ShadingModel::Classic) << int(SpecularModel::BlinnPhong) << 0 << path << q;
            }
    }

    void matchesDoubleReference() {
        QFETCH(int, model);
        QFETCH(int, spec);
        QFETCH(int, diffuse);
        QFETCH(int, path);
        QFETCH(int, quality);
        const bool pbr = ShadingModel(model) == ShadingModel::Pbr;
        const Rig rig = areaRig(ShadingModel(model), SpecularModel(spec), DiffuseModel(diffuse));
        RenderSettings s = floatSettings();
        s.quality = Quality(quality);
        s.shadingPath = path == 1 ? ShadingPath::Deferred : ShadingPath::Forward;
        s.clusteredShading = path == 2 ? 1 : 0;
        checkAgainstReference(pbr ? pbrSpheresScene() : planeScene(),
                              pbr ? pbrSpheresCamera() : planeCamera(), rig, s,
                              Quality(quality) != Quality::Fast);
    }

    // Where the float polygon integrals are nearest their limits (corners within 1e-4 of the horizon, edges
    // clipped at grazing angles, a light 1e4× the scene), exact still matches the double reference.
    void extremesMatchDoubleReference_data() {
        QTest::addColumn<int>("model");
        QTest::addColumn<int>("spec");
        QTest::addRow("pbr") << int(ShadingModel::Pbr) << 0;
        QTest::addRow("phong") << int(ShadingModel::Classic) << int(SpecularModel::Phong);
    }

    void extremesMatchDoubleReference() {
        QFETCH(int, model);
        QFETCH(int, spec);
        checkAgainstReference(planeScene(), planeCamera(),
                              extremeRig(ShadingModel(model), SpecularModel(spec)), floatSettings(), true);
    }

  private:
    // Renders `rig` on `scene` and compares each covered pixel with the double-precision reference: finite,
    // mostly covered, lit, and for `exact` within kExactTolerance wherever the reference is well-conditioned.
    void checkAgainstReference(std::shared_ptr<const Model> scene, const ViewCamera& camera, const Rig& rig,
                               const RenderSettings& s, bool exact) {
        QString error;
        QVERIFY2(m_gl.setModel(std::move(scene), &error), qPrintable(error));
        m_gl.setRig(rig);
        FloatImage radiance;
        GBuffer g;
        QVERIFY2(m_gl.renderRadiance(camera, kSize, s, &radiance, &error), qPrintable(error));
        QVERIFY2(m_gl.renderGBuffer(camera, kSize, floatSettings(), &g, &error), qPrintable(error));
        const ViewCamera cam = m_gl.renderer().effectiveCamera(camera);
        const Comparison c = compareWithReference(radiance, g, rig, m_gl.renderer().sceneFrame(), cam.view(),
                                                  exact ? kExactTolerance : 1.0);
        qInfo().noquote() << c.summary();
        QVERIFY2(c.nonFinite == 0, qPrintable(c.summary()));
        QVERIFY2(c.covered > kSize.width() * kSize.height() / 8, qPrintable(c.summary()));
        QVERIFY2(c.maxReference > 0.0, "the scene should be lit");
        if (exact) {
            QVERIFY2(c.failures == 0, qPrintable(c.summary()));
            QVERIFY2(c.skipped <= c.covered / 50, qPrintable(c.summary()));
        }
    }
};

QTEST_MAIN(TestRenderArea)
#include "tst_renderarea.moc"
