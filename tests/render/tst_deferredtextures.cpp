// The attribute G-buffer (shaders/surface.glsl, RenderSettings::deferredTextures): when every opaque draw
// shares one material the G-pass writes the interpolated attributes and the deferred lighting pass samples
// the textures. It must shade exactly what the forward path and the Surface G-buffer shade, through every
// input it carries: a textured, normal-mapped, texture-transformed, double-sided material on a sphere
// (curved: UV derivatives vary per pixel) and on a plane seen from its back with mirrored tangents; with
// one material, two (two stencil-selected lighting passes) and a visible ground (its material too).
// While the view and the surfaces hold, the G-buffer is kept (passes.h GeometryPass), and what a frame that
// keeps it shades must be what one that draws it again shades.
#include "glfixture.h"
#include "scenes.h"

#include "render/gpumodel.h"
#include "render/offscreen.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace lr::render;
using namespace lr::test;

namespace {

// A texture whose texels all differ (hash colours): any change of mip level or texel shows.
QImage noise(int n, unsigned seed) {
    QImage img(n, n, QImage::Format_RGBA8888);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            unsigned h = (unsigned(x) * 73856093u) ^ (unsigned(y) * 19349663u) ^ (seed * 83492791u);
            h = (h ^ (h >> 13)) * 0x5bd1e995u;
            img.setPixelColor(x, y, QColor(int(h & 255), int((h >> 8) & 255), int((h >> 16) & 255), 255));
        }
    return img;
}

// The sphere and, under it, a plane whose front faces point down (the camera above sees its back faces),
// both with one material using every texture role.
std::shared_ptr<Model> texturedScene() {
    auto m = std::make_shared<Model>(makeSphere(1.0, 48, 24));
    Mesh plane = makePlane(2.0).meshes.front();
    for (Vertex& v : plane.vertices) {
        const auto turn = [](glm::vec3 p) { return glm::vec3(p.x, -p.z, p.y); }; // +Z -> -Y
        v.position = turn(v.position) + glm::vec3(0.0f, -1.1f, 0.0f);
        v.normal = turn(v.normal);
        v.tangent = glm::vec4(turn(glm::vec3(v.tangent)), -1.0f); // mirrored UVs
    }
    plane.material = 0;
    m->meshes.push_back(plane);
    m->bounds.min = glm::dvec3(-2.0, -1.2, -2.0);
    m->bounds.max = glm::dvec3(2.0, 1.0, 2.0);
    QImage normals = noise(32, 2);
    for (int y = 0; y < normals.height(); ++y) // keep the normals in the upper hemisphere (z > 0.5)
        for (int x = 0; x < normals.width(); ++x) {
            QColor c = normals.pixelColor(x, y);
            c.setBlue(200 + c.blue() % 56);
            normals.setPixelColor(x, y, c);
        }
    m->textures = {{QStringLiteral("*base"), noise(64, 1)},
                   {QStringLiteral("*normal"), normals},
                   {QStringLiteral("*emissive"), noise(16, 3)},
                   {QStringLiteral("*mr"), noise(32, 4)}};
    Material& mat = m->materials[0];
    mat.pbr = true;
    mat.baseColor = {0.9f, 0.8f, 0.7f, 1.0f};
    mat.emissive = {0.05f, 0.04f, 0.03f};
    mat.specular = {0.5f, 0.5f, 0.5f};
    mat.shininess = 40.0f;
    mat.baseColorTexture = 0;
    mat.normalTexture = 1;
    mat.normalScale = 0.8f;
    mat.emissiveTexture = 2;
    mat.metallicRoughnessTexture = 3;
    mat.baseColorTransform.rotation = 0.3f;
    mat.baseColorTransform.scale = {2.0f, 1.5f};
    mat.normalTransform.offset = {0.25f, 0.0f};
    mat.doubleSided = true;
    return m;
}

ViewCamera aboveCamera() {
    ViewCamera c;
    c.eye = {0.3, 1.8, 3.2};
    c.target = {0.0, -0.3, 0.0};
    c.yfovDeg = 50.0;
    return c;
}

} // namespace

class TestDeferredTextures : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;

    FloatImage radiance(const Rig& rig, ShadingPath path, bool deferredTextures, bool* attributes,
                        const ViewCamera& camera = aboveCamera()) {
        RenderSettings s;
        s.msaaSamples = 0;
        s.hdrFloat32 = true;
        s.shadingPath = path;
        s.deferredTextures = deferredTextures;
        m_gl.setRig(rig);
        FloatImage out;
        QString error;
        if (!m_gl.renderRadiance(camera, QSize(160, 120), s, &out, &error)) qFatal("%s", qPrintable(error));
        *attributes = m_gl.renderer().stats().deferredTextures;
        return out;
    }

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
    }

    void sameRadianceAsForwardAndSurfaces_data() {
        QTest::addColumn<int>("rigCase");
        QTest::addColumn<bool>("twoMaterials"); // the plane has its own (a second lighting pass)
        QTest::addColumn<bool>("ground");       // a visible ground: its material too
        QTest::newRow("classic") << 0 << false << false;
        QTest::newRow("pbr") << 1 << false << false;
        QTest::newRow("pbr, two materials") << 1 << true << false;
        QTest::newRow("classic, two materials and the ground") << 0 << true << true;
    }

    void sameRadianceAsForwardAndSurfaces() {
        QFETCH(int, rigCase);
        QFETCH(bool, twoMaterials);
        QFETCH(bool, ground);
        auto scene = texturedScene();
        if (twoMaterials) {
            Material second = scene->materials[0];
            second.baseColor = {0.3f, 0.9f, 0.4f, 1.0f};
            second.normalTexture = -1;
            second.emissiveTexture = 0;
            scene->materials.push_back(second);
            scene->meshes[1].material = 1;
        }
        QString error;
        QVERIFY(m_gl.setModel(scene, &error));
        Rig rig = rigCase == 0 ? rigOf({point({1.0, 2.0, 2.5}, FalloffModel::InverseSquare),
                                        directional({-0.3, -1.0, -0.2}, DiffuseModel::Lambert)})
                               : pbrRig({gltfPoint({1.0, 2.0, 2.5}, 15.0, 20.0),
                                         gltfSpot({-1.0, 0.5, 2.0}, {0.0, -1.0, 0.0}, 30.0)},
                                        glm::dvec3(0.05));
        if (ground) rig.ground.mode = GroundMode::Visible;
        bool forwardAttr = true, attr = false, surfaceAttr = true;
        const FloatImage forward = radiance(rig, ShadingPath::Forward, true, &forwardAttr);
        const FloatImage attributes = radiance(rig, ShadingPath::Deferred, true, &attr);
        const FloatImage surfaces = radiance(rig, ShadingPath::Deferred, false, &surfaceAttr);
        QVERIFY(!forwardAttr && attr && !surfaceAttr); // each took the path it names
        int covered = 0, lowerQuarter = 0;             // the plane's back faces are most of the lower quarter
        for (int y = 0; y < forward.height; ++y)
            for (int x = 0; x < forward.width; ++x) {
                covered += forward.at(x, y).a > 0.5f;
                lowerQuarter += forward.at(x, y).a > 0.5f && y > forward.height * 3 / 4;
            }
        QVERIFY2(covered > 6000 && lowerQuarter > 500,
                 qPrintable(QStringLiteral("%1 %2").arg(covered).arg(lowerQuarter)));
        const double a = maxRelativeDifference(forward, attributes),
                     b = maxRelativeDifference(surfaces, attributes);
        qInfo("covered %d (lower quarter %d); max relative difference: forward %g, surfaces %g", covered,
              lowerQuarter, a, b);
        QVERIFY2(a <= 1e-6 && b <= 1e-6, qPrintable(QStringLiteral("forward %1, surfaces %2").arg(a).arg(b)));
        // The textures matter here: without them the image changes (the comparison could fail).
        auto plain = std::make_shared<Model>(*scene);
        for (Material& m : plain->materials)
            m.baseColorTexture = -1;
        QVERIFY(m_gl.setModel(plain, &error));
        bool unused = false;
        QVERIFY(maxRelativeDifference(radiance(rig, ShadingPath::Deferred, true, &unused), attributes) >
                0.05);
    }

    // The G-buffer is kept while the view, the targets and the surfaces hold: a light moved under a still
    // camera shades the kept surfaces, exactly as a frame that draws them again; anything the G-pass draws
    // differently, or a frame in between that did not draw it (the forward path writes the shared depth),
    // draws it again.
    void keptWhileTheViewHolds_data() {
        QTest::addColumn<bool>("deferredTextures"); // attributes, or Surfaces (the model's textures sampled)
        QTest::newRow("attributes") << true;
        QTest::newRow("surfaces") << false;
    }

    void keptWhileTheViewHolds() {
        QFETCH(bool, deferredTextures);
        auto scene = texturedScene();
        Material second = scene->materials[0];
        second.baseColor = {0.3f, 0.9f, 0.4f, 1.0f};
        second.emissiveTexture = 0;
        scene->materials.push_back(second);
        scene->meshes[1].material = 1;
        QString error;
        QVERIFY(m_gl.setModel(scene, &error));
        Rig rig = pbrRig(
            {gltfPoint({1.0, 2.0, 2.5}, 15.0, 20.0), gltfSpot({-1.0, 0.5, 2.0}, {0.0, -1.0, 0.0}, 30.0)},
            glm::dvec3(0.05));
        rig.ground.mode = GroundMode::Visible;
        ViewCamera side = aboveCamera();
        side.eye = {-2.5, 1.2, 2.4};
        const RenderStats& stats = m_gl.renderer().stats();
        bool attr = false;
        const auto frame = [&](const Rig& r, const ViewCamera& c, bool kept,
                               ShadingPath path = ShadingPath::Deferred) {
            const int builds = stats.gbufferBuilds;
            FloatImage out = radiance(r, path, deferredTextures, &attr, c);
            const bool deferred = path == ShadingPath::Deferred;
            if (stats.gbufferKept != kept || stats.gbufferBuilds != builds + (deferred && !kept ? 1 : 0) ||
                stats.deferred != deferred || (deferred && attr != deferredTextures))
                qWarning("kept %d (expected %d), builds %d -> %d", stats.gbufferKept, kept, builds,
                         stats.gbufferBuilds);
            return std::make_pair(out, stats.gbufferKept == kept &&
                                           stats.gbufferBuilds == builds + (deferred && !kept ? 1 : 0));
        };
        const auto same = [](const FloatImage& a, const FloatImage& b) {
            return maxRelativeDifference(a, b) == 0.0;
        };
        // Under the attribute G-buffer every drawn G-buffer's Surfaces are written to the kept surfaces,
        // and the frames that keep the G-buffer shade those without building them again.
        const int surfaceBuilds = stats.surfaceBuilds;
        const auto [first, drawn] = frame(rig, aboveCamera(), false);
        QVERIFY(drawn && !stats.surfacesKept);
        QCOMPARE(stats.surfaceBuilds, surfaceBuilds + (deferredTextures ? 1 : 0));
        const auto [again, kept] = frame(rig, aboveCamera(), true);
        QVERIFY(kept && same(first, again));
        QCOMPARE(stats.surfacesKept, deferredTextures);
        QCOMPARE(stats.surfaceBuilds, surfaceBuilds + (deferredTextures ? 1 : 0));

        // A light moved and brighter: kept, and exactly what a drawn G-buffer gives.
        Rig moved = rig;
        moved.lights[0].position = {-1.5, 1.0, 2.0};
        moved.lights[1].intensity *= 3.0;
        const auto [movedKept, k1] = frame(moved, aboveCamera(), true);
        QVERIFY(k1 && !same(movedKept, first)); // the light matters here
        QCOMPARE(stats.surfacesKept, deferredTextures);
        QCOMPARE(stats.surfaceBuilds, surfaceBuilds + (deferredTextures ? 1 : 0));
        QVERIFY(frame(moved, side, false).second);
        const auto [movedDrawn, k2] = frame(moved, aboveCamera(), false);
        QVERIFY(k2 && same(movedKept, movedDrawn) && !stats.surfacesKept); // a drawn G-buffer: not kept

        // A forward frame of another view in between wrote the shared depth: drawn again.
        QVERIFY(frame(rig, aboveCamera(), true).second);
        QVERIFY(frame(rig, side, false, ShadingPath::Forward).second);
        QVERIFY(!stats.surfacesKept); // the forward frame kept nothing
        const auto [afterForward, k3] = frame(rig, aboveCamera(), false);
        QVERIFY(k3 && same(afterForward, first));
        // So does a read-back of the G-buffer.
        GBuffer g;
        QVERIFY2(m_gl.renderGBuffer(aboveCamera(), QSize(160, 120), RenderSettings(), &g, &error),
                 qPrintable(error));
        QVERIFY(frame(rig, aboveCamera(), false).second);

        // What the G-pass draws differently: the shading model, the ground, the model.
        Rig classic = rig;
        classic.shading.model = ShadingModel::Classic;
        QVERIFY(frame(classic, aboveCamera(), false).second);
        QVERIFY(frame(rig, aboveCamera(), false).second);
        Rig noGround = rig;
        noGround.ground.mode = GroundMode::Off;
        QVERIFY(frame(noGround, aboveCamera(), false).second);
        QVERIFY(frame(rig, aboveCamera(), false).second);
        QVERIFY(frame(rig, aboveCamera(), true).second);
        QVERIFY(m_gl.setModel(texturedScene(), &error));
        QVERIFY(frame(rig, aboveCamera(), false).second);
    }

    // Auto shades deferred at any light count without MSAA (the kept G-buffer makes a still view's frame
    // cost the lighting alone), with the attribute G-buffer when asked for and the model has few materials;
    // vertex colours, or more than kMaxAttributeMaterials materials, keep the Surface G-buffer.
    void autoPathFollowsTheMaterials() {
        const Rig rig = rigOf({point({1.0, 2.0, 2.5}, FalloffModel::InverseSquare)});
        QString error;
        QVERIFY(m_gl.setModel(texturedScene(), &error));
        bool attr = false;
        radiance(rig, ShadingPath::Auto, true, &attr);
        QVERIFY(m_gl.renderer().stats().deferred && attr);
        radiance(rig, ShadingPath::Auto, false, &attr);
        QVERIFY(m_gl.renderer().stats().deferred && !attr); // one light: deferred, Surfaces in the G-buffer
        auto many = std::make_shared<Model>(*texturedScene());
        for (int i = 0; i <= kMaxAttributeMaterials; ++i) {
            Mesh copy = many->meshes[0];
            copy.material = int(many->materials.size());
            many->materials.push_back(many->materials[0]);
            many->meshes.push_back(std::move(copy));
        }
        QVERIFY(m_gl.setModel(many, &error));
        radiance(rig, ShadingPath::Deferred, true, &attr);
        QVERIFY(m_gl.renderer().stats().deferred && !attr);
        auto coloured = std::make_shared<Model>(*texturedScene());
        coloured->meshes[1].hasVertexColors = true;
        QVERIFY(m_gl.setModel(coloured, &error));
        radiance(rig, ShadingPath::Deferred, true, &attr);
        QVERIFY(m_gl.renderer().stats().deferred && !attr);
    }
};

LR_GL_TEST_MAIN(TestDeferredTextures)
#include "tst_deferredtextures.moc"
