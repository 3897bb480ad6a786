// Environment lighting on the GPU (issue 15; shaders/environment.glsl, src/render/environmentgl.h,
// pass_background.cpp), on environments whose answer is known in closed form: a uniform environment
// (the placeholder prefilter's SH9, irradiance map and point-sampled chain are all exact for it) and the
// procedural studio's softbox seen straight on. Checked: the furnace (a white Lambertian sphere shows its
// albedo; physically based, the glTF BRDF's own directional albedo from a brute-force quadrature) in every
// tier and both paths; the classic Phong / Blinn-Phong lobes' integrals; +1 EV doubles the radiance;
// rotation turns the environment as core's mapping says; the background modes and transparency; and the
// programs' text without an environment.
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

const QSize kSize(160, 120);

std::shared_ptr<const LoadedEnvironment> loaded(EnvironmentImage image) {
    auto e = std::make_shared<LoadedEnvironment>();
    e->spec.source = EnvironmentSource::Image;
    e->source = QStringLiteral("test");
    e->prefiltered = prefilterEnvironment(image);
    e->image = std::move(image);
    return e;
}

std::shared_ptr<const LoadedEnvironment> uniformEnvironment(glm::vec3 radiance) {
    EnvironmentImage image;
    image.width = 64;
    image.height = 32;
    image.texels.assign(size_t(64 * 32), radiance);
    return loaded(std::move(image));
}

// The procedural studio with one square softbox (size degrees of arc a side).
Studio oneSoftbox(double azimuth, double elevation, double size, double intensity) {
    Softbox box;
    box.azimuth = azimuth;
    box.elevation = elevation;
    box.width = box.height = size;
    box.intensity = intensity;
    Studio studio;
    studio.softboxes = {box};
    return studio;
}

Rig environmentRig(ShadingModel shading, EnvironmentBackground background = EnvironmentBackground::Color) {
    Rig r;
    r.shading.model = shading;
    r.ambient = glm::dvec3(0.0);
    r.environment.source = EnvironmentSource::Image;
    r.environment.background = background;
    return r;
}

// A white sphere: Lambertian (classic, ks 0) or metallic 0, roughness 1 (physically based).
std::shared_ptr<Model> whiteSphere(glm::vec3 specular = glm::vec3(0.0f), float shininess = 32.0f) {
    auto m = std::make_shared<Model>(makeSphere(1.0, 96, 48));
    m->materials[0].baseColor = {1.0f, 1.0f, 1.0f, 1.0f};
    m->materials[0].specular = specular;
    m->materials[0].shininess = shininess;
    m->materials[0].metallic = 0.0f;
    m->materials[0].roughness = 1.0f;
    return m;
}

ViewCamera frontCamera() {
    ViewCamera c;
    c.eye = {0.0, 0.0, 3.5};
    c.target = {0.0, 0.0, 0.0};
    c.yfovDeg = 45.0;
    return c;
}

RenderSettings settingsFor(Quality q, ShadingPath path = ShadingPath::Forward) {
    RenderSettings s;
    s.quality = q;
    s.msaaSamples = 0;
    s.shadingPath = path;
    return s;
}

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

double srgb(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

} // namespace

class TestEnvironmentRender : public QObject {
    Q_OBJECT
    std::unique_ptr<OffscreenRenderer> m_gl;

    FloatImage radiance(const Rig& rig, const ViewCamera& cam, const RenderSettings& s) {
        m_gl->setRig(rig);
        FloatImage out;
        QString error;
        if (!m_gl->renderRadiance(cam, kSize, s, &out, &error)) qWarning("%s", qPrintable(error));
        return out;
    }
    QImage image(const Rig& rig, const ViewCamera& cam, const RenderSettings& s) {
        m_gl->setRig(rig);
        QString error;
        QImage out = m_gl->renderImage(cam, kSize, s, 1, &error);
        if (out.isNull()) qWarning("%s", qPrintable(error));
        return out;
    }
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

    // +1 EV doubles every pixel's radiance: the lit sphere and the visible background alike.
    void intensityDoubles() {
        QVERIFY(m_gl->setModel(whiteSphere()));
        m_gl->renderer().setEnvironment(uniformEnvironment(glm::vec3(0.3f, 0.5f, 0.7f)));
        Rig rig = environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible);
        const ViewCamera cam = frontCamera();
        const FloatImage a = radiance(rig, cam, settingsFor(Quality::Balanced));
        rig.environment.intensity = 1.0;
        const FloatImage b = radiance(rig, cam, settingsFor(Quality::Balanced));
        QCOMPARE(a.pixels.size(), b.pixels.size());
        for (size_t i = 0; i < a.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c) {
                QVERIFY(a.pixels[i][c] > 0.05f);
                QVERIFY2(
                    std::abs(b.pixels[i][c] / a.pixels[i][c] - 2.0f) < 2e-3f,
                    qPrintable(
                        QStringLiteral("%1 -> %2").arg(double(a.pixels[i][c])).arg(double(b.pixels[i][c]))));
            }
    }

    // The background pass keeps the environment's image while nothing it depends on changes: frames with
    // the same view, environment, exposure and tone map render it once and are identical; each of those
    // changes renders it again (and a stale image would fail the checks of background() and
    // intensityDoubles(), which render one renderer in turn with different settings).
    void backgroundKept() {
        QVERIFY(m_gl->setModel(whiteSphere()));
        m_gl->renderer().setEnvironment(uniformEnvironment(glm::vec3(0.2f, 0.4f, 0.8f)));
        Rig rig = environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible);
        const ViewCamera cam = frontCamera();
        RenderSettings s = settingsFor(Quality::Balanced);
        const QImage first = image(rig, cam, s);
        const int builds = m_gl->renderer().stats().backgroundBuilds;
        QVERIFY(builds >= 1);
        const QImage second = image(rig, cam, s);
        QCOMPARE(m_gl->renderer().stats().backgroundBuilds, builds);
        QCOMPARE(second, first);
        // A light moved under the still camera: the background is not rendered again.
        rig.lights.push_back(Light());
        (void)image(rig, cam, s);
        QCOMPARE(m_gl->renderer().stats().backgroundBuilds, builds);
        rig.environment.rotation = 30.0;
        (void)image(rig, cam, s);
        QCOMPARE(m_gl->renderer().stats().backgroundBuilds, builds + 1);
        s.exposureEV = 1.0;
        const QImage brighter = image(rig, cam, s);
        QCOMPARE(m_gl->renderer().stats().backgroundBuilds, builds + 2);
        QVERIFY(brighter.pixelColor(2, 2).blue() > first.pixelColor(2, 2).blue());
        s.toneMap = ToneMap::Aces;
        (void)image(rig, cam, s);
        QCOMPARE(m_gl->renderer().stats().backgroundBuilds, builds + 3);
        (void)image(rig, frontCamera(), s);
        QCOMPARE(m_gl->renderer().stats().backgroundBuilds, builds + 3);
    }

    // On the deferred path the kept background is looked up only where the G-buffer's depth is the far
    // plane, and kept while that depth is: a model of the same bounds but a smaller silhouette under the
    // same view (the G-buffer drawn again) renders it again, and the pixels it uncovers show the
    // environment as the forward path (every pixel looked up) shows it.
    void backgroundKeptWithTheDepth() {
        const std::shared_ptr<Model> big = whiteSphere();
        auto small = std::make_shared<Model>(makeSphere(0.5, 48, 24));
        small->materials = big->materials;
        small->bounds = big->bounds; // the same clip planes
        m_gl->renderer().setEnvironment(uniformEnvironment(glm::vec3(0.2f, 0.4f, 0.8f)));
        const Rig rig = environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible);
        const ViewCamera cam = frontCamera();
        const RenderSettings deferred = settingsFor(Quality::Exact, ShadingPath::Deferred);
        const RenderStats& stats = m_gl->renderer().stats();
        QVERIFY(m_gl->setModel(big));
        (void)image(rig, cam, deferred);
        QVERIFY(stats.deferred);
        const int builds = stats.backgroundBuilds;
        (void)image(rig, cam, deferred);
        QVERIFY(stats.gbufferKept);
        QCOMPARE(stats.backgroundBuilds, builds);
        QVERIFY(m_gl->setModel(small));
        const QImage after = image(rig, cam, deferred);
        QVERIFY(!stats.gbufferKept);
        QCOMPARE(stats.backgroundBuilds, builds + 1);
        const QImage forward = image(rig, cam, settingsFor(Quality::Exact, ShadingPath::Forward));
        QVERIFY(!stats.deferred);
        const auto px = projectToPixel(m_gl->renderer(), cam, kSize, glm::dvec3(0.75, 0.0, 0.0));
        QVERIFY(px);
        const QColor a = after.pixelColor(*px), f = forward.pixelColor(*px);
        QVERIFY2(a == f && std::abs(a.blue() - srgb(0.8f) * 255.0) <= 1.0,
                 qPrintable(QStringLiteral("%1 against %2").arg(a.name(), f.name())));
    }

    // Background: Visible shows the environment in uncovered pixels, identical on the display and HDR
    // paths; Blurred too (a uniform environment blurs to itself); Color shows the settings' colour;
    // a transparent image keeps alpha 0 there whatever the mode. The plan has the pass only when it draws.
    void background() {
        QVERIFY(m_gl->setModel(whiteSphere()));
        const glm::vec3 sky(0.2f, 0.4f, 0.8f);
        m_gl->renderer().setEnvironment(uniformEnvironment(sky));
        const ViewCamera cam = frontCamera();
        RenderSettings s = settingsFor(Quality::Balanced);
        for (EnvironmentBackground mode : {EnvironmentBackground::Visible, EnvironmentBackground::Blurred}) {
            const Rig rig = environmentRig(ShadingModel::Pbr, mode);
            for (bool hdr : {false, true}) {
                s.hdrTarget = hdr;
                const QImage img = image(rig, cam, s);
                QVERIFY(!img.isNull());
                QVERIFY(m_gl->renderer().renderPlan().contains(QLatin1String("background")));
                const QColor corner = img.pixelColor(2, 2);
                QCOMPARE(corner.alpha(), 255);
                for (const auto& [got, want] : std::initializer_list<std::pair<int, float>>{
                         {corner.red(), sky.r}, {corner.green(), sky.g}, {corner.blue(), sky.b}})
                    QVERIFY2(
                        std::abs(got - srgb(want) * 255.0) <= 1.0,
                        qPrintable(
                            QStringLiteral("%1 vs %2 (hdr %3)").arg(got).arg(srgb(want) * 255.0).arg(hdr)));
            }
            s.hdrTarget = true;
            const FloatImage f = radiance(rig, cam, s);
            QVERIFY(std::abs(f.at(2, 2).b - sky.b) < 2e-3f);
        }
        s.hdrTarget = false;
        s.background = QColor(10, 20, 30);
        const QImage color = image(environmentRig(ShadingModel::Pbr, EnvironmentBackground::Color), cam, s);
        QVERIFY(!m_gl->renderer().renderPlan().contains(QLatin1String("background")));
        QCOMPARE(color.pixelColor(2, 2), QColor(10, 20, 30));
        s.transparentBackground = true;
        for (bool hdr : {false, true}) {
            s.hdrTarget = hdr;
            const QImage clear =
                image(environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible), cam, s);
            QCOMPARE(clear.pixelColor(2, 2).alpha(), 0);
            QCOMPARE(clear.pixelColor(kSize.width() / 2, kSize.height() / 2).alpha(), 255); // the sphere
        }
    }

    // The studio's softbox, seen straight on with no model: the centre pixel looks at it. Rotating the
    // environment by 90° moves it where core's rotateAboutUp says (and away from where it was).
    void rotationMovesSoftbox() {
        Studio studio = oneSoftbox(180.0, 10.0, 30.0, 10.0);
        studio.zenith = studio.horizon = studio.floor = glm::dvec3(0.05);
        const Softbox& box = studio.softboxes[0];
        m_gl->setModel(nullptr);
        m_gl->renderer().setEnvironment(loaded(environment::renderStudio(studio, 256)));
        Rig rig = environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible);
        const auto lookAlong = [](glm::dvec3 d) {
            ViewCamera c;
            c.eye = glm::dvec3(0.0);
            c.target = d;
            c.yfovDeg = 20.0;
            return c;
        };
        const glm::dvec3 boxDir = environment::softboxDirection(box.azimuth, box.elevation);
        const glm::dvec3 turned = environment::rotateAboutUp(boxDir, 90.0);
        RenderSettings s = settingsFor(Quality::Exact);
        s.hdrTarget = true;
        const auto centre = [&](const Rig& r, glm::dvec3 d) {
            return radiance(r, lookAlong(d), s).at(kSize.width() / 2, kSize.height() / 2).g;
        };
        QVERIFY2(centre(rig, boxDir) > 5.0f, qPrintable(QString::number(double(centre(rig, boxDir)))));
        QVERIFY(centre(rig, turned) < 0.1f);
        rig.environment.rotation = 90.0;
        QVERIFY(centre(rig, turned) > 5.0f);
        QVERIFY(centre(rig, boxDir) < 0.1f);
    }

    // Issue 41 item 14: the background and the studio's softboxes had stair-stepped edges. Magnified (about
    // five pixels per texel of the 1024-wide chain), a softbox's straight edge (a great circle: a straight
    // line on screen) must stay straight where the radiance crosses 1 (the clamp tone map's white), not
    // step from texel row to texel row.
    void softboxEdgeIsStraightWhenMagnified() {
        Studio studio = oneSoftbox(0.0, 40.0, 40.0, 4.0);
        studio.zenith = studio.horizon = studio.floor = glm::dvec3(0.05);
        studio.softboxes[0].height = 30.0;
        m_gl->setModel(nullptr);
        m_gl->renderer().setEnvironment(loaded(environment::renderStudio(studio)));
        const Rig rig = environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible);
        const glm::dvec3 c = environment::softboxDirection(0.0, 40.0);
        const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), c));
        ViewCamera cam;
        cam.eye = glm::dvec3(0.0);
        cam.target = glm::normalize(c + right * std::tan(20.0 * environment::kPi / 180.0));
        cam.yfovDeg = 8.0;
        RenderSettings s = settingsFor(Quality::Exact);
        s.hdrTarget = true;
        const FloatImage f = radiance(rig, cam, s);
        std::vector<std::pair<double, double>> edge; // (row, x where the radiance crosses 1)
        for (int y = 0; y < kSize.height(); ++y)
            for (int x = 0; x + 1 < kSize.width(); ++x) {
                const float a = f.at(x, y).g, b = f.at(x + 1, y).g;
                if ((a - 1.0f) * (b - 1.0f) <= 0.0f && a != b) {
                    edge.emplace_back(y, x + (1.0 - a) / (b - a));
                    break;
                }
            }
        QVERIFY2(edge.size() > size_t(kSize.height() * 9 / 10), qPrintable(QString::number(edge.size())));
        double sy = 0, sx = 0, syy = 0, sxy = 0;
        for (const auto& [y, x] : edge) {
            sy += y;
            sx += x;
            syy += y * y;
            sxy += x * y;
        }
        const double n = double(edge.size());
        const double slope = (n * sxy - sy * sx) / (n * syy - sy * sy), offset = (sx - slope * sy) / n;
        double worst = 0.0;
        for (const auto& [y, x] : edge)
            worst = std::max(worst, std::abs(x - (offset + slope * y)));
        qInfo("edge: %d rows, slope %.4f px/row, largest step off the line %.3f px", int(edge.size()), slope,
              worst);
        QVERIFY2(worst < 0.5,
                 qPrintable(QStringLiteral("the edge strays %1 px from a straight line").arg(worst)));
    }

    // Issue 41 item 14: a white light's gizmo lines vanished against a bright environment. They are drawn
    // over a dark halo: away from the light's icon (which has its own dark rim), pixels of the white
    // background turn dark beside the lines.
    void whiteGizmoLinesShowOnABrightBackground() {
        m_gl->setModel(nullptr);
        m_gl->renderer().setEnvironment(uniformEnvironment(glm::vec3(3.0f)));
        Rig rig = environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible);
        // A white spot light aiming across the view: its cone and axis are lines in its own colour.
        Light l = spot({-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, ConeModel::Smooth, 20.0, 30.0, 1.0);
        l.color = glm::dvec3(1.0);
        rig.lights = {l};
        m_gl->setRig(rig);
        const QSize size(320, 240);
        RenderSettings s = settingsFor(Quality::Balanced);
        s.showGizmos = true;
        QString error;
        const QImage img = m_gl->renderImage(frontCamera(), size, s, 1, &error);
        QVERIFY2(!img.isNull(), qPrintable(error));
        const auto icon = projectToPixel(m_gl->renderer(), frontCamera(), size, l.position);
        QVERIFY(icon);
        int dark = 0, white = 0;
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x) {
                if (std::hypot(x - icon->x(), y - icon->y()) < 30.0) continue; // the icon
                const int g = qGray(img.pixel(x, y));
                dark += g < 140;
                white += g > 250;
            }
        QVERIFY2(white > size.width() * size.height() / 2, "the background is white");
        QVERIFY2(dark > 200, qPrintable(QStringLiteral("%1 dark pixels beside the lines").arg(dark)));
    }

    // A tiled render (each tile its own projection) shows the same background as one whole frame.
    void backgroundAcrossTiles() {
        Studio studio;
        Softbox box;
        box.azimuth = 170.0;
        box.elevation = 5.0;
        studio.softboxes = {box};
        QVERIFY(m_gl->setModel(whiteSphere()));
        m_gl->renderer().setEnvironment(loaded(environment::renderStudio(studio, 256)));
        const Rig rig = environmentRig(ShadingModel::Pbr, EnvironmentBackground::Visible);
        const RenderSettings s = settingsFor(Quality::Balanced);
        const QImage whole = image(rig, frontCamera(), s);
        m_gl->setMaxTileSize(48);
        const QImage tiled = image(rig, frontCamera(), s);
        m_gl->setMaxTileSize(4096);
        QCOMPARE(tiled.size(), whole.size());
        int worst = 0;
        for (int y = 0; y < whole.height(); ++y)
            for (int x = 0; x < whole.width(); ++x) {
                const QColor a = whole.pixelColor(x, y), b = tiled.pixelColor(x, y);
                worst = std::max({worst, std::abs(a.red() - b.red()), std::abs(a.green() - b.green()),
                                  std::abs(a.blue() - b.blue())});
            }
        QVERIFY2(worst <= 1, qPrintable(QStringLiteral("tiles differ by %1 levels").arg(worst)));
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

    // The background pass: after the opaque surfaces' depth (forward: after the shaded geometry; deferred:
    // after the G-pass and before the lighting, which shades the covered pixels over the copied
    // background), before the catcher's shadows and the blended meshes (they go over it, writing no
    // depth); only when asked for.
    void backgroundPassPlace() {
        RenderPlan plan;
        for (int bits = 0; bits < 8; ++bits) {
            PlanKey key;
            key.set(PlanBit::Deferred, bits & 1).set(PlanBit::Msaa, bits & 2).set(PlanBit::Hdr, bits & 4);
            key.set(PlanBit::Catcher).set(PlanBit::Blend);
            key.set(PlanBit::Background);
            const auto& passes = plan.select(key);
            QVERIFY2(RenderPlan::check(passes, key.has(PlanBit::Msaa)).isEmpty(),
                     qPrintable(plan.describe()));
            const QString d = plan.describe();
            const QString order = key.has(PlanBit::Deferred)
                                      ? QStringLiteral("geometry (G-buffer) > background > deferred lighting")
                                      : QStringLiteral("geometry (shaded) > background");
            QVERIFY2(d.contains(order + QStringLiteral(" > shadow catcher > blend")), qPrintable(d));
            key.set(PlanBit::Background, false);
            plan.select(key);
            QVERIFY(!plan.describe().contains(QLatin1String("background")));
        }
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
