#include "shadergen.h"

#include "shapinglayers.h"

#include "shadowplan.h"

#include "core/barndoors.h"
#include "core/fallofftraits.h"

#include <QStringList>
#include <cmath>

namespace lr::render {

namespace {

template <typename E> constexpr std::uint8_t bit(E e) {
    return std::uint8_t(1u << unsigned(e));
}

// "range-power" -> "RANGE_POWER"
QByteArray macroName(const char* name) {
    QByteArray s(name);
    s.replace('-', '_');
    return s.toUpper();
}

// #define LR_<PREFIX>_<NAME> <value> for every value of E.
template <typename E> void defineEnum(QByteArray& out, const char* prefix) {
    const auto& names = EnumNames<E>::names;
    for (size_t i = 0; i < names.size(); ++i)
        out += "#define LR_" + QByteArray(prefix) + '_' + macroName(names[i]) + ' ' +
               QByteArray::number(int(i)) + '\n';
}

// LR_HAS_<PREFIX>_<NAME> for each present value, and LR_ONLY_<onlyName> when exactly one is present.
template <typename E>
void definePresent(QByteArray& out, const char* prefix, const char* onlyName, unsigned mask) {
    const auto& names = EnumNames<E>::names;
    int count = 0, last = -1;
    for (size_t i = 0; i < names.size(); ++i) {
        if (!(mask & (1u << i))) continue;
        out += "#define LR_HAS_" + QByteArray(prefix) + '_' + macroName(names[i]) + " 1\n";
        ++count;
        last = int(i);
    }
    if (count == 1) out += "#define LR_ONLY_" + QByteArray(onlyName) + ' ' + QByteArray::number(last) + '\n';
}

template <typename E> QString namesIn(unsigned mask) {
    QStringList parts;
    for (size_t i = 0; i < EnumNames<E>::names.size(); ++i)
        if (mask & (1u << i)) parts << QString::fromLatin1(EnumNames<E>::names[i]);
    return parts.join(QLatin1Char('+'));
}

void defineAllEnums(QByteArray& out) {
    defineEnum<LightType>(out, "LIGHT");
    defineEnum<FalloffModel>(out, "FALLOFF");
    defineEnum<ConeModel>(out, "CONE");
    defineEnum<DiffuseModel>(out, "DIFFUSE");
    defineEnum<SpecularModel>(out, "SPECULAR");
    defineEnum<ViewerModel>(out, "VIEWER");
    defineEnum<ToneMap>(out, "TONEMAP");
}

// LR_FALLOFF_BOUNDED(m, range): whether falloff model m is exactly zero at d >= range, from the traits
// table (core/fallofftraits.h): a required range always, an optional one when range >= 0.
void defineFalloffBounded(QByteArray& out) {
    QList<QByteArray> required, optional;
    for (const FalloffTraits& t : kFalloffTraits) {
        const QByteArray test =
            "(m) == LR_FALLOFF_" + macroName(EnumNames<FalloffModel>::names[size_t(t.model)]);
        if (t.range == RangeRule::Required) required << test;
        if (t.range == RangeRule::Optional) optional << test;
    }
    QList<QByteArray> terms = required;
    if (!optional.isEmpty()) terms << "((" + optional.join(" || ") + ") && (range) >= 0.0)";
    out += "#define LR_FALLOFF_BOUNDED(m, range) (" +
           (terms.isEmpty() ? QByteArray("false") : terms.join(" || ")) + ")\n";
}

} // namespace

FeatureKey::Bits FeatureKey::bits() const {
    Bits b{0, 0};
    int shift = 0;
    auto put = [&](std::uint64_t v, int width) { // a field never straddles the two words
        if (shift < 64 && shift + width > 64) shift = 64;
        b[size_t(shift / 64)] |= v << (shift % 64);
        shift += width;
    };
    put(rig.lightTypes, kLightTypeCount);
    put(rig.falloffs, keybits::kFalloffs);
    put(rig.cones, keybits::kCones);
    put(rig.diffuses, keybits::kDiffuses);
    put(unsigned(rig.specular), keybits::kSpecular);
    put(unsigned(rig.viewer), keybits::kViewer);
    put(rig.lightAmbient, 1);
    put(material.baseColorTexture, 1);
    put(material.normalMap, 1);
    put(material.emissiveTexture, 1);
    put(material.vertexColors, 1);
    put(material.doubleSided, 1);
    put(material.textureTransform, 1);
    put(material.alphaMask, 1);
    put(material.alphaBlend, 1);
    put(material.metalRoughTexture, 1);
    put(material.occlusionTexture, 1);
    put(unsigned(rig.shading), keybits::kShading);
    put(rig.farLights, 1);
    put(unsigned(quality), keybits::kQuality);
    put(unsigned(output), keybits::kOutput);
    put(deferredLighting, 1);
    put(clustered, 1);
    put(shininessInt, keybits::kShininessInt);
    put(approximations, keybits::kApproximations);
    put(unsigned(toneMap), keybits::kToneMap);
    put(rig.shadows, 1);
    put(rig.cubeShadows, 1);
    put(rig.softShadows, 1);
    put(material.shadowCatcher, 1);
    put(rig.environment, 1);
    put(attributes, 1);
    put(rig.linking, 1);
    put(rig.barnDoors, 1);
    put(rig.ies, 1);
    put(rig.gobo, 1);
    Q_ASSERT(shift <= 128);
    return b;
}

QString FeatureKey::describe() const {
    QStringList parts;
    parts << (rig.lightTypes ? namesIn<LightType>(rig.lightTypes) : QStringLiteral("no-lights"));
    if (rig.falloffs) parts << QStringLiteral("falloff:") + namesIn<FalloffModel>(rig.falloffs);
    if (rig.cones) parts << QStringLiteral("cone:") + namesIn<ConeModel>(rig.cones);
    if (rig.diffuses) parts << QStringLiteral("diffuse:") + namesIn<DiffuseModel>(rig.diffuses);
    parts << QStringLiteral("specular:") + toString(rig.specular)
          << QStringLiteral("viewer:") + toString(rig.viewer);
    if (rig.lightAmbient) parts << QStringLiteral("light-ambient");
    if (rig.shading == ShadingModel::Pbr) parts << QStringLiteral("shading:pbr");
    if (rig.farLights) parts << QStringLiteral("far-lights");
    if (rig.environment) parts << QStringLiteral("environment");
    if (rig.linking) parts << QStringLiteral("linking");
    if (rig.barnDoors) parts << QStringLiteral("barn-doors");
    if (rig.ies) parts << QStringLiteral("ies");
    if (rig.gobo) parts << QStringLiteral("gobo");
    if (rig.shadows)
        parts << QStringLiteral("shadows") + (rig.cubeShadows ? QStringLiteral(":cube") : QString()) +
                     (rig.softShadows ? QStringLiteral(":soft") : QString());
    QStringList tex;
    if (material.baseColorTexture) tex << QStringLiteral("base");
    if (material.normalMap) tex << QStringLiteral("normal");
    if (material.emissiveTexture) tex << QStringLiteral("emissive");
    if (material.metalRoughTexture) tex << QStringLiteral("metal-rough");
    if (material.occlusionTexture) tex << QStringLiteral("occlusion");
    if (!tex.isEmpty()) parts << QStringLiteral("tex:") + tex.join(QLatin1Char(','));
    if (material.vertexColors) parts << QStringLiteral("vertex-colors");
    if (material.doubleSided) parts << QStringLiteral("double-sided");
    if (material.textureTransform) parts << QStringLiteral("texture-transform");
    if (material.alphaMask) parts << QStringLiteral("alpha:mask");
    if (material.alphaBlend) parts << QStringLiteral("alpha:blend");
    if (material.shadowCatcher) parts << QStringLiteral("shadow-catcher");
    parts << QStringLiteral("quality:") + toString(quality);
    if (output == ShaderOutput::GBuffer) parts << QStringLiteral("gbuffer");
    if (attributes) parts << QStringLiteral("attributes");
    if (clustered) parts << QStringLiteral("clustered");
    if (shininessInt) parts << QStringLiteral("shininess:%1").arg(shininessInt);
    if (output == ShaderOutput::Display) parts << QStringLiteral("tone-map:") + toString(toneMap);
    return parts.join(QLatin1Char(' '));
}

RigFeatures allRigFeatures(const RigFeatures& rig) {
    RigFeatures f = rig;
    f.lightTypes = std::uint8_t((1u << enumCount<LightType>()) - 1);
    f.falloffs = std::uint8_t((1u << enumCount<FalloffModel>()) - 1);
    f.cones = std::uint8_t((1u << enumCount<ConeModel>()) - 1);
    f.diffuses = std::uint8_t((1u << enumCount<DiffuseModel>()) - 1);
    f.lightAmbient = true;
    f.farLights = f.shading == ShadingModel::Pbr;
    f.cubeShadows = f.shadows;
    f.softShadows = f.shadows;
    f.barnDoors = true;
    return f;
}

QByteArray toneMapDefine(ToneMap toneMap) {
    return "#define LR_TONE_MAP LR_TONEMAP_" + macroName(EnumNames<ToneMap>::names[size_t(toneMap)]) + '\n';
}

RigFeatures frameRigFeatures(const Rig& rig, bool farLights, bool allFeatures, bool environment,
                             bool linking) {
    RigFeatures f = rigFeatures(rig);
    f.farLights = farLights && f.shading == ShadingModel::Pbr;
    f.environment = environment;
    f.linking = linking;
    return allFeatures ? allRigFeatures(f) : f;
}

RigFeatures rigFeatures(const Rig& rig) {
    RigFeatures f;
    f.shading = rig.shading.model;
    // Under PBR neither the specular nor the viewer model applies (prepareSettings: always the local
    // viewer): one value each, so they never split PBR variants.
    f.specular = f.shading == ShadingModel::Pbr ? SpecularModel::Phong : rig.shading.specular;
    f.viewer = f.shading == ShadingModel::Pbr ? ViewerModel::Local : rig.shading.viewer;
    for (const Light& l : rig.lights) {
        if (!l.enabled) continue;
        if (l.hasShadow()) {
            f.shadows = true;
            f.cubeShadows |= shadowKindOf(l.type) == ShadowKind::Cube;
            f.softShadows |= hasSoftShadow(l);
        }
        f.lightTypes |= bit(l.type);
        if (l.type == LightType::Rect && l.barnDoors && barndoors::cuts(*l.barnDoors)) f.barnDoors = true;
        if (l.ies && (l.type == LightType::Point || l.type == LightType::Spot)) f.ies = true;
        if (l.gobo && l.type == LightType::Spot) f.gobo = true;
        if (l.usesFalloff()) f.falloffs |= bit(l.falloff.model);
        if (l.usesCone()) f.cones |= bit(l.cone.model);
        if (l.usesSurfaceModels()) {
            f.diffuses |= bit(l.diffuse);
            if (l.ambient) f.lightAmbient = true;
        }
    }
    return f;
}

MaterialFeatures materialFeatures(const Model& model, const Mesh& mesh) {
    MaterialFeatures f;
    f.vertexColors = mesh.hasVertexColors;
    if (mesh.material < 0 || size_t(mesh.material) >= model.materials.size()) return f;
    const Material& m = model.materials[size_t(mesh.material)];
    const auto valid = [&](int t) {
        return t >= 0 && size_t(t) < model.textures.size() && !model.textures[size_t(t)].image.isNull();
    };
    f.baseColorTexture = valid(m.baseColorTexture);
    f.normalMap = valid(m.normalTexture);
    f.emissiveTexture = valid(m.emissiveTexture);
    f.metalRoughTexture = valid(m.metallicRoughnessTexture);
    f.occlusionTexture = valid(m.occlusionTexture);
    f.doubleSided = m.doubleSided;
    // A transform counts only where its texture is used; identity transforms compile nothing.
    const auto textures = textureReferences(m);
    const auto transforms = textureTransforms(m);
    for (int i = 0; i < kTextureRoles; ++i)
        if (valid(textures[size_t(i)]) && !transforms[size_t(i)]->isIdentity()) f.textureTransform = true;
    f.alphaMask = m.alphaMode == AlphaMode::Mask;
    f.alphaBlend = m.alphaMode == AlphaMode::Blend;
    return f;
}

glm::mat3 textureTransformMatrix(const TextureTransform& t) {
    const float c = std::cos(t.rotation), s = std::sin(t.rotation);
    // Columns: T · R · S with R = [c s; −s c] (rows), S = diag(scale), T = translate(offset).
    return glm::mat3(glm::vec3(c * t.scale.x, -s * t.scale.x, 0.0f),
                     glm::vec3(s * t.scale.y, c * t.scale.y, 0.0f), glm::vec3(t.offset.x, t.offset.y, 1.0f));
}

QByteArray basicPrelude() {
    QByteArray out = "#version 330 core\n";
    defineAllEnums(out);
    defineFalloffBounded(out);
    return out;
}

QByteArray shaderPrelude(const FeatureKey& key) {
    QByteArray out = basicPrelude();
    out += "#define LR_SHADING 1\n";
    const LightTexelLayout layout = lightTexelLayout(key.rig);
    out += "#define LR_LIGHT_TEXELS " + QByteArray::number(layout.texels) + '\n';
    definePresent<LightType>(out, "LIGHT", "LIGHT", key.rig.lightTypes);
    definePresent<FalloffModel>(out, "FALLOFF", "FALLOFF", key.rig.falloffs);
    definePresent<ConeModel>(out, "CONE", "CONE", key.rig.cones);
    definePresent<DiffuseModel>(out, "DIFFUSE", "DIFFUSE", key.rig.diffuses);
    out += "#define LR_SPECULAR LR_SPECULAR_" +
           macroName(EnumNames<SpecularModel>::names[size_t(key.rig.specular)]) + '\n';
    out += "#define LR_VIEWER LR_VIEWER_" + macroName(EnumNames<ViewerModel>::names[size_t(key.rig.viewer)]) +
           '\n';
    if (key.rig.lightAmbient) out += "#define LR_HAS_LIGHT_AMBIENT 1\n";
    // Physically based shading and its textures: only in PBR programs, so classic preludes are unchanged.
    const bool pbr = key.rig.shading == ShadingModel::Pbr;
    if (pbr) out += "#define LR_PBR 1\n";
    if (pbr && key.rig.farLights) out += "#define LR_FAR_LIGHTS 1\n";
    if (key.material.baseColorTexture) out += "#define LR_BASE_COLOR_TEXTURE 1\n";
    if (key.material.normalMap) out += "#define LR_NORMAL_MAP 1\n";
    if (key.material.emissiveTexture) out += "#define LR_EMISSIVE_TEXTURE 1\n";
    if (key.material.vertexColors) out += "#define LR_VERTEX_COLOR 1\n";
    if (key.material.doubleSided) out += "#define LR_DOUBLE_SIDED 1\n";
    if (key.material.textureTransform) out += "#define LR_TEXTURE_TRANSFORM 1\n";
    if (key.material.alphaMask) out += "#define LR_ALPHA_MASK 1\n";
    if (key.material.alphaBlend) out += "#define LR_ALPHA_BLEND 1\n";
    // Shadows (shaders/shadows.glsl) only where some light casts: other preludes are unchanged.
    if (key.rig.shadows)
        out += "#define LR_SHADOWS 1\n#define LR_SHADOW_TEXELS " + QByteArray::number(kShadowTexels) +
               "\n#define LR_MAX_SHADOW_CASTERS " + QByteArray::number(kMaxShadowCasters) +
               "\n#define LR_SHADOW_SLOT_SCALE " + QByteArray::number(kShadowSlotScale) + '\n';
    if (key.rig.shadows && key.rig.cubeShadows) out += "#define LR_SHADOW_CUBE 1\n";
    if (key.rig.shadows && key.rig.softShadows) out += "#define LR_SHADOW_SOFT 1\n";
    if (key.material.shadowCatcher) out += "#define LR_SHADOW_CATCHER 1\n";
    // Environment lighting (shaders/environment.glsl) only where the frame has one: other preludes are
    // unchanged. Never in G-buffer programs (their key carries no rig) or the catcher's.
    if (key.rig.environment && key.output != ShaderOutput::GBuffer && !key.material.shadowCatcher)
        out += "#define LR_ENVIRONMENT 1\n";
    if (pbr && key.material.metalRoughTexture) out += "#define LR_METAL_ROUGH_TEXTURE 1\n";
    if (pbr && key.material.occlusionTexture) out += "#define LR_OCCLUSION_TEXTURE 1\n";
    out += "#define LR_QUALITY_" + macroName(EnumNames<Quality>::names[size_t(key.quality)]) + " 1\n";
    if (key.deferredLighting) out += "#define LR_DEFERRED_LIGHTING 1\n";
    if (key.attributes) out += "#define LR_ATTRIBUTE_GBUFFER 1\n";
    if (key.clustered) out += "#define LR_CLUSTERED 1\n";
    // Light linking (shaders/shadetypes.glsl lightLinked): only where the rig links, so that every other
    // prelude is unchanged. G-buffer programs with it write the part's class into the link target.
    if (key.rig.linking) out += "#define LR_LIGHT_LINKING 1\n";
    // Barn doors (shaders/area.glsl barnWindow): only where a rect light has them.
    if (key.rig.barnDoors) out += "#define LR_BARN_DOORS 1\n";
    // IES profiles and gobos (shaders/shaping.glsl): only where a light has one; each names where its
    // texels start in a light's record.
    if (key.rig.ies)
        out += "#define LR_IES 1\n#define LR_IES_TEXEL " + QByteArray::number(layout.ies) +
               "\n#define LR_IES_GRID_V " + QByteArray::number(kIesGridVertical) +
               "\n#define LR_IES_GRID_H " + QByteArray::number(kIesGridHorizontal) +
               "\n#define LR_IES_STEP_V " + QByteArray::number(kIesGridVerticalStep, 'f', 3) +
               "\n#define LR_IES_STEP_H " + QByteArray::number(kIesGridHorizontalStep, 'f', 3) + '\n';
    if (key.rig.gobo)
        out += "#define LR_GOBO 1\n#define LR_GOBO_TEXEL " + QByteArray::number(layout.gobo) + '\n';
    // The tier's approximations (docs/quality.md), as the key names them (approx::forTier keeps its own).
    const std::uint8_t approximations = approx::forTier(key.approximations, key.quality);
    const std::pair<std::uint8_t, const char*> defines[] = {{approx::kB1, "LR_B1"},
                                                            {approx::kB2, "LR_B2"},
                                                            {approx::kB3, "LR_B3"},
                                                            {approx::kB4, "LR_B4"},
                                                            {approx::kF2, "LR_FAST_INFINITE_VIEWER"}};
    for (const auto& [bit, name] : defines)
        if (approximations & bit) out += "#define " + QByteArray(name) + " 1\n";
    // The BRDF's own approximations exist only in PBR programs (a classic balanced prelude stays as it was).
    if (pbr && (approximations & approx::kB5)) out += "#define LR_B5 1\n";
    if (pbr && (approximations & approx::kB6)) out += "#define LR_B6 1\n";
    if (key.quality == Quality::Balanced && key.shininessInt > 0 && key.shininessInt <= kMaxShininessInt &&
        (approximations & approx::kB2)) {
        // x^n by repeated squaring, unrolled here so the shader is a plain chain of products.
        out += "#define LR_SHININESS_INT " + QByteArray::number(key.shininessInt) + '\n';
        out += "float powShininessInt(float x) {\n    float r = 1.0, b = x;\n";
        for (int n = key.shininessInt; n > 0; n >>= 1) {
            if (n & 1) out += "    r *= b;\n";
            if (n > 1) out += "    b *= b;\n";
        }
        out += "    return r;\n}\n";
    }
    switch (key.output) {
    case ShaderOutput::Display:
        out += "#define LR_OUTPUT_DISPLAY 1\n";
        out += toneMapDefine(key.toneMap);
        break;
    case ShaderOutput::Radiance:
        out += "#define LR_OUTPUT_RADIANCE 1\n";
        break;
    case ShaderOutput::GBuffer:
        out += "#define LR_OUTPUT_GBUFFER 1\n";
        break;
    }
    return out;
}

namespace approx {

namespace {
constexpr std::pair<std::uint8_t, const char*> kNames[] = {{kB1, "b1"}, {kB2, "b2"}, {kB3, "b3"}, {kB4, "b4"},
                                                           {kF2, "f2"}, {kB5, "b5"}, {kB6, "b6"}};
static_assert(std::size(kNames) == kCount);
} // namespace

std::uint8_t forTier(std::uint8_t set, Quality quality) {
    switch (quality) {
    case Quality::Balanced:
        return set & kBalancedMask;
    case Quality::Fast:
        return set & kFastMask;
    default:
        return 0;
    }
}

bool parseApproximations(const QString& text, std::uint8_t* out, QString* error) {
    std::uint8_t set = 0;
    const QString trimmed = text.trimmed().toLower();
    if (trimmed != QLatin1String("none")) {
        for (const QString& word : trimmed.split(QLatin1Char(','))) {
            bool found = false;
            for (const auto& [bit, name] : kNames)
                if (word.trimmed() == QLatin1String(name)) set |= bit, found = true;
            if (!found) {
                if (error)
                    *error = QStringLiteral("unknown approximation '%1' (expected a comma-separated list of "
                                            "b1, b2, b3, b4, b5, b6, f2, or none)")
                                 .arg(word.trimmed());
                return false;
            }
        }
    }
    *out = set;
    return true;
}

QString approximationNames(std::uint8_t set) {
    QStringList names;
    for (const auto& [bit, name] : kNames)
        if (set & bit) names << QLatin1String(name);
    return names.isEmpty() ? QStringLiteral("none") : names.join(QLatin1Char(','));
}

} // namespace approx

} // namespace lr::render
