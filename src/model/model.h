// A model as LightRig renders it: flattened triangle meshes (node transforms applied), materials,
// decoded textures, and the lights and cameras the file carries. No GL here: the renderer uploads it,
// the import worker (a child process) serialises it.
#pragma once

#include "core/rig.h"

#include <QImage>
#include <QString>
#include <QStringList>
#include <array>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace lr {

struct Vertex {
    glm::vec3 position{0.0f}; // relative to Model::origin (keeps float precision far from the world origin)
    glm::vec3 normal{0.0f, 0.0f, 1.0f};
    glm::vec2 uv{0.0f}; // (0, 0) = top-left texel = first QImage row: upload QImage bits as they are
    glm::vec4 tangent{1.0f, 0.0f, 0.0f, 1.0f}; // xyz tangent (+u), w handedness: bitangent = w cross(N, T)
                                               // points up in the image (normal map +Y, as glTF)
    glm::vec4 color{1.0f};                     // linear vertex colour
};

struct Texture {
    QString name; // file path or "*N" for embedded
    QImage image; // RGBA8888, as stored (sRGB-encoded for colour textures)
};

enum class AlphaMode { Opaque, Mask, Blend }; // glTF alphaMode
template <> struct EnumNames<AlphaMode> {     // glTF's names: toString, enumCount, the codec's range check
    static constexpr std::array names{"OPAQUE", "MASK", "BLEND"};
};

// KHR_texture_transform of one texture reference: uv' = offset + R(rotation) · (scale ⊙ uv), in the
// glTF convention (u right, v down the image), and the UV set it reads (0 only today; others warn).
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f; // radians, counter-clockwise in UV space as glTF writes it
    glm::vec2 scale{1.0f};
    bool isIdentity() const {
        return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f);
    }
    bool operator==(const TextureTransform&) const = default;
};

// A glTF sampler's wrap mode along one texture axis (glTF 2.0 "samplers": wrapS, wrapT); other formats'
// clamp maps to ClampToEdge (Assimp's decal too).
enum class TextureWrap { Repeat, ClampToEdge, MirroredRepeat };
template <> struct EnumNames<TextureWrap> {
    static constexpr std::array names{"repeat", "clamp-to-edge", "mirrored-repeat"};
};

// How one texture reference is sampled: its sampler's wrap modes and magnification filter. The
// minification filter stays the tier's (trilinear; the fast tier's nearest mip level, core/quality.h).
struct TextureSampling {
    TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
    bool nearestMagnification = false; // magFilter NEAREST (9728): texels stay sharp when magnified
    bool isDefault() const { return *this == TextureSampling{}; }
    bool operator==(const TextureSampling&) const = default;
};

// One glTF material extension the file's material names ("KHR_materials_clearcoat"), with its JSON object
// as the file writes it (compact, at most kMaxExtensionValues characters), for the Model dock. Which of them
// LightRig renders: materialExtensionRendered.
struct MaterialExtension {
    QString name;
    QString values;
    bool operator==(const MaterialExtension&) const = default;
};
constexpr int kMaxExtensionValues = 512;
constexpr int kMaxMaterialExtensions = 32; // more on one material is a warning, the rest not listed
// Whether LightRig renders a material extension (KHR_materials_emissive_strength: folded into emissive);
// every other one a material uses is a warning at import that names it.
bool materialExtensionRendered(const QString& name);

struct Material {
    QString name;
    glm::vec4 baseColor{1.0f}; // linear RGBA factor
    int baseColorTexture = -1; // index into Model::textures, sampled as sRGB
    int normalTexture = -1;    // linear, tangent space
    int emissiveTexture = -1;  // sRGB
    glm::vec3 emissive{0.0f};  // linear factor, KHR_materials_emissive_strength folded in
    glm::vec3 specular{1.0f};  // ks (classic shading)
    float shininess = -1.0f;   // < 0: use the rig's shading.shininess (classic shading)
    bool doubleSided = false;
    // Physically based (glTF metal-rough). `pbr`: the file carried these values (glTF, or PBR keys of
    // another format); otherwise they were converted from specular/shininess (docs/lighting-models.md).
    bool pbr = false;
    float metallic = 0.0f, roughness = 1.0f;
    int metallicRoughnessTexture = -1; // linear: G = roughness, B = metallic
    int occlusionTexture = -1;         // linear: R = occlusion
    float occlusionStrength = 1.0f;
    float normalScale = 1.0f;
    AlphaMode alphaMode = AlphaMode::Opaque;
    float alphaCutoff = 0.5f;
    // One transform per texture role (base colour, normal, emissive, metal-rough, occlusion).
    TextureTransform baseColorTransform, normalTransform, emissiveTransform, metallicRoughnessTransform,
        occlusionTransform;
    // And one sampling per role, in the same order.
    TextureSampling baseColorSampling, normalSampling, emissiveSampling, metallicRoughnessSampling,
        occlusionSampling;
    // glTF: the material's extensions (those Assimp reads and those it drops alike), sorted by name.
    std::vector<MaterialExtension> extensions;
    bool operator==(const Material&) const = default;
};

// A material's five texture roles, in one order wherever they are listed (the worker codec, the renderer's
// TextureRole and transform uniforms, its feature bits): base colour, normal, emissive,
// metallic-roughness, occlusion.
constexpr int kTextureRoles = 5;
// The texture references (indices into Model::textures, -1: none), by role.
inline std::array<int, kTextureRoles> textureReferences(const Material& m) {
    return {m.baseColorTexture, m.normalTexture, m.emissiveTexture, m.metallicRoughnessTexture,
            m.occlusionTexture};
}
// The KHR_texture_transforms, by role.
inline std::array<const TextureTransform*, kTextureRoles> textureTransforms(const Material& m) {
    return {&m.baseColorTransform, &m.normalTransform, &m.emissiveTransform, &m.metallicRoughnessTransform,
            &m.occlusionTransform};
}
inline std::array<TextureTransform*, kTextureRoles> textureTransforms(Material& m) {
    return {&m.baseColorTransform, &m.normalTransform, &m.emissiveTransform, &m.metallicRoughnessTransform,
            &m.occlusionTransform};
}

// The samplings, by role.
inline std::array<const TextureSampling*, kTextureRoles> textureSamplings(const Material& m) {
    return {&m.baseColorSampling, &m.normalSampling, &m.emissiveSampling, &m.metallicRoughnessSampling,
            &m.occlusionSampling};
}
inline std::array<TextureSampling*, kTextureRoles> textureSamplings(Material& m) {
    return {&m.baseColorSampling, &m.normalSampling, &m.emissiveSampling, &m.metallicRoughnessSampling,
            &m.occlusionSampling};
}

struct Mesh {
    QString name; // the file's mesh name (Assimp's: a glTF mesh with several primitives names each "NAME-N")
    QString node; // the name of the node that places it (light linking matches both, core/lightlink.h)
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices; // triangles
    int material = 0;                   // index into Model::materials
    bool hasVertexColors = false;
    bool hasTangents = false;
};

struct Camera {
    QString name;
    glm::dvec3 position{0.0, 0.0, 5.0}; // world
    glm::dvec3 forward{0.0, 0.0, -1.0}; // unit
    glm::dvec3 up{0.0, 1.0, 0.0};       // unit
    double yfovDegrees = 45.0;
    double znear = 0.01, zfar = 1000.0; // zfar <= 0: infinite
    double aspect = 0.0;                // 0: from the viewport
};

struct Bounds {
    glm::dvec3 min{0.0}, max{0.0}; // world
    glm::dvec3 center() const { return (min + max) * 0.5; }
    double radius() const; // half the diagonal; 1 when empty
};

struct Model {
    QString path;
    glm::dvec3 origin{0.0}; // world position that Vertex::position is relative to
    std::vector<Mesh> meshes;
    std::vector<Material> materials; // never empty after a successful load
    std::vector<Texture> textures;
    std::vector<Camera> cameras;
    Rig lights; // the file's own lights (world space), empty when it has none
    Bounds bounds;
    QStringList warnings; // degenerate geometry dropped, textures missing, ...
    // Texture references (as the file writes them) refused only because they lie outside the model's
    // folder, whose files exist: loading again with ModelLoadOptions::allowTexturesOutsideFolder would
    // use them (the editor asks). Never Windows drive paths, which stay refused. Each has a warning too.
    QStringList texturesOutsideFolder;
    double loadMs = 0.0;

    std::size_t triangleCount() const;
    // Whether any material carries physically based values (opened without a rig, it renders PBR).
    bool hasPbrMaterials() const;
    std::size_t vertexCount() const;
};

// A built-in model for tests and fallbacks: a UV sphere or a plane (z = 0 facing +Z), one material.
Model makeSphere(double radius, int segments, int rings, const glm::dvec3& center = glm::dvec3(0.0));
Model makePlane(double halfSize, const glm::dvec3& center = glm::dvec3(0.0));

} // namespace lr
