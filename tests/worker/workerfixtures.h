// Models built in code for the worker tests: one that sets every field of Model to something other than
// its default, and a check of the guarantees decodeModel makes about whatever it accepts.
#pragma once

#include "model/model.h"

#include <QColorSpace>
#include <QImage>
#include <QString>
#include <cmath>

namespace lr::test {

inline QImage patternImage(int w, int h, QImage::Format format, int seed) {
    QImage img(w, h, format);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.setPixelColor(x, y,
                              QColor((x * 37 + seed) % 256, (y * 59 + seed) % 256, (x * y + seed) % 256,
                                     (x + y * 7 + seed) % 256));
    return img;
}

inline Vertex makeVertex(float k) {
    Vertex v;
    v.position = {k, -2.0f * k, 0.5f + k};
    v.normal = glm::normalize(glm::vec3(0.2f, k, 1.0f));
    v.uv = {0.25f * k, 1.0f - k};
    v.tangent = {1.0f, 0.0f, -0.2f * k, k > 1.0f ? -1.0f : 1.0f};
    v.color = {0.1f * k, 0.2f, 0.3f, 0.9f};
    return v;
}

inline Light lightVariant(int i) {
    Light l = makeLight(LightType(i % enumCount<LightType>()), QStringLiteral("light %1 \u00e9").arg(i));
    l.enabled = i % 2 == 0;
    l.color = {0.1 * i, 0.5, 1.0 - 0.05 * i};
    l.intensity = 3.5 + i;
    if (i % 3 == 0) l.temperature = 3200.0 + i;
    l.position = {1.5 * i, -2.0, 1e5};
    l.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.1 * i));
    l.falloff = {FalloffModel(i % enumCount<FalloffModel>()), 10.0 + i, 1.5, 0.9, 0.01 * i, 0.002};
    l.cone = {ConeModel(i % enumCount<ConeModel>()), 12.0, 40.0 + i, 2.5};
    l.diffuse = DiffuseModel(i % enumCount<DiffuseModel>());
    l.specularIsColor = i % 2 == 1;
    l.specular = {0.5, 0.25 * i, 0.125};
    if (i % 2 == 1) l.ambient = glm::dvec3(0.01 * i, 0.02, 0.03);
    l.rimExponent = 1.0 + 0.1 * i;
    l.area = {0.5 + i, 0.25 * i, 0.125 + i, -10.0 * i, i % 2 == 0};
    // Issues 38 and 39: linking and shaping (a glTF's light nodes carry them, model/gltflightextras.cpp).
    if (i % 2 == 0) l.link.lit.include = {QStringLiteral("Body"), QStringLiteral("material:Gl\u00e4ss")};
    if (i % 3 == 1) l.link.shadow.exclude = {QStringLiteral("Stand")};
    if (i % 2 == 1)
        l.ies = IesSpec{QStringLiteral("/p/%1.ies").arg(i), QStringLiteral("/r/%1.ies").arg(i), 0.5 + i,
                        i % 4 == 1 ? IesLevel::Profile : IesLevel::Light, 15.0 * i};
    if (i % 3 == 2) l.gobo = GoboSpec{QStringLiteral("g%1.png").arg(i), QString(), 0.5 + i, -20.0 * i};
    if (i % 4 == 3) l.barnDoors = BarnDoors{30.0 + i, 0.1 * i};
    return l;
}

// Every field away from its default, every enum value used, a texture in a format the encoder converts,
// an unreferenced null texture, non-ASCII strings.
inline Model fullModel() {
    Model m;
    m.path = QStringLiteral("/tmp/\u00fc models/sc\u00e8ne \u6a21\u578b.glb");
    m.origin = {1e6, -2.5, 3.25};
    Mesh a;
    a.name = QStringLiteral("body");
    for (int i = 0; i < 5; ++i)
        a.vertices.push_back(makeVertex(0.5f * float(i)));
    a.indices = {0, 1, 2, 2, 1, 3, 4, 3, 1};
    a.material = 1;
    a.hasVertexColors = true;
    a.hasTangents = true;
    Mesh b;
    b.name = QStringLiteral("visor");
    for (int i = 0; i < 3; ++i)
        b.vertices.push_back(makeVertex(-1.0f - float(i)));
    b.indices = {2, 1, 0};
    m.meshes = {a, b};
    Material m0;
    m0.name = QStringLiteral("paint");
    m0.baseColor = {0.8f, 0.1f, 0.2f, 0.5f};
    m0.baseColorTexture = 0;
    m0.normalTexture = 1;
    m0.emissive = {0.1f, 0.2f, 0.3f};
    m0.specular = {0.4f, 0.5f, 0.6f};
    m0.shininess = 64.0f;
    m0.doubleSided = true;
    m0.pbr = true;
    m0.metallic = 0.75f;
    m0.roughness = 0.125f;
    m0.metallicRoughnessTexture = 1;
    m0.occlusionTexture = 0;
    m0.occlusionStrength = 0.625f;
    m0.normalScale = -1.5f;
    m0.alphaMode = AlphaMode::Mask;
    m0.alphaCutoff = 0.25f;
    m0.baseColorTransform = {{0.25f, 0.5f}, 0.3f, {2.0f, 3.0f}};
    m0.normalTransform = {{-0.5f, 0.0f}, 0.0f, {1.0f, -1.0f}};
    m0.emissiveTransform = {{0.0f, 0.125f}, -1.2f, {1.0f, 1.0f}};
    m0.metallicRoughnessTransform = {{0.0f, 0.0f}, 3.0f, {0.5f, 0.5f}};
    m0.occlusionTransform = {{7.0f, -7.0f}, 0.0f, {4.0f, 4.0f}};
    m0.baseColorSampling = {TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat, true};
    m0.occlusionSampling.wrapT = TextureWrap::ClampToEdge;
    m0.extensions = {
        {QStringLiteral("KHR_materials_sheen"), QStringLiteral("{\"sheenRoughnessFactor\":0.5}")}};
    Material m1;
    m1.name = QStringLiteral("glass");
    m1.emissiveTexture = 0;
    m1.alphaMode = AlphaMode::Blend;
    m.materials = {m0, m1};
    QImage srgb = patternImage(5, 3, QImage::Format_RGBA8888, 1);
    srgb.setColorSpace(QColorSpace::SRgb);
    m.textures = {{QStringLiteral("*0"), srgb},
                  {QStringLiteral("textures/normal.png"), patternImage(4, 4, QImage::Format_ARGB32, 2)},
                  {QStringLiteral("missing.png"), QImage()}};
    Camera c0;
    c0.name = QStringLiteral("front");
    c0.position = {1.0, 2.0, 3.0};
    c0.forward = glm::normalize(glm::dvec3(0.0, -0.2, -1.0));
    c0.up = glm::normalize(glm::cross(glm::cross(c0.forward, glm::dvec3(0, 1, 0)), c0.forward));
    c0.yfovDegrees = 39.6;
    c0.znear = 0.05;
    c0.zfar = 0.0;
    c0.aspect = 1.5;
    Camera c1;
    c1.name = QStringLiteral("side");
    m.cameras = {c0, c1};
    m.lights.name = QStringLiteral("file lights");
    m.lights.space = RigSpace::Model;
    m.lights.ambient = {0.01, 0.02, 0.03};
    m.lights.shading = {ShadingModel::Pbr, SpecularModel::BlinnPhong, ViewerModel::Infinite, 7.0};
    for (int i = 0; i < 7; ++i)
        m.lights.lights.push_back(lightVariant(i));
    m.bounds = {{-1.0, -2.0, -3.0}, {4.0, 5.0, 6.0}};
    m.warnings = {QStringLiteral("spider.fbx: 56 degenerate triangles dropped"),
                  QStringLiteral("\u8b66\u544a")};
    m.texturesOutsideFolder = {QStringLiteral("../shared/wood.png"),
                               QStringLiteral("/srv/tex/\u00e9t\u00e9.jpg")};
    m.loadMs = 12.5;
    return m;
}

inline bool finiteVec(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// What decodeModel guarantees about any model it returns (independently of the codec's own checks).
inline QString decodedModelUnsafe(const Model& m) {
    for (const Mesh& mesh : m.meshes) {
        if (mesh.indices.size() % 3) return QStringLiteral("partial triangle");
        for (std::uint32_t i : mesh.indices)
            if (i >= mesh.vertices.size()) return QStringLiteral("index out of range");
        if (mesh.material < 0 || std::size_t(mesh.material) >= m.materials.size())
            return QStringLiteral("material out of range");
        for (const Vertex& v : mesh.vertices) {
            const float* f = &v.position.x;
            for (std::size_t k = 0; k < sizeof(Vertex) / sizeof(float); ++k)
                if (!std::isfinite(f[k])) return QStringLiteral("non-finite vertex");
        }
    }
    for (const Material& mat : m.materials) {
        for (int t : {mat.baseColorTexture, mat.normalTexture, mat.emissiveTexture,
                      mat.metallicRoughnessTexture, mat.occlusionTexture})
            if (t != -1 &&
                (t < 0 || std::size_t(t) >= m.textures.size() || m.textures[std::size_t(t)].image.isNull()))
                return QStringLiteral("texture reference out of range");
        for (float f : {mat.metallic, mat.roughness, mat.occlusionStrength, mat.alphaCutoff})
            if (!(f >= 0.0f && f <= 1.0f)) return QStringLiteral("material factor outside [0, 1]");
        for (const TextureTransform& t : {mat.baseColorTransform, mat.normalTransform, mat.emissiveTransform,
                                          mat.metallicRoughnessTransform, mat.occlusionTransform})
            for (float f : {t.offset.x, t.offset.y, t.rotation, t.scale.x, t.scale.y})
                if (!std::isfinite(f)) return QStringLiteral("non-finite texture transform");
        if (int(mat.alphaMode) < 0 || int(mat.alphaMode) >= enumCount<AlphaMode>())
            return QStringLiteral("alpha mode out of range");
    }
    for (const Texture& t : m.textures)
        if (!t.image.isNull() && t.image.format() != QImage::Format_RGBA8888)
            return QStringLiteral("texture format");
    for (const Light& l : m.lights.lights)
        if (!finiteVec(l.position) || !finiteVec(l.direction) || !finiteVec(l.color) ||
            !std::isfinite(l.intensity))
            return QStringLiteral("non-finite light");
    for (const Camera& c : m.cameras)
        if (!finiteVec(c.position) || !finiteVec(c.forward) || !std::isfinite(c.yfovDegrees))
            return QStringLiteral("non-finite camera");
    if (!finiteVec(m.origin) || !finiteVec(m.bounds.min) || !finiteVec(m.bounds.max))
        return QStringLiteral("non-finite origin or bounds");
    return {};
}

} // namespace lr::test
