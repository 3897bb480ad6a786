// Light and shadow linking in the double reference (issue 38; render/reference.h): on a G-buffer built by
// hand (points on the parts, seen from the view's eye, so the tracer finds each pixel's part), a light
// included on part A only adds exactly nothing to B (B's radiance is bit for bit the rig's without that
// light; A's is bit for bit the unlinked rig's), its light groups still sum to the radiance; a part
// excluded from a light's shadow casts none of it (visibility 1 there) while still lit by it and still
// casting the other light's shadow.
#include "shadowscenes.h"

#include "core/lightgroups.h"
#include "core/lighting.h"
#include "render/gbuffer.h"
#include "render/reference.h"
#include "render/referencelayers.h"

#include <QTest>
#include <glm/gtc/matrix_transform.hpp>
#include <vector>

using namespace lr;
using namespace lr::test;
using V = glm::dvec3;

namespace {

// One model of named parts: each ShadowSceneBuilder model's one mesh, its node named.
Model partsModel(const std::vector<std::pair<QString, Model>>& parts) {
    Model m = parts.front().second;
    m.meshes.clear();
    bool first = true;
    for (const auto& [name, part] : parts) {
        Mesh mesh = part.meshes.front();
        mesh.node = name;
        for (Vertex& v : mesh.vertices)
            v.position = glm::vec3(part.origin - m.origin + glm::dvec3(v.position));
        m.meshes.push_back(std::move(mesh));
        m.bounds.min = first ? part.bounds.min : glm::min(m.bounds.min, part.bounds.min);
        m.bounds.max = first ? part.bounds.max : glm::max(m.bounds.max, part.bounds.max);
        first = false;
    }
    return m;
}

// A one-row G-buffer of world points with their normals, seen through `view`.
GBuffer pointsRow(const glm::dmat4& view, const std::vector<std::pair<V, V>>& points) {
    GBuffer g;
    for (FloatImage* f : {&g.position, &g.normal, &g.albedo, &g.specular, &g.emissive}) {
        f->width = int(points.size()), f->height = 1;
        f->pixels.assign(points.size(), glm::vec4(0.0f));
    }
    for (size_t i = 0; i < points.size(); ++i) {
        g.position.pixels[i] = glm::vec4(glm::vec3(view * glm::dvec4(points[i].first, 1.0)), 1.0f);
        g.normal.pixels[i] = glm::vec4(glm::vec3(view * glm::dvec4(points[i].second, 0.0)), 1.0f);
        g.albedo.pixels[i] = glm::vec4(0.5f, 0.5f, 0.5f, 1.0f);
        g.specular.pixels[i] = glm::vec4(0.2f, 0.2f, 0.2f, 16.0f);
    }
    return g;
}

const glm::dmat4 kView = glm::lookAt(V(0.0, 4.0, 6.0), V(0.0), V(0.0, 1.0, 0.0));

ReferenceImage reference(const Model& model, const Rig& rig, const GBuffer& g, bool groups = false) {
    QString error;
    auto scene = makeReferenceScene(model, rig, SceneFrame{}, kView, RenderSettings(), &error);
    if (!scene) {
        QTest::qFail(qPrintable(error), __FILE__, __LINE__);
        return {};
    }
    if (groups) setReferenceGroups(&*scene, rig, lightGroups(rig));
    return computeReference(g, *scene);
}

Light pointLight(const QString& name, const V& position, double intensity, bool shadow) {
    Light l = makeLight(LightType::Point, name);
    l.group = name;
    l.position = position;
    l.falloff = {};
    l.intensity = intensity;
    l.shadow.enabled = shadow;
    l.shadow.size = 0.2;
    return l;
}

} // namespace

class TestReferenceLink : public QObject {
    Q_OBJECT
  private slots:
    // Boxes A and B on a visible ground, a soft-shadowed fill lighting all and a key included on A.
    void lightIncludedOnOnePart_data() {
        QTest::addColumn<int>("type");
        QTest::newRow("point") << int(LightType::Point);
        QTest::newRow("rect") << int(LightType::Rect);
    }
    void lightIncludedOnOnePart() {
        QFETCH(int, type);
        const Model model =
            partsModel({{QStringLiteral("A"), ShadowSceneBuilder().box({-2, 0, -0.5}, {-1, 1, 0.5}).build()},
                        {QStringLiteral("B"), ShadowSceneBuilder().box({1, 0, -0.5}, {2, 1, 0.5}).build()}});
        Rig rig;
        rig.ambient = V(0.02);
        rig.ground.mode = GroundMode::Visible;
        Light key = pointLight(QStringLiteral("key"), V(0.0, 2.0, 0.5), 1.5, true);
        key.type = LightType(type);
        key.direction = V(0.0, -1.0, 0.0);
        key.area.width = 1.0, key.area.height = 0.6;
        key.ambient = V(0.1);
        const Light fill = pointLight(QStringLiteral("fill"), V(0.0, 3.0, 3.0), 0.6, true);
        // Tops of A and B, the ground between them.
        const GBuffer g = pointsRow(kView, {{V(-1.5, 1.0, 0.0), V(0, 1, 0)},
                                            {V(1.5, 1.0, 0.0), V(0, 1, 0)},
                                            {V(0.0, 0.0, 1.0), V(0, 1, 0)}});
        rig.lights = {key, fill};
        const ReferenceImage unlinked = reference(model, rig, g);
        rig.lights[0].link.lit.include = {QStringLiteral("A")};
        const ReferenceImage linked = reference(model, rig, g, true);
        rig.lights = {fill};
        const ReferenceImage without = reference(model, rig, g);
        QVERIFY(linked.covered[0] && linked.covered[1] && linked.covered[2]);
        QVERIFY(linked.radiance[0] == unlinked.radiance[0]); // A: all of the key
        QVERIFY(linked.radiance[0] != without.radiance[0]);
        QVERIFY(linked.radiance[1] == without.radiance[1]); // B: none of it, ambient included
        QVERIFY(unlinked.radiance[1] != without.radiance[1]);
        QVERIFY(linked.radiance[2] == without.radiance[2]); // the ground: none either
        QVERIFY(unlinked.radiance[2] != without.radiance[2]);
        // The groups ("key", "fill", "ambient", "background") sum to the radiance; the key's is 0 on B.
        const int n = linked.groupCount;
        QCOMPARE(n, 4);
        for (size_t i = 0; i < 3; ++i) {
            V sum(0.0);
            for (int k = 0; k < n; ++k)
                sum += linked.groupRadiance[i * size_t(n) + size_t(k)];
            QVERIFY2(glm::length(sum - linked.radiance[i]) <= 1e-13 * glm::length(linked.radiance[i]),
                     qPrintable(QString::number(glm::length(sum - linked.radiance[i]))));
        }
        QCOMPARE(linked.groupRadiance[size_t(n) * 1], V(0.0));
        QVERIFY(linked.groupRadiance[0].x > 0.0);
    }

    // A blocker on a visible ground under a 45° sun (its shadow on x in (-1.5, -0.5)) whose shadow
    // excludes the blocker, and a point light at the other side whose shadow (x > 0.5) does not.
    void partExcludedFromShadow() {
        const Model model =
            partsModel({{QStringLiteral("Blocker"),
                         ShadowSceneBuilder().box({-0.5, 0.0, -0.5}, {0.5, 1.0, 0.5}).build()}});
        Rig rig;
        rig.ambient = V(0.05);
        rig.ground.mode = GroundMode::Visible;
        Light sun = makeLight(LightType::Directional, QStringLiteral("sun"));
        sun.direction = glm::normalize(V(-1.0, -1.0, 0.0));
        sun.shadow.enabled = true;
        const Light other = pointLight(QStringLiteral("other"), V(-3.0, 1.5, 0.0), 0.5, true);
        rig.lights = {sun, other};
        // In the sun's shadow, in the other's, the blocker's top.
        const GBuffer g = pointsRow(kView, {{V(-1.0, 0.0, 0.0), V(0, 1, 0)},
                                            {V(1.0, 0.0, 0.0), V(0, 1, 0)},
                                            {V(0.0, 1.0, 0.0), V(0, 1, 0)}});
        const ReferenceImage unlinked = reference(model, rig, g);
        rig.lights[0].link.shadow.exclude = {QStringLiteral("Blocker")};
        const ReferenceImage linked = reference(model, rig, g);
        QCOMPARE(linked.casters, 2);
        const auto code = [](const ReferenceImage& r, int pixel, int caster) {
            return int(r.visibility[size_t(pixel * r.casters + caster)]);
        };
        QCOMPARE(code(unlinked, 0, 0), 0);
        QCOMPARE(code(linked, 0, 0), 255); // no shadow of the sun from the blocker
        QVERIFY(linked.radiance[0].x > unlinked.radiance[0].x + 0.1);
        QCOMPARE(code(linked, 1, 1), 0); // the other light's shadow stays
        QVERIFY(linked.radiance[1] == unlinked.radiance[1]);
        QVERIFY(linked.radiance[2] == unlinked.radiance[2]); // the blocker still lit by the sun
        QCOMPARE(code(linked, 2, 0), 255);
        // In the sun's shadow the linked radiance is the unshadowed shading.
        QString error;
        const auto scene = makeReferenceScene(model, rig, SceneFrame{}, kView, RenderSettings(), &error);
        QVERIFY2(scene, qPrintable(error));
        const lighting::Surface<double> s = render::surfaceAt(g, 0, 0);
        const std::vector<double> lit{1.0, 1.0};
        QVERIFY(linked.radiance[0] == lighting::shadeSurface<double>(s, scene->lights, scene->settings, lit));
    }

    // Without links nothing of it is made; with links the tracer is built even without casters.
    void linkingOnlyWhenLinked() {
        const Model model =
            partsModel({{QStringLiteral("A"), ShadowSceneBuilder().box({-2, 0, -0.5}, {-1, 1, 0.5}).build()},
                        {QStringLiteral("B"), ShadowSceneBuilder().box({1, 0, -0.5}, {2, 1, 0.5}).build()}});
        Rig rig;
        rig.lights = {pointLight(QStringLiteral("key"), V(0.0, 2.0, 0.0), 1.0, false)};
        QString error;
        auto plain = makeReferenceScene(model, rig, SceneFrame{}, kView, RenderSettings(), &error);
        QVERIFY(plain && !plain->linked() && !plain->tracer);
        rig.lights[0].link.lit.exclude = {QStringLiteral("B")};
        auto linked = makeReferenceScene(model, rig, SceneFrame{}, kView, RenderSettings(), &error);
        QVERIFY(linked && linked->linked() && linked->tracer && linked->casters() == 0);
        QCOMPARE(linked->lightsAt(0)[0].color, plain->lights[0].color);
        QCOMPARE(linked->lightsAt(1)[0].color, V(0.0));
        QCOMPARE(linked->lightsAt(-1)[0].color, plain->lights[0].color); // unknown part: unlinked
    }
};

QTEST_GUILESS_MAIN(TestReferenceLink)
#include "tst_referencelink.moc"
