// The GPU against the double-precision C++ evaluation: for a plane and a sphere built here, one rig per
// light type and per model of the core, the float radiance read back from the renderer must match
// lighting::shadeSurface<double> evaluated at each pixel's G-buffer surface point.
//
// Tolerance (stated, per channel, linear radiance before exposure/tone mapping):
//   |gpu − ref| <= 1e-4 · max(1, |ref|)   (measured on llvmpipe: <= 6e-6)
// over every covered pixel whose reference is well-conditioned (a few-ulp nudge of the point moves it by
// less than the tolerance; at most 2% of pixels may be skipped: hard cone and range edges).
// The tone-mapped 8-bit output must equal the CPU's toneMap + linearToSrgb of the reference within one level.
#include "glfixture.h"
#include "scenes.h"

#include "core/lighting.h"
#include "render/offscreen.h"

#include <QSet>
#include <QTest>
#include <glm/trigonometric.hpp>

using namespace lr;
using namespace lr::test;

namespace {
constexpr double kTolerance = 1e-4;
const QSize kSize(96, 72);

const char* tierNameOf(Quality q) {
    return EnumNames<Quality>::names[size_t(q)];
}

bool near(double got, double expected, double tol) {
    if (std::abs(got - expected) <= tol) return true;
    qWarning("got %.9g, expected %.9g +- %.3g", got, expected, tol);
    return false;
}

RenderSettings floatSettings() {
    RenderSettings s;
    s.msaaSamples = 0;
    s.hdrFloat32 = true;
    return s;
}
} // namespace

class TestRenderAccuracy : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;

    Comparison renderAndCompare(std::shared_ptr<Model> model, const ViewCamera& camera, const Rig& rig) {
        QString error;
        Comparison bad;
        bad.failures = 1;
        if (!m_gl.setModel(model, &error)) return bad.firstFailure = error, bad;
        m_gl.setRig(rig);
        FloatImage radiance;
        GBuffer g;
        if (!m_gl.renderRadiance(camera, kSize, floatSettings(), &radiance, &error) ||
            !m_gl.renderGBuffer(camera, kSize, floatSettings(), &g, &error))
            return bad.firstFailure = error, bad;
        const ViewCamera cam = m_gl.renderer().effectiveCamera(camera);
        return compareWithReference(radiance, g, rig, m_gl.renderer().sceneFrame(), cam.view(), kTolerance);
    }

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
        qInfo().noquote() << "GL:" << m_gl.glDescription();
    }

    void matchesDoubleReference_data() {
        QTest::addColumn<bool>("sphere");
        QTest::addColumn<int>("rigIndex");
        const auto cases = rigCases();
        for (int i = 0; i < int(cases.size()); ++i) {
            QTest::addRow("plane/%s", cases[size_t(i)].name) << false << i;
            QTest::addRow("sphere/%s", cases[size_t(i)].name) << true << i;
        }
    }

    void matchesDoubleReference() {
        QFETCH(bool, sphere);
        QFETCH(int, rigIndex);
        const Rig rig = rigCases()[size_t(rigIndex)].make();
        const Comparison c = sphere ? renderAndCompare(sphereScene(), sphereCamera(), rig)
                                    : renderAndCompare(planeScene(), planeCamera(), rig);
        qInfo().noquote() << c.summary();
        QVERIFY2(c.failures == 0 && c.nonFinite == 0, qPrintable(c.summary()));
        QVERIFY2(c.covered > kSize.width() * kSize.height() / 4, qPrintable(c.summary()));
        QVERIFY2(c.skipped <= c.covered / 50, qPrintable(c.summary()));
        QVERIFY2(c.maxReference > 0.0 || rig.lights.empty(), "the scene should be lit");
    }

    // Physically based shading (issue 13): spheres of metallic 0/1 × roughness 0/0.4/1 under each light
    // type, forward, deferred (deferred.frag) and clustered (cluster.glsl), against the double reference.
    void pbrMatchesDoubleReference_data() {
        QTest::addColumn<int>("rigIndex");
        QTest::addColumn<int>("path");
        const auto cases = pbrRigCases();
        for (int i = 0; i < int(cases.size()); ++i) {
            QTest::addRow("forward/%s", cases[size_t(i)].name) << i << 0;
            QTest::addRow("deferred/%s", cases[size_t(i)].name) << i << 1;
            QTest::addRow("clustered/%s", cases[size_t(i)].name) << i << 2;
        }
    }

    void pbrMatchesDoubleReference() {
        QFETCH(int, rigIndex);
        QFETCH(int, path);
        const Rig rig = pbrRigCases()[size_t(rigIndex)].make();
        RenderSettings s = floatSettings();
        s.shadingPath = path == 1 ? ShadingPath::Deferred : ShadingPath::Forward;
        s.clusteredShading = path == 2 ? 1 : 0;
        QString error;
        QVERIFY(m_gl.setModel(pbrSpheresScene(), &error));
        m_gl.setRig(rig);
        FloatImage radiance;
        GBuffer g;
        QVERIFY2(m_gl.renderRadiance(pbrSpheresCamera(), kSize, s, &radiance, &error), qPrintable(error));
        QCOMPARE(m_gl.renderer().stats().deferred, path == 1); // the path the case names was taken
        QCOMPARE(m_gl.renderer().stats().clustered, path == 2);
        QVERIFY2(m_gl.renderGBuffer(pbrSpheresCamera(), kSize, s, &g, &error), qPrintable(error));
        QVERIFY(g.shading == ShadingModel::Pbr);
        const ViewCamera cam = m_gl.renderer().effectiveCamera(pbrSpheresCamera());
        const Comparison c =
            compareWithReference(radiance, g, rig, m_gl.renderer().sceneFrame(), cam.view(), kTolerance);
        qInfo().noquote() << c.summary();
        QVERIFY2(c.failures == 0 && c.nonFinite == 0, qPrintable(c.summary()));
        QVERIFY2(c.covered > kSize.width() * kSize.height() / 8, qPrintable(c.summary()));
        QVERIFY2(c.skipped <= c.covered / 50, qPrintable(c.summary()));
        QVERIFY2(c.maxReference > 0.0, "the scene should be lit");
        // The G-buffer carries each sphere's factors: both metallic values, and the three roughnesses
        // widened by the geometric roughness (mesh.frag: the screen-space change of the normal), so near
        // each factor at a sphere's centre, larger towards its silhouette, never above 1.
        QSet<int> metallic;
        std::vector<float> roughness;
        for (const glm::vec4& m : g.material.pixels)
            if (m.w > 0.5f) metallic.insert(qRound(m.x * 10)), roughness.push_back(m.y);
        QCOMPARE(metallic, (QSet<int>{0, 10}));
        const auto some = [&](auto pred) { return std::any_of(roughness.begin(), roughness.end(), pred); };
        for (float factor : {0.0f, 0.4f, 1.0f})
            QVERIFY2(some([&](float r) { return std::abs(r - factor) <= 0.12f; }),
                     qPrintable(QString::number(factor)));
        QVERIFY(!some([](float r) { return !(r >= 0.0f && r <= 1.0f); }));
        QVERIFY(some([](float r) { return r > 0.15f && r < 0.3f; })); // a smooth sphere, widened
    }

    // The physically based material inputs (mesh.frag surfaceHere): metallic = factor × B, roughness =
    // factor × G of the metal-rough texture (linear), occlusion = 1 + strength·(R − 1); none: 1. Every
    // channel differs, so that a texture store (GpuModel::TextureStore: R8, RG8 swizzled) reading the
    // wrong one fails; one image serving both roles (glTF's packed occlusion-roughness-metallic) too.
    void pbrMaterialInputs() {
        QString error;
        auto model = planeScene();
        QImage mr(8, 8, QImage::Format_RGBA8888);
        mr.fill(QColor(77, 128, 191, 30)); // linear: G = 128/255 roughness, B = 191/255 metal
        QImage ao(8, 8, QImage::Format_RGBA8888);
        ao.fill(QColor(51, 200, 150, 90)); // R = 0.2
        model->textures.push_back({QStringLiteral("*0"), mr});
        model->textures.push_back({QStringLiteral("*1"), ao});
        Material& m = model->materials[0];
        m.pbr = true, m.metallic = 0.5f, m.roughness = 0.8f, m.metallicRoughnessTexture = 0;
        m.occlusionTexture = 1, m.occlusionStrength = 0.5f;
        QVERIFY(m_gl.setModel(model, &error));
        m_gl.setRig(pbrRigCases()[3].make()); // with ambient light: the occlusion texture is read
        ViewCamera cam;
        cam.eye = {0, 0, 3};
        GBuffer g;
        QVERIFY2(m_gl.renderGBuffer(cam, QSize(16, 16), floatSettings(), &g, &error), qPrintable(error));
        const glm::vec4 got = g.material.at(8, 8);
        QVERIFY(near(got.x, 0.5 * 191 / 255.0, 1e-3));
        QVERIFY(near(got.y, 0.8 * 128 / 255.0, 1e-3));
        QVERIFY(near(got.z, 1.0 + 0.5 * (0.2 - 1.0), 1e-3));
        // One image for both: occlusion from its R, roughness from its G, metallic from its B.
        m.occlusionTexture = 0;
        QVERIFY(m_gl.setModel(model, &error));
        QVERIFY2(m_gl.renderGBuffer(cam, QSize(16, 16), floatSettings(), &g, &error), qPrintable(error));
        const glm::vec4 packed = g.material.at(8, 8);
        QVERIFY(near(packed.x, 0.5 * 191 / 255.0, 1e-3));
        QVERIFY(near(packed.y, 0.8 * 128 / 255.0, 1e-3));
        QVERIFY(near(packed.z, 1.0 + 0.5 * (77 / 255.0 - 1.0), 1e-3));
        m.occlusionTexture = 1;
        QVERIFY(m_gl.setModel(model, &error));
        // Without ambient light occlusion changes nothing, so it is not read: the G-buffer holds 1.
        m_gl.setRig(pbrRigCases()[0].make());
        QVERIFY2(m_gl.renderGBuffer(cam, QSize(16, 16), floatSettings(), &g, &error), qPrintable(error));
        QVERIFY(near(g.material.at(8, 8).y, 0.8 * 128 / 255.0, 1e-3));
        QCOMPARE(g.material.at(8, 8).z, 1.0f);
        // Shaded with the textures in every tier (the fast tier reads the roughness in the vertex stage):
        // finite everywhere, and the exact tier equal to the double reference of its G-buffer.
        const Rig lit = pbrRigCases()[3].make();
        m_gl.setRig(lit);
        for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast}) {
            RenderSettings s = floatSettings();
            s.quality = q;
            FloatImage radiance;
            QVERIFY2(m_gl.renderRadiance(cam, QSize(24, 24), s, &radiance, &error), qPrintable(error));
            QVERIFY2(m_gl.renderGBuffer(cam, QSize(24, 24), s, &g, &error), qPrintable(error));
            const Comparison c = compareWithReference(radiance, g, lit, m_gl.renderer().sceneFrame(),
                                                      m_gl.renderer().effectiveCamera(cam).view(),
                                                      q == Quality::Exact ? kTolerance : 1.0);
            qInfo().noquote() << tierNameOf(q) << c.summary();
            QVERIFY2(c.nonFinite == 0 && c.covered > 0 && c.maxReference > 0.0, qPrintable(c.summary()));
            if (q == Quality::Exact) QVERIFY2(c.failures == 0, qPrintable(c.summary()));
        }
        m_gl.setRig(pbrRigCases()[0].make());
        // Without the textures: the factors, and occlusion 1.
        m.metallicRoughnessTexture = m.occlusionTexture = -1;
        QVERIFY(m_gl.setModel(model, &error));
        QVERIFY2(m_gl.renderGBuffer(cam, QSize(16, 16), floatSettings(), &g, &error), qPrintable(error));
        QVERIFY(near(g.material.at(8, 8).x, 0.5, 0));
        QVERIFY(near(g.material.at(8, 8).y, 0.8, 1e-7));
        QVERIFY(near(g.material.at(8, 8).z, 1.0, 0));
        // A classic rig neither samples nor stores them.
        m_gl.setRig(rigCases()[0].make());
        QVERIFY2(m_gl.renderGBuffer(cam, QSize(16, 16), floatSettings(), &g, &error), qPrintable(error));
        QVERIFY(g.shading == ShadingModel::Classic);
        QVERIFY(g.material.isNull());
        QCOMPARE(g.specular.at(8, 8).w, 24.0f);
    }

    // Exposure, tone map and sRGB encoding of the output against lighting::toneMap/linearToSrgb, on each
    // path that applies them: per fragment forward (mesh.frag) and deferred (deferred.frag), and the
    // HDR path's full-screen pass (tonemap.frag). Each compiles the tone map in as a constant
    // (FeatureKey::toneMap, LR_TONE_MAP), so every operator is a program of its own on every path.
    void toneMappedOutput_data() {
        QTest::addColumn<int>("toneMap");
        QTest::addColumn<double>("ev");
        QTest::addColumn<int>("path");
        const std::pair<int, double> ops[] = {{int(ToneMap::Clamp), 0.0},    {int(ToneMap::Clamp), 1.5},
                                              {int(ToneMap::Reinhard), 2.0}, {int(ToneMap::Aces), -0.5},
                                              {int(ToneMap::Neutral), 0.0},  {int(ToneMap::Neutral), 2.0},
                                              {int(ToneMap::Agx), 0.0},      {int(ToneMap::Agx), 3.0}};
        const char* paths[] = {"forward", "deferred", "hdr"};
        for (int path = 0; path < 3; ++path)
            for (const auto& [op, ev] : ops)
                QTest::addRow("%s %s %+.1f", paths[path], qPrintable(toString(ToneMap(op))), ev)
                    << op << ev << path;
    }

    void toneMappedOutput() {
        QFETCH(int, toneMap);
        QFETCH(double, ev);
        QFETCH(int, path);
        QString error;
        QVERIFY(m_gl.setModel(sphereScene(), &error));
        const Rig rig = rigCases()[size_t(rigCases().size() - 1)].make(); // mixed: a wide range of values
        m_gl.setRig(rig);
        RenderSettings s = floatSettings();
        s.toneMap = ToneMap(toneMap);
        s.exposureEV = ev;
        s.background = QColor(10, 20, 30);
        FloatImage radiance;
        QVERIFY2(m_gl.renderRadiance(sphereCamera(), kSize, s, &radiance, &error), qPrintable(error));
        RenderSettings display = s;
        display.shadingPath = path == 1 ? ShadingPath::Deferred : ShadingPath::Forward;
        display.hdrTarget = path == 2;
        const QImage image = m_gl.renderImage(sphereCamera(), kSize, display, 1, &error);
        QVERIFY2(!image.isNull(), qPrintable(error));
        QCOMPARE(m_gl.renderer().stats().deferred, path == 1);
        int worst = 0;
        for (int y = 0; y < kSize.height(); ++y) {
            for (int x = 0; x < kSize.width(); ++x) {
                const glm::vec4 r = radiance.at(x, y);
                const QRgb px = image.pixel(x, y);
                const int got[3] = {qRed(px), qGreen(px), qBlue(px)};
                // Neutral and AgX act on the colour, the others per channel: colour::toneMapRgb does both.
                const glm::dvec3 mappedRgb =
                    colour::toneMapRgb(ToneMap(toneMap), glm::dvec3(r.x, r.y, r.z) * std::exp2(ev));
                for (int k = 0; k < 3; ++k) {
                    const double bg[3] = {10 / 255.0, 20 / 255.0, 30 / 255.0};
                    const double mapped = r.w > 0.5f ? mappedRgb[k] : lighting::srgbToLinear(bg[k]);
                    const int expected = int(std::lround(lighting::linearToSrgb(mapped) * 255.0));
                    worst = std::max(worst, std::abs(got[k] - expected));
                }
                QCOMPARE(qAlpha(px), 255);
            }
        }
        QVERIFY2(worst <= 1, qPrintable(QStringLiteral("worst difference %1 levels").arg(worst)));
    }

    // Material inputs reach the Surface as the CPU expects: sRGB-decoded textures with the UV convention
    // of model.h, vertex colours, normal maps, double-sided flipping.
    void materialInputs() {
        QString error;
        auto model = planeScene();
        QImage tex(64, 64, QImage::Format_RGBA8888); // four solid quadrants
        for (int y = 0; y < 64; ++y)
            for (int x = 0; x < 64; ++x)
                tex.setPixelColor(x, y,
                                  y < 32 ? (x < 32 ? QColor(200, 0, 0) : QColor(0, 200, 0))
                                         : (x < 32 ? QColor(0, 0, 200) : QColor(128, 128, 128)));
        model->textures.push_back({QStringLiteral("*0"), tex});
        model->materials[0].baseColorTexture = 0;
        model->materials[0].baseColor = {1.0f, 1.0f, 1.0f, 1.0f};
        QVERIFY(m_gl.setModel(model, &error));
        m_gl.setRig(rigCases()[0].make());
        ViewCamera cam;
        cam.eye = {0, 0, 3};
        cam.yfovDeg = 2.0 * glm::degrees(std::atan(2.0 / 3.0)); // the plane (half size 2) fills the view
        GBuffer g;
        QVERIFY2(m_gl.renderGBuffer(cam, QSize(64, 64), floatSettings(), &g, &error), qPrintable(error));
        const double c200 = lighting::srgbToLinear(200 / 255.0), c128 = lighting::srgbToLinear(128 / 255.0);
        const glm::vec4 tl = g.albedo.at(16, 16), tr = g.albedo.at(48, 16), bl = g.albedo.at(16, 48),
                        br = g.albedo.at(48, 48);
        QVERIFY2(std::abs(tl.r - c200) < 2e-3 && tl.g < 0.05 && tl.b < 0.05,
                 "top-left texel on the top-left of the plane");
        QVERIFY2(std::abs(tr.g - c200) < 2e-3 && tr.r < 0.05, "top-right texel");
        QVERIFY2(std::abs(bl.b - c200) < 2e-3 && bl.r < 0.05, "bottom-left texel");
        QVERIFY2(std::abs(br.r - c128) < 2e-3 && std::abs(br.g - c128) < 2e-3,
                 "bottom-right texel, sRGB-decoded");

        // A normal map tilted towards +u (red) and towards image-up (green).
        for (const auto& [rgb, expected] : {std::pair{QColor(255, 128, 128), glm::dvec3(1, 0, 0)},
                                            std::pair{QColor(128, 255, 128), glm::dvec3(0, 1, 0)}}) {
            auto m = planeScene();
            QImage n(4, 4, QImage::Format_RGBA8888);
            n.fill(rgb);
            m->textures.push_back({QStringLiteral("*0"), n});
            m->materials[0].normalTexture = 0;
            QVERIFY(m_gl.setModel(m, &error));
            QVERIFY2(m_gl.renderGBuffer(cam, QSize(16, 16), floatSettings(), &g, &error), qPrintable(error));
            const glm::dvec3 got(g.normal.at(8, 8));
            QVERIFY2(glm::dot(got, expected) > 0.99,
                     qPrintable(QStringLiteral("normal (%1, %2, %3)").arg(got.x).arg(got.y).arg(got.z)));
        }

        // Vertex colours multiply the base colour.
        auto vc = planeScene();
        for (Vertex& v : vc->meshes[0].vertices)
            v.color = {0.5f, 0.25f, 1.0f, 1.0f};
        vc->meshes[0].hasVertexColors = true;
        QVERIFY(m_gl.setModel(vc, &error));
        QVERIFY(m_gl.renderGBuffer(cam, QSize(16, 16), floatSettings(), &g, &error));
        QVERIFY(std::abs(g.albedo.at(8, 8).r - 0.4f) < 1e-5 && std::abs(g.albedo.at(8, 8).g - 0.15f) < 1e-5);

        // Seen from behind: culled when single-sided, flipped towards the viewer when double-sided.
        ViewCamera behind = cam;
        behind.eye = {0, 0, -3};
        QVERIFY(m_gl.setModel(planeScene(), &error));
        QVERIFY(m_gl.renderGBuffer(behind, QSize(16, 16), floatSettings(), &g, &error));
        QCOMPARE(g.position.at(8, 8).w, 0.0f);
        auto two = planeScene();
        two->materials[0].doubleSided = true;
        QVERIFY(m_gl.setModel(two, &error));
        QVERIFY(m_gl.renderGBuffer(behind, QSize(16, 16), floatSettings(), &g, &error));
        QCOMPARE(g.position.at(8, 8).w, 1.0f);
        QVERIFY2(g.normal.at(8, 8).z > 0.99f, "a back face's normal faces the viewer");
    }
};

LR_GL_TEST_MAIN(TestRenderAccuracy)
#include "tst_renderaccuracy.moc"
