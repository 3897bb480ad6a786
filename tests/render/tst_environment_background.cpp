// The environment behind the model on the GPU (issue 15; pass_background.cpp), on environments whose
// answer is known in closed form (environmentfixture.h): +1 EV doubles the radiance; the background pass
// kept while nothing it depends on changes; the background modes and transparency; rotation turns the
// studio's softbox as core's mapping says, its edge stays straight when magnified; white gizmo lines show
// over a bright background; tiles; and the pass's place in the plan. Lighting: tst_environment_render.
#include "environmentfixture.h"
#include "glfixture.h"
#include "scenes.h"
#include "shadowscenes.h"

#include "render/offscreen.h"
#include "render/renderplan.h"
#include "scene/envprefilter.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace lr::render;
using namespace lr::test;

namespace {

double srgb(double x) {
    x = std::clamp(x, 0.0, 1.0);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

} // namespace

class TestEnvironmentBackground : public QObject, protected EnvironmentFixture {
    Q_OBJECT
  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        m_gl = std::make_unique<OffscreenRenderer>();
        QString error;
        if (!m_gl->initialize(&error)) qFatal("%s", qPrintable(error));
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
};

LR_GL_TEST_MAIN(TestEnvironmentBackground)
#include "tst_environment_background.moc"
