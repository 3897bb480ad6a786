// Every texture unit the renderer uses, in one enum, and the sampler uniforms bound to them. ProgramCache
// sets every sampler uniform a program declares from kSamplerBindings once after linking; the passes bind
// textures with glActiveTexture(textureUnit(TextureUnit::X)). Nothing else numbers a unit.
#pragma once

#include <QOpenGLFunctions_3_3_Core>

namespace lr::render {

enum class TextureUnit : GLuint {
    BaseColor = 0, // material textures (mesh.frag); GpuDraw's order
    Normal = 1,
    Emissive = 2,
    Lights = 3,   // the packed light buffer (samplerBuffer, kLightTexels texels per light)
    GBuffer0 = 4, // .. GBuffer0 + kGBufferTargets - 1: the deferred lighting pass's input (gbuffer.h)
    ClusterRanges = 8,
    ClusterIndices = 9,
    SceneColor = 10, // the tone-map pass's input (resolved radiance)
    // The G-buffer's link target (light linking: each pixel's lighting class, Targets::gbufferLink), read
    // by the deferred lighting programs only. It shares SceneColor's unit: no program reads both, and the
    // 16 units GL 3.3 guarantees are otherwise taken.
    GBufferLink = SceneColor,
    SceneDepth = 11, // the overlay pass's occlusion test (resolved depth)
    MetalRough = 12, // physically based material textures (mesh.frag, LR_PBR; GpuDraw's PBR textures)
    Occlusion = 13,
    ShadowMaps = 14,   // the shadow-map array with its compare sampler (shadowmaps.h, shaders/shadows.glsl)
    ShadowDepths = 15, // the same array with a raw-depth sampler (PCSS's blocker search)
    // Environment lighting (environmentgl.h, shaders/environment.glsl): beyond the 16 units GL 3.3
    // guarantees, so EnvironmentGl checks GL_MAX_TEXTURE_IMAGE_UNITS (32 on Mesa, NVIDIA, AMD, Intel) and
    // lights without the environment, with a warning, where there are fewer than kEnvironmentUnitsNeeded.
    EnvSpecular = 16,   // the GGX chain, one mip level per roughness step
    EnvIrradiance = 17, // E(n), equirectangular
    EnvDfg = 18,        // the split-sum table (core/envbrdf.h)
    // Area lights' LTC table (core/ltc.h, ltcgl.h), bound only when a rect or disk light exists; beyond
    // 16 too: GL_MAX_TEXTURE_IMAGE_UNITS is 32 on every driver this targets.
    Ltc = 19,
    BackgroundCache = 20, // the background pass's kept environment image (passes.h BackgroundPass)
    // The lights' IES profiles and gobo images (issue 39, lightshapinggl.h), bound only when a light has
    // one; beyond 16 too, as Ltc.
    Ies = 21,
    Gobos = 22,
};

constexpr int kEnvironmentUnitsNeeded = 21; // up to BackgroundCache

constexpr GLenum textureUnit(TextureUnit unit, int offset = 0) {
    return GLenum(GL_TEXTURE0 + GLuint(unit) + GLuint(offset));
}

struct SamplerBinding {
    const char* uniform;
    TextureUnit unit;
    int offset = 0;
};

inline constexpr SamplerBinding kSamplerBindings[] = {
    {"uBaseColorTex", TextureUnit::BaseColor},
    {"uNormalTex", TextureUnit::Normal},
    {"uEmissiveTex", TextureUnit::Emissive},
    {"uLights", TextureUnit::Lights},
    {"uGBuffer0", TextureUnit::GBuffer0, 0},
    {"uGBuffer1", TextureUnit::GBuffer0, 1},
    {"uGBuffer2", TextureUnit::GBuffer0, 2},
    {"uGBuffer3", TextureUnit::GBuffer0, 3},
    {"uClusterRanges", TextureUnit::ClusterRanges},
    {"uClusterIndices", TextureUnit::ClusterIndices},
    {"uHdr", TextureUnit::SceneColor},
    {"uGBufferLink", TextureUnit::GBufferLink},
    {"uBackgroundCache", TextureUnit::BackgroundCache},
    {"uSceneDepth", TextureUnit::SceneDepth},
    {"uMetalRoughTex", TextureUnit::MetalRough},
    {"uOcclusionTex", TextureUnit::Occlusion},
    {"uShadowMaps", TextureUnit::ShadowMaps},
    {"uShadowDepths", TextureUnit::ShadowDepths},
    {"uEnvSpecular", TextureUnit::EnvSpecular},
    {"uEnvIrradiance", TextureUnit::EnvIrradiance},
    {"uEnvDfg", TextureUnit::EnvDfg},
    {"uLtc", TextureUnit::Ltc},
    {"uIes", TextureUnit::Ies},
    {"uGobos", TextureUnit::Gobos},
};

// GL 3.3 guarantees 16 texture image units per fragment stage: every unit but the environment's.
static_assert(GLuint(TextureUnit::ShadowDepths) < 16);
static_assert(GLuint(TextureUnit::EnvDfg) < GLuint(kEnvironmentUnitsNeeded));
static_assert(GLuint(TextureUnit::BackgroundCache) < GLuint(kEnvironmentUnitsNeeded));
static_assert(GLuint(TextureUnit::GBuffer0) + 4 <= GLuint(TextureUnit::ClusterRanges));

} // namespace lr::render
