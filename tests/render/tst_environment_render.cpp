// Environment lighting on the GPU (issue 15; shaders/environment.glsl, src/render/environmentgl.h), on
// environments whose answer is known in closed form (environmentfixture.h): a uniform environment (the
// placeholder prefilter's SH9, irradiance map and point-sampled chain are all exact for it) and the
// procedural studio's softbox. Checked: the furnace (a white Lambertian sphere shows its albedo; physically
// based, the glTF BRDF's own directional albedo from a brute-force quadrature) in every tier and both paths;
// the classic Phong / Blinn-Phong lobes' integrals; rotation moves a mirror's highlight as core's mapping
// says; an environment still loading; and the programs' text without an environment. The background
// (pass_background.cpp): tst_environment_background.
#include "environmentfixture.h"
#include "glfixture.h"
#include "scenes.h"
#include "shadowscenes.h"

#include "core/envbrdf.h"
#include "render/offscreen.h"
#include "render/programcache.h"
#include "render/renderplan.h"
#include "render/shadergen.h"
#include "scene/environmentloader.h"
#include "scene/envprefilter.h"

#include <QTest>
#include <QThread>
#include <QtConcurrent/QtConcurrentRun>
#include <cmath>

using namespace lr;
using namespace lr::render;
using namespace lr::test;

namespace {

// n·v at pixel (x, y) (image order) of the unit sphere at the origin; < 0 where the pixel's ray misses it.
double sphereNDotV(const Renderer& r, const ViewCamera& cam, int x, int y) {
    const ViewCamera c = r.effectiveCamera(cam);
    const glm::dmat4 inv = glm::inverse(c.projection(double(kSize.width()) / kSize.height()) * c.view());
    const double nx = (x + 0.5) / kSize.width() * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / kSize.height() * 2.0;
    const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0), b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
    const glm::dvec3 p0 = glm::dvec3(a) / a.w, d = glm::normalize(glm::dvec3(b) / b.w - p0);
    const double half = glm::dot(p0, d), disc = half * half - (glm::dot(p0, p0) - 1.0);
    if (!(disc > 0.0)) return -1.0;
    const glm::dvec3 p = p0 + (-half - std::sqrt(disc)) * d;
    return glm::dot(glm::normalize(p), glm::normalize(c.eye - p));
}

} // namespace

class TestEnvironmentRender : public QObject, protected EnvironmentFixture {
    Q_OBJECT
    glm::vec4 at(const FloatImage& f, glm::dvec3 world, const ViewCamera& cam) {
        const auto px = projectToPixel(m_gl->renderer(), cam, kSize, world);
        return px ? f.at(px->x(), px->y()) : glm::vec4(-1.0f);
    }

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        m_gl = std::make_unique<OffscreenRenderer>();
        QString error;
        if (!m_gl->initialize(&error)) qFatal("%s", qPrintable(error));
    }

    void furnace_data() {
        QTest::addColumn<int>("shading");
        QTest::addColumn<int>("quality");
        QTest::addColumn<int>("path");
        for (ShadingModel m : {ShadingModel::Classic, ShadingModel::Pbr})
            for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast})
                for (ShadingPath p : {ShadingPath::Forward, ShadingPath::Deferred}) {
                    if (q == Quality::Fast && p == ShadingPath::Deferred) continue; // fast is forward only
                    QTest::addRow("%s %s %s", toString(m).toLatin1().constData(),
                                  toString(q).toLatin1().constData(),
                                  p == ShadingPath::Forward ? "forward" : "deferred")
                        << int(m) << int(q) << int(p);
                }
    }

    // A white sphere in a uniform environment of radiance 1. Classic Lambert: exactly its albedo, 1
    // (tolerance 1 %: half floats, the SH9's quadrature). Physically based (metallic 0, roughness 1): the
    // glTF BRDF's directional albedo (1 − F0)·W + F0·A + B at the pixel's n·v, which the split sum
    // reproduces exactly in a uniform environment: compared with a brute-force quadrature of the BRDF
    // (core/envbrdf.h quadrature) within 0.5 % where n·v > 0.2 (nearer the silhouette the faceted sphere's
    // normals and the pixel's n·v part); everywhere within 5 % of the albedo (0.972 at normal incidence,
    // up to 1.018 at grazing: the glTF BRDF is not energy-conserving).
    void furnace() {
        QFETCH(int, shading);
        QFETCH(int, quality);
        QFETCH(int, path);
        const auto model = ShadingModel(shading);
        QVERIFY(m_gl->setModel(whiteSphere()));
        m_gl->renderer().setEnvironment(uniformEnvironment(glm::vec3(1.0f)));
        const ViewCamera cam = frontCamera();
        const FloatImage f =
            radiance(environmentRig(model), cam, settingsFor(Quality(quality), ShadingPath(path)));
        QVERIFY(!f.pixels.empty());
        std::vector<double> table; // the definition's value at n·v = i / 32
        for (int i = 0; i <= 32; ++i) {
            const envbrdf::Dfg q = envbrdf::quadrature(std::max(i / 32.0, 1e-3), 1.0, 100);
            table.push_back(model == ShadingModel::Pbr ? 0.96 * q.diffuse + 0.04 * q.scale + q.bias : 1.0);
        }
        int covered = 0, compared = 0;
        double worst = 0.0;
        for (int y = 0; y < f.height; ++y)
            for (int x = 0; x < f.width; ++x) {
                const glm::vec4 p = f.at(x, y);
                if (p.a < 0.5f) continue; // background (Color: nothing drawn)
                ++covered;
                for (int c = 0; c < 3; ++c)
                    QVERIFY2(std::abs(p[c] - 1.0f) <= (model == ShadingModel::Pbr ? 0.05f : 0.01f),
                             qPrintable(QStringLiteral("pixel (%1, %2) channel %3 = %4")
                                            .arg(x)
                                            .arg(y)
                                            .arg(c)
                                            .arg(double(p[c]))));
                const double nv = sphereNDotV(m_gl->renderer(), cam, x, y);
                if (nv < 0.2) continue;
                const double t = nv * 32.0;
                const int i = std::min(int(t), 31);
                const double expected =
                    table[size_t(i)] + (t - i) * (table[size_t(i) + 1] - table[size_t(i)]);
                worst = std::max(worst, std::abs(p.g - expected) / expected);
                ++compared;
            }
        QVERIFY(covered > 1000 && compared > 500);
        qInfo("furnace: %d pixels compared with the quadrature, worst relative error %.4f", compared, worst);
        QVERIFY2(worst < 0.005, qPrintable(QStringLiteral("worst relative error %1").arg(worst)));
    }

    // Classic specular in a uniform environment of 1, seen head on (v = n = r): Phong ks·2/(n + 1),
    // Blinn-Phong ks·8/(n + 2)·(1 − 2^−(n+2)/2): the definition's integrals, here checked against a
    // quadrature of ∫_{n·ω>0} (lobe) dω / π written in the test.
    void classicSpecularLobes_data() {
        QTest::addColumn<int>("specular");
        QTest::addColumn<double>("shininess");
        for (SpecularModel m : {SpecularModel::Phong, SpecularModel::BlinnPhong})
            for (double n : {4.0, 32.0})
                QTest::addRow("%s %g", toString(m).toLatin1().constData(), n) << int(m) << n;
    }

    void classicSpecularLobes() {
        QFETCH(int, specular);
        QFETCH(double, shininess);
        auto sphere = whiteSphere(glm::vec3(1.0f), float(shininess));
        sphere->materials[0].baseColor = {0.0f, 0.0f, 0.0f, 1.0f};
        QVERIFY(m_gl->setModel(sphere));
        m_gl->renderer().setEnvironment(uniformEnvironment(glm::vec3(1.0f)));
        Rig rig = environmentRig(ShadingModel::Classic);
        rig.shading.specular = SpecularModel(specular);
        const ViewCamera cam = frontCamera();
        // ∫ over the hemisphere about n = v = +z of (r·ω)^n (Phong, r = n) or (n·h)^n (Blinn-Phong) / π.
        double integral = 0.0;
        const int steps = 2000;
        for (int i = 0; i < steps; ++i) {
            const double t = (i + 0.5) * (std::acos(-1.0) / 2) / steps, c = std::cos(t);
            const double lobe = SpecularModel(specular) == SpecularModel::Phong
                                    ? std::pow(c, shininess)
                                    : std::pow(std::cos(t / 2), shininess);
            integral += lobe * std::sin(t) * (std::acos(-1.0) / 2 / steps) * 2.0; // 2π / π
        }
        const FloatImage f = radiance(rig, cam, settingsFor(Quality::Exact));
        const glm::vec4 centre = at(f, {0.0, 0.0, 1.0}, cam);
        QVERIFY2(std::abs(centre.g - integral) < 0.01 * integral + 2e-3,
                 qPrintable(QStringLiteral("centre %1, integral %2").arg(double(centre.g)).arg(integral)));
    }

    // The same on a surface: a mirror sphere (metallic 1, roughness 0) reflects the softbox placed on the
    // camera's axis at its centre; turned 90°, the highlight leaves the centre for the point whose
    // reflection vector is the turned direction.
    void rotationMovesHighlight() {
        Studio studio = oneSoftbox(0.0, 0.0, 30.0, 10.0); // +Z: behind the camera, which looks along −Z
        studio.zenith = studio.horizon = studio.floor = glm::dvec3(0.02);
        auto mirror = whiteSphere();
        mirror->materials[0].metallic = 1.0f;
        mirror->materials[0].roughness = 0.0f;
        QVERIFY(m_gl->setModel(mirror));
        m_gl->renderer().setEnvironment(loaded(environment::renderStudio(studio, 256)));
        Rig rig = environmentRig(ShadingModel::Pbr);
        const ViewCamera cam = frontCamera();
        RenderSettings s = settingsFor(Quality::Exact);
        const glm::dvec3 turned = environment::rotateAboutUp(environment::softboxDirection(0.0, 0.0), 90.0);
        // The sphere point reflecting `turned` towards the eye: n = normalize(v + d), solved by iteration.
        glm::dvec3 n(0.0, 0.0, 1.0);
        for (int i = 0; i < 20; ++i)
            n = glm::normalize(glm::normalize(cam.eye - n) + turned);
        const FloatImage before = radiance(rig, cam, s);
        rig.environment.rotation = 90.0;
        const FloatImage after = radiance(rig, cam, s);
        const glm::dvec3 centre(0.0, 0.0, 1.0);
        QVERIFY2(at(before, centre, cam).g > 3.0f,
                 qPrintable(QString::number(double(at(before, centre, cam).g))));
        QVERIFY(at(before, n, cam).g < 0.5f);
        QVERIFY(at(after, centre, cam).g < 0.5f);
        QVERIFY2(at(after, n, cam).g > 3.0f, qPrintable(QString::number(double(at(after, n, cam).g))));
    }

    // An environment still loading (Renderer::setEnvironment with a future, as the command line gives it
    // after the model's upload): the frame is the one the loaded environment gives, byte for byte, on
    // both paths; the G-pass runs before anything waits for it (the first pass reading it is the
    // background or the lighting). A load that fails fails that frame with its error; the next frame
    // has no environment.
    void loadingEnvironment() {
        const auto sky = loaded(environment::renderStudio(oneSoftbox(30.0, 20.0, 40.0, 8.0), 128));
        const Rig rig = environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible);
        QVERIFY(m_gl->setModel(whiteSphere(glm::vec3(0.04f))));
        const auto later = [](std::shared_ptr<const LoadedEnvironment> e, QString error) {
            return QtConcurrent::run([e, error] {
                QThread::msleep(50); // still loading when the frame starts
                EnvironmentLoadResult r;
                r.environment = e;
                r.error = error;
                return r;
            });
        };
        for (ShadingPath path : {ShadingPath::Forward, ShadingPath::Deferred}) {
            const RenderSettings s = settingsFor(Quality::Exact, path);
            m_gl->renderer().setEnvironment(sky);
            const QImage expected = image(rig, frontCamera(), s);
            QVERIFY(!expected.isNull());
            m_gl->setModel(whiteSphere(glm::vec3(0.04f))); // nothing kept from that frame
            m_gl->renderer().setEnvironment(later(sky, QString()));
            QVERIFY(m_gl->renderer().environment() == nullptr);
            const QImage got = image(rig, frontCamera(), s);
            QVERIFY(m_gl->renderer().environment() == sky);
            QCOMPARE(got, expected);

            m_gl->renderer().setEnvironment(
                later(nullptr, QStringLiteral("could not read sky.exr: truncated")));
            m_gl->setRig(rig);
            QString error;
            QVERIFY(m_gl->renderImage(frontCamera(), kSize, s, 1, &error).isNull());
            QVERIFY2(error.contains(QLatin1String("could not read sky.exr: truncated")), qPrintable(error));
            QVERIFY(m_gl->renderer().environment() == nullptr);
            const FloatImage dark = radiance(rig, frontCamera(), s); // no environment, no lights
            QVERIFY(!dark.pixels.empty());
            for (const glm::vec4& p : dark.pixels)
                QCOMPARE(p.g, 0.0f);
        }
        // Where the plan waits: never in the G-pass, first in the background or the lighting.
        RenderPlan plan;
        for (bool deferred : {false, true}) {
            PlanKey key;
            key.set(PlanBit::Deferred, deferred).set(PlanBit::Background);
            QString first;
            for (const RenderPass* p : plan.select(key))
                if ((p->reads() & resource::Environment) && first.isEmpty()) first = QLatin1String(p->name());
            QCOMPARE(first, deferred ? QStringLiteral("background") : QStringLiteral("geometry (shaded)"));
        }
        m_gl->renderer().setEnvironment(nullptr);
    }

    // Without an environment (source None, or nothing loaded) no program changes: no define, the
    // configurations without environment.glsl, no background pass; G-buffer and catcher programs never
    // carry it.
    void programTextWithoutEnvironment() {
        for (ShadingModel m : {ShadingModel::Classic, ShadingModel::Pbr})
            for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast})
                for (bool deferred : {false, true}) {
                    FeatureKey key;
                    key.rig = frameRigFeatures(environmentRig(m), false, false);
                    key.quality = q;
                    key.deferredLighting = deferred;
                    QVERIFY(!key.rig.environment);
                    QVERIFY(!shaderPrelude(key).contains("ENVIRONMENT"));
                    const ShaderConfig& plain = shaderConfig(key);
                    for (const char* file : plain.fragment)
                        QVERIFY(!file || QByteArray(file) != "environment.glsl");
                    FeatureKey lit = key;
                    lit.rig.environment = true;
                    QVERIFY(shaderPrelude(lit).contains("#define LR_ENVIRONMENT 1\n"));
                    QVERIFY(lit.bits() != key.bits());
                    // Only the define differs.
                    QByteArray text = shaderPrelude(lit);
                    text.replace("#define LR_ENVIRONMENT 1\n", "");
                    QCOMPARE(text, shaderPrelude(key));
                    FeatureKey gbuffer = lit;
                    gbuffer.output = ShaderOutput::GBuffer;
                    QVERIFY(!shaderPrelude(gbuffer).contains("ENVIRONMENT"));
                    FeatureKey catcher = lit;
                    catcher.material.shadowCatcher = true;
                    QVERIFY(!shaderPrelude(catcher).contains("ENVIRONMENT"));
                }
        // Rendering: a rig with no environment source ignores a loaded environment.
        QVERIFY(m_gl->setModel(whiteSphere()));
        m_gl->renderer().setEnvironment(uniformEnvironment(glm::vec3(1.0f)));
        Rig none = environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible);
        none.environment.source = EnvironmentSource::None;
        const FloatImage f = radiance(none, frontCamera(), settingsFor(Quality::Exact));
        QVERIFY(!m_gl->renderer().renderPlan().contains(QLatin1String("background")));
        for (const glm::vec4& p : f.pixels)
            QCOMPARE(p.g, 0.0f);
        m_gl->renderer().setEnvironment(nullptr);
    }
};

LR_GL_TEST_MAIN(TestEnvironmentRender)
#include "tst_environment_render.moc"
