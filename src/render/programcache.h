// Compiled shader programs, one per distinct FeatureKey, plus the fixed passes (tone map, overlay).
// Every program is a named ShaderConfig: the files of each stage, in order, after the prelude. Sources are
// the embedded :/shaders/NAME files (overridable for tests) and the generated G-buffer codec
// (gbuffer.glsl, gbuffer.h); compile and link errors carry the GLSL log. Sampler uniforms are bound to
// their units once, from textureunits.h. Needs the current context of the owning Renderer.
#pragma once

#include "shadergen.h"

#include <QHash>
#include <QOpenGLShaderProgram>
#include <array>
#include <memory>
#include <unordered_map>

namespace lr::render {

// A named shader configuration (TrenchBroom's idea): which files make each stage.
struct ShaderConfig {
    const char* name;
    std::array<const char*, 14> vertex{}; // files under :/shaders/, in order; nullptr ends the list
    std::array<const char*, 14> fragment{};
};

// The shading files, each the twin of a core header (colour.h, lighting.h, shadetypes.h, lighting_area.h,
// shade.h): a program lists only those it needs. shadows.glsl is empty unless the key casts shadows
// (LR_SHADOWS), area.glsl unless the rig has an area light, shaping.glsl unless a light has an IES profile
// or a gobo; shadevertex.glsl (the fast tier) is listed only
// by the vertex-lit programs.
#define LR_SHADING_FILES                                                                                     \
    "colour.glsl", "lighting.glsl", "shadetypes.glsl", "shaping.glsl", "area.glsl", "shade.glsl"
inline constexpr ShaderConfig kMeshShader{
    "mesh",
    {"mesh.vert"},
    {LR_SHADING_FILES, "shadows.glsl", "cluster.glsl", "gbuffer.glsl", "surface.glsl", "mesh.frag"}};
// The fast tier lights the vertices.
inline constexpr ShaderConfig kVertexLitMeshShader{
    "mesh, vertex-lit",
    {LR_SHADING_FILES, "shadevertex.glsl", "shadows.glsl", "mesh.vert"},
    {LR_SHADING_FILES, "shadevertex.glsl", "shadows.glsl", "cluster.glsl", "gbuffer.glsl", "surface.glsl",
     "mesh.frag"}};
inline constexpr ShaderConfig kDeferredLightingShader{
    "deferred lighting",
    {"fullscreen.vert"},
    {LR_SHADING_FILES, "shadows.glsl", "cluster.glsl", "gbuffer.glsl", "surface.glsl", "deferred.frag"}};
// Depth only, into a shadow map (shadowmaps.h): uLightMatrix = the light's clip from model positions.
inline constexpr ShaderConfig kShadowDepthShader{"shadow depth", {"shadow.vert"}, {"shadow.frag"}};
inline constexpr ShaderConfig kToneMapShader{
    "tone map", {"fullscreen.vert"}, {"colour.glsl", "tonemap.frag"}};
inline constexpr ShaderConfig kOverlayShader{"overlay", {"gizmo.vert"}, {"gizmo.frag"}};
// The overlay pass's highlighted parts (RenderSettings::highlightedParts): positions only, a flat tint.
inline constexpr ShaderConfig kHighlightShader{"part highlight", {"highlight.vert"}, {"highlight.frag"}};
// MeshPass::primeSamplerSlots (pass_geometry.cpp): a draw that covers no pixel.
inline constexpr ShaderConfig kSlotPrimerShader{
    "sampler-slot primer", {"slotprimer.vert"}, {"slotprimer.frag"}};
// Environment lighting (LR_ENVIRONMENT, environmentgl.h): the lit configurations with environment.glsl
// before the stage that shades, chosen only for keys with the bit, so every other program's text is
// exactly what it was. The background pass (pass_background.cpp) draws the environment behind the model.
inline constexpr ShaderConfig kMeshEnvironmentShader{"mesh",
                                                     {"mesh.vert"},
                                                     {LR_SHADING_FILES, "shadows.glsl", "cluster.glsl",
                                                      "gbuffer.glsl", "environment.glsl", "surface.glsl",
                                                      "mesh.frag"}};
inline constexpr ShaderConfig kVertexLitMeshEnvironmentShader{
    "mesh, vertex-lit",
    {LR_SHADING_FILES, "shadevertex.glsl", "shadows.glsl", "mesh.vert"},
    {LR_SHADING_FILES, "shadevertex.glsl", "shadows.glsl", "cluster.glsl", "gbuffer.glsl", "environment.glsl",
     "surface.glsl", "mesh.frag"}};
inline constexpr ShaderConfig kDeferredLightingEnvironmentShader{
    "deferred lighting",
    {"fullscreen.vert"},
    {LR_SHADING_FILES, "shadows.glsl", "cluster.glsl", "gbuffer.glsl", "environment.glsl", "surface.glsl",
     "deferred.frag"}};
#undef LR_SHADING_FILES
inline constexpr ShaderConfig kBackgroundShader{
    "environment background",
    {"fullscreen.vert"},
    {"colour.glsl", "lighting.glsl", "environment.glsl", "background.frag"}};
// The background kept by BackgroundPass, copied where no surface is (the forward path; deferred blits it).
inline constexpr ShaderConfig kBackgroundCopyShader{
    "background copy", {"fullscreen.vert"}, {"backgroundcopy.frag"}};

// The configuration a FeatureKey compiles with.
const ShaderConfig& shaderConfig(const FeatureKey& key);

// A mesh program and its uniform locations (looked up once).
struct MeshProgram {
    std::unique_ptr<QOpenGLShaderProgram> program;
    int modelView = -1, normalMatrix = -1, projection = -1;
    int baseColor = -1, emissive = -1, specular = -1, shininess = -1, ambient = -1, distanceScale = -1;
    int lightCount = -1;
    int shadowCount = -1;   // LR_SHADOWS: casters
    int shadowRecords = -1; // LR_SHADOWS: their records (shadowmaps.h kShadowTexels vec4s each)
    int exposureScale = -1; // display output only
    int metallic = -1, roughness = -1, occlusionStrength = -1; // LR_PBR only
    int normalScale = -1, alphaCutoff = -1;
    int linkClass = -1; // LR_LIGHT_LINKING: the drawn part's lighting class (uLinkClass)
    // KHR_texture_transform's mat3 per texture role (LR_TEXTURE_TRANSFORM), in TextureRole's order.
    std::array<int, kTextureRoles> textureTransforms{-1, -1, -1, -1, -1};
};

// The texture roles of a glTF material, each with its own KHR_texture_transform, in model.h's role order
// (textureTransforms(), textureReferences()).
enum class TextureRole { BaseColor, Normal, Emissive, MetalRough, Occlusion };
// The mat3 uniform of each role in mesh.frag (uBaseColorTransform, ...).
inline constexpr const char* kTextureTransformUniforms[] = {"uBaseColorTransform", "uNormalTransform",
                                                            "uEmissiveTransform", "uMetalRoughTransform",
                                                            "uOcclusionTransform"};
static_assert(std::size(kTextureTransformUniforms) == kTextureRoles,
              "one transform uniform per texture role");

class ProgramCache {
  public:
    // The program for `key`, compiled on first request; nullptr when it failed (error says why; a failed
    // key is not retried until clear()).
    MeshProgram* meshProgram(const FeatureKey& key, QString* error);
    // A fixed pass (kToneMapShader, kOverlayShader), with the basic prelude and `defines` after it;
    // compiled once per distinct `defines`.
    QOpenGLShaderProgram* fixedProgram(const ShaderConfig& config, QString* error,
                                       const QByteArray& defines = {});

    int compiledCount() const { return m_compiled; } // variants compiled since construction
    int cachedCount() const { return int(m_mesh.size()); }
    void clear(); // context current

    // Replace a shader file's text (tests, live editing); an empty source restores the embedded one.
    // Clears the cache.
    void setSourceOverride(const QString& name, const QByteArray& source);

  private:
    QByteArray source(const QString& name);
    std::unique_ptr<QOpenGLShaderProgram> build(const QByteArray& prelude, const ShaderConfig& config,
                                                const QString& what, QString* error);

    std::unordered_map<FeatureKey, std::unique_ptr<MeshProgram>, FeatureKeyHash> m_mesh;
    std::unordered_map<FeatureKey, QString, FeatureKeyHash> m_failed;
    QHash<QString, std::shared_ptr<QOpenGLShaderProgram>> m_fixed;
    QHash<QString, QByteArray> m_sources, m_overrides;
    int m_compiled = 0;
};

} // namespace lr::render
