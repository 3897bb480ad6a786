// Model import basics on small hand-made files (tests/data/model, written by make_test_data.py), the
// bundled Suzanne resource, a file built here and the analytic sphere, plane and ground: geometry, vertex
// colours, a glTF's hierarchy, lights and camera, progress and cancelling. Expected values come from the
// files' own data, not from the loader. Materials: tst_modelmaterials; broken input: tst_modelhostile.
#include "model/ground.h"
#include "model/modelloader.h"
#include "modelchecks.h"
#include "modelimport.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QQuaternion>
#include <QTemporaryDir>
#include <QTest>
#include <QVector3D>
#include <cmath>
#include <numbers>

using namespace lr;
using namespace lr::test;

namespace {

glm::dvec3 vec3Of(const QJsonValue& v, glm::dvec3 fallback) {
    const QJsonArray a = v.toArray();
    return a.size() == 3 ? glm::dvec3(a[0].toDouble(), a[1].toDouble(), a[2].toDouble()) : fallback;
}

// Rotates v by the glTF node's rotation quaternion [x, y, z, w] (identity when absent).
glm::dvec3 rotateByNode(const QJsonObject& node, const glm::dvec3& v) {
    const QJsonArray q = node.value(QStringLiteral("rotation")).toArray();
    if (q.size() != 4) return v;
    const QQuaternion rot(float(q[3].toDouble()), float(q[0].toDouble()), float(q[1].toDouble()),
                          float(q[2].toDouble()));
    const QVector3D r = rot.rotatedVector(QVector3D(float(v.x), float(v.y), float(v.z)));
    return glm::dvec3(r.x(), r.y(), r.z());
}

const Vertex* vertexAt(const Model& m, const glm::dvec3& world) {
    for (const Mesh& mesh : m.meshes)
        for (const Vertex& v : mesh.vertices)
            if (near(glm::dvec3(v.position) + m.origin, world, 1e-5)) return &v;
    return nullptr;
}

QRgb sample(const QImage& image, glm::vec2 uv) {
    const int x = std::clamp(int(uv.x * float(image.width())), 0, image.width() - 1);
    const int y = std::clamp(int(uv.y * float(image.height())), 0, image.height() - 1);
    return image.pixel(x, y);
}

} // namespace

class TestModel : public QObject {
    Q_OBJECT
  private slots:
    // The ground lies under the model's lowest point, centred on it, kGroundExtent radii wide, facing up.
    void groundPlaneUnderTheModel() {
        Bounds b;
        b.min = {-1.0, -2.0, 3.0};
        b.max = {3.0, 4.0, 5.0};
        const GroundPlane g = groundPlane(b);
        QCOMPARE(g.height, -2.0);
        const double half = 0.5 * kGroundExtent * b.radius();
        glm::dvec3 sum(0.0);
        for (const glm::dvec3& c : g.corners) {
            QCOMPARE(c.y, -2.0);
            QCOMPARE(std::max(std::abs(c.x - 1.0), std::abs(c.z - 4.0)), half);
            sum += c;
        }
        QVERIFY(glm::length(sum / 4.0 - glm::dvec3(1.0, -2.0, 4.0)) < 1e-12);
        const glm::dvec3 n = glm::cross(g.corners[1] - g.corners[0], g.corners[3] - g.corners[0]);
        QVERIFY(glm::dot(n, g.normal) > 0.0); // counter-clockwise seen from above
        QCOMPARE(g.normal, glm::dvec3(0.0, 1.0, 0.0));
    }

    void sphereIsExact();
    void planeFacesPlusZ();
    void objWithMaterialAndTexture();
    void stlNormalsPointOutward();
    void plyVertexColours();
    void gltfHierarchyLightsCameraNormalMap();
    void bundledSuzanneFromResources();
    void farFromOriginKeepsPrecision();
    void progressAndCancel();
    void importableSuffixesListTheCommonFormats();
};

void TestModel::sphereIsExact() {
    const glm::dvec3 center(1.0, -2.0, 1e6);
    const double radius = 2.5;
    const Model m = makeSphere(radius, 32, 16, center);
    QCOMPARE(test::modelProblems(m), QString());
    QCOMPARE(m.meshes.size(), size_t(1));
    QVERIFY(near(m.origin, center, 0.0));
    QVERIFY(near(m.bounds.min, center - glm::dvec3(radius), 1e-12));
    QVERIFY(near(m.bounds.max, center + glm::dvec3(radius), 1e-12));
    const Mesh& mesh = m.meshes.front();
    for (const Vertex& v : mesh.vertices) {
        QVERIFY(std::abs(glm::length(glm::dvec3(v.position)) - radius) < 1e-5);
        QVERIFY(glm::length(v.normal - glm::normalize(v.position)) < 1e-6f);
    }
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[t]].position,
                        b = mesh.vertices[mesh.indices[t + 1]].position,
                        c = mesh.vertices[mesh.indices[t + 2]].position;
        QVERIFY2(glm::length(glm::cross(b - a, c - a)) > 1e-6f, "zero-area triangle in the sphere");
    }
    QCOMPARE(test::clockwiseTriangles(mesh), size_t(0));
    QCOMPARE(test::tangentFrameMismatches(mesh), size_t(0));
}

void TestModel::planeFacesPlusZ() {
    const Model m = makePlane(3.0, glm::dvec3(0.0, 0.0, -4.0));
    QCOMPARE(test::modelProblems(m), QString());
    const Mesh& mesh = m.meshes.front();
    QCOMPARE(mesh.indices.size(), size_t(6));
    for (const Vertex& v : mesh.vertices) {
        QCOMPARE(v.normal, glm::vec3(0.0f, 0.0f, 1.0f));
        QCOMPARE(v.position.z, 0.0f);
        QCOMPARE(std::abs(v.position.x), 3.0f);
    }
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[t]].position,
                        b = mesh.vertices[mesh.indices[t + 1]].position,
                        c = mesh.vertices[mesh.indices[t + 2]].position;
        QVERIFY(glm::cross(b - a, c - a).z > 0.0f); // counter-clockwise seen from +Z
    }
    QCOMPARE(m.bounds.min, glm::dvec3(-3.0, -3.0, -4.0));
    QCOMPARE(m.bounds.max, glm::dvec3(3.0, 3.0, -4.0));
    // uv (0, 0) is the image's top-left: the corner at -x, +y.
    const Vertex* topLeft = vertexAt(m, glm::dvec3(-3.0, 3.0, -4.0));
    QVERIFY(topLeft);
    QCOMPARE(topLeft->uv, glm::vec2(0.0f, 0.0f));
    QCOMPARE(test::tangentFrameMismatches(mesh), size_t(0));
}

void TestModel::objWithMaterialAndTexture() {
    const auto m = mustLoad(dataFile(QStringLiteral("quad.obj")));
    QVERIFY(m);
    QCOMPARE(test::modelProblems(*m), QString());
    QCOMPARE(m->triangleCount(), size_t(2));
    const Mesh& mesh = m->meshes.front();
    const Material& mat = m->materials[size_t(mesh.material)];
    QCOMPARE(mat.name, QStringLiteral("checker"));
    QCOMPARE(mat.baseColor, glm::vec4(0.5f, 0.25f, 1.0f, 1.0f)); // Kd
    QCOMPARE(mat.specular, glm::vec3(0.2f));                     // Ks
    QCOMPARE(mat.shininess, 50.0f);                              // Ns
    QVERIFY(mat.baseColorTexture >= 0);
    const QImage& image = m->textures[size_t(mat.baseColorTexture)].image;
    QCOMPARE(image.size(), QSize(2, 2));
    QCOMPARE(image.format(), QImage::Format_RGBA8888);
    QCOMPARE(image.pixel(0, 0), qRgb(255, 0, 0)); // stored as in the file, top row first
    // Each corner samples the texel the OBJ's (bottom-left origin) UVs put there.
    const struct {
        glm::dvec3 position;
        QRgb color;
    } corners[] = {{{-1, 1, 0}, qRgb(255, 0, 0)},
                   {{1, 1, 0}, qRgb(0, 255, 0)},
                   {{-1, -1, 0}, qRgb(0, 0, 255)},
                   {{1, -1, 0}, qRgb(255, 255, 255)}};
    for (const auto& c : corners) {
        const Vertex* v = vertexAt(*m, c.position);
        QVERIFY(v);
        const glm::vec2 inside = v->uv * 0.98f + glm::vec2(0.01f); // pull corner UVs into their texel
        QCOMPARE(sample(image, inside), c.color);
    }
    QCOMPARE(test::clockwiseTriangles(mesh), size_t(0));
}

void TestModel::stlNormalsPointOutward() {
    const auto m = mustLoad(dataFile(QStringLiteral("tetra.stl")));
    QVERIFY(m);
    QCOMPARE(test::modelProblems(*m), QString());
    QCOMPARE(m->triangleCount(), size_t(4));
    QVERIFY(near(m->bounds.center(), glm::dvec3(0.0), 1e-9));
    for (const Mesh& mesh : m->meshes) {
        QCOMPARE(test::clockwiseTriangles(mesh), size_t(0));
        for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
            glm::dvec3 centroid(0.0);
            for (int k = 0; k < 3; ++k)
                centroid += glm::dvec3(mesh.vertices[mesh.indices[t + k]].position) + m->origin;
            QVERIFY(glm::dot(glm::dvec3(mesh.vertices[mesh.indices[t]].normal), centroid) > 0.0);
        }
    }
}

void TestModel::plyVertexColours() {
    const auto m = mustLoad(dataFile(QStringLiteral("colors.ply")));
    QVERIFY(m);
    QCOMPARE(test::modelProblems(*m), QString());
    QVERIFY(m->meshes.front().hasVertexColors);
    const struct {
        glm::dvec3 position;
        glm::vec4 color;
    } expected[] = {{{0, 0, 0}, {1, 0, 0, 1}}, {{1, 0, 0}, {0, 1, 0, 1}}, {{1, 1, 0}, {0, 0, 1, 1}}};
    for (const auto& e : expected) {
        const Vertex* v = vertexAt(*m, e.position);
        QVERIFY(v);
        QVERIFY(glm::length(v->color - e.color) < 1e-6f);
    }
}

void TestModel::gltfHierarchyLightsCameraNormalMap() {
    const QString path = dataFile(QStringLiteral("scene.gltf"));
    const QJsonObject json = readJson(path);
    QVERIFY(!json.isEmpty());
    const QJsonArray nodes = json[QStringLiteral("nodes")].toArray();
    const auto m = mustLoad(path);
    QVERIFY(m);
    QCOMPARE(test::modelProblems(*m), QString());

    // Geometry: the square instanced by a scaled child and a mirrored node under a translated parent.
    QCOMPARE(m->meshes.size(), size_t(2));
    const glm::dvec3 parent = vec3Of(nodes[0][QStringLiteral("translation")], {});
    const glm::dvec3 childScale = vec3Of(nodes[1][QStringLiteral("scale")], glm::dvec3(1.0));
    const glm::dvec3 mirrorT = vec3Of(nodes[2][QStringLiteral("translation")], {});
    const glm::dvec3 lo = parent - 0.5 * childScale, hi = parent + 0.5 * childScale; // square is [-0.5, 0.5]²
    const glm::dvec3 mirrorHi = parent + mirrorT + glm::dvec3(0.5);
    QVERIFY(near(m->bounds.min, glm::dvec3(lo.x, lo.y, 0.0), 1e-6));
    QVERIFY(near(m->bounds.max, glm::dvec3(hi.x, mirrorHi.y, 0.0), 1e-6));
    QVERIFY(near(m->origin, m->bounds.center(), 0.0));
    for (const Mesh& mesh : m->meshes) {
        QVERIFY(mesh.hasVertexColors);
        QVERIFY(mesh.hasTangents);
        for (const Vertex& v : mesh.vertices)
            QCOMPARE(v.normal, glm::vec3(0.0f, 0.0f, 1.0f));
        QCOMPARE(test::clockwiseTriangles(mesh), size_t(0)); // the mirrored instance was re-wound
        QCOMPARE(test::tangentFrameMismatches(mesh), size_t(0));
    }
    // COLOR_0 of the vertex at (-0.5, -0.5) is red; in the child instance it sits at parent - scale/2.
    const Vertex* red = vertexAt(*m, glm::dvec3(lo.x, lo.y, 0.0));
    QVERIFY(red);
    QCOMPARE(red->color, glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));

    // Material: factors, normal map (external PNG), double-sided.
    const QJsonObject jm = json[QStringLiteral("materials")][0].toObject();
    const Material& mat = m->materials[size_t(m->meshes.front().material)];
    QCOMPARE(mat.name, jm[QStringLiteral("name")].toString());
    QVERIFY(near(glm::dvec3(mat.emissive), vec3Of(jm[QStringLiteral("emissiveFactor")], {}), 1e-6));
    QCOMPARE(
        mat.baseColor.r,
        float(jm[QStringLiteral("pbrMetallicRoughness")][QStringLiteral("baseColorFactor")][0].toDouble()));
    QCOMPARE(mat.doubleSided, true);
    QCOMPARE(mat.baseColorTexture, -1);
    QVERIFY(mat.normalTexture >= 0);
    QCOMPARE(m->textures[size_t(mat.normalTexture)].image.pixel(0, 0), qRgb(128, 128, 255));

    // Lights: type, place, direction (-Z rotated by the node), colour x intensity, range, cone.
    const QJsonArray lights =
        json[QStringLiteral("extensions")][QStringLiteral("KHR_lights_punctual")][QStringLiteral("lights")]
            .toArray();
    QCOMPARE(m->lights.lights.size(), size_t(lights.size()));
    QVERIFY(m->lights.space == RigSpace::World);
    for (const Light& l : m->lights.lights) {
        QJsonObject node, jl;
        for (const QJsonValue& n : nodes)
            if (n[QStringLiteral("name")].toString() == l.name) node = n.toObject();
        QVERIFY2(!node.isEmpty(), qPrintable(l.name));
        jl = lights[node[QStringLiteral("extensions")][QStringLiteral("KHR_lights_punctual")]
                        [QStringLiteral("light")]
                            .toInt()]
                 .toObject();
        const glm::dvec3 radiance =
            vec3Of(jl[QStringLiteral("color")], glm::dvec3(1.0)) * jl[QStringLiteral("intensity")].toDouble();
        QVERIFY(near(l.color * l.intensity, radiance, 1e-5));
        QVERIFY(std::abs(std::max({l.color.r, l.color.g, l.color.b}) - 1.0) < 1e-12);
        QVERIFY(near(l.direction, rotateByNode(node, glm::dvec3(0, 0, -1)), 1e-6));
        const QString type = jl[QStringLiteral("type")].toString();
        if (type == QLatin1String("spot")) {
            QVERIFY(l.type == LightType::Spot);
            QVERIFY(near(l.position, vec3Of(node[QStringLiteral("translation")], {}), 1e-6));
            QVERIFY(l.falloff.model == FalloffModel::InverseSquare);
            QCOMPARE(l.falloff.range, jl[QStringLiteral("range")].toDouble());
            QVERIFY(l.cone.model == ConeModel::Smooth);
            const QJsonObject spot = jl[QStringLiteral("spot")].toObject();
            const double toDeg = 180.0 / std::numbers::pi;
            // glTF's inner 0 comes in as the smallest inner angle the rig's smooth cone takes (1e-3°).
            const double inner = std::max(spot[QStringLiteral("innerConeAngle")].toDouble() * toDeg, 1e-3);
            QVERIFY(std::abs(l.cone.inner - inner) < 1e-4);
            QVERIFY(std::abs(l.cone.outer - spot[QStringLiteral("outerConeAngle")].toDouble() * toDeg) <
                    1e-4);
        } else {
            QCOMPARE(type, QStringLiteral("directional"));
            QVERIFY(l.type == LightType::Directional);
        }
    }

    // Camera: at its node, looking down the node's -Z, glTF's yfov and aspect.
    QCOMPARE(m->cameras.size(), size_t(1));
    const Camera& cam = m->cameras.front();
    const QJsonObject persp = json[QStringLiteral("cameras")][0][QStringLiteral("perspective")].toObject();
    QVERIFY(near(cam.position, vec3Of(nodes[5][QStringLiteral("translation")], {}), 1e-6));
    QVERIFY(near(cam.forward, glm::dvec3(0, 0, -1), 1e-9));
    QVERIFY(near(cam.up, glm::dvec3(0, 1, 0), 1e-9));
    QVERIFY(std::abs(cam.yfovDegrees - persp[QStringLiteral("yfov")].toDouble() * 180.0 / std::numbers::pi) <
            1e-4);
    QVERIFY(std::abs(cam.aspect - persp[QStringLiteral("aspectRatio")].toDouble()) < 1e-6);
    QVERIFY(std::abs(cam.znear - persp[QStringLiteral("znear")].toDouble()) < 1e-6);
    QVERIFY(std::abs(cam.zfar - persp[QStringLiteral("zfar")].toDouble()) < 1e-6);
}

void TestModel::bundledSuzanneFromResources() {
    const QString path = QStringLiteral(":/resources/models/suzanne/Suzanne.gltf");
    const QJsonObject json = readJson(path);
    QVERIFY(!json.isEmpty());
    std::size_t expectedTriangles = 0;
    for (const QJsonValue& mesh : json[QStringLiteral("meshes")].toArray())
        for (const QJsonValue& prim : mesh[QStringLiteral("primitives")].toArray())
            expectedTriangles += size_t(json[QStringLiteral("accessors")]
                                            [prim[QStringLiteral("indices")].toInt()][QStringLiteral("count")]
                                                .toInt()) /
                                 3;
    const auto m = mustLoad(path);
    QVERIFY(m);
    QCOMPARE(test::modelProblems(*m), QString());
    QCOMPARE(m->triangleCount(), expectedTriangles);
    const Material& mat = m->materials[size_t(m->meshes.front().material)];
    QVERIFY(mat.baseColorTexture >= 0);
    const Texture& tex = m->textures[size_t(mat.baseColorTexture)];
    QVERIFY(tex.name.startsWith(QStringLiteral(":/resources/models/suzanne/")));
    QVERIFY(tex.image.width() > 1 && tex.image.height() > 1);
    QVERIFY(m->warnings.isEmpty());
}

void TestModel::farFromOriginKeepsPrecision() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const QString path = tmp.filePath(QStringLiteral("far.obj"));
    // Values exactly representable in float; far apart from the world origin, close to each other.
    QVERIFY(writeFile(
        path, "v 4000000.5 -3000000 1000000\nv 4000001 -3000000 1000000\nv 4000000.5 -2999999.5 1000000\n"
              "f 1 2 3\n"));
    const auto m = mustLoad(path);
    QVERIFY(m);
    QCOMPARE(m->origin, glm::dvec3(4000000.75, -2999999.75, 1000000.0));
    const Vertex* v = vertexAt(*m, glm::dvec3(4000000.5, -3000000.0, 1000000.0));
    QVERIFY(v);
    QCOMPARE(v->position, glm::vec3(-0.25f, -0.25f, 0.0f)); // exact, not rounded to float steps of 0.25-0.5
}

void TestModel::progressAndCancel() {
    const QString path = dataFile(QStringLiteral("scene.gltf"));
    std::vector<double> seen;
    ModelLoadOptions options;
    options.progress = [&](double f) {
        seen.push_back(f);
        return true;
    };
    QVERIFY(loadModel(path, options).ok());
    QVERIFY(seen.size() >= 2);
    QCOMPARE(seen.back(), 1.0);
    for (std::size_t i = 0; i < seen.size(); ++i) {
        QVERIFY(seen[i] >= 0.0 && seen[i] <= 1.0);
        if (i) QVERIFY(seen[i] >= seen[i - 1]);
    }
    // Cancelling at any report ends the load with a "cancelled" error and no model.
    for (std::size_t stopAt = 0; stopAt < seen.size(); ++stopAt) {
        std::size_t calls = 0;
        ModelLoadOptions cancel;
        cancel.progress = [&](double) { return calls++ < stopAt; };
        const ModelLoadResult r = loadModel(path, cancel);
        QVERIFY(!r.ok());
        QVERIFY(r.cancelled);
        QCOMPARE(r.error, QStringLiteral("could not import %1: cancelled").arg(path));
    }
}

void TestModel::importableSuffixesListTheCommonFormats() {
    const QStringList suffixes = importableSuffixes();
    for (const char* s : {"obj", "gltf", "glb", "fbx", "ply", "stl", "dae", "3ds"})
        QVERIFY2(suffixes.contains(QLatin1String(s)), s);
    QVERIFY(modelFileFilter().contains(QStringLiteral("*.gltf")));
}

QTEST_GUILESS_MAIN(TestModel)
#include "tst_model.moc"
