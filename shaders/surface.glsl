// The Surface at a fragment, built from the mesh's interpolated attributes and its material (uniforms and
// textures). Two stages build it with the same code:
//   mesh.frag: from its varyings, textures sampled with the derivatives of the fragment's own quad;
//   deferred.frag under LR_ATTRIBUTE_GBUFFER: from the attributes the G-pass stored (encodeAttributes
//     below), filled into globals of the varyings' names by decodeAttributes. A full-screen pass has no
//     neighbours on the same triangle, so the G-pass also stores the UV's screen derivatives and the
//     geometric-roughness term, and the textures are sampled with textureGrad.
// The attribute G-buffer (four RGBA32F targets, every value an exact float of what the forward fragment
// interpolated; only valid where depth < 1):
//   0: position.xy, position.z (negated on back faces: view-space z < 0 at every drawn fragment), uv.x
//   1: the interpolated normal (not normalised), uv.y
//   2: the interpolated tangent.xyz, the geometric-roughness term with the tangent's handedness as its
//      sign bit (the term is >= 0, so the sign is free; -0.0 keeps it)
//   3: dFdx(uv), dFdy(uv)
#if defined(LR_BASE_COLOR_TEXTURE) || defined(LR_NORMAL_MAP) || defined(LR_EMISSIVE_TEXTURE) || \
    defined(LR_METAL_ROUGH_TEXTURE) || defined(LR_OCCLUSION_TEXTURE)
#define LR_HAS_UV 1
#endif

#ifdef LR_DEFERRED_LIGHTING
vec3 vPosition;
vec3 vNormal;
vec2 vUv;
vec4 vTangent;
vec2 lrUvDx, lrUvDy;     // the G-pass's dFdx(uv), dFdy(uv)
bool lrFrontFacing;      // gl_FrontFacing at the G-pass
float lrGeometric;       // geometricRoughness() at the G-pass
#define LR_FRONT_FACING lrFrontFacing
#else
in vec3 vPosition;
in vec3 vNormal;
#ifdef LR_HAS_UV
in vec2 vUv;
#endif
#ifdef LR_NORMAL_MAP
in vec4 vTangent;
#endif
#ifdef LR_VERTEX_COLOR
in vec4 vColor;
#endif
#define LR_FRONT_FACING gl_FrontFacing
#endif

#ifdef LR_HAS_UV
// A texture role's UV: KHR_texture_transform's T·R·S (a mat3 per role, ProgramCache's uniforms, set from
// Material's TextureTransform), or the vertex UV as it is when no used texture has a transform.
#ifdef LR_TEXTURE_TRANSFORM
uniform mat3 uBaseColorTransform;
uniform mat3 uNormalTransform;
uniform mat3 uEmissiveTransform;
uniform mat3 uMetalRoughTransform;
uniform mat3 uOcclusionTransform;
vec2 lrUv(mat3 t) { return (t * vec3(vUv, 1.0)).xy; }
#define lrUvGrad(t, d) (mat2(t) * (d))  // the affine transform's linear part carries the derivatives
#else
#define lrUv(t) vUv
#define lrUvGrad(t, d) (d)
#endif
#if defined(LR_DEFERRED_LIGHTING)
#define lrTexture(s, t) textureGrad(s, lrUv(t), lrUvGrad(t, lrUvDx), lrUvGrad(t, lrUvDy))
#elif defined(LR_QUALITY_FAST)
#define lrTexture(s, t) texture(s, lrUv(t))
#else
// The exact and balanced tiers sample with the fragment's own derivatives, as the attribute G-buffer's
// full-screen pass must (it has no quad of the same triangle): both paths pick each pixel's mip level the
// same way, where an implicit derivative would be shared by the 2x2 quad.
#define lrTexture(s, t) textureGrad(s, lrUv(t), lrUvGrad(t, dFdx(vUv)), lrUvGrad(t, dFdy(vUv)))
#endif
#endif

uniform vec4 uBaseColor;  // linear
uniform vec3 uEmissive;   // linear
uniform vec3 uSpecular;   // ks
uniform float uShininess;
#ifdef LR_BASE_COLOR_TEXTURE
uniform sampler2D uBaseColorTex;  // sRGB texture: sampled as linear
#endif
#ifdef LR_NORMAL_MAP
uniform sampler2D uNormalTex;
uniform float uNormalScale;  // glTF normalTexture.scale: multiplies the sampled X and Y
#endif
#ifdef LR_ALPHA_MASK
uniform float uAlphaCutoff;  // glTF alphaCutoff
#endif
#ifdef LR_ALPHA_BLEND
float lrAlpha = 1.0;  // the base alpha, for "over" blending (pass_blend.cpp)
#endif
#ifdef LR_EMISSIVE_TEXTURE
uniform sampler2D uEmissiveTex;  // sRGB
#endif
#ifdef LR_PBR
uniform float uMetallic, uRoughness;  // glTF factors
#ifdef LR_METAL_ROUGH_TEXTURE
uniform sampler2D uMetalRoughTex;  // linear: G = roughness, B = metallic
#endif
#ifdef LR_OCCLUSION_TEXTURE
uniform sampler2D uOcclusionTex;  // linear: R = occlusion
uniform float uOcclusionStrength;
#endif
#endif

#ifndef LR_DEFERRED_LIGHTING
// Geometric roughness (specular anti-aliasing, as three.js and Filament): the screen-space change of the
// interpolated (not normal-mapped) normal widens the lobe where a pixel spans a range of normals, so a
// highlight narrower than a pixel neither flickers nor vanishes. Both G-buffers carry it: the deferred pass
// and the double reference shade the same roughness.
float geometricRoughness(vec3 unperturbed) {
    vec3 g = max(abs(dFdx(unperturbed)), abs(dFdy(unperturbed)));
    return max(max(g.x, g.y), g.z);
}
#endif

Surface surfaceHere() {
    Surface s;
    s.position = vPosition;
#if defined(LR_QUALITY_FAST) && !defined(LR_SHADOWS) && !defined(LR_ENVIRONMENT)
    vec3 n = vec3(0.0, 0.0, 1.0);  // unused: the fast tier lit the vertices (mesh.vert)
#else
    vec3 n = safeNormalize(vNormal, vec3(0.0, 0.0, 1.0));
#endif
#ifdef LR_PBR
    vec3 unperturbed = n;  // the interpolated normal, before the normal map and the flip
#endif
#if defined(LR_NORMAL_MAP) && !defined(LR_QUALITY_FAST)
    vec3 t = safeNormalize(vTangent.xyz - n * dot(n, vTangent.xyz), vec3(0.0));
    vec3 b = cross(n, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
    vec3 m = lrTexture(uNormalTex, uNormalTransform).xyz * 2.0 - 1.0;
    m *= vec3(uNormalScale, uNormalScale, 1.0);  // glTF: scale X and Y before normalising
    n = safeNormalize(t * m.x + b * m.y + n * m.z, n);
#endif
#ifdef LR_DOUBLE_SIDED
    if (!LR_FRONT_FACING) n = -n;
#endif
    s.normal = n;
    vec4 base = uBaseColor;
#ifdef LR_BASE_COLOR_TEXTURE
    base *= lrTexture(uBaseColorTex, uBaseColorTransform);
#endif
#ifdef LR_VERTEX_COLOR
    base *= vColor;
#endif
#ifdef LR_ALPHA_MASK
    if (!(base.a >= uAlphaCutoff)) discard;  // glTF: opaque where alpha >= cutoff (NaN discarded)
#endif
#ifdef LR_ALPHA_BLEND
    lrAlpha = saturate(base.a);
#endif
    s.albedo = base.rgb;
    s.specular = uSpecular;
    s.emissive = uEmissive;
#ifdef LR_EMISSIVE_TEXTURE
    s.emissive *= lrTexture(uEmissiveTex, uEmissiveTransform).rgb;
#endif
    s.shininess = uShininess;
#ifdef LR_PBR
    // glTF metal-rough: factor × texel (each through its own transform); occlusion = 1 + strength·(R − 1).
    s.metallic = uMetallic;
    s.roughness = uRoughness;
#ifdef LR_METAL_ROUGH_TEXTURE
    vec4 metalRough = lrTexture(uMetalRoughTex, uMetalRoughTransform);
    s.metallic *= metalRough.b;
    s.roughness *= metalRough.g;
#endif
#ifdef LR_DEFERRED_LIGHTING
    s.roughness = min(s.roughness + lrGeometric, 1.0);
#else
    s.roughness = min(s.roughness + geometricRoughness(unperturbed), 1.0);
#endif
    s.occlusion = 1.0;
#ifdef LR_OCCLUSION_TEXTURE
    s.occlusion = 1.0 + uOcclusionStrength * (lrTexture(uOcclusionTex, uOcclusionTransform).r - 1.0);
#endif
#endif
    return s;
}

#ifdef LR_ATTRIBUTE_GBUFFER
#ifdef LR_DEFERRED_LIGHTING
// The attribute G-buffer's texels at a pixel into the globals surfaceHere() reads.
void decodeAttributes(vec4 g0, vec4 g1, vec4 g2, vec4 g3) {
    vPosition = vec3(g0.xy, -abs(g0.z));
    lrFrontFacing = g0.z < 0.0;
    vNormal = g1.xyz;
    vUv = vec2(g0.w, g1.w);
    bool negative = (floatBitsToUint(g2.w) & 0x80000000u) != 0u;
    vTangent = vec4(g2.xyz, negative ? -1.0 : 1.0);
    lrGeometric = abs(g2.w);
    lrUvDx = g3.xy;
    lrUvDy = g3.zw;
}
#else
// The G-pass's output under LR_ATTRIBUTE_GBUFFER: this fragment's attributes (layout above).
void encodeAttributes(out vec4 g0, out vec4 g1, out vec4 g2, out vec4 g3) {
    vec2 uv = vec2(0.0), dx = vec2(0.0), dy = vec2(0.0);
#ifdef LR_HAS_UV
    uv = vUv;
    dx = dFdx(vUv);
    dy = dFdy(vUv);
#endif
    vec4 tangent = vec4(0.0, 0.0, 0.0, 1.0);
#ifdef LR_NORMAL_MAP
    tangent = vTangent;
#endif
    float geometric = 0.0;
#ifdef LR_PBR
    geometric = geometricRoughness(safeNormalize(vNormal, vec3(0.0, 0.0, 1.0)));
#endif
    g0 = vec4(vPosition.xy, gl_FrontFacing ? vPosition.z : -vPosition.z, uv.x);
    g1 = vec4(vNormal, uv.y);
    g2 = vec4(tangent.xyz,
              uintBitsToFloat(floatBitsToUint(geometric) | (tangent.w < 0.0 ? 0x80000000u : 0u)));
    g3 = vec4(dx, dy);
}
#endif
#endif
