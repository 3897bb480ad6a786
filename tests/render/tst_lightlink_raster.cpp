// Light and shadow linking in the OpenGL raster (issue 38): every tier and path (forward, deferred with
// Surfaces or attributes, clustered, per vertex), classic and physically based, honours a light's lit set;
// a part left out of a light's shadow casts none of it while that light still lights it; an unlinked scene
// compiles and packs exactly what it did; the light-group split follows; the editor's part highlight.
// Scenes: two spheres "A" and "B" over a visible ground, a linked key light and an unlinked fill; every
// probe is a world point projected with the renderer's own camera.
#include "glfixture.h"
#include "scenes.h"
#include "shadowfixture.h"
#include "shadowscenes.h"

#include "core/lightgroups.h"
#include "render/offscreen.h"
#include "render/rasterlayers.h"
#include "render/shadergen.h"

#include <QImage>
#include <QTest>
#include <cstring>
#include <glm/geometric.hpp>
#include <memory>
#include <vector>

using namespace lr;
using namespace lr::test;

namespace {

const QSize kImage(200, 150);
constexpr double kRadius = 0.5;
const glm::dvec3 kCentreA(-1.0, 0.6, 0.0), kCentreB(1.0, 0.6, 0.0);

// A sphere named (mesh and node) `name`.
Model namedSphere(const QString& name, const glm::dvec3& centre) {
    Model m = makeSphere(kRadius, 48, 24, centre);
    m.meshes.front().name = m.meshes.front().node = name;
    m.materials.front().baseColor = {0.7f, 0.7f, 0.7f, 1.0f};
    m.materials.front().specular = {0.3f, 0.3f, 0.3f};
    m.materials.front().roughness = 0.5f;
    return m;
}

std::shared_ptr<Model> twoSpheres() {
    auto m = std::make_shared<Model>();
    appendMeshes(*m, namedSphere(QStringLiteral("A"), kCentreA));
    appendMeshes(*m, namedSphere(QStringLiteral("B"), kCentreB));
    recomputeBounds(*m);
    return m;
}

ViewCamera camera() {
    ViewCamera c;
    c.eye = {0.0, 2.5, 4.0};
    c.target = {0.0, 0.4, 0.0};
    c.yfovDeg = 50.0;
    return c;
}

// The sphere's point facing the camera (seen by it).
glm::dvec3 facing(const glm::dvec3& centre) {
    return centre + kRadius * glm::normalize(camera().eye - centre);
}
const glm::dvec3 kGroundProbe(0.0, 0.0, 1.0); // between the spheres, in front

// Key: a range-bounded point light (in the clusters' lists) with an ambient term of its own; Fill: an
// unlinked directional light (in every cluster).
// `casting`: the key casts a shadow (a cube map; the fast tier then shades it per pixel).
Rig linkRig(ShadingModel shading, const QStringList& keyInclude, bool casting = false) {
    Light key = point({0.0, 2.0, 1.0}, FalloffModel::InverseSquare, 20.0);
    key.name = QStringLiteral("Key");
    key.intensity = 3.0;
    key.ambient = glm::dvec3(0.05, 0.04, 0.03);
    key.link.lit.include = keyInclude;
    key.shadow.enabled = casting;
    Light fill = directional({0.3, -1.0, -0.4}, DiffuseModel::Lambert);
    fill.name = QStringLiteral("Fill");
    fill.intensity = 0.4;
    Rig r = rigOf({key, fill});
    r.ground.mode = GroundMode::Visible;
    r.shading.model = shading;
    return r;
}

Rig withoutKey(Rig r) {
    r.lights[0].enabled = false;
    return r;
}

struct PathCase {
    const char* name;
    Quality quality;
    ShadingPath path;
    bool clustered = false;
    bool attributes = false; // RenderSettings::deferredTextures
};

std::vector<PathCase> pathCases() {
    std::vector<PathCase> cases = {{"fast", Quality::Fast, ShadingPath::Forward}};
    for (Quality q : {Quality::Balanced, Quality::Exact}) {
        cases.push_back({"forward", q, ShadingPath::Forward});
        cases.push_back({"deferred", q, ShadingPath::Deferred});
        cases.push_back({"clustered forward", q, ShadingPath::Forward, true});
        cases.push_back({"clustered deferred", q, ShadingPath::Deferred, true});
        cases.push_back({"attribute deferred", q, ShadingPath::Deferred, false, true});
    }
    return cases;
}

RenderSettings settingsOf(const PathCase& c) {
    RenderSettings s;
    s.quality = c.quality;
    s.msaaSamples = 0;
    s.shadingPath = c.path;
    s.clusteredShading = c.clustered ? 1 : 0;
    s.deferredTextures = c.attributes;
    return s;
}

QString caseName(const PathCase& c, ShadingModel shading) {
    return QStringLiteral("%1 %2 %3").arg(toString(c.quality), QLatin1String(c.name), toString(shading));
}

bool close(double a, double b, double tol) {
    return std::abs(a - b) <= tol * std::max(1e-3, std::max(std::abs(a), std::abs(b)));
}

bool sameImage(const FloatImage& a, const FloatImage& b) {
    return a.width == b.width && a.height == b.height &&
           std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(a.pixels[0])) == 0;
}

} // namespace

class TestLightLinkRaster : public QObject {
    Q_OBJECT

    std::unique_ptr<OffscreenRenderer> m_gl;

    void start() {
        LR_REQUIRE_DISPLAY();
        if (m_gl) return;
        m_gl = std::make_unique<OffscreenRenderer>();
        QString error;
        if (!m_gl->initialize(&error)) qFatal("%s", qPrintable(error));
    }

    FloatImage radiance(const Rig& rig, const RenderSettings& s, const ViewCamera& cam = camera()) {
        m_gl->setRig(rig);
        FloatImage out;
        QString error;
        if (!m_gl->renderRadiance(cam, kImage, s, &out, &error)) qWarning("%s", qPrintable(error));
        return out;
    }

    double lum(const FloatImage& img, const glm::dvec3& p, const ViewCamera& cam = camera()) {
        const auto px = projectToPixel(m_gl->renderer(), cam, kImage, p);
        if (!px) qFatal("probe off the image");
        return luminance(img.at(px->x(), px->y()));
    }

  private slots:
    // A prelude without linking is what it was: no define, 8 texels a light; the key's bit is separate.
    void unlinkedProgramsAreUnchanged() {
        render::FeatureKey key;
        key.rig.lightTypes = 1u << int(LightType::Point);
        const QByteArray plain = render::shaderPrelude(key);
        QVERIFY(!plain.contains("LINKING"));
        QVERIFY(plain.contains("#define LR_LIGHT_TEXELS 8\n"));
        render::FeatureKey linked = key;
        linked.rig.linking = true;
        const QByteArray withLinking = render::shaderPrelude(linked);
        QVERIFY(withLinking.contains("#define LR_LIGHT_LINKING 1\n"));
        QVERIFY(withLinking.contains("#define LR_LIGHT_TEXELS 9\n"));
        QVERIFY(key.bits() != linked.bits());
        QVERIFY(linked.describe().contains(QLatin1String("linking")));
        QVERIFY(!key.describe().contains(QLatin1String("linking")));
    }

    // B receives nothing from the key linked to A (neither its direct light nor its ambient term), in every
    // tier and path; A is lit as without the link; the unlinked rig lights both (so this could fail).
    void linkedLightSkipsOtherParts_data() {
        QTest::addColumn<int>("index");
        QTest::addColumn<int>("shading");
        QTest::addColumn<bool>("casting");
        const auto cases = pathCases();
        for (bool casting : {false, true})
            for (ShadingModel shading : {ShadingModel::Classic, ShadingModel::Pbr})
                for (size_t i = 0; i < cases.size(); ++i)
                    QTest::newRow(qPrintable(caseName(cases[i], shading) +
                                             (casting ? QStringLiteral(" casting") : QString())))
                        << int(i) << int(shading) << casting;
    }
    void linkedLightSkipsOtherParts() {
        start();
        QFETCH(int, index);
        QFETCH(int, shading);
        QFETCH(bool, casting);
        const PathCase c = pathCases()[size_t(index)];
        const ShadingModel model = ShadingModel(shading);
        QString error;
        QVERIFY2(m_gl->setModel(twoSpheres(), &error), qPrintable(error));
        const RenderSettings s = settingsOf(c);
        const Rig unlinked = linkRig(model, {}, casting);
        const FloatImage all = radiance(unlinked, s);
        const FloatImage noKey = radiance(withoutKey(unlinked), s);
        const FloatImage linked = radiance(linkRig(model, {QStringLiteral("A")}, casting), s);
        QCOMPARE(m_gl->renderer().stats().shadowCasters, casting ? 1 : 0);
        const RenderStats& stats = m_gl->renderer().stats();
        QCOMPARE(stats.deferred, c.path == ShadingPath::Deferred);
        QCOMPARE(stats.clustered, c.clustered);
        QCOMPARE(stats.deferredTextures, c.attributes);
        const glm::dvec3 a = facing(kCentreA), b = facing(kCentreB);
        // The key reaches B and the ground when unlinked.
        QVERIFY2(
            lum(all, b) > 1.5 * lum(noKey, b),
            qPrintable(QStringLiteral("B: %1 vs %2 without the key").arg(lum(all, b)).arg(lum(noKey, b))));
        QVERIFY(lum(all, kGroundProbe) > 1.5 * lum(noKey, kGroundProbe));
        // Linked to A: B and the ground as without the key, A as unlinked.
        const double tol = 1e-4;
        QVERIFY2(
            close(lum(linked, b), lum(noKey, b), tol),
            qPrintable(
                QStringLiteral("B linked %1, without the key %2").arg(lum(linked, b)).arg(lum(noKey, b))));
        QVERIFY2(close(lum(linked, kGroundProbe), lum(noKey, kGroundProbe), tol),
                 qPrintable(QStringLiteral("ground linked %1, without the key %2")
                                .arg(lum(linked, kGroundProbe))
                                .arg(lum(noKey, kGroundProbe))));
        QVERIFY2(close(lum(linked, a), lum(all, a), tol),
                 qPrintable(QStringLiteral("A linked %1, unlinked %2").arg(lum(linked, a)).arg(lum(all, a))));
    }

    // A link that keeps every part (linking on, every mask all ones) renders the unlinked image bit for bit,
    // and only a linked frame packs the ninth texel.
    void everythingLinkedMatchesUnlinked_data() {
        QTest::addColumn<int>("index");
        const auto cases = pathCases();
        for (size_t i = 0; i < cases.size(); ++i)
            QTest::newRow(qPrintable(caseName(cases[i], ShadingModel::Classic))) << int(i);
    }
    void everythingLinkedMatchesUnlinked() {
        start();
        QFETCH(int, index);
        const RenderSettings s = settingsOf(pathCases()[size_t(index)]);
        QString error;
        QVERIFY2(m_gl->setModel(twoSpheres(), &error), qPrintable(error));
        const FloatImage plain = radiance(linkRig(ShadingModel::Classic, {}), s);
        QCOMPARE(m_gl->renderer().stats().lightBytesUploaded, qint64(2 * render::kLightTexels * 16));
        const Rig everything = linkRig(ShadingModel::Classic,
                                       {QStringLiteral("A"), QStringLiteral("B"), QStringLiteral("ground")});
        const FloatImage linked = radiance(everything, s);
        QVERIFY(m_gl->renderer().scene().links().active);
        QCOMPARE(m_gl->renderer().stats().lightBytesUploaded, qint64(2 * render::kLinkedLightTexels * 16));
        QVERIFY2(
            sameImage(plain, linked),
            qPrintable(QStringLiteral("largest difference %1").arg(maxRelativeDifference(plain, linked))));
    }

    // A caster left out of a light's shadow casts none of it and is still lit by it; the map is drawn again
    // when the link changes (its cache key holds the casters).
    void shadowExclusion_data() {
        QTest::addColumn<int>("quality");
        QTest::addColumn<int>("path");
        for (Quality q : {Quality::Fast, Quality::Balanced, Quality::Exact})
            for (ShadingPath p : {ShadingPath::Forward, ShadingPath::Deferred}) {
                if (q == Quality::Fast && p == ShadingPath::Deferred) continue;
                QTest::newRow(qPrintable(QStringLiteral("%1 %2").arg(
                    toString(q),
                    p == ShadingPath::Forward ? QStringLiteral("forward") : QStringLiteral("deferred"))))
                    << int(q) << int(p);
            }
    }
    void shadowExclusion() {
        start();
        QFETCH(int, quality);
        QFETCH(int, path);
        auto model = std::make_shared<Model>();
        Model ball = makeSphere(0.4, 48, 24, glm::dvec3(0.0, 1.0, 0.0));
        ball.meshes.front().name = ball.meshes.front().node = QStringLiteral("Ball");
        appendMeshes(*model, ball);
        Model floor = horizontalQuad(2.0, glm::dvec3(0.0));
        floor.meshes.front().name = floor.meshes.front().node = QStringLiteral("Floor");
        appendMeshes(*model, floor);
        recomputeBounds(*model);
        QString error;
        QVERIFY2(m_gl->setModel(model, &error), qPrintable(error));
        RenderSettings s = settingsOf({"", Quality(quality), ShadingPath(path)});
        const ViewCamera cam = groundCamera();
        Light spotLight = castingSpot({0.0, 4.0, 0.0}, {0.0, 0.0, 0.0}, 40.0, 0.0);
        spotLight.name = QStringLiteral("Key");
        const Rig casting = rigOf({spotLight});
        Rig excluded = casting;
        excluded.lights[0].link.shadow.exclude = {QStringLiteral("Ball")};
        const FloatImage on = radiance(casting, s, cam);
        const FloatImage cut = radiance(excluded, s, cam);
        QCOMPARE(m_gl->renderer().stats().shadowMapsRendered, 1); // the link changed the map
        // Back to casting: the map is drawn with the ball again.
        const FloatImage again = radiance(casting, s, cam);
        QCOMPARE(m_gl->renderer().stats().shadowMapsRendered, 1);
        QVERIFY(sameImage(again, on));
        const FloatImage off = radiance(withoutShadows(casting), referenceFor(s), cam);
        const glm::dvec3 under(0.0, 0.0, 0.0), top(0.0, 1.4, 0.0);
        const double lumOff = lum(off, under, cam);
        QVERIFY(lumOff > 1e-3);
        QVERIFY2(lum(on, under, cam) < 0.3 * lumOff,
                 qPrintable(QStringLiteral("shadowed %1, lit %2").arg(lum(on, under, cam)).arg(lumOff)));
        const double tol = litTolerance(Quality(quality));
        QVERIFY2(
            close(lum(cut, under, cam), lumOff, tol),
            qPrintable(
                QStringLiteral("excluded %1, without shadows %2").arg(lum(cut, under, cam)).arg(lumOff)));
        // The ball is still lit by the light, as with its shadow.
        QVERIFY(lum(on, top, cam) > 1e-3);
        QVERIFY2(
            close(lum(cut, top, cam), lum(on, top, cam), tol),
            qPrintable(QStringLiteral("ball %1, casting %2").arg(lum(cut, top, cam)).arg(lum(on, top, cam))));
    }

    // The light-group split (rasterlayers.h) renders each group with the linked rig: the key's layer has
    // nothing on B.
    void groupLayersFollowLinks() {
        start();
        QString error;
        QVERIFY2(m_gl->setModel(twoSpheres(), &error), qPrintable(error));
        m_gl->setRig(linkRig(ShadingModel::Classic, {QStringLiteral("A")}));
        RenderSettings s;
        s.msaaSamples = 0;
        const auto layers = renderRasterLayers(*m_gl, camera(), kImage, s, &error);
        QVERIFY2(layers, qPrintable(error));
        int key = -1;
        for (size_t i = 0; i < layers->groups.size(); ++i)
            if (layers->groups[i].name == QLatin1String("Key")) key = int(i);
        QVERIFY(key >= 0);
        const FloatImage& keyImage = layers->groupImages[size_t(key)];
        QVERIFY(lum(keyImage, facing(kCentreA)) > 1e-3);
        QCOMPARE(lum(keyImage, facing(kCentreB)), 0.0);
        QCOMPARE(lum(keyImage, kGroundProbe), 0.0);
    }

    // RenderSettings::highlightedParts tints exactly the listed parts (a model mesh, the ground) in the
    // overlay and leaves the radiance alone.
    void highlightedParts() {
        start();
        QString error;
        QVERIFY2(m_gl->setModel(twoSpheres(), &error), qPrintable(error));
        m_gl->setRig(linkRig(ShadingModel::Classic, {}));
        RenderSettings s;
        s.msaaSamples = 0;
        const QImage plain = m_gl->renderImage(camera(), kImage, s, 1, &error);
        QVERIFY2(!plain.isNull(), qPrintable(error));
        RenderSettings marked = s;
        marked.highlightedParts = {0, 999}; // A, and an index of no part
        const QImage tinted = m_gl->renderImage(camera(), kImage, marked, 1, &error);
        QVERIFY2(!tinted.isNull(), qPrintable(error));
        const auto pixel = [&](const QImage& img, const glm::dvec3& p) {
            const auto px = projectToPixel(m_gl->renderer(), camera(), kImage, p);
            return img.pixel(*px);
        };
        QVERIFY(pixel(tinted, facing(kCentreA)) != pixel(plain, facing(kCentreA)));
        QCOMPARE(pixel(tinted, facing(kCentreB)), pixel(plain, facing(kCentreB)));
        QCOMPARE(pixel(tinted, kGroundProbe), pixel(plain, kGroundProbe));
        // Toward the tint: more red than blue than there was.
        const QColor a = QColor::fromRgba(pixel(tinted, facing(kCentreA)));
        const QColor a0 = QColor::fromRgba(pixel(plain, facing(kCentreA)));
        QVERIFY(a.red() - a.blue() > a0.red() - a0.blue());
        // The ground's part: the ground tinted, and faintly the parts in front of it.
        RenderSettings ground = s;
        ground.highlightedParts = {int(m_gl->renderer().scene().groundPart(0))};
        const QImage groundTinted = m_gl->renderImage(camera(), kImage, ground, 1, &error);
        QVERIFY(pixel(groundTinted, kGroundProbe) != pixel(plain, kGroundProbe));
        s.hdrTarget = marked.hdrTarget = true;
        QVERIFY(sameImage(radiance(linkRig(ShadingModel::Classic, {}), s),
                          radiance(linkRig(ShadingModel::Classic, {}), marked)));
    }
};

LR_GL_TEST_MAIN(TestLightLinkRaster)
#include "tst_lightlink_raster.moc"
