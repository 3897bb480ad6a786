// The physically based values of a material (glTF 2.0 metal-rough and its extensions), as Assimp 5.2.5
// hands them over, checked on real files (tests/model): metallicFactor / roughnessFactor as
// AI_MATKEY_METALLIC_FACTOR / AI_MATKEY_ROUGHNESS_FACTOR, occlusion strength as $tex.strength and normal
// scale as $tex.scale of their texture, alphaMode / alphaCutoff as AI_MATKEY_GLTF_ALPHA*, texture
// transforms as aiUVTransform. Formats without metal-rough values get them converted from
// specular/shininess (docs/lighting-models.md, "Materials").
#include "importdetail.h"

#include <QFileInfo>
#include <algorithm>
#include <assimp/GltfMaterial.h>
#include <assimp/material.h>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <vector>

namespace lr::detail {

namespace {

QString number(double v) {
    return QString::number(v, 'g', 7);
}

// A finite value clamped to [lo, hi]; a non-finite one becomes `fallback`. Either change is a warning.
float checked(float v, float lo, float hi, float fallback, const char* field, const MaterialContext& ctx) {
    if (!std::isfinite(v)) {
        ctx.warn(QStringLiteral("%1 is not finite; using %2").arg(QLatin1String(field), number(fallback)));
        return fallback;
    }
    const float c = std::clamp(v, lo, hi);
    if (c != v)
        ctx.warn(QStringLiteral("%1 %2 is outside [%3, %4]; clamped to %5")
                     .arg(QLatin1String(field), number(v), number(lo), number(hi), number(c)));
    return c;
}

AlphaMode alphaModeOf(const aiMaterial* am, const MaterialContext& ctx) {
    aiString mode;
    if (am->Get(AI_MATKEY_GLTF_ALPHAMODE, mode) != AI_SUCCESS) return AlphaMode::Opaque;
    const QString text = QString::fromUtf8(mode.C_Str());
    if (const std::optional<AlphaMode> parsed = fromString<AlphaMode>(text)) return *parsed;
    ctx.warn(QStringLiteral("unknown alphaMode \"%1\"; using OPAQUE").arg(text));
    return AlphaMode::Opaque;
}

// The entries of the file's "materials" array this aiMaterial may have come from. Assimp numbers materials
// in the order meshes reference them, not as the file does, so they are found by name and emissive factor.
// Empty with a warning when more than kMaxSameName share the name (bounded work per material: a file of
// many materials of one name would otherwise cost quadratic time).
std::vector<const GltfMaterialExtras*> jsonMaterialsOf(const Material& m, const glm::vec3& emissiveFactor,
                                                       const MaterialContext& ctx) {
    constexpr int kMaxSameName = 256;
    std::vector<const GltfMaterialExtras*> found;
    int seen = 0;
    for (auto it = ctx.gltfExtras.constFind(m.name); it != ctx.gltfExtras.cend() && it.key() == m.name;
         ++it) {
        if (++seen > kMaxSameName) {
            ctx.warn(QStringLiteral("more than %1 materials share this name; its glTF extensions are not "
                                    "looked up")
                         .arg(kMaxSameName));
            return {};
        }
        const GltfMaterialExtras& e = it.value();
        // (Assimp's JSON reader may round a factor differently in the last bit.)
        const glm::vec3 d = glm::abs(e.emissiveFactor - emissiveFactor);
        if (std::max({d.x, d.y, d.z}) > 1e-6f * std::max(1.0f, glm::length(emissiveFactor))) continue;
        found.push_back(&e);
    }
    return found;
}

// KHR_materials_emissive_strength of those entries; when they have different strengths, none is used.
double emissiveStrength(const std::vector<const GltfMaterialExtras*>& entries,
                        const glm::vec3& emissiveFactor, const MaterialContext& ctx) {
    if (emissiveFactor == glm::vec3(0.0f) || entries.empty()) return 1.0; // nothing to scale
    for (const GltfMaterialExtras* e : entries)
        if (e->emissiveStrength != entries.front()->emissiveStrength) {
            ctx.warn(QStringLiteral("several materials of this name and emissive factor have different "
                                    "KHR_materials_emissive_strength values; using 1"));
            return 1.0;
        }
    const double s = entries.front()->emissiveStrength;
    if (!std::isfinite(s) || s < 0.0) {
        ctx.warn(QStringLiteral("emissiveStrength %1 is not a finite value >= 0; using 1").arg(number(s)));
        return 1.0;
    }
    return s;
}

// Material::extensions from those entries, and a warning naming every extension LightRig does not render
// (issue 42: never silence). When the entries list different extensions, none is listed and every one of
// them is named.
void readExtensions(const std::vector<const GltfMaterialExtras*>& entries, const MaterialContext& ctx,
                    Material& m) {
    if (entries.empty()) return;
    QStringList notRendered;
    bool same = true;
    for (const GltfMaterialExtras* e : entries) {
        same = same && e->extensions == entries.front()->extensions;
        for (const MaterialExtension& x : e->extensions)
            // KHR_materials_pbrSpecularGlossiness has its own warning (readPhysicalValues).
            if (!materialExtensionRendered(x.name) &&
                x.name != QLatin1String("KHR_materials_pbrSpecularGlossiness") &&
                !notRendered.contains(x.name))
                notRendered << x.name;
    }
    if (same)
        m.extensions = entries.front()->extensions;
    else
        ctx.warn(QStringLiteral("several materials of this name and emissive factor differ in their "
                                "extensions; none is listed"));
    if (const int more = entries.front()->extensionCount - int(entries.front()->extensions.size()); more > 0)
        ctx.warn(QStringLiteral("%1 more extensions than the %2 listed are not read")
                     .arg(more)
                     .arg(kMaxMaterialExtensions));
    if (!notRendered.isEmpty())
        ctx.warn(QStringLiteral("%1 not rendered: the material is drawn with its core metal-rough values "
                                "(the Model dock lists the values)")
                     .arg(notRendered.size() == 1
                              ? notRendered.front() + QStringLiteral(" is")
                              : notRendered.join(QStringLiteral(", ")) + QStringLiteral(" are")));
}

} // namespace

MaterialSource materialSource(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("gltf") || suffix == QLatin1String("glb")) return MaterialSource::Gltf;
    if (suffix == QLatin1String("fbx")) return MaterialSource::Fbx;
    return MaterialSource::Other;
}

TextureTransform textureTransformFromAssimp(const aiUVTransform& t, const QString& role,
                                            const MaterialContext& ctx) {
    const double values[] = {t.mTranslation.x, t.mTranslation.y, t.mScaling.x, t.mScaling.y, t.mRotation};
    for (double v : values)
        if (!std::isfinite(v)) {
            ctx.warn(QStringLiteral("%1 texture transform is not finite; using none").arg(role));
            return {};
        }
    // Assimp 5.2.5 (glTF2Importer.cpp) stores rotation r as mRotation = -r, the scale s as it is, and
    //   mTranslation.x = s.x/2 (1 - cos r - sin r) + offset.x   [cos(-mRotation) = cos r, sin(-mRotation) =
    //   sin r] mTranslation.y = s.y/2 (cos r + sin r - 1) + 1 - s.y - offset.y
    // (Assimp rotates about the texture's centre and flips v). Inverted in double precision:
    TextureTransform x;
    const double r = -double(t.mRotation), sx = t.mScaling.x, sy = t.mScaling.y;
    const double c = std::cos(r), s = std::sin(r);
    x.rotation = r == 0.0 ? 0.0f : float(r);
    x.scale = glm::vec2(float(sx), float(sy));
    x.offset.x = float(double(t.mTranslation.x) - 0.5 * sx * (1.0 - c + s));
    x.offset.y = float(0.5 * sy * (s + c - 1.0) + 1.0 - sy - double(t.mTranslation.y));
    for (float* v : {&x.offset.x, &x.offset.y, &x.rotation, &x.scale.x, &x.scale.y})
        if (!std::isfinite(*v)) {
            ctx.warn(QStringLiteral("%1 texture transform is out of range; using none").arg(role));
            return {};
        }
    return x;
}

void readPhysicalValues(const aiMaterial* am, const MaterialContext& ctx, Material& m) {
    float metallic = 0.0f, roughness = 1.0f;
    const bool hasMetallic = am->Get(AI_MATKEY_METALLIC_FACTOR, metallic) == AI_SUCCESS;
    const bool hasRoughness = am->Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness) == AI_SUCCESS;
    // Assimp's FBX importer derives a roughness from every shininess exponent (1 - sqrt(n) / 10, "as
    // Blender does"); only Maya's PBR properties (which set the metallic factor too) are authored values.
    const bool authoredRoughness = hasRoughness && (ctx.source != MaterialSource::Fbx || hasMetallic);
    m.pbr = hasMetallic || authoredRoughness;
    float glossiness = 0.0f;
    if (ctx.source == MaterialSource::Gltf && am->Get(AI_MATKEY_GLOSSINESS_FACTOR, glossiness) == AI_SUCCESS)
        ctx.warn(QStringLiteral("KHR_materials_pbrSpecularGlossiness is not supported; using the material's "
                                "metallic-roughness values, as viewers without that extension do"));
    if (m.pbr) {
        m.metallic = hasMetallic ? checked(metallic, 0.0f, 1.0f, 1.0f, "metallicFactor", ctx) : 0.0f;
        m.roughness = authoredRoughness ? checked(roughness, 0.0f, 1.0f, 1.0f, "roughnessFactor", ctx) : 1.0f;
    } else {
        // Blinn-Phong's exponent n and a microfacet roughness alpha match where their distributions have the
        // same peak width: n = 2 / alpha^2 - 2 (Walter et al. 2007, Beckmann; GGX agrees near the peak),
        // and glTF's perceptual roughness is sqrt(alpha). No exponent: glTF's default roughness, 1.
        m.metallic = 0.0f;
        m.roughness =
            m.shininess > 0.0f ? float(std::sqrt(std::sqrt(2.0 / (double(m.shininess) + 2.0)))) : 1.0f;
    }

    const aiTextureType occlusionType =
        ctx.source == MaterialSource::Gltf ? aiTextureType_LIGHTMAP : aiTextureType_AMBIENT_OCCLUSION;
    float strength = 1.0f;
    if (m.occlusionTexture >= 0 &&
        am->Get(AI_MATKEY_GLTF_TEXTURE_STRENGTH(occlusionType, 0), strength) == AI_SUCCESS)
        m.occlusionStrength = checked(strength, 0.0f, 1.0f, 1.0f, "occlusion strength", ctx);
    float scale = 1.0f;
    if (m.normalTexture >= 0 &&
        am->Get(AI_MATKEY_GLTF_TEXTURE_SCALE(aiTextureType_NORMALS, 0), scale) == AI_SUCCESS)
        m.normalScale = checked(scale, -1e3f, 1e3f, 1.0f, "normal scale", ctx);

    m.alphaMode = alphaModeOf(am, ctx);
    float cutoff = 0.5f;
    if (am->Get(AI_MATKEY_GLTF_ALPHACUTOFF, cutoff) == AI_SUCCESS)
        m.alphaCutoff = checked(cutoff, 0.0f, 1.0f, 0.5f, "alphaCutoff", ctx);

    if (ctx.source == MaterialSource::Gltf && !ctx.gltfExtras.empty()) {
        aiColor3D e(0.0f, 0.0f, 0.0f);
        am->Get(AI_MATKEY_COLOR_EMISSIVE, e);
        const auto entries = jsonMaterialsOf(m, glm::vec3(e.r, e.g, e.b), ctx);
        const double s = emissiveStrength(entries, glm::vec3(e.r, e.g, e.b), ctx);
        for (int i = 0; i < 3; ++i)
            m.emissive[i] = std::min(float(double(m.emissive[i]) * s), 1e6f);
        readExtensions(entries, ctx, m);
    }
}

} // namespace lr::detail
