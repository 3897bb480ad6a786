// Light and shadow linking in the path-traced tier (issue 38; core/lightlink.h, trace/tracescene.h): a light
// included on part A only adds nothing to part B — neither by next-event estimation nor by BSDF rays that
// meet its emitter — while A gets all of it (the estimator stays unbiased for the linked set); a part
// excluded from a light's shadow casts none of that light's shadow but is still lit by it and still casts
// the others'; the light groups still sum to the image; and Embree's ray masks and the filter functions
// that stand in for them where a device lacks masks agree.
#include "tracescenes.h"

#include "scene/embreescene.h"
#include "trace/camerarays.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace tracetest;
using V = glm::dvec3;

namespace {

const QSize kSize(40, 30);

// Straight down at the floor y = 0: image right is +x, image down is +z.
ViewCamera topCamera() {
    return lookAt(V(0.0, 4.0, 0.0), V(0.0), 45.0, V(0.0, 0.0, -1.0));
}

// A horizontal quad y = height, x in [x0, x1], z in [z0, z1], facing up, as a part named `node`.
Model floorPart(const QString& node, double x0, double x1, double z0, double z1, double height = 0.0) {
    Model m = quadsModel({{V(x0, height, z1), V(x1, height, z1), V(x1, height, z0), V(x0, height, z0)}},
                         pbrMaterial(glm::vec3(0.6f), 0.0f, 0.8f));
    m.meshes.front().node = node;
    return m;
}

Light light(LightType type, const QString& name, const V& position, double intensity) {
    Light l = makeLight(type, name);
    l.group = name;
    l.position = position;
    l.direction = V(0.0, -1.0, 0.0);
    l.intensity = intensity;
    l.falloff.model = FalloffModel::InverseSquare;
    l.area.width = 1.2, l.area.height = 0.8;
    return l;
}

struct Traced {
    FloatImage image;
    RenderLayers layers;
};

Traced traceImage(const Model& model, const Rig& rig, int samples, int bounces = 8) {
    auto description = describe(model, rig);
    QString error;
    auto scene = trace::TraceScene::build(*description, &error);
    if (!scene) {
        QTest::qFail(qPrintable(error), __FILE__, __LINE__);
        return {};
    }
    trace::TraceSettings settings;
    settings.bounces = bounces;
    trace::PathTracer tracer(scene, topCamera(), kSize, settings, 2);
    tracer.setLayers(true);
    tracer.render(samples);
    return {tracer.image(), tracer.layers()};
}

// Where the camera ray through pixel (x, y) meets y = height.
V floorPoint(int x, int y, double height = 0.0) {
    const trace::CameraRays rays(topCamera(), kSize);
    const V d = rays.direction(x + 0.5, y + 0.5);
    return rays.origin() + d * ((height - rays.origin().y) / d.y);
}

// The mean luminance of the pixels whose floor point `inside` accepts, and its standard error (the
// pixels' spread over √count: lighting that varies across the region only widens it).
struct Region {
    double mean = 0.0, error = 0.0;
    int pixels = 0;
};
template <typename F> Region region(const FloatImage& image, F inside) {
    Region r;
    double sum = 0.0, sq = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (!inside(floorPoint(x, y))) continue;
            const glm::vec4& p = image.pixels[size_t(y) * size_t(image.width) + size_t(x)];
            const double l = 0.2126 * p.x + 0.7152 * p.y + 0.0722 * p.z;
            sum += l, sq += l * l, ++r.pixels;
        }
    if (r.pixels < 2) return r;
    r.mean = sum / r.pixels;
    r.error = std::sqrt(std::max(0.0, sq / r.pixels - r.mean * r.mean) / (r.pixels - 1));
    return r;
}

// Whether two regions agree within noise (four standard errors) / differ well beyond it.
bool agree(const Region& a, const Region& b) {
    return std::abs(a.mean - b.mean) <= 4.0 * std::hypot(a.error, b.error) + 1e-12;
}
bool differ(const Region& a, const Region& b) {
    return std::abs(a.mean - b.mean) > 10.0 * std::hypot(a.error, b.error) + 1e-6;
}

QString describeRegions(const char* what, const Region& a, const Region& b) {
    return QStringLiteral("%1: %2 ± %3 against %4 ± %5 (%6 pixels)")
        .arg(QLatin1String(what))
        .arg(a.mean)
        .arg(a.error)
        .arg(b.mean)
        .arg(b.error)
        .arg(a.pixels);
}

} // namespace

class TraceLightLink : public QObject {
    Q_OBJECT
  private slots:
    // Two floor parts side by side (they cannot see each other: nothing bounces between them), a fill
    // lighting both and a key linked to A. B is what it is without the key; A what it is with the key
    // unlinked (next-event estimation and, for the rect, BSDF rays meeting it, weighed together).
    void lightIncludedOnOnePart_data() {
        QTest::addColumn<int>("type");
        QTest::newRow("point") << int(LightType::Point);
        QTest::newRow("rect") << int(LightType::Rect);
    }
    void lightIncludedOnOnePart() {
        QFETCH(int, type);
        Model model = floorPart(QStringLiteral("A"), -2.4, -0.05, -1.8, 1.8);
        merge(model, floorPart(QStringLiteral("B"), 0.05, 2.4, -1.8, 1.8));
        Rig rig = pbrRig(false);
        const Light fill = light(LightType::Point, QStringLiteral("fill"), V(0.0, 2.5, 0.0), 3.0);
        Light key = light(LightType(type), QStringLiteral("key"), V(0.0, 1.2, 0.0), 4.0);
        rig.lights = {fill, key};
        const Traced unlinked = traceImage(model, rig, 64);
        rig.lights[1].link.lit.include = {QStringLiteral("A")};
        const Traced linked = traceImage(model, rig, 64);
        rig.lights = {fill};
        const Traced without = traceImage(model, rig, 64);

        const auto inA = [](const V& p) { return p.x < -0.3 && p.x > -2.2 && std::abs(p.z) < 1.6; };
        const auto inB = [](const V& p) { return p.x > 0.3 && p.x < 2.2 && std::abs(p.z) < 1.6; };
        const Region bLinked = region(linked.image, inB), bWithout = region(without.image, inB),
                     bUnlinked = region(unlinked.image, inB);
        const Region aLinked = region(linked.image, inA), aWithout = region(without.image, inA),
                     aUnlinked = region(unlinked.image, inA);
        qInfo().noquote() << describeRegions("B linked/without", bLinked, bWithout);
        qInfo().noquote() << describeRegions("A linked/unlinked", aLinked, aUnlinked);
        QVERIFY(bLinked.pixels > 100 && aLinked.pixels > 100);
        QVERIFY2(agree(bLinked, bWithout), qPrintable(describeRegions("B", bLinked, bWithout)));
        QVERIFY2(differ(bUnlinked, bWithout), qPrintable(describeRegions("B", bUnlinked, bWithout)));
        QVERIFY2(agree(aLinked, aUnlinked), qPrintable(describeRegions("A", aLinked, aUnlinked)));
        QVERIFY2(differ(aLinked, aWithout), qPrintable(describeRegions("A", aLinked, aWithout)));

        // The groups still sum to the image, and the key's group is 0 wherever B is seen.
        const double error = groupSumError(linked.layers);
        QVERIFY2(error <= 1e-5, qPrintable(QString::number(error)));
        const QStringList names = groupNames(linked.layers.groups);
        const qsizetype keyGroup = names.indexOf(QStringLiteral("key"));
        QVERIFY(keyGroup >= 0);
        QCOMPARE(region(linked.layers.groupImages[size_t(keyGroup)], inB).mean, 0.0);
        QVERIFY(region(linked.layers.groupImages[size_t(keyGroup)], inA).mean > 0.0);
    }

    // A blocker above a floor, a key at one side whose shadow excludes the blocker and another light at
    // the other side. Direct light only (one bounce), so the floor in the key's shadow is what it is with
    // no blocker at all; the blocker is still lit by the key, and still casts the other light's shadow.
    void partExcludedFromShadow() {
        Model model = floorPart(QStringLiteral("Floor"), -2.4, 2.4, -1.8, 1.8);
        merge(model, floorPart(QStringLiteral("Blocker"), -0.3, 0.3, -0.3, 0.3, 0.5));
        Rig rig = pbrRig(false);
        Light key = light(LightType::Point, QStringLiteral("key"), V(2.0, 2.0, 0.0), 12.0);
        key.shadow.enabled = true;
        Light other = light(LightType::Point, QStringLiteral("other"), V(-2.0, 2.0, 0.0), 2.0);
        other.shadow.enabled = true;
        rig.lights = {key, other};
        const Traced unlinked = traceImage(model, rig, 32, 1);
        rig.lights[0].link.shadow.exclude = {QStringLiteral("Blocker")};
        const Traced linked = traceImage(model, rig, 32, 1);
        const Traced open = traceImage(floorPart(QStringLiteral("Floor"), -2.4, 2.4, -1.8, 1.8), rig, 32, 1);

        // The key's shadow of the blocker lies about x -1.07 .. -0.27, the other's about 0.27 .. 1.07.
        const auto keyShadow = [](const V& p) { return std::abs(p.x + 0.67) < 0.2 && std::abs(p.z) < 0.2; };
        const auto otherShadow = [](const V& p) { return std::abs(p.x - 0.67) < 0.2 && std::abs(p.z) < 0.2; };
        // The blocker's top, seen from above (its floor point is under it).
        const auto blocker = [](const V& p) { return std::abs(p.x) < 0.15 && std::abs(p.z) < 0.15; };
        const Region kLinked = region(linked.image, keyShadow), kUnlinked = region(unlinked.image, keyShadow),
                     kOpen = region(open.image, keyShadow);
        qInfo().noquote() << describeRegions("key's shadow linked/unlinked", kLinked, kUnlinked);
        QVERIFY(kLinked.pixels >= 4);
        QVERIFY2(kLinked.mean > 2.0 * kUnlinked.mean && differ(kLinked, kUnlinked),
                 qPrintable(describeRegions("key's shadow", kLinked, kUnlinked)));
        QVERIFY2(agree(kLinked, kOpen), qPrintable(describeRegions("key's shadow/open", kLinked, kOpen)));
        // The other light's own share (its group) in its shadow: none, as unlinked; some with no blocker.
        const auto otherLight = [](const Traced& t) {
            return t.layers.groupImages[size_t(groupNames(t.layers.groups).indexOf(QStringLiteral("other")))];
        };
        const Region oLinked = region(otherLight(linked), otherShadow),
                     oUnlinked = region(otherLight(unlinked), otherShadow),
                     oOpen = region(otherLight(open), otherShadow);
        QCOMPARE(oLinked.mean, 0.0);
        QCOMPARE(oUnlinked.mean, 0.0);
        QVERIFY2(oOpen.mean > 0.01 && oOpen.mean > 10.0 * oOpen.error,
                 qPrintable(QString::number(oOpen.mean)));
        const Region bLinked = region(linked.image, blocker), bUnlinked = region(unlinked.image, blocker);
        QVERIFY(bLinked.pixels >= 4);
        QVERIFY2(agree(bLinked, bUnlinked) && bLinked.mean > kUnlinked.mean,
                 qPrintable(describeRegions("blocker", bLinked, bUnlinked)));
        QVERIFY2(groupSumError(linked.layers) <= 1e-5,
                 qPrintable(QString::number(groupSumError(linked.layers))));
    }

    // The traced scene reads SceneDescription::links(): unlinked, nothing is set (no masks, linked()
    // false); linked, the parts' classes and each light's masks.
    void sceneCarriesTheLinks() {
        Model model = floorPart(QStringLiteral("A"), -2.0, -0.1, -1.0, 1.0);
        merge(model, floorPart(QStringLiteral("B"), 0.1, 2.0, -1.0, 1.0));
        Rig rig = pbrRig(false);
        rig.lights = {light(LightType::Point, QStringLiteral("key"), V(0.0, 1.0, 0.0), 1.0)};
        auto plain = trace::TraceScene::build(*describe(model, rig), nullptr);
        QVERIFY(plain && !plain->linked());
        QCOMPARE(plain->lights().front().litMask, kAllLinkClasses);
        QCOMPARE(plain->lights().front().emitter.shadowMask, kAllLinkClasses);
        rig.lights[0].link.lit.exclude = {QStringLiteral("B")};
        rig.lights[0].link.shadow.exclude = {QStringLiteral("A")};
        auto linked = trace::TraceScene::build(*describe(model, rig), nullptr);
        QVERIFY(linked && linked->linked());
        const trace::TraceLight& key = linked->lights().front();
        QVERIFY(linked->lights(key, 0) && !linked->lights(key, 1));
        QVERIFY(key.emitter.shadowMask != kAllLinkClasses);
    }

    // EmbreeScene's part masks: two stacked quads of classes 0 and 1, rays up through both. Ray masks
    // (where the device has them) and the filter functions agree.
    void masksAndFiltersAgree_data() {
        QTest::addColumn<bool>("filter");
        QTest::newRow("device's choice") << false;
        QTest::newRow("filter functions") << true;
    }
    void masksAndFiltersAgree() {
        QFETCH(bool, filter);
        Model model = floorPart(QStringLiteral("low"), -1.0, 1.0, -1.0, 1.0, 1.0);
        merge(model, floorPart(QStringLiteral("high"), -1.0, 1.0, -1.0, 1.0, 2.0));
        const EmbreeScene scene({&model}, model.bounds.center(), {1u << 0, 1u << 1}, filter);
        QVERIFY2(scene.ok(), qPrintable(scene.error()));
        qInfo("mask method: %s",
              scene.maskMethod() == EmbreeScene::MaskMethod::RayMask ? "ray masks" : "filter");
        if (filter) QCOMPARE(scene.maskMethod(), EmbreeScene::MaskMethod::Filter);
        const V o(0.2, 0.0, 0.1), up(0.0, 1.0, 0.0);
        const double inf = std::numeric_limits<double>::infinity();
        EmbreeHit h = scene.intersect(o, up, 0.0, inf);
        QVERIFY(h.hit && h.part == 0 && std::abs(h.t - 1.0) < 1e-6);
        h = scene.intersect(o, up, 0.0, inf, 1u << 1);
        QVERIFY(h.hit && h.part == 1 && std::abs(h.t - 2.0) < 1e-6);
        QVERIFY(!scene.intersect(o, up, 0.0, inf, 1u << 2).hit);
        QVERIFY(scene.occluded(o, up, inf));
        QVERIFY(scene.occluded(o, up, inf, 0.0, 1u << 1));
        QVERIFY(!scene.occluded(o, up, 1.5, 0.0, 1u << 1)); // the high quad lies beyond
        QVERIFY(!scene.occluded(o, up, inf, 0.0, 1u << 2));
        // No masks: nothing set, every ray sees everything.
        const EmbreeScene plain({&model}, model.bounds.center());
        QCOMPARE(plain.maskMethod(), EmbreeScene::MaskMethod::None);
        QVERIFY(plain.occluded(o, up, inf, 0.0, 1u << 2));
    }
};

QTEST_GUILESS_MAIN(TraceLightLink)
#include "tst_trace_lightlink.moc"
