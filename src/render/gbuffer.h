// The G-buffer codec, written once: where each field of a Surface lives in the kGBufferTargets RGBA32F
// targets. The GLSL side (encodeGBuffer / decodeGBuffer, used by mesh.frag's G-buffer output and by
// deferred.frag) is generated from kGBufferLayout (gbufferGlsl(), served to ProgramCache as the shader file
// "gbuffer.glsl"); the C++ side decodes the read-back (Renderer::renderGBuffer) and hands each pixel's
// Surface to the CPU reference (surfaceAt). Layout:
//     0: view-space position.xyz, shininess   1: normal.xyz, emissive.r
//     2: albedo.rgb, emissive.g               3: specular (ks).rgb, emissive.b
// Physically based shading (LR_PBR) has no ks or shininess: metallic, roughness and occlusion take
// target 3's rgb and 0.w is unused. The classic rows, their GLSL and their pixels are what they were.
// All fields are exact floats (RGBA32F): the deferred path shades the same values as the forward path.
#pragma once

#include "core/shade.h"
#include "floatimage.h"

#include <QByteArray>
#include <array>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace lr::render {

constexpr int kGBufferTargets = 4;

using GBufferTexels = std::array<glm::vec4, kGBufferTargets>;

// Which shading models a slot is written and read under (the GLSL wraps the others in #ifdef LR_PBR).
enum class GBufferUse { Both, Classic, Pbr };

struct GBufferSlot {
    GBufferUse use;
    const char* member;                         // the GLSL Surface member (shaders/shadetypes.glsl)
    int target;                                 // 0 .. kGBufferTargets - 1
    int channel;                                // first channel (0 = r/x)
    int width;                                  // channels
    float* (*field)(lighting::Surface<float>&); // the same member in C++
};

inline constexpr GBufferSlot kGBufferLayout[] = {
    {GBufferUse::Both, "position", 0, 0, 3,
     [](lighting::Surface<float>& s) { return glm::value_ptr(s.position); }},
    {GBufferUse::Classic, "shininess", 0, 3, 1, [](lighting::Surface<float>& s) { return &s.shininess; }},
    {GBufferUse::Both, "normal", 1, 0, 3,
     [](lighting::Surface<float>& s) { return glm::value_ptr(s.normal); }},
    {GBufferUse::Both, "emissive.r", 1, 3, 1, [](lighting::Surface<float>& s) { return &s.emissive.r; }},
    {GBufferUse::Both, "albedo", 2, 0, 3,
     [](lighting::Surface<float>& s) { return glm::value_ptr(s.albedo); }},
    {GBufferUse::Both, "emissive.g", 2, 3, 1, [](lighting::Surface<float>& s) { return &s.emissive.g; }},
    {GBufferUse::Classic, "specular", 3, 0, 3,
     [](lighting::Surface<float>& s) { return glm::value_ptr(s.specular); }},
    {GBufferUse::Both, "emissive.b", 3, 3, 1, [](lighting::Surface<float>& s) { return &s.emissive.b; }},
    {GBufferUse::Pbr, "metallic", 3, 0, 1, [](lighting::Surface<float>& s) { return &s.metallic; }},
    {GBufferUse::Pbr, "roughness", 3, 1, 1, [](lighting::Surface<float>& s) { return &s.roughness; }},
    {GBufferUse::Pbr, "occlusion", 3, 2, 1, [](lighting::Surface<float>& s) { return &s.occlusion; }},
};

// Whether `slot` is stored for a surface shaded with `model`.
constexpr bool usedUnder(const GBufferSlot& slot, ShadingModel model) {
    return slot.use == GBufferUse::Both || (slot.use == GBufferUse::Pbr) == (model == ShadingModel::Pbr);
}

GBufferTexels encodeGBuffer(const lighting::Surface<float>& surface,
                            ShadingModel model = ShadingModel::Classic);
lighting::Surface<float> decodeGBuffer(const GBufferTexels& texels,
                                       ShadingModel model = ShadingModel::Classic);

// GLSL: `void encodeGBuffer(Surface s, out vec4 g0, ..., out vec4 g3)` and
// `Surface decodeGBuffer(vec4 g0, ..., vec4 g3)`, after shadetypes.glsl (which defines Surface).
QByteArray gbufferGlsl();

// The read-back of the targets (image order) and the depth buffer (GL order: bottom row first; < 1 where
// a surface was drawn) as the GBuffer of floatimage.h: w = coverage, except specular.w = shininess;
// under PBR (`model`) also GBuffer::material (metallic, roughness, occlusion).
void decodeGBufferImages(const FloatImage (&targets)[kGBufferTargets], const std::vector<float>& depth,
                         ShadingModel model, GBuffer* out);
// The surface a GBuffer pixel recorded, in double for the reference.
lighting::Surface<double> surfaceAt(const GBuffer& g, int x, int y);

} // namespace lr::render
