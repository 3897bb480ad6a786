// Model import of materials: glTF's metal-rough model (tests/data/model/pbr.gltf and variants written
// here), its clamped values, emissive strength, undecodable textures and KHR_texture_transform, and an
// OBJ's Blinn-Phong and PBR keys converted to metal-rough. Expected values come from the files' own data.
#include "model/importdetail.h"
#include "model/modelloader.h"
#include "modelchecks.h"
#include "modelimport.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <assimp/material.h>
#include <cmath>
#include <limits>

using namespace lr;
using namespace lr::test;

namespace {

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

class TestModelMaterials : public QObject {
    Q_OBJECT
  private slots:
    void gltfMetalRoughMaterials();
    void gltfOutOfRangeValuesAreClampedWithWarnings();
    void gltfEmissiveStrengthFindsItsMaterial();
    void undecodableTexturesNameTheirRole();
    void gltfSamplersAndExtensionsAreRead();
    void objClampIsClampToEdge();
    void specularGlossinessWarns();
    void textureTransformInvertsAssimpsConversion();
    void objShininessConvertsToRoughness();
};

// tests/data/model/pbr.gltf: each material exercises part of glTF's metal-rough model; the expected values
// are read from the file's JSON. Textures are data URIs of distinct sizes, so each role is told by size.
void TestModelMaterials::gltfMetalRoughMaterials() {
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

void TestModelMaterials::gltfOutOfRangeValuesAreClampedWithWarnings() {
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
void TestModelMaterials::gltfEmissiveStrengthFindsItsMaterial() {
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
    const auto m = loadGltfJson(gltf, dir, QStringLiteral("strength.gltf"));
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

// Issue 42: a texture's glTF sampler (wrap modes, magnification filter) reaches its role; every material
// extension is listed with its values, and those LightRig does not render are one warning per material
// naming them; KHR_materials_variants is a warning naming the variants.
void TestModelMaterials::gltfSamplersAndExtensionsAreRead() {
    QJsonObject gltf = readJson(dataFile(QStringLiteral("pbr.gltf")));
    gltf[QStringLiteral("samplers")] = QJsonArray{QJsonObject{{QStringLiteral("wrapS"), 33071},
                                                              {QStringLiteral("wrapT"), 33648},
                                                              {QStringLiteral("magFilter"), 9728}}};
    QJsonArray textures = gltf[QStringLiteral("textures")].toArray();
    QJsonObject t0 = textures[0].toObject();
    t0[QStringLiteral("sampler")] = 0;
    textures[0] = t0;
    gltf[QStringLiteral("textures")] = textures;
    QJsonArray materials = gltf[QStringLiteral("materials")].toArray();
    for (int i = 0; i < materials.size(); ++i) {
        QJsonObject mat = materials[i].toObject();
        if (mat[QStringLiteral("name")].toString() != QLatin1String("blend")) continue;
        mat[QStringLiteral("extensions")] =
            QJsonObject{{QStringLiteral("KHR_materials_sheen"),
                         QJsonObject{{QStringLiteral("sheenRoughnessFactor"), 0.5}}},
                        {QStringLiteral("KHR_materials_clearcoat"),
                         QJsonObject{{QStringLiteral("clearcoatFactor"), 1.0}}}};
        materials[i] = mat;
    }
    gltf[QStringLiteral("materials")] = materials;
    QJsonObject root = gltf[QStringLiteral("extensions")].toObject();
    root[QStringLiteral("KHR_materials_variants")] =
        QJsonObject{{QStringLiteral("variants"),
                     QJsonArray{QJsonObject{{QStringLiteral("name"), QStringLiteral("red")}},
                                QJsonObject{{QStringLiteral("name"), QStringLiteral("blue")}}}}};
    gltf[QStringLiteral("extensions")] = root;
    QTemporaryDir dir;
    const auto m = loadGltfJson(gltf, dir, QStringLiteral("extended.gltf"));
    QVERIFY(m);

    // Texture 0 is "transformed"'s base colour: clamp along S, mirrored along T, magnified nearest; its
    // emissive texture (image 1, no sampler) keeps glTF's default.
    const Material* xf = materialNamed(*m, QStringLiteral("transformed"));
    QVERIFY(xf && xf->baseColorTexture >= 0 && xf->emissiveTexture >= 0);
    QVERIFY(xf->baseColorSampling ==
            (TextureSampling{TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat, true}));
    QVERIFY(xf->emissiveSampling.isDefault());
    // Its emissive strength is rendered: listed, no warning.
    QCOMPARE(xf->extensions.size(), std::size_t(1));
    QCOMPARE(xf->extensions[0].name, QStringLiteral("KHR_materials_emissive_strength"));
    QVERIFY(xf->extensions[0].values.contains(QLatin1String("emissiveStrength")));
    QVERIFY(warningsWith(*m, {QStringLiteral("\"transformed\""), QStringLiteral("not rendered")}).isEmpty());

    const Material* blend = materialNamed(*m, QStringLiteral("blend"));
    QVERIFY(blend);
    QCOMPARE(blend->extensions.size(), std::size_t(2));
    QCOMPARE(blend->extensions[0].name, QStringLiteral("KHR_materials_clearcoat"));
    QCOMPARE(blend->extensions[0].values, QStringLiteral("{\"clearcoatFactor\":1}"));
    QCOMPARE(blend->extensions[1].name, QStringLiteral("KHR_materials_sheen"));
    QCOMPARE(
        warningsWith(*m, {QStringLiteral("extended.gltf: material \"blend\""),
                          QStringLiteral("KHR_materials_clearcoat, KHR_materials_sheen are not rendered")})
            .size(),
        1);
    QCOMPARE(warningsWith(*m, {QStringLiteral("extended.gltf"), QStringLiteral("KHR_materials_variants"),
                               QStringLiteral("2 variants (red, blue)")})
                 .size(),
             1);
    // Materials without extensions list none.
    QVERIFY(materialNamed(*m, QStringLiteral("metalRough"))->extensions.empty());
}

// Other formats' wrap modes reach the sampling too: MTL's "-clamp on" is CLAMP_TO_EDGE on both axes; without
// it the map repeats.
void TestModelMaterials::objClampIsClampToEdge() {
    QTemporaryDir dir;
    for (const char* file : {"quad.obj", "checker.png"})
        QVERIFY(QFile::copy(dataFile(QLatin1String(file)), dir.filePath(QLatin1String(file))));
    QFile mtl(dataFile(QStringLiteral("quad.mtl")));
    QVERIFY(mtl.open(QIODevice::ReadOnly));
    const QByteArray text = mtl.readAll();
    for (const bool clamp : {false, true}) {
        QByteArray edited = text;
        if (clamp) edited.replace("map_Kd checker.png", "map_Kd -clamp on checker.png");
        QVERIFY(writeFile(dir.filePath(QStringLiteral("quad.mtl")), edited));
        const auto m = mustLoad(dir.filePath(QStringLiteral("quad.obj")));
        QVERIFY(m);
        const Material* mat = materialNamed(*m, QStringLiteral("checker"));
        QVERIFY(mat && mat->baseColorTexture >= 0);
        const TextureWrap expected = clamp ? TextureWrap::ClampToEdge : TextureWrap::Repeat;
        QVERIFY(mat->baseColorSampling.wrapS == expected);
        QVERIFY(mat->baseColorSampling.wrapT == expected);
        QVERIFY(!mat->baseColorSampling.nearestMagnification);
    }
}

// pbr.gltf with its metallic-roughness (image 1) and occlusion (image 2) images broken: not used, and the
// warnings say which role lost its texture.
void TestModelMaterials::undecodableTexturesNameTheirRole() {
    QJsonObject gltf = readJson(dataFile(QStringLiteral("pbr.gltf")));
    QJsonArray images = gltf[QStringLiteral("images")].toArray();
    for (int i : {1, 2})
        images[i] = QJsonObject{{QStringLiteral("uri"), QStringLiteral("data:image/png;base64,AAAA")}};
    gltf[QStringLiteral("images")] = images;
    QTemporaryDir dir;
    const auto m = loadGltfJson(gltf, dir, QStringLiteral("broken.gltf"));
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
void TestModelMaterials::specularGlossinessWarns() {
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
    const auto m = loadGltfJson(gltf, dir, QStringLiteral("specgloss.gltf"));
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
void TestModelMaterials::textureTransformInvertsAssimpsConversion() {
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
void TestModelMaterials::objShininessConvertsToRoughness() {
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

QTEST_GUILESS_MAIN(TestModelMaterials)
#include "tst_modelmaterials.moc"
