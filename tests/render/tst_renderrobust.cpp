// Renderer robustness: no NaN/Inf pixel for the extreme rigs of the foundation issue, the shader-variant
// cache (a value change never compiles, the first spot light does), compile errors surfacing with the
// GLSL log, thousands of lights, and the screenshot path (tiles, supersampling, transparency, gizmos).
#include "glfixture.h"
#include "scenes.h"

#include "render/offscreen.h"
#include "render/shadergen.h"

#include <QTest>
#include <glm/ext/matrix_clip_space.hpp>

using namespace lr;
using namespace lr::test;

namespace {

RenderSettings floatSettings() {
    RenderSettings s;
    s.msaaSamples = 0;
    s.hdrFloat32 = true;
    return s;
}

// Extreme rigs: ranges 0/1e-30/1e30, lights on the surface, degenerate cones, zero exponents, 1e6 intensity.
std::vector<RigCase> extremeCases() {
    std::vector<RigCase> out;
    const FalloffModel falloffs[] = {FalloffModel::None, FalloffModel::RangePower,
                                     FalloffModel::InversePolynomial, FalloffModel::RangeQuadratic,
                                     FalloffModel::InverseSquare};
    for (double range : {0.0, 1e-30, 1e30}) {
        out.push_back({range == 0.0  ? "range-0"
                       : range < 1.0 ? "range-1e-30"
                                     : "range-1e30",
                       [=] {
                           std::vector<Light> ls;
                           for (FalloffModel f : falloffs)
                               ls.push_back(point({0.3, 0.2, 1.0}, f, range));
                           Light s = spot({0.0, 0.0, 1.0}, {0, 0, 0}, ConeModel::Smooth, 10.0, 20.0, 1.0);
                           s.falloff = {FalloffModel::RangePower, range, 2.0};
                           ls.push_back(s);
                           return rigOf(ls);
                       }});
    }
    out.push_back(
        {"light-on-surface", [=] {
             std::vector<Light> ls;
             for (FalloffModel f : falloffs)
                 ls.push_back(point({0.0, 0.0, 0.0}, f, 2.0));
             ls.push_back(point({0.0, 0.0, 1.0}, FalloffModel::InverseSquare)); // on the sphere's pole
             ls.push_back(spot({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, ConeModel::Smooth, 10.0, 20.0, 1.0));
             return rigOf(ls);
         }});
    out.push_back({"inner-equals-outer", [] {
                       return rigOf({spot({0, 0, 2}, {0, 0, 0}, ConeModel::Smooth, 25.0, 25.0, 1.0),
                                     spot({0.5, 0, 2}, {0.5, 0, 0}, ConeModel::Smooth, 0.0, 0.0, 1.0)});
                   }});
    out.push_back({"outer-to-0", [] {
                       return rigOf({spot({0, 0, 2}, {0, 0, 0}, ConeModel::Smooth, 0.0, 1e-6, 1.0),
                                     spot({0, 0, 2}, {0, 0, 0}, ConeModel::AnglePower, 0.0, 1e-6, 1.0),
                                     spot({0, 0, 2}, {0, 0, 0}, ConeModel::Hard, 0.0, 1e-6, 1.0)});
                   }});
    out.push_back({"outer-90", [] {
                       return rigOf({spot({0, 0, 0.5}, {0, 0, 0}, ConeModel::Smooth, 0.0, 90.0, 1.0),
                                     spot({0, 0.2, 0.5}, {0, 0, 0}, ConeModel::AnglePower, 0.0, 90.0, 2.0),
                                     spot({0.3, 0, 0.5}, {0, 0, 0}, ConeModel::Hard, 0.0, 90.0, 1.0)});
                   }});
    out.push_back({"exponent-0", [] {
                       Light a = point({0.3, 0.2, 1.0}, FalloffModel::RangePower, 3.0);
                       a.falloff.exponent = 0.0;
                       Light b = spot({0, 0, 2}, {0, 0, 0}, ConeModel::Smooth, 10.0, 20.0, 0.0);
                       Light c = spot({0, 0, 2}, {0, 0, 0}, ConeModel::AnglePower, 0.0, 20.0, 0.0);
                       Light d = rim({0, 0, -1}, 0.0);
                       Rig r = rigOf({a, b, c, d});
                       r.shading.shininess = 0.0;
                       return r;
                   }});
    out.push_back(
        {"intensity-1e6", [] {
             Light a = point({0.3, 0.2, 1.0}, FalloffModel::InverseSquare);
             a.intensity = 1e6;
             Light b = point({0.0, 0.0, 0.3}, FalloffModel::InversePolynomial); // floored denominator
             b.intensity = 1e6;
             b.falloff.constant = b.falloff.linear = b.falloff.quadratic = 0.0;
             Light c = directional({0, 0, -1}, DiffuseModel::HalfLambert);
             c.intensity = 1e6;
             c.ambient = glm::dvec3(1.0);
             Light d = rim({0, 0, -1}, 1.0);
             d.intensity = 1e6;
             Rig r = rigOf({a, b, c, d});
             r.shading.specular = SpecularModel::BlinnPhong;
             return r;
         }});
    return out;
}

int maxLevelDifference(const QImage& a, const QImage& b, double* mean = nullptr) {
    int worst = 0;
    double sum = 0;
    for (int y = 0; y < a.height(); ++y) {
        const uchar* p = a.constScanLine(y);
        const uchar* q = b.constScanLine(y);
        for (int x = 0; x < a.width() * 4; ++x) {
            worst = std::max(worst, std::abs(int(p[x]) - int(q[x])));
            sum += std::abs(int(p[x]) - int(q[x]));
        }
    }
    if (mean) *mean = sum / (double(a.width()) * a.height() * 4);
    return worst;
}

} // namespace

class TestRenderRobust : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
    }

    void extremesStayFinite_data() {
        QTest::addColumn<bool>("sphere");
        QTest::addColumn<int>("rigIndex");
        const auto cases = extremeCases();
        for (int i = 0; i < int(cases.size()); ++i) {
            QTest::addRow("plane/%s", cases[size_t(i)].name) << false << i;
            QTest::addRow("sphere/%s", cases[size_t(i)].name) << true << i;
        }
    }

    // Every pixel finite; where the reference is well-conditioned it agrees within 1e-3 relative
    // (looser than the ordinary scenes' 1e-4: 1e6 intensities and d -> 0 amplify float rounding).
    void extremesStayFinite() {
        QFETCH(bool, sphere);
        QFETCH(int, rigIndex);
        const Rig rig = extremeCases()[size_t(rigIndex)].make();
        QString error;
        QVERIFY(m_gl.setModel(sphere ? sphereScene() : planeScene(), &error));
        m_gl.setRig(rig);
        const ViewCamera cam = sphere ? sphereCamera() : planeCamera();
        FloatImage radiance;
        GBuffer g;
        QVERIFY2(m_gl.renderRadiance(cam, QSize(80, 60), floatSettings(), &radiance, &error),
                 qPrintable(error));
        QVERIFY2(m_gl.renderGBuffer(cam, QSize(80, 60), floatSettings(), &g, &error), qPrintable(error));
        const Comparison c = compareWithReference(radiance, g, rig, m_gl.renderer().sceneFrame(),
                                                  m_gl.renderer().effectiveCamera(cam).view(), 1e-3);
        qInfo().noquote() << c.summary();
        QCOMPARE(c.nonFinite, 0);
        QVERIFY2(c.failures == 0, qPrintable(c.summary()));
        QVERIFY2(c.skipped <= c.covered / 20, qPrintable(c.summary()));
        // The 8-bit output of the same frame is produced without error.
        RenderSettings s;
        s.toneMap = ToneMap::Reinhard;
        QVERIFY2(!m_gl.renderImage(cam, QSize(80, 60), s, 1, &error).isNull(), qPrintable(error));
    }

    void valueChangesNeverCompile() {
        QString error;
        QVERIFY(m_gl.setModel(planeScene(), &error));
        const ViewCamera cam = planeCamera();
        const RenderSettings s;
        const QSize size(64, 48);
        Rig rig = rigOf({point({0.5, 0.5, 1.5}, FalloffModel::RangePower, 4.0)});
        rig.shading.specular = SpecularModel::BlinnPhong; // a key no other test of this run uses first
        m_gl.setRig(rig);
        QVERIFY(!m_gl.renderImage(cam, size, s, 1, &error).isNull());
        const int base = m_gl.renderer().stats().shaderVariantsCompiled;

        rig.lights[0].color = {0.2, 0.9, 0.1};
        rig.lights[0].position = {-0.7, 0.1, 0.9};
        rig.lights[0].intensity = 5.0;
        rig.lights[0].falloff.range = 2.0;
        rig.lights[0].falloff.exponent = 1.0;
        rig.ambient = {0.1, 0.1, 0.1};
        rig.shading.shininess = 64.0;
        m_gl.setRig(rig);
        QVERIFY(!m_gl.renderImage(cam, size, s, 1, &error).isNull());
        QCOMPARE(m_gl.renderer().stats().shaderVariantsCompiled, base);

        // Moving the light out of reach of the model: not uploaded, still no compile.
        rig.lights[0].position = {0.0, 0.0, 50.0};
        m_gl.setRig(rig);
        QVERIFY(!m_gl.renderImage(cam, size, s, 1, &error).isNull());
        QCOMPARE(m_gl.renderer().stats().lightsUploaded, 0);
        QCOMPARE(m_gl.renderer().stats().lightsInRig, 1);
        QCOMPARE(m_gl.renderer().stats().shaderVariantsCompiled, base);

        // The first spot light compiles one variant; a second spot does not.
        rig.lights.push_back(spot({0, 0, 2}, {0, 0, 0}, ConeModel::Smooth, 10.0, 20.0, 1.0));
        m_gl.setRig(rig);
        QVERIFY(!m_gl.renderImage(cam, size, s, 1, &error).isNull());
        QCOMPARE(m_gl.renderer().stats().shaderVariantsCompiled, base + 1);
        rig.lights.push_back(spot({0.5, 0, 2}, {0, 0, 0}, ConeModel::Smooth, 5.0, 40.0, 2.0));
        m_gl.setRig(rig);
        QVERIFY(!m_gl.renderImage(cam, size, s, 1, &error).isNull());
        QCOMPARE(m_gl.renderer().stats().shaderVariantsCompiled, base + 1);
        QCOMPARE(m_gl.renderer().stats().lightsUploaded, 2);

        // Disabling the spots returns to the cached point-only variant.
        rig.lights[1].enabled = rig.lights[2].enabled = false;
        m_gl.setRig(rig);
        QVERIFY(!m_gl.renderImage(cam, size, s, 1, &error).isNull());
        QCOMPARE(m_gl.renderer().stats().shaderVariantsCompiled, base + 1);

        // Thousands of lights of the same models: no compile, all uploaded. More than a few bounded lights
        // switch clustered shading on, which is one variant of its own: compiled once at 9 lights, then
        // growing to 3000 lights compiles nothing beyond the one switch of shading path.
        auto ringOf = [](int n) {
            Rig r = rigOf({});
            r.shading.specular = SpecularModel::BlinnPhong;
            for (int i = 0; i < n; ++i) {
                Light l = point({std::cos(i * 0.1), std::sin(i * 0.1), 0.5 + (i % 7) * 0.1},
                                FalloffModel::RangePower, 4.0);
                l.intensity = 1.0 / n;
                r.lights.push_back(l);
            }
            return r;
        };
        m_gl.setRig(ringOf(9));
        QVERIFY(!m_gl.renderImage(cam, size, s, 1, &error).isNull());
        QVERIFY(m_gl.renderer().stats().shaderVariantsCompiled <= base + 2);
        // From kDeferredMsaaMaxLights lights on, Auto leaves MSAA for the deferred path: its variants compile
        // once there, and nothing compiles from then on.
        m_gl.setRig(ringOf(kDeferredMsaaMaxLights));
        QVERIFY(!m_gl.renderImage(cam, size, s, 1, &error).isNull());
        QVERIFY(m_gl.renderer().stats().deferred);
        const int clusteredBase = m_gl.renderer().stats().shaderVariantsCompiled;
        QVERIFY(clusteredBase <= base + 4);
        Rig many = ringOf(3000);
        m_gl.setRig(many);
        QVERIFY(!m_gl.renderImage(cam, size, s, 1, &error).isNull());
        QCOMPARE(m_gl.renderer().stats().lightsUploaded, 3000);
        QCOMPARE(m_gl.renderer().stats().shaderVariantsCompiled, clusteredBase);
        FloatImage radiance;
        QVERIFY2(m_gl.renderRadiance(cam, size, floatSettings(), &radiance, &error), qPrintable(error));
        GBuffer g;
        QVERIFY(m_gl.renderGBuffer(cam, size, floatSettings(), &g, &error));
        const Comparison c = compareWithReference(radiance, g, many, m_gl.renderer().sceneFrame(),
                                                  m_gl.renderer().effectiveCamera(cam).view(), 1e-4);
        QVERIFY2(c.failures == 0 && c.compared > 1000, qPrintable(c.summary()));
    }

    // The deferred path (G-pass + full-screen lighting) and the forward path shade the same surfaces
    // with the same code: radiance equal within float rounding, 8-bit output within one level.
    void forwardEqualsDeferred_data() {
        QTest::addColumn<bool>("sphere");
        QTest::newRow("plane") << false;
        QTest::newRow("sphere") << true;
    }

    void forwardEqualsDeferred() {
        QFETCH(bool, sphere);
        QString error;
        auto model = sphere ? sphereScene() : planeScene();
        QImage tex(8, 8, QImage::Format_RGBA8888);
        for (int i = 0; i < 64; ++i)
            tex.setPixelColor(i % 8, i / 8, QColor::fromHsv(i * 5, 200, 230));
        model->textures.push_back({QStringLiteral("*0"), tex});
        model->materials[0].baseColorTexture = 0;
        model->materials[0].emissiveTexture = 0;
        model->materials[0].emissive = {0.05f, 0.02f, 0.01f};
        QVERIFY(m_gl.setModel(model, &error));
        m_gl.setRig(rigCases()[rigCases().size() - 1].make());
        const ViewCamera cam = sphere ? sphereCamera() : planeCamera();
        RenderSettings f = floatSettings(), d = floatSettings();
        f.shadingPath = ShadingPath::Forward;
        d.shadingPath = ShadingPath::Deferred;
        FloatImage rf, rd;
        QVERIFY2(m_gl.renderRadiance(cam, QSize(96, 72), f, &rf, &error), qPrintable(error));
        QVERIFY(!m_gl.renderer().stats().deferred);
        QVERIFY2(m_gl.renderRadiance(cam, QSize(96, 72), d, &rd, &error), qPrintable(error));
        QVERIFY(m_gl.renderer().stats().deferred);
        double worst = 0;
        for (size_t i = 0; i < rf.pixels.size(); ++i)
            for (int k = 0; k < 4; ++k)
                worst = std::max(worst, double(std::abs(rf.pixels[i][k] - rd.pixels[i][k])) /
                                            std::max(1.0, double(std::abs(rf.pixels[i][k]))));
        QVERIFY2(worst <= 1e-5, qPrintable(QStringLiteral("relative difference %1").arg(worst)));
        f.hdrFloat32 = d.hdrFloat32 = false;
        const QImage a = m_gl.renderImage(cam, QSize(96, 72), f, 1, &error);
        const QImage b = m_gl.renderImage(cam, QSize(96, 72), d, 1, &error);
        QVERIFY2(!a.isNull() && !b.isNull(), qPrintable(error));
        QVERIFY(maxLevelDifference(a, b) <= 1);
    }

    void compileErrorsCarryTheLog() {
        QString error;
        QVERIFY(m_gl.setModel(planeScene(), &error));
        m_gl.setRig(rigCases()[0].make());
        m_gl.renderer().setShaderSourceOverride(QStringLiteral("mesh.frag"),
                                                "void main() { this is not glsl; }\n");
        const QImage broken = m_gl.renderImage(planeCamera(), QSize(32, 32), RenderSettings(), 1, &error);
        QVERIFY(broken.isNull());
        QVERIFY2(error.contains(QLatin1String("fragment shader compile")), qPrintable(error));
        QVERIFY2(error.contains(QLatin1String("mesh.frag")) &&
                     error.contains(QLatin1String("error"), Qt::CaseInsensitive),
                 qPrintable(error));
        m_gl.renderer().setShaderSourceOverride(QStringLiteral("mesh.frag"), {});
        QVERIFY2(!m_gl.renderImage(planeCamera(), QSize(32, 32), RenderSettings(), 1, &error).isNull(),
                 qPrintable(error));
    }

    void tilesMatchOneTarget() {
        QString error;
        QVERIFY(m_gl.setModel(sphereScene(), &error));
        m_gl.setRig(rigCases()[rigCases().size() - 1].make());
        RenderSettings s;
        s.msaaSamples = 0;
        const QSize size(203, 151);
        const QImage whole = m_gl.renderImage(sphereCamera(), size, s, 1, &error);
        QVERIFY2(!whole.isNull(), qPrintable(error));
        m_gl.setMaxTileSize(64);
        const QImage tiled = m_gl.renderImage(sphereCamera(), size, s, 1, &error);
        const QImage tiledSuper = m_gl.renderImage(sphereCamera(), size, s, 3, &error);
        m_gl.setMaxTileSize(4096);
        QVERIFY2(!tiled.isNull() && !tiledSuper.isNull(), qPrintable(error));
        QCOMPARE(tiled.size(), size);
        QCOMPARE(tiledSuper.size(), size);
        double mean = 0;
        const int worst = maxLevelDifference(whole, tiled, &mean);
        // Cropped projections rasterise the same triangles; only a silhouette pixel may flip.
        QVERIFY2(mean < 0.05, qPrintable(QStringLiteral("mean %1, worst %2").arg(mean).arg(worst)));
        const QImage super = m_gl.renderImage(sphereCamera(), size, s, 3, &error);
        QVERIFY2(maxLevelDifference(super, tiledSuper, &mean) <= 2, "supersampled tiles agree");
        maxLevelDifference(super, whole, &mean);
        QVERIFY2(mean < 1.0,
                 qPrintable(QStringLiteral("supersampling changes edges only (mean %1)").arg(mean)));
    }

    void transparentBackgroundAndGizmos() {
        QString error;
        QVERIFY(m_gl.setModel(sphereScene(), &error));
        Light red = point({1.2, 0.0, 1.2}, FalloffModel::RangePower, 3.0);
        red.color = {1.0, 0.0, 0.0};
        m_gl.setRig(rigOf({red, spot({0, 1.5, 1.5}, {0, 0, 0}, ConeModel::Smooth, 10, 20, 1),
                           directional({0, -1, -1}, DiffuseModel::Lambert), rim({0, 0, -1}, 1.0)}));
        RenderSettings s;
        s.transparentBackground = true;
        const QSize size(160, 120);
        const QImage img = m_gl.renderImage(sphereCamera(), size, s, 1, &error);
        QVERIFY2(!img.isNull(), qPrintable(error));
        QCOMPARE(qAlpha(img.pixel(2, 2)), 0);
        QCOMPARE(qAlpha(img.pixel(80, 60)), 255);

        s.transparentBackground = false;
        s.showGizmos = true;
        s.showGrid = true;
        s.selectedLights = {1};
        const QImage withGizmos = m_gl.renderImage(sphereCamera(), size, s, 1, &error);
        QVERIFY2(!withGizmos.isNull(), qPrintable(error));
        // The red light's icon sits where the camera projects it.
        const ViewCamera cam = m_gl.renderer().effectiveCamera(sphereCamera());
        const glm::dvec4 clip = cam.projection(160.0 / 120.0) * cam.view() * glm::dvec4(1.2, 0.0, 1.2, 1.0);
        const int px = int((clip.x / clip.w * 0.5 + 0.5) * 160),
                  py = int((0.5 - clip.y / clip.w * 0.5) * 120);
        const QColor c = withGizmos.pixelColor(px, py);
        QVERIFY2(c.red() > 200 && c.green() < 60 && c.blue() < 60,
                 qPrintable(QStringLiteral("icon pixel (%1,%2) is %3").arg(px).arg(py).arg(c.name())));
        s.showGizmos = s.showGrid = false;
        const QImage without = m_gl.renderImage(sphereCamera(), size, s, 1, &error);
        QVERIFY(maxLevelDifference(withGizmos, without) > 100);
    }

    // Dragging a light (a value change) compiles nothing and uploads only that light's texels, and the
    // partial upload draws exactly what a fresh renderer draws; a camera move re-uploads (nearly) every light
    // (lights live in view space).
    void editingALightUploadsOnlyThatLight() {
        QString error;
        QVERIFY(m_gl.setModel(sphereScene(), &error));
        Rig rig;
        for (int i = 0; i < 64; ++i) {
            const double a = i * 0.0981747704; // 2π / 64
            rig.lights.push_back(
                point({2.0 * std::cos(a), 1.0, 2.0 * std::sin(a)}, FalloffModel::InverseSquare));
        }
        RenderSettings s;
        s.msaaSamples = 0;
        const ViewCamera cam = sphereCamera();
        m_gl.setRig(rig);
        QVERIFY(!m_gl.renderImage(cam, QSize(96, 72), s, 1, &error).isNull());
        const RenderStats before = m_gl.renderer().stats();
        QCOMPARE(before.lightBytesUploaded, qint64(64 * render::kLightTexels * 16));

        rig.lights[17].position += glm::dvec3(0.25, -0.5, 0.1);
        rig.lights[17].color = {0.2, 0.4, 1.0};
        m_gl.setRig(rig);
        const QImage edited = m_gl.renderImage(cam, QSize(96, 72), s, 1, &error);
        QVERIFY(!edited.isNull());
        const RenderStats after = m_gl.renderer().stats();
        QVERIFY2(after.lightBytesUploaded > 0 &&
                     after.lightBytesUploaded <= qint64(render::kLightTexels * 16),
                 qPrintable(QString::number(after.lightBytesUploaded)));
        QCOMPARE(after.shaderVariantsCompiled, before.shaderVariantsCompiled);

        OffscreenRenderer fresh;
        QVERIFY2(fresh.initialize(&error), qPrintable(error));
        QVERIFY(fresh.setModel(sphereScene(), &error));
        fresh.setRig(rig);
        const QImage expected = fresh.renderImage(cam, QSize(96, 72), s, 1, &error);
        QVERIFY(!expected.isNull());
        QVERIFY(m_gl.renderer().isInitialized()); // renderImage makes its own context current again
        QCOMPARE(edited.convertToFormat(QImage::Format_RGBA8888),
                 expected.convertToFormat(QImage::Format_RGBA8888));

        ViewCamera moved = cam;
        moved.eye.x += 0.3;
        QVERIFY(!m_gl.renderImage(moved, QSize(96, 72), s, 1, &error).isNull());
        // (the unchanged words at either end, e.g. the last light's unused texel, stay)
        QVERIFY(m_gl.renderer().stats().lightBytesUploaded > qint64(63 * render::kLightTexels * 16));
    }
};

LR_GL_TEST_MAIN(TestRenderRobust)
#include "tst_renderrobust.moc"
