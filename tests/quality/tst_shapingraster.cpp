// Issue 39: the raster tiers shape IES profiles and gobos (render/shapinglayers.h, shaders/shaping.glsl)
// as core does, each tier against the double reference of the same G-buffer (render/reference.h, which
// interpolates the profile and samples the image exactly): a spot with a profile, a point light with a
// turned profile at level "profile", and a spot with a checkerboard gobo decoded by the import worker, each
// over a plane. The balanced and exact tiers are within 2 levels (measured: 1); the fast tier lights the
// vertices, so it is only asked to be nearer the reference than the same light unshaped. Then the grid the
// raster samples: on a profile whose angles are multiples of the grid's it is core's bilinear profile itself;
// and a rig without shaping compiles none of it.
#include "qualityscenes.h"

#include "model/isolatedimport.h"
#include "render/shadergen.h"
#include "render/shapinglayers.h"

#include <QImage>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;
using namespace lr::test;
using V = glm::dvec3;

namespace {

const QSize kSize(96, 72);

Rig shapedRig(const Light& light) {
    Rig rig;
    rig.space = RigSpace::World;
    rig.ambient = V(0.0);
    rig.shading.model = ShadingModel::Classic;
    rig.lights = {light};
    return rig;
}

Light iesSpot() {
    Light l = makeLight(LightType::Spot, QStringLiteral("IES spot"));
    l.position = {0.2, -0.1, 1.6};
    l.direction = glm::normalize(V(-0.1, 0.05, -1.0));
    l.falloff = {};
    l.cone.model = ConeModel::Smooth;
    l.cone.inner = 50.0, l.cone.outer = 70.0;
    l.intensity = 1.5;
    l.specular = V(0.0), l.ambient = V(0.0);
    l.ies = IesSpec{};
    l.ies->file = QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies");
    l.ies->rotation = 20.0;
    return l;
}

Light iesPoint() { // level "profile": the file's candela set the level
    Light l = makeLight(LightType::Point, QStringLiteral("IES point"));
    l.position = {-0.3, 0.2, 1.2};
    l.direction = glm::normalize(V(0.3, -0.2, -1.0));
    l.falloff.model = FalloffModel::InverseSquare;
    l.falloff.range = -1.0;
    l.specular = V(0.0), l.ambient = V(0.0);
    l.ies = IesSpec{};
    l.ies->file = QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies");
    l.ies->level = IesLevel::Profile;
    l.ies->multiplier = 0.001;
    l.ies->rotation = -35.0;
    return l;
}

Light goboSpot(const QString& file) {
    Light l = makeLight(LightType::Spot, QStringLiteral("Gobo spot"));
    l.position = {0.0, 0.0, 1.5};
    l.direction = V(0.0, 0.0, -1.0);
    l.falloff = {};
    l.cone.model = ConeModel::Hard;
    l.cone.outer = 40.0;
    l.specular = V(0.0), l.ambient = V(0.0);
    l.gobo = GoboSpec{file, {}, 0.8, 25.0};
    return l;
}

struct Shaped {
    ErrorFigures shaped, unshaped; // the tier against the reference, with and without the shaping drawn
    QString error;
};

// One frame of tier `q` of `rig`, against the reference of the renderer's own scene description (its
// loaded profiles and images); and, as a yardstick, the same frame drawn with the shaping removed.
Shaped renderShaped(OffscreenRenderer& gl, const std::shared_ptr<Model>& model, const Rig& rig, Quality q) {
    Shaped out;
    RenderSettings settings;
    settings.msaaSamples = 0;
    settings.quality = q;
    if (!gl.setModel(model, &out.error)) return out;
    gl.setRig(rig);
    GBuffer g;
    RenderSettings floats = settings;
    floats.hdrFloat32 = true;
    if (!gl.renderGBuffer(planeCamera(), kSize, floats, &g, &out.error)) return out;
    const QImage image = gl.renderImage(planeCamera(), kSize, settings, 1, &out.error);
    if (image.isNull()) return out;
    const glm::dmat4 view = gl.renderer().effectiveCamera(planeCamera()).view();
    const auto scene = makeReferenceScene(gl.renderer().scene(), view, settings, &out.error);
    if (!scene) return out;
    const ReferenceImage reference = computeReference(g, *scene);
    out.shaped = lr::compareWithReference(image, reference);
    Rig plain = rig;
    for (Light& l : plain.lights)
        l.ies.reset(), l.gobo.reset();
    gl.setRig(plain);
    const QImage unshaped = gl.renderImage(planeCamera(), kSize, settings, 1, &out.error);
    if (unshaped.isNull()) return out;
    out.unshaped = lr::compareWithReference(unshaped, reference);
    return out;
}

QString describe(const ErrorFigures& e) {
    return QStringLiteral("max %1, mean %2, >1 level %3%")
        .arg(e.maxLevels)
        .arg(e.meanLevels, 0, 'f', 3)
        .arg(100.0 * e.shareOver1(), 0, 'f', 2);
}

} // namespace

class TestShapingRaster : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;
    QTemporaryDir m_dir;

    void checkTiers(const Rig& rig) {
        auto model = gridPlane(2.0, 16);
        model->materials[0].specular = {0.0f, 0.0f, 0.0f};
        for (Quality q : {Quality::Fast, Quality::Balanced, Quality::Exact}) {
            const Shaped s = renderShaped(m_gl, model, rig, q);
            QVERIFY2(s.error.isEmpty(), qPrintable(s.error));
            qInfo("%s: shaped %s | unshaped %s", tierName(q), qPrintable(describe(s.shaped)),
                  qPrintable(describe(s.unshaped)));
            // The shaping changes the picture a lot: drawn unshaped, the light is far from the reference.
            QVERIFY2(s.unshaped.meanLevels > 4.0, qPrintable(describe(s.unshaped)));
            QVERIFY2(s.shaped.meanLevels * 2.0 < s.unshaped.meanLevels, qPrintable(describe(s.shaped)));
            if (q == Quality::Fast) continue; // per vertex
            QVERIFY2(s.shaped.maxLevels <= 2, qPrintable(describe(s.shaped)));
            QVERIFY2(s.shaped.shareOver1() < 0.001, qPrintable(describe(s.shaped)));
        }
    }

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE));
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
        QVERIFY(m_dir.isValid());
    }

    void iesSpotMatchesTheReference() { checkTiers(shapedRig(iesSpot())); }

    void iesPointAtProfileLevelMatchesTheReference() { checkTiers(shapedRig(iesPoint())); }

    void goboSpotMatchesTheReference() {
        QImage board(64, 48, QImage::Format_RGB888); // not square: the layer's corner and its own clamp
        for (int y = 0; y < board.height(); ++y)
            for (int x = 0; x < board.width(); ++x)
                board.setPixelColor(x, y, (x / 16 + y / 16) % 2 == 0 ? QColor(255, 230, 200) : Qt::black);
        const QString file = m_dir.filePath(QStringLiteral("board.png"));
        QVERIFY(board.save(file));
        checkTiers(shapedRig(goboSpot(file)));
    }

    // Two gobos of different sizes and one profile shared by two lights: one layer each, every light its
    // own (the array is as large as the largest image; the smaller one is clamped to its own edge).
    void sharedAndMixedLayersMatchTheReference() {
        QImage stripes(32, 32, QImage::Format_RGB888);
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                stripes.setPixelColor(x, y, x / 8 % 2 ? Qt::white : QColor(40, 90, 200));
        const QString file = m_dir.filePath(QStringLiteral("stripes.png"));
        QVERIFY(stripes.save(file));
        QImage board(64, 48, QImage::Format_RGB888);
        board.fill(Qt::white);
        for (int y = 0; y < 48; y += 2)
            for (int x = 0; x < 64; ++x)
                board.setPixelColor(x, y, Qt::black);
        const QString wide = m_dir.filePath(QStringLiteral("lines.png"));
        QVERIFY(board.save(wide));
        Rig rig = shapedRig(iesSpot());
        Light a = goboSpot(file), b = goboSpot(wide), c = iesPoint();
        a.position = {-0.6, 0.3, 1.4}, b.position = {0.6, -0.3, 1.4};
        c.position = {0.5, 0.6, 1.0};
        rig.lights.insert(rig.lights.end(), {a, b, c});
        const render::ShapingLayers layers = [&] {
            m_gl.setRig(rig);
            return render::shapingLayers(m_gl.renderer().scene().rig(),
                                         m_gl.renderer().scene().lightAssets());
        }();
        QCOMPARE(int(layers.profiles.size()), 1);
        QCOMPARE(int(layers.gobos.size()), 2);
        QVERIFY(layers.iesLayer == (std::vector<int>{0, -1, -1, 0}));
        QVERIFY(layers.goboLayer == (std::vector<int>{-1, 0, 1, -1}));
        QCOMPARE(layers.goboWidth, 64);
        QCOMPARE(layers.goboHeight, 48);
        checkTiers(rig);
    }

    // The grid holds I / peak at its nodes; GL_LINEAR between them is core's bilinear profile exactly when
    // the file's angles are multiples of the grid's (full.ies: 22.5° vertical, 45° horizontal).
    void theGridIsTheProfileOnAlignedFiles() {
        QString error;
        const auto profile = readIesFile(QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies"), &error);
        QVERIFY2(profile, qPrintable(error));
        const std::vector<float> grid = render::resampleIes(*profile);
        QCOMPARE(grid.size(), size_t(render::kIesGridVertical) * render::kIesGridHorizontal);
        const auto at = [&](int j, int i) {
            return double(grid[size_t(j) * render::kIesGridHorizontal +
                               size_t((i + render::kIesGridHorizontal) % render::kIesGridHorizontal)]);
        };
        QRandomGenerator rng(39);
        double worst = 0.0;
        for (int k = 0; k < 5000; ++k) {
            const double theta = rng.bounded(180.0), phi = rng.bounded(360.0);
            const double fj = theta / render::kIesGridVerticalStep, fi = phi / render::kIesGridHorizontalStep;
            const int j = std::min(int(fj), render::kIesGridVertical - 2), i = int(fi);
            const double tj = fj - j, ti = fi - i;
            const double bilinear = (at(j, i) * (1 - ti) + at(j, i + 1) * ti) * (1 - tj) +
                                    (at(j + 1, i) * (1 - ti) + at(j + 1, i + 1) * ti) * tj;
            worst = std::max(worst, std::abs(bilinear - iesCandela(*profile, theta, phi) / profile->peak));
        }
        qInfo("grid against core's profile, 5000 random directions: worst %.3g of the peak", worst);
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
    }

    // A rig without a profile or a gobo compiles none of it and packs no texel for it.
    void noShapingCostsNothing() {
        Rig rig = shapedRig(iesSpot());
        rig.lights.front().ies.reset();
        render::FeatureKey plain;
        plain.rig = render::rigFeatures(rig);
        QVERIFY(!plain.rig.ies && !plain.rig.gobo);
        const QByteArray text = render::shaderPrelude(plain);
        QVERIFY(!text.contains("LR_IES") && !text.contains("LR_GOBO"));
        QVERIFY(text.contains("#define LR_LIGHT_TEXELS 8\n"));
        render::FeatureKey shaped;
        shaped.rig = render::rigFeatures(shapedRig(iesSpot()));
        QVERIFY(shaped.rig.ies && !shaped.rig.gobo);
        QVERIFY(render::shaderPrelude(shaped).contains("#define LR_LIGHT_TEXELS 10\n"));
        QVERIFY(shaped.bits() != plain.bits());
        rig.lights.front().gobo = GoboSpec{QStringLiteral("x.png"), {}, 1.0, 0.0};
        QVERIFY(render::rigFeatures(rig).gobo);
        rig.lights.front().type = LightType::Point; // a gobo is a spot's only
        QVERIFY(!render::rigFeatures(rig).gobo);
    }
};

QTEST_MAIN(TestShapingRaster)
#include "tst_shapingraster.moc"
