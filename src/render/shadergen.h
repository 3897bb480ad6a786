// Shader specialisation: the features a scene actually uses (light types and models present in the rig,
// the rig's specular and viewer models, the material's textures) form a FeatureKey; each distinct key is
// compiled once into a program whose source is shaders/*.glsl with #defines prepended. No GL here.
#pragma once

#include "approximations.h"
#include "core/quality.h"
#include "core/rig.h"
#include "model/model.h"

#include <QByteArray>
#include <QString>
#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/mat3x3.hpp>

namespace lr::render {

// Display: exposure, tone map and sRGB per fragment into an 8-bit target (the fast default path).
// Radiance: linear HDR radiance into a float target (tone-mapped by a separate pass; for read-backs).
// GBuffer: the Surface each fragment shades, into float targets (the CPU reference's input).
enum class ShaderOutput : std::uint8_t { Display, Radiance, GBuffer };

// What the rig contributes to a key. Computed from the enabled lights (whether they reach the model or
// not), so moving a light never changes it; only adding a light of a new type or model does.
struct RigFeatures {
    std::uint8_t lightTypes = 0; // bit (1 << int(LightType))
    std::uint8_t falloffs = 0;   // bit per FalloffModel among point and spot lights
    std::uint8_t cones = 0;      // bit per ConeModel among spot lights
    std::uint8_t diffuses = 0;   // bit per DiffuseModel among point, spot and directional lights
    SpecularModel specular = SpecularModel::Phong;
    ViewerModel viewer = ViewerModel::Local;
    bool lightAmbient = false; // some surface light has an ambient colour
    // Physically based (LR_PBR): the glTF BRDF; specular is then Phong and viewer Local (neither applies).
    ShadingModel shading = ShadingModel::Classic;
    // Physically based only: some positional light may be 1e15 or more from a visible surface (view space),
    // so L is rescaled before it is normalised (LR_FAR_LIGHTS). Not a property of the rig alone: the
    // renderer sets it per frame from the light set's bound (LightSet::farLights()); rigFeatures() leaves
    // it false.
    bool farLights = false;
    // Some light casts a shadow (Light::hasShadow; LR_SHADOWS): the lit programs sample the shadow maps
    // with the key's quality tier's filter (shaders/shadows.glsl). Without it a program's text is what it
    // was before shadows existed.
    bool shadows = false;
    // Some casting light is a point light (LR_SHADOW_CUBE): only then is the six-face lookup compiled in.
    // llvmpipe runs both sides of a branch, so a spot-only rig paid for the face selection per light and
    // pixel (helmet_8spot, 8 casting spots over a ground: fast 136 -> 114 ms/frame, exact 362 -> 266).
    bool cubeShadows = false;
    // Some casting light has an extent (hasSoftShadow; LR_SHADOW_SOFT): only then are the balanced tier's
    // PCF and the exact tier's PCSS compiled in. Without it every tier takes one compared tap, as a point
    // emitter does anyway (helmet_ground_8spot, 8 casting spots of size 0: exact 196 -> 91 ms/frame).
    bool softShadows = false;
    // The rig's environment lights the model (LR_ENVIRONMENT, shaders/environment.glsl): its source is not
    // None AND an environment is loaded (Renderer::environment()). Like farLights, set per frame by the
    // renderer (frameRigFeatures); rigFeatures() leaves it false. Without it a program's text is exactly
    // what it was before environments existed.
    bool environment = false;
    // Light and shadow linking (issue 38, core/lightlink.h): some light of the rig links
    // (SceneDescription::links().active; LR_LIGHT_LINKING). Each light then carries its lit-class mask in
    // one more texel (kLinkedLightTexels), each draw its part's lighting class (uLinkClass; in the deferred
    // path the G-pass writes it into the G-buffer's link target), and the lights a part's class is not in
    // add nothing there. Like environment, set per frame by the renderer (frameRigFeatures); rigFeatures()
    // leaves it false, and without it a program's text is exactly what it was before linking existed.
    bool linking = false;
    // Some enabled rect light has barn doors that cut (issue 39, core/barndoors.h; LR_BARN_DOORS): the area
    // integrals run over the part of each rect the point sees. Without it a program's text is what it was.
    bool barnDoors = false;
    // Some enabled point or spot light has an IES profile (LR_IES; issue 39, core/iesshade.h), some enabled
    // spot a gobo (LR_GOBO; core/gobo.h): each light then carries kIesTexels or kGoboTexels more texels
    // (lightTexelLayout) and the lit programs read the profile or image from a texture array
    // (lightshapinggl.h). From the rig alone, so the light buffer (LightSet) and the keys agree; without
    // them a program's text is what it was before shaping existed.
    bool ies = false;
    bool gobo = false;
    bool operator==(const RigFeatures&) const = default;
};

struct MaterialFeatures {
    bool baseColorTexture = false;
    bool normalMap = false;
    bool emissiveTexture = false;
    bool vertexColors = false;
    bool doubleSided = false;
    // glTF's rest of the material (docs/lighting-models.md, Materials): a used texture with a
    // non-identity KHR_texture_transform; alphaMode MASK (discard under the cutoff); BLEND (drawn by the
    // blend pass, after all opaque geometry, its alpha written for "over" blending).
    bool textureTransform = false;
    bool alphaMask = false;
    bool alphaBlend = false;
    // glTF metal-rough textures, sampled under physically based shading only (the geometry pass clears
    // them for classic rigs, so a classic program never sees them).
    bool metalRoughTexture = false;
    bool occlusionTexture = false;
    // The ground as a shadow catcher (LR_SHADOW_CATCHER, pass_catcher.cpp): writes only its shadows'
    // opacity. Set by the catcher pass, never by a model's material.
    bool shadowCatcher = false;
    bool operator==(const MaterialFeatures&) const = default;
};

struct FeatureKey {
    RigFeatures rig;
    MaterialFeatures material;
    Quality quality = Quality::Exact;
    ShaderOutput output = ShaderOutput::Display;
    // The deferred lighting pass (fullscreen.vert + deferred.frag; `material` unused) rather than a mesh
    // program (mesh.vert + mesh.frag). G-buffer mesh programs ignore `rig`: the renderer leaves it empty.
    bool deferredLighting = false;
    // The G-buffer holds the fragments' attributes (LR_ATTRIBUTE_GBUFFER, shaders/surface.glsl), not their
    // Surface: the G-pass (output GBuffer) writes them and the deferred lighting pass, keyed with the
    // drawn material's `material` features, builds the Surface from them and that material's textures.
    bool attributes = false;
    // Clustered forward shading (cluster.h, shaders/cluster.glsl): each fragment loops over its cluster's
    // lights only. Chosen per frame by the renderer when the rig has many range-bounded lights.
    bool clustered = false;
    // Balanced tier (B2 in docs/quality.md): the material's shininess when it is a whole number in
    // 1..kMaxShininessInt, so the specular power compiles to a chain of products; 0 otherwise.
    std::uint16_t shininessInt = 0;
    // The tier's approximations compiled in (named bits, approx:: below; docs/quality.md). Only the bits of
    // the key's own tier are kept (approx::forTier), so exact variants never multiply.
    std::uint8_t approximations = 0;
    // The tone map a display-output program applies, compiled in as a constant (LR_TONE_MAP): selected at
    // run time, every operator's code ran for every pixel (llvmpipe evaluates all sides of a branch),
    // a fifth of the helmet's frame. Other outputs leave it Clamp so that it never splits their variants.
    ToneMap toneMap = ToneMap::Clamp;

    // A unique packing, for hashing and ordering: two words, since the fields outgrew one.
    using Bits = std::array<std::uint64_t, 2>;
    Bits bits() const;
    QString describe() const; // "point+spot falloff:range-power cone:smooth ... tex:base,normal"
    bool operator==(const FeatureKey&) const = default;
};

struct FeatureKeyHash {
    std::size_t operator()(const FeatureKey& k) const {
        const FeatureKey::Bits b = k.bits();
        return std::hash<std::uint64_t>()(b[0] ^ (b[1] * 0x9e3779b97f4a7c15ull));
    }
};

constexpr int kMaxShininessInt = 256;

// Widths of FeatureKey::bits()'s fields (shadergen.cpp packs them in this order). A model or tier that
// outgrows its field fails to compile here instead of silently aliasing two shader variants.
namespace keybits {
constexpr int kFalloffs = 5, kCones = 3, kDiffuses = 2, kSpecular = 1, kViewer = 1, kQuality = 2, kOutput = 2,
              kShininessInt = 9, kShading = 1, kToneMap = 3;
} // namespace keybits
static_assert(enumCount<FalloffModel>() <= keybits::kFalloffs, "widen FeatureKey::bits()'s falloff field");
static_assert(enumCount<ConeModel>() <= keybits::kCones, "widen FeatureKey::bits()'s cone field");
static_assert(enumCount<DiffuseModel>() <= keybits::kDiffuses, "widen FeatureKey::bits()'s diffuse field");
static_assert(enumCount<SpecularModel>() <= (1 << keybits::kSpecular));
static_assert(enumCount<ViewerModel>() <= (1 << keybits::kViewer));
static_assert(enumCount<ShadingModel>() <= (1 << keybits::kShading),
              "widen FeatureKey::bits()'s shading field");
static_assert(enumCount<Quality>() <= (1 << keybits::kQuality));
static_assert(enumCount<ToneMap>() <= (1 << keybits::kToneMap), "widen FeatureKey::bits()'s tone-map field");
static_assert(int(ShaderOutput::GBuffer) < (1 << keybits::kOutput));
static_assert(kMaxShininessInt < (1 << keybits::kShininessInt));
namespace keybits {
constexpr int kApproximations = 7;
}
static_assert(approx::kCount <= keybits::kApproximations, "widen FeatureKey::bits()'s approximation field");

RigFeatures rigFeatures(const Rig& rig);
// Every light type and model present (the über-shader); the rig-wide specular and viewer models stay.
RigFeatures allRigFeatures(const RigFeatures& rig);
// The features a frame shades the rig with: rigFeatures() and the frame's far-lights bound, or all of
// them (allRigFeatures) for the über-shader. Every lit pass builds its keys from this.
// `environment`: the frame has an environment to light with (FrameContext::environment); the shadow
// catcher passes false (it shows shadows only).
// `linking`: SceneDescription::links().active (RigFeatures::linking).
RigFeatures frameRigFeatures(const Rig& rig, bool farLights, bool allFeatures, bool environment = false,
                             bool linking = false);
// "#define LR_TONE_MAP LR_TONEMAP_ACES\n": the operator mesh.frag, deferred.frag and tonemap.frag pass to
// displayEncode()/toneMapRgb() as a compile-time constant.
QByteArray toneMapDefine(ToneMap toneMap);
// Texture indices out of range count as absent.
MaterialFeatures materialFeatures(const Model& model, const Mesh& mesh);
// KHR_texture_transform as mesh.frag's lrUv applies it: uv' = T · R · S · uv (the extension's order:
// scale, then rotation counter-clockwise in UV space with v down the image, i.e. u' = cos·u + sin·v,
// v' = −sin·u + cos·v, then offset), column-major for glUniformMatrix3fv.
glm::mat3 textureTransformMatrix(const TextureTransform& t);

// Texels (RGBA32F) per light in the light buffer; layout: shaders/shadetypes.glsl loadLight.
constexpr int kLightTexels = 8;
// ... when the frame links lights (RigFeatures::linking): texel 8 holds the light's lit-class mask as two
// exact 16-bit halves (lightpack.h packLinkTexel). An unlinked frame packs kLightTexels as before.
constexpr int kLinkedLightTexels = kLightTexels + 1;
// ... an IES profile's (RigFeatures::ies; lightpack.h packIesTexels) and a gobo's (RigFeatures::gobo;
// packGoboTexels), after the link texel: every light of such a frame has them (layer -1: none).
constexpr int kIesTexels = 2, kGoboTexels = 3;
// Where each optional part of a light's record starts (-1: absent) and its texels in all.
struct LightTexelLayout {
    int texels = kLightTexels;
    int link = -1, ies = -1, gobo = -1;
};
constexpr LightTexelLayout lightTexelLayout(bool linking, bool ies, bool gobo) {
    LightTexelLayout l;
    if (linking) l.link = l.texels++;
    if (ies) l.ies = l.texels, l.texels += kIesTexels;
    if (gobo) l.gobo = l.texels, l.texels += kGoboTexels;
    return l;
}
inline LightTexelLayout lightTexelLayout(const RigFeatures& f) {
    return lightTexelLayout(f.linking, f.ies, f.gobo);
}

// "#version 330 core" plus the enum values and the key's feature defines (the same for both stages).
QByteArray shaderPrelude(const FeatureKey& key);
// The prelude for passes that only need the enum values and the formulas (tone map, gizmos).
QByteArray basicPrelude();

} // namespace lr::render
