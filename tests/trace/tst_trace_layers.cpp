// The path tracer's split by light group (issue 37, docs/light-mixing.md, docs/path-tracing.md "Layers"):
// every term of a path goes to the group of its emitter, so the groups sum to the radiance sample for
// sample; the tracer's group images sum to its image; a group scaled or switched off by a mix is what a
// render of the rig with those lights scaled or switched off gives; the albedo, normal and depth layers of
// a quad at a known distance; and the command line's memory estimate counts the layers.
#include "tracescenes.h"

#include "cli/renderestimate.h"
#include "cli/rendertraced.h"
#include "trace/camerarays.h"

#include <QTest>
#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <random>

using namespace lr;
using namespace tracetest;
using V = glm::dvec3;

namespace {

double maxOf(const glm::dvec3& c) {
    return std::max({c.x, c.y, c.z});
}

double luminance(const glm::vec4& p) {
    return 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
}

// An open box with an emissive panel on its left wall: bounce light, occlusion and an emissive surface.
Model emitterBox() {
    Model box = openBox(pbrMaterial(glm::vec3(0.6f, 0.55f, 0.5f), 0.2f, 0.4f));
    Material glow = pbrMaterial(glm::vec3(0.1f), 0.0f, 1.0f);
    glow.emissive = glm::vec3(2.0f, 1.5f, 1.0f);
    merge(box,
          quadsModel({{V(-0.99, -0.5, 0.3), V(-0.99, -0.5, -0.3), V(-0.99, 0.2, -0.3), V(-0.99, 0.2, 0.3)}},
                     glow));
    return box;
}

Light pointLight(const QString& name, const QString& group, const glm::dvec3& position, double intensity) {
    Light l;
    l.name = name;
    l.group = group;
    l.type = LightType::Point;
    l.position = position;
    l.intensity = intensity;
    l.falloff.model = FalloffModel::InverseSquare;
    return l;
}

Light areaLight(LightType type, const QString& name, const QString& group, const glm::dvec3& position,
                double intensity) {
    Light l = pointLight(name, group, position, intensity);
    l.type = type;
    l.direction = V(0.0, -1.0, 0.0);
    l.area.width = 0.6, l.area.height = 0.4, l.area.radius = 0.2;
    return l;
}

// Every kind of emitter: two lights in group "key" (a soft point light with its own ambient term, a
// rect), "fill" (a spot), an ungrouped disk and sun, a rim and a disabled light (in no group), the scene
// ambient and a uniform environment.
Rig everyEmitterRig(EnvironmentBackground background) {
    Rig rig = pbrRig(true);
    rig.environment.background = background;
    rig.ambient = V(0.03, 0.03, 0.04);
    Light key = pointLight(QStringLiteral("key point"), QStringLiteral("key"), V(0.3, 0.3, 0.2), 1.5);
    key.shadow.enabled = true, key.shadow.size = 0.1;
    key.ambient = V(0.02, 0.01, 0.0);
    const Light rect =
        areaLight(LightType::Rect, QStringLiteral("key rect"), QStringLiteral("key"), V(0.0, 0.9, 0.0), 3.0);
    Light fill = pointLight(QStringLiteral("fill spot"), QStringLiteral("fill"), V(-0.5, 0.8, 0.5), 2.0);
    fill.type = LightType::Spot;
    fill.direction = glm::normalize(V(0.3, -1.0, -0.3));
    Light disk = areaLight(LightType::Disk, QStringLiteral("disk"), {}, V(0.5, 0.6, -0.5), 2.0);
    disk.area.twoSided = true;
    Light sun;
    sun.name = QStringLiteral("sun");
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(V(0.2, -1.0, 0.1));
    sun.shadow.enabled = true, sun.shadow.angle = 2.0;
    Light rim;
    rim.name = QStringLiteral("rim");
    rim.type = LightType::Rim;
    Light off = pointLight(QStringLiteral("off"), QStringLiteral("off"), V(0.0, 0.5, 0.0), 5.0);
    off.enabled = false;
    rig.lights = {key, rect, fill, disk, sun, rim, off};
    return rig;
}

std::shared_ptr<const trace::TraceScene> build(const Model& model, const Rig& rig, bool environment = true) {
    auto description =
        describe(model, rig, environment ? uniformEnvironment(glm::vec3(0.4f, 0.5f, 0.6f)) : nullptr);
    QString error;
    auto scene = trace::TraceScene::build(*description, &error);
    if (!scene) qWarning().noquote() << error;
    return scene;
}

// Per group, the sum over the samples of its luminance.
struct SplitStats {
    std::vector<double> totals;
    int nonFinite = 0, clamped = 0;
    double worst = 0.0; // the largest |Σ groups − radiance| / Σ |groups| of any channel
};

// tracePath with and without a split on random camera rays from above the box: the radiance the same bit
// for bit, the groups summing to it to 1e-12 of the groups' magnitude, all 0 for a dropped sample.
SplitStats checkSplit(const trace::TraceScene& scene, const trace::TraceSettings& settings, int samples) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    SplitStats stats;
    stats.totals.assign(scene.groups().size(), 0.0);
    std::vector<glm::dvec3> groups(scene.groups().size());
    for (int k = 0; k < samples; ++k) {
        const V origin = V(0.0, 2.5, 1.5) + 0.2 * V(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
        V dir;
        if (k % 5 == 0) { // anywhere: escaped rays see the environment or the background
            const double z = 2.0 * u(rng) - 1.0, phi = 2.0 * std::numbers::pi * u(rng),
                         r = std::sqrt(1.0 - z * z);
            dir = V(r * std::cos(phi), z, r * std::sin(phi));
        } else { // into the box
            dir = glm::normalize(V(2.0 * u(rng) - 1.0, 2.0 * u(rng) - 1.0, 2.0 * u(rng) - 1.0) - origin);
        }
        trace::Sampler a(std::uint32_t(k), std::uint32_t(k % 13), 3), b = a;
        const trace::PathSample plain = trace::tracePath(scene, origin, dir, a, settings);
        trace::PathSplit split;
        split.groups = groups.data();
        const trace::PathSample s = trace::tracePath(scene, origin, dir, b, settings, &split);
        if (!(s.radiance == plain.radiance) || s.alpha != plain.alpha || s.finite != plain.finite) {
            QTest::qFail(qPrintable(QStringLiteral("sample %1: the split changed the radiance").arg(k)),
                         __FILE__, __LINE__);
            return stats;
        }
        glm::dvec3 sum(0.0), magnitude(0.0);
        for (size_t g = 0; g < groups.size(); ++g) {
            sum += groups[g];
            magnitude += glm::abs(groups[g]);
            stats.totals[g] += 0.2126 * groups[g].x + 0.7152 * groups[g].y + 0.0722 * groups[g].z;
        }
        if (!s.finite) {
            ++stats.nonFinite;
            if (magnitude != glm::dvec3(0.0))
                QTest::qFail(
                    qPrintable(QStringLiteral("sample %1: dropped, but its groups are not 0").arg(k)),
                    __FILE__, __LINE__);
            continue;
        }
        if (settings.fireflyClamp > 0.0 && maxOf(s.radiance) == settings.fireflyClamp) ++stats.clamped;
        for (int c = 0; c < 3; ++c)
            if (magnitude[c] > 0.0)
                stats.worst = std::max(stats.worst, std::abs(sum[c] - s.radiance[c]) / magnitude[c]);
        for (int c = 0; c < 3; ++c)
            if (!(std::abs(sum[c] - s.radiance[c]) <= 1e-12 * magnitude[c])) {
                QTest::qFail(qPrintable(QStringLiteral("sample %1 channel %2: groups sum to %3, radiance %4")
                                            .arg(k)
                                            .arg(c)
                                            .arg(sum[c], 0, 'g', 17)
                                            .arg(s.radiance[c], 0, 'g', 17)),
                             __FILE__, __LINE__);
                return stats;
            }
    }
    return stats;
}

int groupNamed(const trace::TraceScene& scene, const QString& name) {
    const QStringList names = groupNames(scene.groups());
    return int(names.indexOf(name));
}

// Above the box, looking in: the walls, the floor, the panel and some sky.
std::unique_ptr<trace::PathTracer> tracerFor(std::shared_ptr<const trace::TraceScene> scene, QSize size,
                                             bool layers) {
    const ViewCamera camera = lookAt({0.3, 2.6, 2.2}, {0.0, -0.4, 0.0}, 45.0);
    auto t = std::make_unique<trace::PathTracer>(std::move(scene), camera, size, trace::TraceSettings{}, 2);
    t->setLayers(layers);
    return t;
}

// The largest |a − b| over pixels and rgb, relative to b's largest channel.
double relativeDifference(const FloatImage& a, const FloatImage& b) {
    if (a.pixels.size() != b.pixels.size()) return INFINITY;
    double worst = 0.0, peak = 1e-30;
    for (size_t i = 0; i < a.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            peak = std::max(peak, std::abs(double(b.pixels[i][c])));
            worst = std::max(worst, std::abs(double(a.pixels[i][c]) - double(b.pixels[i][c])));
        }
    return worst / peak;
}

Rig withGroup(Rig rig, const QString& group, const std::function<void(Light&)>& change) {
    for (Light& l : rig.lights)
        if (l.group == group) change(l);
    return rig;
}

} // namespace

class TraceLayers : public QObject {
    Q_OBJECT
  private slots:
    // The groups of the traced scene: the rig's (rims and disabled lights left out), each light's index.
    void sceneGroups() {
        const auto scene = build(emitterBox(), everyEmitterRig(EnvironmentBackground::Visible));
        QVERIFY(scene);
        QCOMPARE(groupNames(scene->groups()), QStringList({"key", "fill", "disk", "sun", "environment",
                                                           "emissive", "ambient", "background"}));
        QStringList ofLights;
        for (const trace::TraceLight& l : scene->lights())
            ofLights << scene->groups()[size_t(l.group)].name;
        QCOMPARE(ofLights, QStringList({"key", "key", "fill", "disk", "sun"}));
        QCOMPARE(scene->environmentGroup(), 4);
        QCOMPARE(scene->emissiveGroup(), 5);
        QCOMPARE(scene->ambientGroup(), 6);
        QCOMPARE(scene->backgroundGroup(), 7);
    }

    // Sample for sample, with each kind of emitter, the background colour and the shadow catcher.
    void perSampleSumIsTheRadiance() {
        const auto visible = build(emitterBox(), everyEmitterRig(EnvironmentBackground::Visible));
        QVERIFY(visible);
        trace::TraceSettings settings;
        const SplitStats a = checkSplit(*visible, settings, 4000);
        QCOMPARE(a.nonFinite, 0);
        for (size_t g = 0; g + 1 < a.totals.size(); ++g) // every emitter's group receives light
            QVERIFY2(a.totals[g] > 0.0, qPrintable(visible->groups()[g].name));
        QCOMPARE(a.totals.back(), 0.0); // nothing is background when the environment is visible

        const auto colour = build(emitterBox(), everyEmitterRig(EnvironmentBackground::Color));
        QVERIFY(colour);
        const SplitStats b = checkSplit(*colour, settings, 2000);
        QVERIFY(b.totals[size_t(colour->backgroundGroup())] > 0.0);
        QVERIFY(b.totals[size_t(colour->environmentGroup())] > 0.0); // its light still

        // The catcher's composite: a wall standing on it, camera rays from above.
        Rig catcherRig = everyEmitterRig(EnvironmentBackground::Visible);
        catcherRig.ground.mode = GroundMode::Catcher;
        const Model wall = quadsModel({{V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)}},
                                      pbrMaterial(glm::vec3(0.5f), 0.0f, 0.7f));
        const auto catcher = build(wall, catcherRig);
        QVERIFY(catcher && catcher->catcher());
        const SplitStats c = checkSplit(*catcher, settings, 2000);
        QVERIFY(c.totals[size_t(catcher->backgroundGroup())] > 0.0);

        // The firefly clamp scales the groups with the radiance.
        settings.fireflyClamp = 0.3;
        const SplitStats d = checkSplit(*visible, settings, 2000);
        QVERIFY2(d.clamped > 100, qPrintable(QString::number(d.clamped)));

        // A dropped sample drops its groups: an infinitely bright sun.
        Rig bright = everyEmitterRig(EnvironmentBackground::Visible);
        bright.lights[4].intensity = INFINITY;
        const auto infinite = build(emitterBox(), bright);
        QVERIFY(infinite);
        const SplitStats e = checkSplit(*infinite, {}, 1000);
        QVERIFY2(e.nonFinite > 100, qPrintable(QString::number(e.nonFinite)));
        qInfo().noquote() << QStringLiteral(
                                 "largest relative deviation of a sample's groups from its radiance: "
                                 "%1 (environment visible), %2 (background colour), %3 (catcher), "
                                 "%4 (clamped), %5 (%6 samples dropped)")
                                 .arg(a.worst)
                                 .arg(b.worst)
                                 .arg(c.worst)
                                 .arg(d.worst)
                                 .arg(e.worst)
                                 .arg(e.nonFinite);
    }

    // The group images sum to the image, which is the image without layers bit for bit; resuming adds
    // to them as one render does; restart and switching layers forget them.
    void imageSumAndResume() {
        const auto scene = build(emitterBox(), everyEmitterRig(EnvironmentBackground::Visible));
        QVERIFY(scene);
        const QSize size(24, 20);
        const auto plain = tracerFor(scene, size, false);
        plain->render(6);
        QVERIFY(plain->layers().groupImages.empty());
        const auto split = tracerFor(scene, size, true);
        split->render(2);
        split->render(4);
        const RenderLayers layers = split->layers();
        QVERIFY(layers.beauty.pixels == plain->image().pixels);
        QCOMPARE(layers.groups, scene->groups());
        QCOMPARE(layers.groupImages.size(), scene->groups().size());
        const double error = groupSumError(layers);
        qInfo().noquote() << QStringLiteral("groupSumError %1").arg(error);
        QVERIFY2(error <= 1e-5, qPrintable(QString::number(error)));
        double peak = 0.0;
        for (const FloatImage& g : layers.groupImages)
            peak = std::max(peak, meanChannel(g, 1));
        QVERIFY(peak > 0.0);

        const auto once = tracerFor(scene, size, true);
        once->render(6);
        const RenderLayers whole = once->layers();
        for (size_t g = 0; g < whole.groupImages.size(); ++g)
            QVERIFY2(whole.groupImages[g].pixels == layers.groupImages[g].pixels,
                     qPrintable(whole.groups[g].name));
        QVERIFY(whole.albedo.pixels == layers.albedo.pixels);
        QVERIFY(whole.depth.pixels == layers.depth.pixels);

        split->restart();
        QCOMPARE(split->samplesDone(), 0);
        for (const FloatImage& g : split->layers().groupImages)
            QCOMPARE(meanChannel(g, 0), 0.0);
        split->render(6);
        QVERIFY(split->layers().groupImages[0].pixels == whole.groupImages[0].pixels);
        split->setLayers(false);
        QCOMPARE(split->samplesDone(), 0);
        QVERIFY(split->layers().groupImages.empty());
    }

    // Scaling a group by a mix is rendering its lights at that intensity: the light loop draws the same
    // numbers whatever the intensities (no light is chosen by power; MIS weighs densities, not
    // intensities; roulette reads the throughput), so with the same seed the images agree to rounding.
    void scaledGroupIsAScaledRig() {
        const Model box = emitterBox();
        const Rig rig = everyEmitterRig(EnvironmentBackground::Visible);
        const double k = 2.7;
        const Rig scaled = withGroup(rig, QStringLiteral("key"), [&](Light& l) { l.intensity *= k; });
        const QSize size(24, 20);
        const auto a = tracerFor(build(box, rig), size, true);
        const auto b = tracerFor(build(box, scaled), size, true);
        a->render(8);
        b->render(8);
        const RenderLayers la = a->layers(), lb = b->layers();
        LightMix mix;
        mix.groups[QStringLiteral("key")].ev = std::log2(k);
        const double mixed = relativeDifference(mixGroupImages(la, mix), lb.beauty);
        const double unmixed = relativeDifference(la.beauty, lb.beauty); // what the test would miss
        qInfo().noquote() << QStringLiteral("key ×%1: mixed against the scaled rig %2, unmixed %3")
                                 .arg(k)
                                 .arg(mixed)
                                 .arg(unmixed);
        QVERIFY2(mixed < 1e-5, qPrintable(QString::number(mixed)));
        QVERIFY(unmixed > 1e-2);
        for (size_t g = 1; g < la.groupImages.size(); ++g) // the other groups: untouched
            QVERIFY2(relativeDifference(lb.groupImages[g], la.groupImages[g]) < 1e-6,
                     qPrintable(la.groups[g].name));
    }

    // A group switched off by a mix is a render with its lights disabled. Hard point and spot lights draw
    // no numbers, so there the images agree to rounding; an area light draws its point whether or not it
    // is bright, so at intensity 0 they agree to rounding too, but disabled, the numbers of the lights
    // after it shift and the two images differ by noise, bounded below by the tracers' own noise estimate.
    void groupOffIsLightsOff() {
        const Model box = emitterBox();
        Rig rig = everyEmitterRig(EnvironmentBackground::Color);
        rig.lights[0].shadow.size = 0.0; // a hard point light: no number drawn for it
        const auto off = [](Light& l) { l.enabled = false; };
        const QSize size(32, 24);
        const auto a = tracerFor(build(box, rig), size, true);
        a->render(16);
        const RenderLayers la = a->layers();

        // (a) "fill" (a hard spot): exact. "key" holds the rect: see below.
        {
            const auto b = tracerFor(build(box, withGroup(rig, QStringLiteral("fill"), off)), size, true);
            b->render(16);
            LightMix mix;
            mix.groups[QStringLiteral("fill")].enabled = false;
            const double d = relativeDifference(mixGroupImages(la, mix), b->image());
            QVERIFY2(d < 1e-5, qPrintable(QString::number(d)));
            QVERIFY(relativeDifference(la.beauty, b->image()) > 1e-2);
        }
        LightMix keyOff;
        keyOff.groups[QStringLiteral("key")].enabled = false;
        const FloatImage mixed = mixGroupImages(la, keyOff);
        // (b) "key" (the point light and the rect) at intensity 0: exact.
        {
            const auto b = tracerFor(
                build(box, withGroup(rig, QStringLiteral("key"), [](Light& l) { l.intensity = 0.0; })), size,
                true);
            b->render(16);
            const double d = relativeDifference(mixed, b->image());
            QVERIFY2(d < 1e-5, qPrintable(QString::number(d)));
        }
        // (c) "key" disabled: within noise. Per pixel the difference of two estimates has a variance of
        // at most the sum of theirs (they share numbers, which correlates them positively), and each
        // tracer's noiseEstimate × mean luminance is the root mean square of its pixels' standard errors:
        // so the RMS difference stays under 2√(σa² + σb²) and the mean difference under 4√((σa² + σb²)/N)
        // over N pixels, while the key group itself is far above both.
        const auto b = tracerFor(build(box, withGroup(rig, QStringLiteral("key"), off)), size, true);
        b->render(16);
        const FloatImage ib = b->image();
        const double sa = a->noiseEstimate() * [&] {
            double m = 0.0;
            for (const glm::vec4& p : la.beauty.pixels)
                m += luminance(p);
            return m / double(la.beauty.pixels.size());
        }();
        const double sb = b->noiseEstimate() * [&] {
            double m = 0.0;
            for (const glm::vec4& p : ib.pixels)
                m += luminance(p);
            return m / double(ib.pixels.size());
        }();
        double meanDiff = 0.0, squares = 0.0, keyMean = 0.0;
        const size_t n = ib.pixels.size();
        const int key = groupNamed(*build(box, rig), QStringLiteral("key"));
        for (size_t i = 0; i < n; ++i) {
            const double d = luminance(mixed.pixels[i]) - luminance(ib.pixels[i]);
            meanDiff += d / double(n);
            squares += d * d / double(n);
            keyMean += luminance(la.groupImages[size_t(key)].pixels[i]) / double(n);
        }
        const double sigma = std::sqrt(sa * sa + sb * sb), rms = std::sqrt(squares);
        const QString figures = QStringLiteral("key off against disabled: mean difference %1, RMS %2; noise "
                                               "σa %3, σb %4; the key group's mean %5")
                                    .arg(meanDiff)
                                    .arg(rms)
                                    .arg(sa)
                                    .arg(sb)
                                    .arg(keyMean);
        qInfo().noquote() << figures;
        QVERIFY2(std::abs(meanDiff) < 4.0 * sigma / std::sqrt(double(n)), qPrintable(figures));
        QVERIFY2(rms < 2.0 * sigma, qPrintable(figures));
        QVERIFY2(keyMean > 5.0 * 4.0 * sigma / std::sqrt(double(n)), qPrintable(figures));
    }

    // A quad across the view at depth 5: its base colour, its normal turned towards the camera (it faces
    // away: seen from behind) and depth 5 along the view axis at every pixel it covers (not the distance,
    // which grows off the axis); the background's albedo and normal 0, depth kBackgroundDepth.
    void albedoNormalDepth() {
        const glm::vec3 base(0.2f, 0.4f, 0.6f);
        const Model quad = quadsModel({{V(-1, -1, 0), V(-1, 1, 0), V(1, 1, 0), V(1, -1, 0)}}, // normal −Z
                                      pbrMaterial(base, 0.0f, 0.5f));
        Rig rig = pbrRig(false);
        rig.lights = {pointLight(QStringLiteral("p"), {}, V(0, 0, 3), 4.0)};
        const auto scene = build(quad, rig, false);
        QVERIFY(scene);
        const ViewCamera camera = lookAt({0.0, 0.0, 5.0}, glm::dvec3(0.0), 40.0);
        const QSize size(32, 32);
        trace::PathTracer tracer(scene, camera, size, {}, 2);
        tracer.setLayers(true);
        tracer.render(4);
        const RenderLayers l = tracer.layers();
        const trace::CameraRays rays(camera, size);
        const auto onQuad = [&](double x, double y) {
            const glm::dvec3 d = rays.direction(x, y);
            const glm::dvec3 p = rays.origin() + d * (5.0 / -d.z);
            return std::abs(p.x) < 1.0 && std::abs(p.y) < 1.0;
        };
        int inside = 0, outside = 0, offAxis = 0;
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x) {
                const int corners = int(onQuad(x, y)) + int(onQuad(x + 1, y)) + int(onQuad(x, y + 1)) +
                                    int(onQuad(x + 1, y + 1));
                const glm::vec4 a = l.albedo.at(x, y), n = l.normal.at(x, y), z = l.depth.at(x, y);
                const QString where = QStringLiteral("(%1, %2): albedo %3 %4 %5, normal %6 %7 %8, depth %9")
                                          .arg(x)
                                          .arg(y)
                                          .arg(a.x)
                                          .arg(a.y)
                                          .arg(a.z)
                                          .arg(n.x)
                                          .arg(n.y)
                                          .arg(n.z)
                                          .arg(z.x);
                if (corners == 4) {
                    ++inside;
                    QVERIFY2(glm::all(glm::lessThan(glm::abs(glm::vec3(a) - base), glm::vec3(1e-6f))),
                             qPrintable(where));
                    QVERIFY2(glm::all(glm::lessThan(glm::abs(glm::vec3(n) - glm::vec3(0, 0, 1)),
                                                    glm::vec3(1e-6f))),
                             qPrintable(where));
                    QVERIFY2(std::abs(z.x - 5.0) < 1e-5, qPrintable(where));
                    const glm::dvec3 corner = rays.direction(x, y);
                    if (5.0 / -corner.z > 5.05) ++offAxis; // here a distance would be off by 1 %
                } else if (corners == 0) {
                    ++outside;
                    QVERIFY2(glm::vec3(a) == glm::vec3(0.0f) && glm::vec3(n) == glm::vec3(0.0f),
                             qPrintable(where));
                    QCOMPARE(z.x, kBackgroundDepth);
                }
            }
        QVERIFY2(inside > 100 && outside > 100 && offAxis > 20,
                 qPrintable(QStringLiteral("%1 %2 %3").arg(inside).arg(outside).arg(offAxis)));
    }

    // The command line's estimate holds what the tracer allocates for the layers and the RenderLayers it
    // returns, and refuses a size that fits without layers but not with them.
    void memoryEstimateCountsLayers() {
        const auto scene = build(emitterBox(), everyEmitterRig(EnvironmentBackground::Visible));
        QVERIFY(scene);
        const int groups = int(scene->groups().size());
        const QSize size(40, 30);
        const auto plain = tracerFor(scene, size, false);
        const auto split = tracerFor(scene, size, true);
        split->render(1);
        const RenderLayers layers = split->layers();
        std::int64_t returned = 0;
        for (const FloatImage* f : {&layers.beauty, &layers.albedo, &layers.normal, &layers.depth})
            returned += std::int64_t(f->pixels.size() * sizeof(glm::vec4));
        for (const FloatImage& f : layers.groupImages)
            returned += std::int64_t(f.pixels.size() * sizeof(glm::vec4));
        const std::int64_t extra = cli::tracedImageBytes(size, groups) - cli::tracedImageBytes(size);
        const std::int64_t allocated = std::int64_t(split->bytes()) - std::int64_t(plain->bytes());
        QVERIFY2(allocated > 0 && extra >= allocated + returned,
                 qPrintable(QStringLiteral("estimate +%1, allocated +%2, returned %3")
                                .arg(extra)
                                .arg(allocated)
                                .arg(returned)));
        QVERIFY(std::int64_t(plain->bytes()) <=
                cli::tracedImageBytes(size) - cli::tracedImageBytes(QSize(0, 0)));

        QString what;
        const std::int64_t available = cli::availableMemory(&what);
        if (available <= 0) QSKIP("this machine's memory is unknown");
        const std::int64_t base = cli::tracedImageBytes(QSize(0, 0));
        const std::int64_t perPixel = cli::tracedImageBytes(QSize(1, 1)) - base;
        const std::int64_t perPixelLayers = cli::tracedImageBytes(QSize(1, 1), groups) - base;
        const std::int64_t pixels = (available - base) / ((perPixel + perPixelLayers) / 2);
        const int width = 20000;
        const QSize big(width, int(std::min<std::int64_t>(pixels / width, 1 << 30)));
        QString error;
        QVERIFY2(cli::checkTracedMemory(big, false, &error), qPrintable(error));
        QVERIFY(!cli::checkTracedMemory(big, false, &error, groups));
        QVERIFY2(error.contains(QStringLiteral("%1 light groups").arg(groups)), qPrintable(error));
        QVERIFY(cli::checkTracedMemory(big, true, &error, groups)); // --no-memory-check
    }
};

QTEST_GUILESS_MAIN(TraceLayers)
#include "tst_trace_layers.moc"
