// Model import on small hand-made files (tests/data/model, written by make_test_data.py), the bundled
// Suzanne resource, files built here (degenerate geometry, paths leaving the folder), and the analytic
// sphere and plane. Expected values come from the files' own data, not from the loader.
#include "core/rigjson.h"
#include "model/ground.h"
#include "model/importdetail.h"
#include "model/modelloader.h"
#include "modelchecks.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QQuaternion>
#include <QTemporaryDir>
#include <QTest>
#include <QVector3D>
#include <assimp/material.h>
#include <cmath>
#include <numbers>

using namespace lr;

namespace {

QString dataFile(const QString& name) {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/model/") + name;
}

bool writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

QJsonObject readJson(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

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

bool near(const glm::dvec3& a, const glm::dvec3& b, double tol) {
    return glm::length(a - b) <= tol;
}

std::shared_ptr<Model> mustLoad(const QString& path, const ModelLoadOptions& options = {}) {
    ModelLoadResult r = loadModel(path, options);
    if (!r.ok()) qWarning("%s", qPrintable(r.error));
    return r.model;
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

const Material* materialNamed(const Model& m, const QString& name) {
    for (const Material& mat : m.materials)
        if (mat.name == name) return &mat;
    return nullptr;
}

QJsonObject jsonMaterialNamed(const QJsonObject& gltf, const QString& name) {
    for (const QJsonValue& v : gltf.value(QStringLiteral("materials")).toArray())
        if (v.toObject().value(QStringLiteral("name")).toString() == name) return v.toObject();
    return {};
}

// KHR_texture_transform of a textureInfo, as the file writes it.
TextureTransform jsonTransform(const QJsonObject& textureInfo) {
    const QJsonObject x = textureInfo.value(QStringLiteral("extensions"))
                              .toObject()
                              .value(QStringLiteral("KHR_texture_transform"))
                              .toObject();
    TextureTransform t;
    const QJsonArray offset = x.value(QStringLiteral("offset")).toArray({0.0, 0.0});
    const QJsonArray scale = x.value(QStringLiteral("scale")).toArray({1.0, 1.0});
    t.offset = {float(offset[0].toDouble()), float(offset[1].toDouble())};
    t.rotation = float(x.value(QStringLiteral("rotation")).toDouble(0.0));
    t.scale = {float(scale[0].toDouble()), float(scale[1].toDouble())};
    return t;
}

bool nearTransform(const TextureTransform& a, const TextureTransform& b) {
    return glm::length(a.offset - b.offset) < 1e-5f && std::abs(a.rotation - b.rotation) < 1e-6f &&
           glm::length(a.scale - b.scale) < 1e-6f;
}

QString transformText(const TextureTransform& t) {
    return QStringLiteral("offset (%1, %2) rotation %3 scale (%4, %5)")
        .arg(t.offset.x)
        .arg(t.offset.y)
        .arg(t.rotation)
        .arg(t.scale.x)
        .arg(t.scale.y);
}

// The warnings that mention all of `words`.
QStringList warningsWith(const Model& m, const QStringList& words) {
    QStringList out;
    for (const QString& w : m.warnings)
        if (std::all_of(words.begin(), words.end(), [&](const QString& word) { return w.contains(word); }))
            out << w;
    return out;
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
    void gltfMetalRoughMaterials();
    void gltfOutOfRangeValuesAreClampedWithWarnings();
    void gltfEmissiveStrengthFindsItsMaterial();
    void undecodableTexturesNameTheirRole();
    void specularGlossinessWarns();
    void textureTransformInvertsAssimpsConversion();
    void objShininessConvertsToRoughness();
    void bundledSuzanneFromResources();
    void referencesOutsideTheFolderAreRefused();
    void degenerateGeometryIsDroppedWithWarnings();
    void farFromOriginKeepsPrecision();
    void progressAndCancel();
    void dataUriLimit();
    void hostileHeadersAndPlyCommentsAreRefused();
    void coincidentVerticesSkipSmoothing();
    void modelLightsGetTheRigLimits();
    void unusableCameraIsIgnored();
    void errorsNameTheFile();
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
            QVERIFY(std::abs(l.cone.inner - spot[QStringLiteral("innerConeAngle")].toDouble() * toDeg) <
                    1e-4);
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

// tests/data/model/pbr.gltf: each material exercises part of glTF's metal-rough model; the expected values
// are read from the file's JSON. Textures are data URIs of distinct sizes, so each role is told by size.
void TestModel::gltfMetalRoughMaterials() {
    const QString path = dataFile(QStringLiteral("pbr.gltf"));
    const auto m = mustLoad(path);
    QVERIFY(m);
    QCOMPARE(test::modelProblems(*m), QString());
    QVERIFY(m->hasPbrMaterials());
    const QJsonObject gltf = readJson(path);
    const auto factor = [](const QJsonObject& o, const char* key, double fallback) {
        return float(o.value(QLatin1String(key)).toDouble(fallback));
    };
    const auto textureSize = [&](int t) { return t >= 0 ? m->textures[size_t(t)].image.size() : QSize(); };

    const Material* mr = materialNamed(*m, QStringLiteral("metalRough"));
    QVERIFY(mr);
    const QJsonObject jmr = jsonMaterialNamed(gltf, mr->name);
    const QJsonObject pbr = jmr.value(QStringLiteral("pbrMetallicRoughness")).toObject();
    QVERIFY(mr->pbr);
    QCOMPARE(mr->metallic, factor(pbr, "metallicFactor", 1.0));
    QCOMPARE(mr->roughness, factor(pbr, "roughnessFactor", 1.0));
    QVERIFY(mr->alphaMode == AlphaMode::Mask);
    QCOMPARE(mr->alphaCutoff, factor(jmr, "alphaCutoff", 0.5));
    QVERIFY(mr->doubleSided);
    const QJsonArray base = pbr.value(QStringLiteral("baseColorFactor")).toArray();
    QCOMPARE(mr->baseColor, glm::vec4(float(base[0].toDouble()), float(base[1].toDouble()),
                                      float(base[2].toDouble()), float(base[3].toDouble())));
    // The metallic-roughness texture (3x1): G = roughness, B = metallic, stored as in the file.
    QCOMPARE(textureSize(mr->metallicRoughnessTexture), QSize(3, 1));
    const QImage& mrImage = m->textures[size_t(mr->metallicRoughnessTexture)].image;
    QCOMPARE(QColor(mrImage.pixel(0, 0)), QColor(0, 64, 192));
    QCOMPARE(textureSize(mr->occlusionTexture), QSize(1, 3));
    QCOMPARE(mr->occlusionStrength,
             factor(jmr.value(QStringLiteral("occlusionTexture")).toObject(), "strength", 1.0));
    QCOMPARE(textureSize(mr->normalTexture), QSize(1, 1));
    QCOMPARE(mr->normalScale, factor(jmr.value(QStringLiteral("normalTexture")).toObject(), "scale", 1.0));
    QVERIFY2(nearTransform(mr->metallicRoughnessTransform,
                           jsonTransform(pbr.value(QStringLiteral("metallicRoughnessTexture")).toObject())),
             qPrintable(transformText(mr->metallicRoughnessTransform)));
    QVERIFY2(nearTransform(mr->occlusionTransform,
                           jsonTransform(jmr.value(QStringLiteral("occlusionTexture")).toObject())),
             qPrintable(transformText(mr->occlusionTransform)));
    QVERIFY(mr->normalTransform.isIdentity());
    QVERIFY(mr->baseColorTransform.isIdentity());

    const Material* blend = materialNamed(*m, QStringLiteral("blend"));
    QVERIFY(blend);
    QVERIFY(blend->alphaMode == AlphaMode::Blend);
    QCOMPARE(blend->baseColor.a, 0.4f);
    QCOMPARE(blend->metallic, 1.0f); // glTF's defaults
    QCOMPARE(blend->roughness, 1.0f);
    QCOMPARE(blend->metallicRoughnessTexture, -1);

    // KHR_texture_transform with offset, rotation and scale; KHR_materials_emissive_strength.
    const Material* xf = materialNamed(*m, QStringLiteral("transformed"));
    QVERIFY(xf);
    const QJsonObject jxf = jsonMaterialNamed(gltf, xf->name);
    const TextureTransform expectedBase = jsonTransform(jxf.value(QStringLiteral("pbrMetallicRoughness"))
                                                            .toObject()
                                                            .value(QStringLiteral("baseColorTexture"))
                                                            .toObject());
    QVERIFY(expectedBase.rotation != 0.0f && expectedBase.scale != glm::vec2(1.0f) &&
            expectedBase.offset != glm::vec2(0.0f));
    QVERIFY2(nearTransform(xf->baseColorTransform, expectedBase),
             qPrintable(transformText(xf->baseColorTransform)));
    QVERIFY2(nearTransform(xf->emissiveTransform,
                           jsonTransform(jxf.value(QStringLiteral("emissiveTexture")).toObject())),
             qPrintable(transformText(xf->emissiveTransform)));
    QCOMPARE(textureSize(xf->baseColorTexture), QSize(2, 2));
    QCOMPARE(textureSize(xf->emissiveTexture), QSize(2, 3));
    const double strength = jxf.value(QStringLiteral("extensions"))
                                .toObject()
                                .value(QStringLiteral("KHR_materials_emissive_strength"))
                                .toObject()
                                .value(QStringLiteral("emissiveStrength"))
                                .toDouble();
    QVERIFY(strength > 1.0);
    const QJsonArray e = jxf.value(QStringLiteral("emissiveFactor")).toArray();
    for (int i = 0; i < 3; ++i)
        QCOMPARE(xf->emissive[i], float(e[i].toDouble() * strength));

    // An occlusion texture on TEXCOORD_1: not used, with a warning naming the file, material and role.
    const Material* uv1 = materialNamed(*m, QStringLiteral("secondUv"));
    QVERIFY(uv1);
    QCOMPARE(uv1->occlusionTexture, -1);
    QVERIFY(uv1->baseColorTexture >= 0);
    QCOMPARE(warningsWith(*m, {QStringLiteral("pbr.gltf"), QStringLiteral("\"secondUv\""),
                               QStringLiteral("occlusion texture"), QStringLiteral("UV set 1")})
                 .size(),
             1);
}

void TestModel::gltfOutOfRangeValuesAreClampedWithWarnings() {
    const auto m = mustLoad(dataFile(QStringLiteral("pbr.gltf")));
    QVERIFY(m);
    const Material* bad = materialNamed(*m, QStringLiteral("outOfRange"));
    QVERIFY(bad);
    QCOMPARE(bad->metallic, 0.0f);          // -0.5
    QCOMPARE(bad->roughness, 1.0f);         // 2.5
    QCOMPARE(bad->alphaCutoff, 0.0f);       // -1
    QCOMPARE(bad->occlusionStrength, 1.0f); // 3
    for (const char* field :
         {"metallicFactor -0.5", "roughnessFactor 2.5", "alphaCutoff -1", "occlusion strength 3"})
        QVERIFY2(warningsWith(*m, {QStringLiteral("pbr.gltf"), QStringLiteral("\"outOfRange\""),
                                   QLatin1String(field), QStringLiteral("clamped")})
                         .size() == 1,
                 qPrintable(QStringLiteral("%1 in [%2]").arg(QLatin1String(field), m->warnings.join(u"; "))));
    // The values in range warn about nothing.
    QVERIFY(warningsWith(*m, {QStringLiteral("\"metalRough\"")}).isEmpty());
}

// Assimp numbers materials in the order meshes use them, so KHR_materials_emissive_strength (read from the
// JSON) is matched by name and emissive factor: same name, other factor -> its own strength; same name and
// factor with different strengths -> 1 and a warning. pbr.gltf's five primitives get five new materials.
void TestModel::gltfEmissiveStrengthFindsItsMaterial() {
    QJsonObject gltf = readJson(dataFile(QStringLiteral("pbr.gltf")));
    const auto material = [](const char* name, QJsonArray factor, double strength) {
        QJsonObject m{{QStringLiteral("emissiveFactor"), factor},
                      {QStringLiteral("extensions"),
                       QJsonObject{{QStringLiteral("KHR_materials_emissive_strength"),
                                    QJsonObject{{QStringLiteral("emissiveStrength"), strength}}}}}};
        if (name) m.insert(QStringLiteral("name"), QLatin1String(name));
        return m;
    };
    // Used in reverse order, so Assimp's numbering differs from the file's.
    gltf[QStringLiteral("materials")] =
        QJsonArray{material("glow", {1.0, 0.0, 0.0}, 5.0), material("glow", {0.0, 1.0, 0.0}, 7.0),
                   material("lamp", {1.0, 1.0, 1.0}, 2.0), material("lamp", {1.0, 1.0, 1.0}, 3.0),
                   material(nullptr, {0.0, 0.0, 0.5}, 6.0)};
    QJsonArray meshes = gltf[QStringLiteral("meshes")].toArray();
    QJsonObject mesh = meshes[0].toObject();
    QJsonArray primitives = mesh[QStringLiteral("primitives")].toArray();
    for (int i = 0; i < primitives.size(); ++i) {
        QJsonObject p = primitives[i].toObject();
        p[QStringLiteral("material")] = int(primitives.size()) - 1 - i;
        primitives[i] = p;
    }
    mesh[QStringLiteral("primitives")] = primitives;
    meshes[0] = mesh;
    gltf[QStringLiteral("meshes")] = meshes;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("strength.gltf"));
    QVERIFY(writeFile(path, QJsonDocument(gltf).toJson()));
    const auto m = mustLoad(path);
    QVERIFY(m);
    const auto emissive = [&](const glm::vec3& factor) {
        for (const Material& mat : m->materials)
            for (float s : {1.0f, 2.0f, 3.0f, 5.0f, 6.0f, 7.0f})
                if (glm::length(mat.emissive - factor * s) < 1e-6f) return s;
        return 0.0f;
    };
    QCOMPARE(emissive({1.0f, 0.0f, 0.0f}), 5.0f);
    QCOMPARE(emissive({0.0f, 1.0f, 0.0f}), 7.0f);
    QCOMPARE(emissive({0.0f, 0.0f, 0.5f}), 6.0f);
    QCOMPARE(emissive({1.0f, 1.0f, 1.0f}), 1.0f);
    QCOMPARE(warningsWith(*m, {QStringLiteral("strength.gltf: material \"lamp\""),
                               QStringLiteral("different KHR_materials_emissive_strength")})
                 .size(),
             2);
}

// pbr.gltf with its metallic-roughness (image 1) and occlusion (image 2) images broken: not used, and the
// warnings say which role lost its texture.
void TestModel::undecodableTexturesNameTheirRole() {
    QJsonObject gltf = readJson(dataFile(QStringLiteral("pbr.gltf")));
    QJsonArray images = gltf[QStringLiteral("images")].toArray();
    for (int i : {1, 2})
        images[i] = QJsonObject{{QStringLiteral("uri"), QStringLiteral("data:image/png;base64,AAAA")}};
    gltf[QStringLiteral("images")] = images;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("broken.gltf"));
    QVERIFY(writeFile(path, QJsonDocument(gltf).toJson()));
    const auto m = mustLoad(path);
    QVERIFY(m);
    QCOMPARE(test::modelProblems(*m), QString());
    const Material* mr = materialNamed(*m, QStringLiteral("metalRough"));
    QVERIFY(mr);
    QCOMPARE(mr->metallicRoughnessTexture, -1);
    QCOMPARE(mr->occlusionTexture, -1);
    QVERIFY(mr->normalTexture >= 0);
    for (const char* role : {"metallic-roughness texture", "occlusion texture"})
        QVERIFY2(warningsWith(*m, {QStringLiteral("broken.gltf: "), QLatin1String(role),
                                   QStringLiteral("could not decode")})
                         .size() == 1,
                 qPrintable(m->warnings.join(u"; ")));
}

// KHR_materials_pbrSpecularGlossiness (archived by Khronos): the metal-rough values are used, with a warning.
void TestModel::specularGlossinessWarns() {
    QJsonObject gltf = readJson(dataFile(QStringLiteral("pbr.gltf")));
    QJsonArray used = gltf[QStringLiteral("extensionsUsed")].toArray();
    used.append(QStringLiteral("KHR_materials_pbrSpecularGlossiness"));
    gltf[QStringLiteral("extensionsUsed")] = used;
    QJsonArray materials = gltf[QStringLiteral("materials")].toArray();
    QJsonObject blend = materials[1].toObject();
    blend[QStringLiteral("extensions")] =
        QJsonObject{{QStringLiteral("KHR_materials_pbrSpecularGlossiness"),
                     QJsonObject{{QStringLiteral("diffuseFactor"), QJsonArray{0.5, 0.5, 0.5, 1.0}},
                                 {QStringLiteral("glossinessFactor"), 0.8}}}};
    materials[1] = blend;
    gltf[QStringLiteral("materials")] = materials;
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("specgloss.gltf"));
    QVERIFY(writeFile(path, QJsonDocument(gltf).toJson()));
    const auto m = mustLoad(path);
    QVERIFY(m);
    const Material* mat = materialNamed(*m, QStringLiteral("blend"));
    QVERIFY(mat);
    QVERIFY(mat->pbr);
    QCOMPARE(mat->baseColor.a, 0.4f); // the metal-rough baseColorFactor
    QCOMPARE(warningsWith(*m, {QStringLiteral("specgloss.gltf: material \"blend\""),
                               QStringLiteral("KHR_materials_pbrSpecularGlossiness is not supported")})
                 .size(),
             1);
}

// Assimp 5.2.5 turns KHR_texture_transform into an aiUVTransform (glTF2Importer.cpp); the importer inverts
// that. Forward conversion written here as Assimp does it, for rotations in every quadrant.
void TestModel::textureTransformInvertsAssimpsConversion() {
    QStringList warnings;
    const detail::MaterialContext ctx{
        QStringLiteral("x.gltf"), QStringLiteral("material 0"), detail::MaterialSource::Gltf, &warnings, {}};
    for (float rotation : {0.0f, 0.3f, -1.2f, 2.5f, -3.0f, 6.0f})
        for (glm::vec2 scale : {glm::vec2(1.0f), glm::vec2(2.0f, 3.0f), glm::vec2(-0.5f, 0.25f)})
            for (glm::vec2 offset : {glm::vec2(0.0f), glm::vec2(0.25f, 0.5f), glm::vec2(-3.0f, 7.0f)}) {
                aiUVTransform t;
                t.mScaling = aiVector2D(scale.x, scale.y);
                t.mRotation = -rotation;
                const float c = std::cos(rotation), s = std::sin(rotation);
                t.mTranslation.x = 0.5f * scale.x * (-c + s + 1.0f) + offset.x;
                t.mTranslation.y = 0.5f * scale.y * (s + c - 1.0f) + 1.0f - scale.y - offset.y;
                const TextureTransform back =
                    detail::textureTransformFromAssimp(t, QStringLiteral("base colour"), ctx);
                const TextureTransform expected{offset, rotation, scale};
                QVERIFY2(nearTransform(back, expected),
                         qPrintable(transformText(back) + QStringLiteral(" vs ") + transformText(expected)));
            }
    QVERIFY(warnings.isEmpty());
    aiUVTransform broken;
    broken.mRotation = std::numeric_limits<float>::quiet_NaN();
    QVERIFY(detail::textureTransformFromAssimp(broken, QStringLiteral("normal"), ctx).isIdentity());
    QCOMPARE(warnings.size(), 1);
    QVERIFY2(
        warnings[0].contains(QLatin1String("x.gltf: material 0: normal texture transform is not finite")),
        qPrintable(warnings[0]));
}

// tests/data/model/shiny.mtl: a Blinn-Phong material (Ns) converted to metal-rough, one with MTL's PBR keys
// (Pr, Pm) taken as they are, one without an exponent, and one with separate roughness/metallic maps.
void TestModel::objShininessConvertsToRoughness() {
    const auto m = mustLoad(dataFile(QStringLiteral("shiny.obj")));
    QVERIFY(m);
    QCOMPARE(test::modelProblems(*m), QString());
    const Material* glossy = materialNamed(*m, QStringLiteral("glossy"));
    QVERIFY(glossy);
    QVERIFY(!glossy->pbr);
    QCOMPARE(glossy->shininess, 98.0f); // classic values kept
    QCOMPARE(glossy->specular, glm::vec3(0.5f));
    QCOMPARE(glossy->metallic, 0.0f);
    // n = 98: alpha = sqrt(2 / (n + 2)) = sqrt(0.02), roughness = sqrt(alpha).
    QVERIFY(std::abs(glossy->roughness - float(std::pow(0.02, 0.25))) < 1e-6f);
    const Material* authored = materialNamed(*m, QStringLiteral("authored"));
    QVERIFY(authored);
    QVERIFY(authored->pbr);
    QCOMPARE(authored->metallic, 0.8f);
    QCOMPARE(authored->roughness, 0.3f);
    const Material* matte = materialNamed(*m, QStringLiteral("matte"));
    QVERIFY(matte);
    QVERIFY(!matte->pbr);
    QCOMPARE(matte->roughness, 1.0f);
    QVERIFY(matte->alphaMode == AlphaMode::Opaque);
    QVERIFY(m->hasPbrMaterials());
    // Separate map_Pr / map_Pm maps: the factor is used, the maps are not (one warning).
    const Material* separate = materialNamed(*m, QStringLiteral("separateMaps"));
    QVERIFY(separate);
    QVERIFY(separate->pbr);
    QCOMPARE(separate->roughness, 0.5f);
    QCOMPARE(separate->metallicRoughnessTexture, -1);
    QCOMPARE(m->warnings,
             QStringList{QStringLiteral("shiny.obj: material \"separateMaps\": separate metallic and "
                                        "roughness maps are not supported (not used)")});
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

void TestModel::referencesOutsideTheFolderAreRefused() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const QString root = tmp.path();
    QVERIFY(QDir(root).mkdir(QStringLiteral("model")));
    QImage outside(4, 4, QImage::Format_RGBA8888);
    outside.fill(Qt::yellow);
    QVERIFY(outside.save(root + QStringLiteral("/outside.png")));
    QVERIFY(outside.save(root + QStringLiteral("/model/local.png")));
    // Relative escape, absolute path, and a Windows path whose file name exists beside the model.
    QVERIFY(writeFile(root + QStringLiteral("/model/quad.mtl"),
                      "newmtl up\nmap_Kd ../outside.png\nnewmtl abs\nmap_Kd " + root.toUtf8() +
                          "/outside.png\nnewmtl win\nmap_Kd C:\\textures\\local.png\n"));
    QVERIFY(writeFile(root + QStringLiteral("/model/quad.obj"),
                      "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                      "vt 0 0\nusemtl up\nf 1/1 2/1 3/1\nusemtl abs\n"
                      "f 1/1 3/1 4/1\nusemtl win\nf 2/1 3/1 4/1\n"));
    // A glTF whose buffer lies outside: the import itself must fail, naming the file.
    const float triangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    QVERIFY(writeFile(root + QStringLiteral("/outside.bin"),
                      QByteArray(reinterpret_cast<const char*>(triangle), 36)));
    QVERIFY(writeFile(root + QStringLiteral("/model/buffer.gltf"),
                      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
                         "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
                         "buffers":[{"uri":"../outside.bin","byteLength":36}],
                         "bufferViews":[{"buffer":0,"byteLength":36}],
                         "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",
                                       "min":[0,0,0],"max":[1,1,0]}]})"));

    const auto refused = mustLoad(root + QStringLiteral("/model/quad.obj"));
    QVERIFY(refused);
    QCOMPARE(refused->textures.size(), size_t(1)); // only the Windows path's stand-in beside the model
    QCOMPARE(QFileInfo(refused->textures.front().name).fileName(), QStringLiteral("local.png"));
    const QString warnings = refused->warnings.join(QLatin1Char('\n'));
    QVERIFY2(warnings.contains(QStringLiteral("../outside.png")) &&
                 warnings.contains(root + QStringLiteral("/outside.png")),
             qPrintable(warnings));
    QVERIFY2(warnings.count(QStringLiteral("outside the model's folder")) >= 3, qPrintable(warnings));
    // The two that permission would load are listed for the question; the Windows path is not.
    QStringList outsideRefs = refused->texturesOutsideFolder;
    outsideRefs.sort();
    QCOMPARE(outsideRefs,
             QStringList({QStringLiteral("../outside.png"), root + QStringLiteral("/outside.png")}));

    const ModelLoadResult buffer = loadModel(root + QStringLiteral("/model/buffer.gltf"));
    QVERIFY(!buffer.ok());
    QVERIFY2(buffer.error.startsWith(QStringLiteral("could not import %1/model/buffer.gltf: ").arg(root)),
             qPrintable(buffer.error));
    QVERIFY2(buffer.error.contains(QStringLiteral("outside the model's folder")), qPrintable(buffer.error));

    ModelLoadOptions allow;
    allow.allowTexturesOutsideFolder = true;
    const auto allowed = mustLoad(root + QStringLiteral("/model/quad.obj"), allow);
    QVERIFY(allowed);
    QCOMPARE(allowed->textures.size(), size_t(2)); // ../outside.png and the absolute path are one file
    QVERIFY(allowed->texturesOutsideFolder.isEmpty());
    const auto upMat = std::find_if(allowed->materials.begin(), allowed->materials.end(),
                                    [](const Material& mat) { return mat.name == QLatin1String("up"); });
    QVERIFY(upMat != allowed->materials.end() && upMat->baseColorTexture >= 0);
    QCOMPARE(allowed->textures[size_t(upMat->baseColorTexture)].image.pixel(0, 0), QColor(Qt::yellow).rgb());
    const auto viaBuffer = mustLoad(root + QStringLiteral("/model/buffer.gltf"), allow);
    QVERIFY(viaBuffer);
    QCOMPARE(viaBuffer->triangleCount(), size_t(1));
}

void TestModel::degenerateGeometryIsDroppedWithWarnings() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const QString path = tmp.filePath(QStringLiteral("degenerate.obj"));
    QVERIFY(writeFile(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 1 1 0\nv 2 2 0\nv nan 0 0\nv 0 inf 0\n"
                            "vn 0 0 1\nvn 0 0 0\n"
                            "f 1//1 2//1 3//1\n"    // good
                            "f 2//1 4//1 5//1\n"    // two vertices at one place: no area
                            "f 1//1 4//1 6//1\n"    // collinear: no area
                            "f 1//1 2//1 7//1\n"    // NaN position
                            "f 1//1 8//1 3//1\n"    // infinite position
                            "f 2//2 4//2 3//2\n")); // good triangle with zero-length normals
    const ModelLoadResult r = loadModel(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    const Model& m = *r.model;
    QCOMPARE(test::modelProblems(m), QString());
    QCOMPARE(m.triangleCount(), size_t(2));
    QVERIFY(near(m.bounds.min, glm::dvec3(0.0), 0.0));
    QVERIFY(near(m.bounds.max, glm::dvec3(1.0, 1.0, 0.0), 0.0));
    const QString warnings = m.warnings.join(QLatin1Char('\n'));
    QVERIFY2(warnings.contains(QStringLiteral("degenerate.obj: 2 triangles with NaN or infinite")),
             qPrintable(warnings));
    QVERIFY2(warnings.contains(QStringLiteral("2 zero-area triangles dropped")), qPrintable(warnings));
    QVERIFY2(warnings.contains(QStringLiteral("normals recomputed")), qPrintable(warnings));
    for (const Mesh& mesh : m.meshes) {
        QCOMPARE(test::clockwiseTriangles(mesh), size_t(0));
        for (const Vertex& v : mesh.vertices)
            QVERIFY(glm::length(v.normal - glm::vec3(0, 0, 1)) < 1e-6f);
    }
    // Nothing usable at all: an error, not an empty model.
    const QString empty = tmp.filePath(QStringLiteral("allbad.obj"));
    QVERIFY(writeFile(empty, "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n"));
    const ModelLoadResult none = loadModel(empty);
    QVERIFY(!none.ok());
    QVERIFY2(none.error.startsWith(QStringLiteral("could not import %1: ").arg(empty)),
             qPrintable(none.error));
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

void TestModel::dataUriLimit() {
    const QString path = dataFile(QStringLiteral("scene.gltf"));
    ModelLoadOptions tight;
    tight.maxDataUriBytes = 64; // the buffer's data URI is a few hundred bytes
    const ModelLoadResult r = loadModel(path, tight);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.startsWith(QStringLiteral("could not import %1: a data URI of ").arg(path)),
             qPrintable(r.error));
    QVERIFY(loadModel(path).ok());
}

// A GLB header (magic, version 2, `length`) and the header of a JSON chunk of `chunk` bytes.
static QByteArray glb(quint32 length, quint32 chunk) {
    QByteArray b("glTF");
    for (const quint32 v : {2u, length, chunk, 0x4E4F534Au}) // "JSON"
        for (int k = 0; k < 4; ++k)
            b += char((v >> (8 * k)) & 0xFF);
    return b;
}

void TestModel::hostileHeadersAndPlyCommentsAreRefused() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const QByteArray header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const struct {
        const char* name;
        QByteArray content;
        const char* reason;
    } cases[] = {
        // Assimp 5.2.5 misparses comment lines inside PLY data (and aborts on some, see tst_model_shared).
        {"comment.ply", header + "0 0 0\n1 0 0\n0 1 0\ncomment added by hand\n3 0 1 2\n",
         "not a row of numbers"},
        // Element counts the file cannot hold: Assimp would allocate for them before noticing.
        {"bomb.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 1500000000\nproperty float x\n"
         "property float y\nproperty float z\nend_header\n",
         "the header declares 1500000000 elements"},
        {"bomb.off", "OFF\n353535235358 6 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "the header declares"},
        // An 80-byte GLB whose JSON chunk claims 4 GB: Assimp allocated 4.2 GB for it.
        {"huge-chunk.glb", glb(88, 0xFFFFFFF0u) + QByteArray(68, ' '),
         "GLB chunk 0 declares 4294967280 bytes, but only 68 follow"},
        // A header claiming more bytes than the file has (2.1 GB and 41 s in Assimp).
        {"long-header.glb", glb(30604, 2) + "{}" + QByteArray(62, ' '),
         "the GLB header declares 30604 bytes, but the file has 84"},
        {"short.glb", QByteArray("glTF\x02\0\0\0", 8), "shorter than a GLB header"},
        // A Collada index list with a character that is not part of a number: Assimp 5.2.5 loops forever
        // (a mutated duck.dae in scripts/sweep).
        {"loop.dae",
         "<?xml version=\"1.0\"?>\n<COLLADA>\n<library_geometries><geometry><mesh>\n<triangles count=\"1\">"
         "<p>0 1 2 178$</p></triangles></mesh></geometry></library_geometries></COLLADA>\n",
         "line 4: the <p> index list holds '$', which is not part of an integer"},
        // A PLY header that never ends: Assimp waited for end_header until the worker's time limit.
        {"trunc.ply", "ply\nformat ascii 1.0          \ne", "the PLY header has no end_header line"},
    };
    for (const auto& c : cases) {
        const QString path = tmp.filePath(QLatin1String(c.name));
        QVERIFY(writeFile(path, c.content));
        const ModelLoadResult r = loadModel(path);
        QVERIFY2(!r.ok(), c.name);
        QVERIFY2(r.error.startsWith(QStringLiteral("could not import %1: ").arg(path)), qPrintable(r.error));
        QVERIFY2(r.error.contains(QLatin1String(c.reason)), qPrintable(r.error));
    }
    // The sweep's reproducers themselves (tests/data/model/hostile).
    for (const auto& [file, reason] :
         {std::pair{"hostile/glb-huge-chunk.glb", "the GLB header declares 100 bytes, but the file has 80"},
          std::pair{"hostile/trunc-cube-32.ply", "the PLY header has no end_header line"}}) {
        const ModelLoadResult r = loadModel(dataFile(QLatin1String(file)));
        QVERIFY2(!r.ok() && r.error.contains(QLatin1String(reason)), qPrintable(r.error));
    }
    // A well-formed GLB (a JSON and a BIN chunk) passes the checks and loads.
    QByteArray json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"accessors":[{"bufferView":0,)"
        R"("componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36}]})";
    while (json.size() % 4)
        json += ' ';
    const float triangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    QByteArray bin(reinterpret_cast<const char*>(triangle), sizeof triangle);
    QByteArray good = glb(quint32(12 + 8 + json.size() + 8 + bin.size()), quint32(json.size())) + json;
    for (const quint32 v : {quint32(bin.size()), 0x004E4942u}) // "BIN\0"
        for (int k = 0; k < 4; ++k)
            good += char((v >> (8 * k)) & 0xFF);
    good += bin;
    const QString goodPath = tmp.filePath(QStringLiteral("good.glb"));
    QVERIFY(writeFile(goodPath, good));
    const ModelLoadResult loaded = loadModel(goodPath);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    // The same PLY without the comment loads.
    const QString clean = tmp.filePath(QStringLiteral("clean.ply"));
    QVERIFY(writeFile(clean, header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
    QVERIFY(loadModel(clean).ok());
}

// An OBJ of 30,000 copies of one triangle: Assimp's SpatialSort-based steps (smooth normals, tangents,
// joining vertices) are quadratic in coincident vertices (100,000 copies took over two minutes). The
// file loads without them, with flat normals and a warning saying why.
void TestModel::coincidentVerticesSkipSmoothing() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    QByteArray obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 30'000; ++i)
        obj += "f 1 2 3\n";
    const QString path = tmp.filePath(QStringLiteral("copies.obj"));
    QVERIFY(writeFile(path, obj));
    const ModelLoadResult r = loadModel(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    size_t triangles = 0;
    for (const Mesh& m : r.model->meshes) {
        triangles += m.indices.size() / 3;
        for (const Vertex& v : m.vertices)
            QVERIFY(std::abs(v.normal.z - 1.0f) < 1e-6f); // the face's own normal
    }
    QCOMPARE(triangles, size_t(30'000));
    QVERIFY2(r.model->warnings.join(QLatin1Char('\n'))
                 .contains(QStringLiteral("share a position; normals are flat")),
             qPrintable(r.model->warnings.join(QLatin1Char('\n'))));
    // An ordinary file keeps smooth normals and no such warning.
    const auto suzanne = mustLoad(QStringLiteral(":/resources/models/suzanne/Suzanne.gltf"));
    QVERIFY(suzanne);
    QVERIFY(!suzanne->warnings.join(QLatin1Char('\n')).contains(QStringLiteral("share a position")));
}

// Lights in a model file used to skip the rig format's limits: gltf-light-neg.gltf (colour [-1, 2, 1e30],
// intensity -5, range 0) was imported and rendered, and the rig could not be saved. Now each value out
// of range is clamped with a warning naming the light, and the model's rig saves and reads back.
void TestModel::modelLightsGetTheRigLimits() {
    const ModelLoadResult r = loadModel(dataFile(QStringLiteral("hostile/gltf-light-neg.gltf")));
    QVERIFY2(r.ok(), qPrintable(r.error));
    const QString warnings = r.model->warnings.join(QLatin1Char('\n'));
    QCOMPARE(r.model->lights.lights.size(), size_t(1));
    const Light& l = r.model->lights.lights[0];
    QVERIFY(l.intensity >= 0.0 && l.intensity <= kMaxRigIntensity);
    for (int i = 0; i < 3; ++i)
        QVERIFY(l.color[i] >= 0.0 && l.color[i] <= kMaxRigIntensity);
    QVERIFY2(warnings.contains(QStringLiteral("gltf-light-neg.gltf: light ")) &&
                 warnings.contains(QStringLiteral("negative or non-finite components; clamped to 0")),
             qPrintable(warnings));
    const RigReadResult back = readRigJson(writeRigJson(r.model->lights), QStringLiteral("model.json"));
    QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));

    // Each limit on its own: intensity, a falloff range, a position past the format's ±1e12 (dropped).
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    QJsonObject gltf = readJson(dataFile(QStringLiteral("hostile/gltf-light-neg.gltf")));
    QJsonObject ext = gltf[QStringLiteral("extensions")].toObject();
    QJsonObject punctual = ext[QStringLiteral("KHR_lights_punctual")].toObject();
    punctual[QStringLiteral("lights")] = QJsonArray{
        QJsonObject{{QStringLiteral("type"), QStringLiteral("point")},
                    {QStringLiteral("intensity"), 1e9},
                    {QStringLiteral("range"), 1e15}},
        QJsonObject{{QStringLiteral("type"), QStringLiteral("point")}},
    };
    ext[QStringLiteral("KHR_lights_punctual")] = punctual;
    gltf[QStringLiteral("extensions")] = ext;
    QJsonArray nodes = gltf[QStringLiteral("nodes")].toArray();
    nodes.append(QJsonObject{
        {QStringLiteral("translation"), QJsonArray{0, 1e13, 0}},
        {QStringLiteral("extensions"),
         QJsonObject{{QStringLiteral("KHR_lights_punctual"), QJsonObject{{QStringLiteral("light"), 1}}}}}});
    gltf[QStringLiteral("nodes")] = nodes;
    QJsonArray scenes = gltf[QStringLiteral("scenes")].toArray();
    scenes[0] = QJsonObject{{QStringLiteral("nodes"), QJsonArray{0, 1, 2}}};
    gltf[QStringLiteral("scenes")] = scenes;
    const QString path = tmp.filePath(QStringLiteral("limits.gltf"));
    QVERIFY(writeFile(path, QJsonDocument(gltf).toJson()));
    const ModelLoadResult limits = loadModel(path);
    QVERIFY2(limits.ok(), qPrintable(limits.error));
    const QString said = limits.model->warnings.join(QLatin1Char('\n'));
    QCOMPARE(limits.model->lights.lights.size(), size_t(1)); // the one at y = 1e13 is dropped
    const Light& kept = limits.model->lights.lights[0];
    QCOMPARE(kept.intensity, kMaxRigIntensity);
    QCOMPARE(kept.falloff.range, kMaxRigLength);
    QVERIFY2(said.contains(QStringLiteral("intensity 1e+09 clamped to 1e+06")), qPrintable(said));
    QVERIFY2(said.contains(QStringLiteral("falloff value 1e+15 clamped to 1e+12")), qPrintable(said));
    QVERIFY2(said.contains(QStringLiteral("position beyond ±1e+12")) &&
                 said.contains(QStringLiteral("skipped")),
             qPrintable(said));
    QVERIFY(readRigJson(writeRigJson(limits.model->lights), QStringLiteral("m.json")).ok());
}

// gltf-camera-nan.gltf: yfov 1e39, znear 1e-45. The near plane leaves no depth precision (the model
// rendered as the background alone): the camera is ignored with a warning, and the model's views remain.
void TestModel::unusableCameraIsIgnored() {
    const ModelLoadResult r = loadModel(dataFile(QStringLiteral("hostile/gltf-camera-nan.gltf")));
    QVERIFY2(r.ok(), qPrintable(r.error));
    QVERIFY(r.model->cameras.empty());
    QVERIFY2(r.model->warnings.join(QLatin1Char('\n'))
                 .contains(QStringLiteral("has an unusable near plane (1.4013e-45); ignored")),
             qPrintable(r.model->warnings.join(QLatin1Char('\n'))));
    // A camera with an ordinary near plane is kept (scene.gltf's).
    const ModelLoadResult scene = loadModel(dataFile(QStringLiteral("scene.gltf")));
    QVERIFY2(scene.ok() && !scene.model->cameras.empty(), qPrintable(scene.error));
}

// Errors name the path as given, not only its file name ("could not import empty.obj" was ambiguous in
// batch runs): absolute, relative and with "..", each as written.
void TestModel::errorsNameTheFile() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const ModelLoadResult missing = loadModel(tmp.filePath(QStringLiteral("nothing.obj")));
    QVERIFY(!missing.ok());
    QCOMPARE(
        missing.error,
        QStringLiteral("could not import %1: no such file").arg(tmp.filePath(QStringLiteral("nothing.obj"))));
    const QString relative =
        QDir::current().relativeFilePath(tmp.filePath(QStringLiteral("sub/../nothing.obj")));
    const ModelLoadResult relativeMissing = loadModel(relative);
    QCOMPARE(relativeMissing.error, QStringLiteral("could not import %1: no such file").arg(relative));
    const ModelLoadResult folder = loadModel(tmp.path());
    QVERIFY(!folder.ok());
    QCOMPARE(folder.error,
             QStringLiteral("could not import %1: not a regular file (a folder, FIFO, socket or device)")
                 .arg(tmp.path()));
    const QString junk = tmp.filePath(QStringLiteral("junk.fbx"));
    QByteArray bytes;
    for (int i = 0; i < 4096; ++i)
        bytes.append(char((i * 7919) % 251));
    QVERIFY(writeFile(junk, bytes));
    const ModelLoadResult garbage = loadModel(junk);
    QVERIFY(!garbage.ok());
    QVERIFY2(garbage.error.startsWith(QStringLiteral("could not import %1: ").arg(junk)),
             qPrintable(garbage.error));
}

void TestModel::importableSuffixesListTheCommonFormats() {
    const QStringList suffixes = importableSuffixes();
    for (const char* s : {"obj", "gltf", "glb", "fbx", "ply", "stl", "dae", "3ds"})
        QVERIFY2(suffixes.contains(QLatin1String(s)), s);
    QVERIFY(modelFileFilter().contains(QStringLiteral("*.gltf")));
}

QTEST_GUILESS_MAIN(TestModel)
#include "tst_model.moc"
