// The rest of the glTF material on the GPU (issue 13, item 1): normal-map scale, KHR_texture_transform per
// texture role, alpha modes (OPAQUE ignores alpha, MASK discards under the cutoff, BLEND composites over
// the opaque scene back to front in the forward and deferred paths), double-sided lighting and culling.
// Models are built here (planes, hand-set Material fields, small QImage textures): no importer involved.
//
// Most scenes look straight down -Z at a plane of half size 1 from distance 1 with a 90° field of view, so
// the plane fills the square image exactly and pixel (x, y) of an N×N image sees uv ((x+½)/N, (y+½)/N).
#include "glfixture.h"
#include "scenes.h"

#include "render/offscreen.h"
#include "render/renderplan.h"
#include "render/shadergen.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace lr::render;
using namespace lr::test;

namespace {

constexpr int kSize = 64;

RenderSettings floatSettings(ShadingPath path = ShadingPath::Forward) {
    RenderSettings s;
    s.msaaSamples = 0;
    s.hdrFloat32 = true;
    s.shadingPath = path;
    return s;
}

ViewCamera straightCamera(double z = 1.0) {
    ViewCamera c;
    c.eye = {0.0, 0.0, z};
    c.target = {0.0, 0.0, 0.0};
    c.yfovDeg = 90.0;
    return c;
}

// The pixel that sees uv (u, v) of the full-view plane.
QPoint pixelAt(double u, double v) {
    return {int(std::floor(u * kSize)), int(std::floor(v * kSize))};
}

// An N×N texture of four quadrants: top-left, top-right, bottom-left, bottom-right.
QImage quadrants(int n, QColor tl, QColor tr, QColor bl, QColor br) {
    QImage img(n, n, QImage::Format_RGBA8888);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            img.setPixelColor(x, y, y < n / 2 ? (x < n / 2 ? tl : tr) : (x < n / 2 ? bl : br));
    return img;
}

// A plane showing only its emissive texture (black base colour, no lights): radiance = the texel, linear.
std::shared_ptr<Model> emissivePlane(const QImage& texture) {
    auto m = std::make_shared<Model>(makePlane(1.0));
    m->textures.push_back({QStringLiteral("*0"), texture});
    Material& mat = m->materials[0];
    mat.baseColor = {0.0f, 0.0f, 0.0f, 1.0f};
    mat.emissive = {1.0f, 1.0f, 1.0f};
    mat.emissiveTexture = 0;
    return m;
}

// A square of half size `half` at height z, facing +Z, with its own material.
Mesh square(double half, double z, int material) {
    Mesh mesh = makePlane(half).meshes.front();
    for (Vertex& v : mesh.vertices)
        v.position.z = float(z);
    mesh.material = material;
    return mesh;
}

Material emissiveMaterial(glm::vec3 colour, float alpha, AlphaMode mode) {
    Material m;
    m.baseColor = {0.0f, 0.0f, 0.0f, alpha};
    m.emissive = colour;
    m.alphaMode = mode;
    return m;
}

bool near(glm::vec4 a, glm::vec4 b, float tol = 1e-5f) {
    for (int k = 0; k < 4; ++k)
        if (!(std::abs(a[k] - b[k]) <= tol)) return false;
    return true;
}

QString str(glm::vec4 v) {
    return QStringLiteral("(%1, %2, %3, %4)").arg(v.r).arg(v.g).arg(v.b).arg(v.a);
}

} // namespace

class TestMaterials : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;

    FloatImage radiance(std::shared_ptr<const Model> model, const Rig& rig, const RenderSettings& s,
                        const ViewCamera& cam = straightCamera()) {
        QString error;
        FloatImage out;
        if (!m_gl.setModel(std::move(model), &error)) qFatal("%s", qPrintable(error));
        m_gl.setRig(rig);
        if (!m_gl.renderRadiance(cam, QSize(kSize, kSize), s, &out, &error)) qFatal("%s", qPrintable(error));
        return out;
    }

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
    }

    // Feature bits: only what a material uses compiles; identity transforms and OPAQUE compile nothing.
    void featureBitsFollowTheMaterial() {
        Model m = makePlane(1.0);
        m.textures.push_back({QStringLiteral("*0"), quadrants(4, Qt::red, Qt::green, Qt::blue, Qt::white)});
        Material& mat = m.materials[0];
        mat.baseColorTexture = 0;
        const FeatureKey plain{{}, materialFeatures(m, m.meshes[0])};
        QVERIFY(!plain.material.textureTransform && !plain.material.alphaMask && !plain.material.alphaBlend);
        const QByteArray prelude = shaderPrelude(plain);
        QVERIFY(!prelude.contains("LR_TEXTURE_TRANSFORM") && !prelude.contains("LR_ALPHA"));
        mat.normalTransform.offset = {0.5f, 0.0f}; // a role without a texture: nothing
        QVERIFY(!materialFeatures(m, m.meshes[0]).textureTransform);
        mat.baseColorTransform.rotation = 0.1f;
        FeatureKey k{{}, materialFeatures(m, m.meshes[0])};
        QVERIFY(k.material.textureTransform);
        QVERIFY(shaderPrelude(k).contains("#define LR_TEXTURE_TRANSFORM 1"));
        QVERIFY(k.bits() != plain.bits());
        mat.alphaMode = AlphaMode::Mask;
        k.material = materialFeatures(m, m.meshes[0]);
        QVERIFY(k.material.alphaMask && !k.material.alphaBlend);
        QVERIFY(shaderPrelude(k).contains("#define LR_ALPHA_MASK 1"));
        mat.alphaMode = AlphaMode::Blend;
        k.material = materialFeatures(m, m.meshes[0]);
        QVERIFY(!k.material.alphaMask && k.material.alphaBlend);
        QVERIFY(shaderPrelude(k).contains("#define LR_ALPHA_BLEND 1"));
    }

    // KHR_texture_transform's matrix against the extension's own example: offset (0, 1), rotation 90°,
    // scale ½ uses "only the lower left quadrant of the source image, rotated clockwise 90°".
    void transformMatrixFollowsTheExtension() {
        TextureTransform t;
        QCOMPARE(textureTransformMatrix(t), glm::mat3(1.0f));
        t.offset = {0.0f, 1.0f};
        t.rotation = float(M_PI / 2);
        t.scale = {0.5f, 0.5f};
        const glm::mat3 m = textureTransformMatrix(t);
        const auto apply = [&](float u, float v) { return glm::vec2(m * glm::vec3(u, v, 1.0f)); };
        const auto close = [](glm::vec2 a, glm::vec2 b) { return glm::length(a - b) < 1e-6f; };
        QVERIFY(close(apply(0, 0), {0.0f, 1.0f})); // the origin goes to the bottom-left corner
        QVERIFY(close(apply(1, 0), {0.0f, 0.5f})); // +u goes up the image (v down)
        QVERIFY(close(apply(0, 1), {0.5f, 1.0f})); // +v goes right
        QVERIFY(close(apply(1, 1), {0.5f, 0.5f})); // the image's centre
    }

    // glTF normalTexture.scale: 0 flattens the map to the vertex normal, 1 is today's map.
    void normalScaleZeroEqualsNoNormalMap() {
        const Rig rig = rigCases()[0].make();
        auto base = planeScene();
        auto flat = std::make_shared<Model>(*base);
        QImage normals(4, 4, QImage::Format_RGBA8888);
        normals.fill(QColor(200, 90, 210)); // tilted towards +X and -Y
        auto mapped = [&](float scale) {
            auto m = std::make_shared<Model>(*base);
            m->textures.push_back({QStringLiteral("*n"), normals});
            m->materials[0].normalTexture = 0;
            m->materials[0].normalScale = scale;
            return m;
        };
        const FloatImage none = radiance(flat, rig, floatSettings());
        const FloatImage zero = radiance(mapped(0.0f), rig, floatSettings());
        const FloatImage half = radiance(mapped(0.5f), rig, floatSettings());
        const FloatImage one = radiance(mapped(1.0f), rig, floatSettings());
        QVERIFY2(maxRelativeDifference(none, zero) <= 1e-5,
                 qPrintable(QString::number(maxRelativeDifference(none, zero))));
        QVERIFY(maxRelativeDifference(none, one) > 0.02); // the map does tilt the normal
        QVERIFY(maxRelativeDifference(half, one) > 0.005);
        QVERIFY(maxRelativeDifference(half, none) > 0.005);
    }

    // Offset (½, 0) with REPEAT: a texture of a red left half and a blue right half shows swapped halves.
    void transformOffsetShiftsByHalf() {
        const QImage two = quadrants(8, Qt::red, Qt::blue, Qt::red, Qt::blue);
        auto plain = emissivePlane(two);
        auto shifted = std::make_shared<Model>(*plain);
        shifted->materials[0].emissiveTransform.offset = {0.5f, 0.0f};
        const FloatImage a = radiance(plain, Rig(), floatSettings());
        const FloatImage b = radiance(shifted, Rig(), floatSettings());
        int checked = 0;
        for (double v : {0.1, 0.5, 0.9}) {
            for (double u : {0.1, 0.2, 0.3, 0.4}) {
                const QPoint p = pixelAt(u, v), q = pixelAt(u + 0.5, v);
                QVERIFY2(a.at(p.x(), p.y()).r > 0.9f && a.at(q.x(), q.y()).b > 0.9f, "left red, right blue");
                QVERIFY2(near(b.at(p.x(), p.y()), a.at(q.x(), q.y())), qPrintable(str(b.at(p.x(), p.y()))));
                QVERIFY2(near(b.at(q.x(), q.y()), a.at(p.x(), p.y())), qPrintable(str(b.at(q.x(), q.y()))));
                checked += 2;
            }
        }
        QCOMPARE(checked, 24);
    }

    // Rotation 90°: uv (u, v) samples (v, −u), i.e. (v, 1 − u) with REPEAT: the top-left quadrant of the
    // plane shows the texture's bottom-left quadrant, the top-right its top-left, and so on.
    void transformRotationMapsAKnownTexel() {
        const QColor tl(255, 0, 0), tr(0, 255, 0), bl(0, 0, 255), br(255, 255, 255);
        auto plain = emissivePlane(quadrants(8, tl, tr, bl, br));
        auto rotated = std::make_shared<Model>(*plain);
        rotated->materials[0].emissiveTransform.rotation = float(M_PI / 2);
        const FloatImage a = radiance(plain, Rig(), floatSettings());
        const FloatImage b = radiance(rotated, Rig(), floatSettings());
        const auto at = [](const FloatImage& img, double u, double v) {
            const QPoint p = pixelAt(u, v);
            return img.at(p.x(), p.y());
        };
        // Texel colours as the unrotated render shows them.
        const glm::vec4 red = at(a, 0.25, 0.25), green = at(a, 0.75, 0.25), blue = at(a, 0.25, 0.75),
                        white = at(a, 0.75, 0.75);
        QVERIFY(red.r > 0.9f && red.g < 0.1f && blue.b > 0.9f && blue.r < 0.1f && white.g > 0.9f);
        QVERIFY2(near(at(b, 0.25, 0.25), blue), qPrintable(str(at(b, 0.25, 0.25))));
        QVERIFY2(near(at(b, 0.75, 0.25), red), qPrintable(str(at(b, 0.75, 0.25))));
        QVERIFY2(near(at(b, 0.25, 0.75), white), qPrintable(str(at(b, 0.25, 0.75))));
        QVERIFY2(near(at(b, 0.75, 0.75), green), qPrintable(str(at(b, 0.75, 0.75))));
        // The same through the base colour and the normal roles' uniforms: a transform on another role
        // leaves the emissive texture where it was.
        auto other = std::make_shared<Model>(*plain);
        other->materials[0].baseColorTexture = 0; // black factor: contributes nothing, but compiles the bit
        other->materials[0].baseColorTransform.rotation = float(M_PI / 2);
        QVERIFY(materialFeatures(*other, other->meshes[0]).textureTransform);
        QVERIFY(maxRelativeDifference(radiance(other, Rig(), floatSettings()), a) <= 1e-6);
    }

    // The glTF sampler's wrap modes (issue 42): scale 2 along u reads u' = 2u, beyond the image on the
    // plane's right half. Left red, right blue: REPEAT shows red then blue again, CLAMP_TO_EDGE the right
    // edge's blue, MIRRORED_REPEAT blue then red. In every tier (the fast one filters with its own sampler)
    // and through the traced tier's sampler (tests/trace/tst_trace_texture.cpp) alike.
    void wrapModesFollowTheSampler_data() {
        QTest::addColumn<int>("wrap");
        QTest::addColumn<int>("quality");
        for (Quality q : {Quality::Exact, Quality::Fast}) {
            QTest::addRow("repeat, %s", qPrintable(toString(q))) << int(TextureWrap::Repeat) << int(q);
            QTest::addRow("clamp, %s", qPrintable(toString(q))) << int(TextureWrap::ClampToEdge) << int(q);
            QTest::addRow("mirror, %s", qPrintable(toString(q)))
                << int(TextureWrap::MirroredRepeat) << int(q);
        }
    }
    void wrapModesFollowTheSampler() {
        QFETCH(int, wrap);
        QFETCH(int, quality);
        auto m = emissivePlane(quadrants(8, Qt::red, Qt::blue, Qt::red, Qt::blue));
        m->materials[0].emissiveTransform.scale = {2.0f, 1.0f};
        m->materials[0].emissiveSampling.wrapS = TextureWrap(wrap);
        RenderSettings s = floatSettings();
        s.quality = Quality(quality);
        const FloatImage img = radiance(m, Rig(), s);
        const auto isRed = [&](double u) {
            const glm::vec4 c = img.at(pixelAt(u, 0.5).x(), pixelAt(u, 0.5).y());
            return c.r > 0.9f && c.b < 0.1f;
        };
        const auto isBlue = [&](double u) {
            const glm::vec4 c = img.at(pixelAt(u, 0.5).x(), pixelAt(u, 0.5).y());
            return c.b > 0.9f && c.r < 0.1f;
        };
        QVERIFY(isRed(0.1) && isBlue(0.4)); // inside the image every mode agrees
        switch (TextureWrap(wrap)) {
        case TextureWrap::Repeat:
            QVERIFY(isRed(0.6) && isBlue(0.9));
            break;
        case TextureWrap::ClampToEdge:
            QVERIFY(isBlue(0.6) && isBlue(0.9));
            break;
        case TextureWrap::MirroredRepeat:
            QVERIFY(isBlue(0.6) && isRed(0.9));
            break;
        }
    }

    // A NEAREST magnification filter keeps a 2×2 texture's texels hard: no pixel blends two of them.
    void nearestMagnificationKeepsTexelsHard() {
        auto smooth = emissivePlane(quadrants(2, Qt::red, Qt::blue, Qt::red, Qt::blue));
        auto hard = std::make_shared<Model>(*smooth);
        hard->materials[0].emissiveSampling.nearestMagnification = true;
        const FloatImage a = radiance(smooth, Rig(), floatSettings());
        const FloatImage b = radiance(hard, Rig(), floatSettings());
        int blended = 0, hardBlended = 0;
        for (int x = 0; x < kSize; ++x) {
            const glm::vec4 ca = a.at(x, kSize / 2), cb = b.at(x, kSize / 2);
            blended += ca.r > 0.05f && ca.b > 0.05f;
            hardBlended += cb.r > 0.05f && cb.b > 0.05f;
            QVERIFY2(near(cb, x < kSize / 2 ? glm::vec4(1, 0, 0, cb.a) : glm::vec4(0, 0, 1, cb.a), 1e-3f),
                     qPrintable(QStringLiteral("x %1: %2").arg(x).arg(str(cb))));
        }
        QVERIFY2(blended > kSize / 4, "linear magnification blends the two texels across the plane");
        QCOMPARE(hardBlended, 0);
    }

    // OPAQUE ignores alpha: a base alpha of 0.3 draws exactly what alpha 1 draws, opaque.
    void opaqueIgnoresAlpha() {
        auto solid = planeScene();
        auto faint = std::make_shared<Model>(*solid);
        faint->materials[0].baseColor.a = 0.3f;
        const Rig rig = rigCases()[0].make();
        const FloatImage a = radiance(solid, rig, floatSettings());
        const FloatImage b = radiance(faint, rig, floatSettings());
        QCOMPARE(maxRelativeDifference(a, b), 0.0);
        QCOMPARE(b.at(kSize / 2, kSize / 2).a, 1.0f);
    }

    // MASK: base alpha = factor × texture × vertex colour; fragments under the cutoff are discarded in
    // the forward, deferred, G-buffer and fast paths alike.
    void maskDiscardsExactlyUnderTheCutoff_data() {
        QTest::addColumn<float>("factor");
        QTest::addColumn<float>("cutoff");
        QTest::newRow("factor 1, cutoff 0.5") << 1.0f << 0.5f;
        QTest::newRow("factor 0.5, cutoff 0.35") << 0.5f << 0.35f;
        QTest::newRow("cutoff 0: nothing discarded") << 1.0f << 0.0f;
    }

    void maskDiscardsExactlyUnderTheCutoff() {
        QFETCH(float, factor);
        QFETCH(float, cutoff);
        // Quadrant alphas 0.2, 0.4, 0.6, 0.8; 16 texels so quadrant centres are far from filtered edges.
        const int alphas[4] = {51, 102, 153, 204};
        const QImage tex = quadrants(16, QColor(255, 255, 255, alphas[0]), QColor(255, 255, 255, alphas[1]),
                                     QColor(255, 255, 255, alphas[2]), QColor(255, 255, 255, alphas[3]));
        auto m = emissivePlane(tex);
        m->materials[0].baseColorTexture = 0;
        m->materials[0].baseColor.a = factor;
        m->materials[0].alphaMode = AlphaMode::Mask;
        m->materials[0].alphaCutoff = cutoff;
        const FloatImage forward = radiance(m, Rig(), floatSettings());
        const FloatImage deferred = radiance(m, Rig(), floatSettings(ShadingPath::Deferred));
        QVERIFY(m_gl.renderer().stats().deferred);
        QString error;
        GBuffer g;
        QVERIFY2(m_gl.renderGBuffer(straightCamera(), QSize(kSize, kSize), floatSettings(), &g, &error),
                 qPrintable(error));
        RenderSettings fast;
        fast.quality = Quality::Fast;
        fast.transparentBackground = true;
        const QImage fastImage = m_gl.renderImage(straightCamera(), QSize(kSize, kSize), fast, 1, &error);
        QVERIFY2(!fastImage.isNull(), qPrintable(error));
        int kept = 0, discarded = 0;
        const double centres[2] = {0.25, 0.75};
        for (int q = 0; q < 4; ++q) {
            const bool keep = alphas[q] / 255.0f * factor >= cutoff;
            // Pixels within the quadrant's middle half: their texels are the quadrant's own.
            for (double du = -0.1; du <= 0.1; du += 0.05) {
                for (double dv = -0.1; dv <= 0.1; dv += 0.05) {
                    const QPoint p = pixelAt(centres[q % 2] + du, centres[q / 2] + dv);
                    const QString where =
                        QStringLiteral("quadrant %1 pixel (%2,%3)").arg(q).arg(p.x()).arg(p.y());
                    QVERIFY2(forward.at(p.x(), p.y()).a == (keep ? 1.0f : 0.0f), qPrintable(where));
                    QVERIFY2(deferred.at(p.x(), p.y()).a == (keep ? 1.0f : 0.0f), qPrintable(where));
                    QVERIFY2((g.position.at(p.x(), p.y()).w > 0.5f) == keep, qPrintable(where));
                    QVERIFY2((qAlpha(fastImage.pixel(p)) == 255) == keep, qPrintable(where));
                    QVERIFY2(qAlpha(fastImage.pixel(p)) == 255 || qAlpha(fastImage.pixel(p)) == 0,
                             qPrintable(where));
                    keep ? ++kept : ++discarded;
                }
            }
        }
        QVERIFY(kept > 0);
        QCOMPARE(discarded > 0, cutoff > 0.0f);
    }

    // BLEND: a 50 % red square in front of an opaque green plane composites "over" it (linear radiance on
    // the HDR path, display colours on the 8-bit path), forward and deferred alike, whatever the meshes'
    // order; the G-buffer read-back holds only the opaque plane.
    void blendCompositesOverOpaque_data() {
        QTest::addColumn<bool>("deferred");
        QTest::addColumn<bool>("blendedFirst");
        QTest::newRow("forward") << false << false;
        QTest::newRow("forward, blended mesh first") << false << true;
        QTest::newRow("deferred") << true << false;
        QTest::newRow("deferred, blended mesh first") << true << true;
    }

    void blendCompositesOverOpaque() {
        QFETCH(bool, deferred);
        QFETCH(bool, blendedFirst);
        auto m = std::make_shared<Model>(makePlane(1.0));
        m->materials = {emissiveMaterial({0, 1, 0}, 1.0f, AlphaMode::Opaque),
                        emissiveMaterial({1, 0, 0}, 0.5f, AlphaMode::Blend)};
        m->meshes = {square(1.0, 0.0, 0), square(0.25, 0.5, 1)};
        if (blendedFirst) std::swap(m->meshes[0], m->meshes[1]);
        m->bounds.max.z = 0.5;
        const RenderSettings s = floatSettings(deferred ? ShadingPath::Deferred : ShadingPath::Forward);
        const FloatImage img = radiance(m, Rig(), s);
        QCOMPARE(m_gl.renderer().stats().deferred, deferred);
        QVERIFY2(m_gl.renderer().renderPlan().contains(QLatin1String("blend")),
                 qPrintable(m_gl.renderer().renderPlan()));
        const glm::vec4 centre = img.at(kSize / 2, kSize / 2), corner = img.at(2, 2);
        QVERIFY2(near(centre, {0.5f, 0.5f, 0.0f, 1.0f}), qPrintable(str(centre)));
        QVERIFY2(near(corner, {0.0f, 1.0f, 0.0f, 1.0f}), qPrintable(str(corner)));
        // The 8-bit display path blends the display colours (as three.js does): 50 % of 255 each.
        RenderSettings d = s;
        d.hdrFloat32 = false;
        QString error;
        const QImage display = m_gl.renderImage(straightCamera(), QSize(kSize, kSize), d, 1, &error);
        QVERIFY2(!display.isNull(), qPrintable(error));
        const QColor c = display.pixelColor(kSize / 2, kSize / 2);
        QVERIFY2(std::abs(c.red() - 128) <= 1 && std::abs(c.green() - 128) <= 1 && c.blue() == 0,
                 qPrintable(c.name()));
        QCOMPARE(display.pixelColor(2, 2), QColor(0, 255, 0));
        if (!deferred) { // the fast tier (vertex-lit) blends the same way
            RenderSettings fast = d;
            fast.quality = Quality::Fast;
            const QImage f = m_gl.renderImage(straightCamera(), QSize(kSize, kSize), fast, 1, &error);
            QVERIFY2(!f.isNull(), qPrintable(error));
            QCOMPARE(f.pixelColor(kSize / 2, kSize / 2), c);
        }
        if (!deferred) { // multisampled: the blend pass draws into the MSAA target before the resolve
            d.msaaSamples = 4;
            const QImage msaa = m_gl.renderImage(straightCamera(), QSize(kSize, kSize), d, 1, &error);
            QVERIFY2(!msaa.isNull(), qPrintable(error));
            const QColor cm = msaa.pixelColor(kSize / 2, kSize / 2);
            QVERIFY2(std::abs(cm.red() - c.red()) <= 1 && std::abs(cm.green() - c.green()) <= 1 &&
                         cm.blue() == 0,
                     qPrintable(cm.name()));
        }
        // The G-buffer (the CPU reference's input) holds the opaque surfaces only.
        GBuffer g;
        QVERIFY(m_gl.renderGBuffer(straightCamera(), QSize(kSize, kSize), s, &g, &error));
        QVERIFY(near(g.emissive.at(kSize / 2, kSize / 2),
                     {0.0f, 1.0f, 0.0f, g.emissive.at(kSize / 2, kSize / 2).a}));
    }

    // Two blended squares over the plane: drawn back to front whatever the meshes' order, so the nearer
    // red one is over the blue one: 0.5·red + 0.25·blue + 0.25·green.
    void blendOrderIsBackToFront() {
        std::vector<FloatImage> images;
        for (int order = 0; order < 2; ++order) {
            auto m = std::make_shared<Model>(makePlane(1.0));
            m->materials = {emissiveMaterial({0, 1, 0}, 1.0f, AlphaMode::Opaque),
                            emissiveMaterial({1, 0, 0}, 0.5f, AlphaMode::Blend),
                            emissiveMaterial({0, 0, 1}, 0.5f, AlphaMode::Blend)};
            m->meshes = {square(1.0, 0.0, 0), square(0.25, 0.5, 1), square(0.25, 0.25, 2)};
            if (order) std::swap(m->meshes[1], m->meshes[2]);
            m->bounds.max.z = 0.5;
            images.push_back(radiance(m, Rig(), floatSettings()));
        }
        const glm::vec4 centre = images[0].at(kSize / 2, kSize / 2);
        QVERIFY2(near(centre, {0.5f, 0.25f, 0.25f, 1.0f}), qPrintable(str(centre)));
        QCOMPARE(maxRelativeDifference(images[0], images[1]), 0.0);
    }

    // glTF: single-sided back faces are culled; double-sided ones are lit with the flipped normal, as the
    // front is when seen and lit from the front.
    void doubleSidedBackFacesAreLitSingleSidedCulled() {
        auto m = planeScene();
        m->materials[0].emissive = {0.0f, 0.0f, 0.0f};
        Light front = makeLight(LightType::Directional, QStringLiteral("front"));
        front.direction = {0.0, 0.0, -1.0};
        Light back = front;
        back.direction = {0.0, 0.0, 1.0};
        const FloatImage seenFront = radiance(m, rigOf({front}), floatSettings(), straightCamera(2.0));
        const FloatImage culled = radiance(m, rigOf({back}), floatSettings(), straightCamera(-2.0));
        QCOMPARE(culled.at(kSize / 2, kSize / 2).a, 0.0f);
        m->materials[0].doubleSided = true;
        const FloatImage seenBack = radiance(m, rigOf({back}), floatSettings(), straightCamera(-2.0));
        const glm::vec4 f = seenFront.at(kSize / 2, kSize / 2), b = seenBack.at(kSize / 2, kSize / 2);
        QVERIFY2(f.r > 0.2f, qPrintable(str(f)));
        QVERIFY2(near(f, b, 1e-4f), qPrintable(str(f) + QStringLiteral(" vs ") + str(b)));
    }

    // The plans with a blend pass: after the surfaces (forward or deferred), before resolve and output.
    void blendPassSitsAfterTheSurfaces() {
        RenderPlan plan;
        for (int bits = 0; bits < 32; ++bits) {
            const PlanKey key{unsigned(bits)}; // deferred, hdr, msaa, overlays, blend: PlanBit's first five
            const auto& passes = plan.select(key);
            QVERIFY2(RenderPlan::check(passes, key.has(PlanBit::Msaa)).isEmpty(),
                     qPrintable(plan.describe()));
            QCOMPARE(plan.describe().contains(QLatin1String("blend")), key.has(PlanBit::Blend));
            if (key.has(PlanBit::Blend)) {
                const QString expected = key.has(PlanBit::Deferred)
                                             ? QStringLiteral("deferred lighting > blend")
                                             : QStringLiteral("geometry (shaded) > blend");
                QVERIFY2(plan.describe().contains(expected), qPrintable(plan.describe()));
            }
        }
        BlendPass blend;
        QVERIFY(RenderPlan::check({&blend}, false).contains(QLatin1String("blend reads")));
    }
};

LR_GL_TEST_MAIN(TestMaterials)
#include "tst_materials.moc"
