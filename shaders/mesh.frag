// Mesh fragment stage: builds the Surface (material, textures through their KHR_texture_transform, normal
// map with its scale, double-sided flip; alpha MASK discards under the cutoff; under LR_PBR also metallic,
// roughness and occlusion from the glTF factors and textures), then
//   LR_OUTPUT_DISPLAY: shades it with every uploaded light and applies exposure, tone map and sRGB
//     encoding right here (exactly what tonemap.frag does to a float target, without the extra pass);
//   LR_OUTPUT_RADIANCE: writes the linear HDR radiance (alpha = coverage) for the tone-map pass;
//   LR_OUTPUT_GBUFFER: writes the Surface (encodeGBuffer: the codec of src/render/gbuffer.h) for the
//     deferred lighting pass
//     (deferred.frag) and for the CPU double-precision reference.
in vec3 vPosition;
in vec3 vNormal;
#if defined(LR_BASE_COLOR_TEXTURE) || defined(LR_NORMAL_MAP) || defined(LR_EMISSIVE_TEXTURE) || \
    defined(LR_METAL_ROUGH_TEXTURE) || defined(LR_OCCLUSION_TEXTURE)
in vec2 vUv;
// A texture role's UV: KHR_texture_transform's T·R·S (a mat3 per role, ProgramCache's uniforms, set from
// Material's TextureTransform), or the vertex UV as it is when no used texture has a transform.
#ifdef LR_TEXTURE_TRANSFORM
uniform mat3 uBaseColorTransform;
uniform mat3 uNormalTransform;
uniform mat3 uEmissiveTransform;
uniform mat3 uMetalRoughTransform;
uniform mat3 uOcclusionTransform;
vec2 lrUv(mat3 t) { return (t * vec3(vUv, 1.0)).xy; }
#else
#define lrUv(t) vUv
#endif
#endif
#ifdef LR_NORMAL_MAP
in vec4 vTangent;
#endif
#ifdef LR_VERTEX_COLOR
in vec4 vColor;
#endif
#ifdef LR_QUALITY_FAST
in vec3 vLitDiffuse;  // per-vertex lighting (mesh.vert), interpolated
in vec3 vLitSpecular;
in vec3 vLitAdded;
#ifdef LR_PBR
in vec3 vLitFresnel;  // B of the PBR split (lighting.glsl shadeVertexPbr); vLitSpecular is A,
in vec3 vLitAmbient;  // vLitDiffuse E
#endif
#endif

uniform vec4 uBaseColor;  // linear
uniform vec3 uEmissive;   // linear
uniform vec3 uSpecular;   // ks
uniform float uShininess;
uniform vec3 uAmbient;  // scene ambient
uniform float uDistanceScale;
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

#ifdef LR_OUTPUT_GBUFFER
layout(location = 0) out vec4 oGBuffer0;  // encodeGBuffer's g0 .. g3 (gbuffer.glsl)
layout(location = 1) out vec4 oGBuffer1;
layout(location = 2) out vec4 oGBuffer2;
layout(location = 3) out vec4 oGBuffer3;
#elif defined(LR_OUTPUT_DISPLAY)
uniform float uExposureScale;  // 2^EV
layout(location = 0) out vec4 oColor;  // sRGB-encoded display colour, alpha 1 (BLEND: premultiplied)
#else
layout(location = 0) out vec4 oColor;  // linear radiance, alpha 1 (coverage after the MSAA resolve;
                                       // BLEND: premultiplied by the base alpha)
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
    vec3 unperturbed = n;  // the interpolated normal, before the normal map and the flip: see below
#endif
#if defined(LR_NORMAL_MAP) && !defined(LR_QUALITY_FAST)
    vec3 t = safeNormalize(vTangent.xyz - n * dot(n, vTangent.xyz), vec3(0.0));
    vec3 b = cross(n, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
    vec3 m = texture(uNormalTex, lrUv(uNormalTransform)).xyz * 2.0 - 1.0;
    m *= vec3(uNormalScale, uNormalScale, 1.0);  // glTF: scale X and Y before normalising
    n = safeNormalize(t * m.x + b * m.y + n * m.z, n);
#endif
#ifdef LR_DOUBLE_SIDED
    if (!gl_FrontFacing) n = -n;
#endif
    s.normal = n;
    vec4 base = uBaseColor;
#ifdef LR_BASE_COLOR_TEXTURE
    base *= texture(uBaseColorTex, lrUv(uBaseColorTransform));
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
    s.emissive *= texture(uEmissiveTex, lrUv(uEmissiveTransform)).rgb;
#endif
    s.shininess = uShininess;
#ifdef LR_PBR
    // glTF metal-rough: factor × texel (each through its own transform); occlusion = 1 + strength·(R − 1).
    s.metallic = uMetallic;
    s.roughness = uRoughness;
#ifdef LR_METAL_ROUGH_TEXTURE
    vec4 metalRough = texture(uMetalRoughTex, lrUv(uMetalRoughTransform));
    s.metallic *= metalRough.b;
    s.roughness *= metalRough.g;
#endif
    // Geometric roughness (specular anti-aliasing, as three.js and Filament): the screen-space change of the
    // interpolated (not normal-mapped) normal widens the lobe where a pixel spans a range of normals, so a
    // highlight narrower than a pixel neither flickers nor vanishes. The G-buffer stores the result: the
    // deferred pass and the double reference shade the same roughness.
    vec3 geometric = max(abs(dFdx(unperturbed)), abs(dFdy(unperturbed)));
    s.roughness = min(s.roughness + max(max(geometric.x, geometric.y), geometric.z), 1.0);
    s.occlusion = 1.0;
#ifdef LR_OCCLUSION_TEXTURE
    s.occlusion = 1.0 + uOcclusionStrength * (texture(uOcclusionTex, lrUv(uOcclusionTransform)).r - 1.0);
#endif
#endif
    return s;
}

void main() {
    Surface s = surfaceHere();
#ifdef LR_OUTPUT_GBUFFER
    vec4 g0, g1, g2, g3;
    encodeGBuffer(s, g0, g1, g2, g3);
    oGBuffer0 = g0;
    oGBuffer1 = g1;
    oGBuffer2 = g2;
    oGBuffer3 = g3;
#elif defined(LR_SHADOW_CATCHER)
    // The ground as a shadow catcher: only its shadows, as the opacity 1 − (shadowed / unshadowed light),
    // each light weighted by its unshadowed contribution (luminance; no ambient, no emission), written as
    // premultiplied black over the scene (pass_catcher.cpp).
    float opacity = 0.0;
#ifdef LR_SHADOWS
    ShadeSettings st;
    st.ambient = vec3(0.0);
    st.distanceScale = uDistanceScale;
    s.emissive = vec3(0.0);
    const vec3 luminance = vec3(0.2126, 0.7152, 0.0722);
    float shadowed = dot(shadeSurface(s, st), luminance);
    lrShadowsOn = false;
    float unshadowed = dot(shadeSurface(s, st), luminance);
    opacity = unshadowed > 0.0 ? saturate(1.0 - shadowed / unshadowed) : 0.0;
#endif
    oColor = vec4(0.0, 0.0, 0.0, opacity);
#else
    ShadeSettings st;
    st.ambient = uAmbient;
    st.distanceScale = uDistanceScale;
#if defined(LR_QUALITY_FAST) && defined(LR_PBR)
    vec3 radiance = shadePixelPbr(s, st, vLitSpecular, vLitFresnel, vLitDiffuse, vLitAmbient, vLitAdded);
#elif defined(LR_QUALITY_FAST)
    vec3 radiance = s.albedo * vLitDiffuse + s.specular * vLitSpecular + vLitAdded + s.emissive;
#elif defined(LR_CLUSTERED)
    vec3 radiance = shadeSurfaceClustered(s, st, gl_FragCoord.xy);
#else
    vec3 radiance = shadeSurface(s, st);
#endif
#if defined(LR_QUALITY_FAST) && defined(LR_SHADOWS)
    radiance += shadeCastingLights(s, st);
#endif
#ifdef LR_ENVIRONMENT
    radiance += shadeEnvironment(s, viewVector(st, s.position));  // environment.glsl, per pixel in every tier
#endif
#ifdef LR_OUTPUT_DISPLAY
    vec3 colour = displayEncode(radiance, uExposureScale, LR_TONE_MAP);
#else
    vec3 colour = radiance;
#endif
#ifdef LR_ALPHA_BLEND
    oColor = vec4(colour * lrAlpha, lrAlpha);  // premultiplied "over" (pass_blend.cpp)
#else
    oColor = vec4(colour, 1.0);
#endif
#endif
}
