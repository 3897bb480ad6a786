// Mesh fragment stage: builds the Surface (surface.glsl: material, textures through their
// KHR_texture_transform, normal map with its scale, double-sided flip; alpha MASK discards under the
// cutoff; under LR_PBR also metallic, roughness and occlusion from the glTF factors and textures), then
//   LR_OUTPUT_DISPLAY: shades it with every uploaded light and applies exposure, tone map and sRGB
//     encoding right here (exactly what tonemap.frag does to a float target, without the extra pass);
//   LR_OUTPUT_RADIANCE: writes the linear HDR radiance (alpha = coverage) for the tone-map pass;
//   LR_OUTPUT_GBUFFER: writes the Surface (encodeGBuffer: the codec of src/render/gbuffer.h) for the
//     deferred lighting pass (deferred.frag) and for the CPU double-precision reference; with
//     LR_ATTRIBUTE_GBUFFER it writes only the interpolated attributes the Surface is built from
//     (encodeAttributes, surface.glsl), and the deferred lighting pass builds it. Under LR_LIGHT_LINKING
//     it also writes the part's lighting class into the link target (location 4).
#ifdef LR_QUALITY_FAST
in vec3 vLitDiffuse;  // per-vertex lighting (mesh.vert), interpolated
in vec3 vLitSpecular;
in vec3 vLitAdded;
#ifdef LR_PBR
in vec3 vLitFresnel;  // B of the PBR split (shadevertex.glsl shadeVertexPbr); vLitSpecular is A,
in vec3 vLitAmbient;  // vLitDiffuse E
#endif
#endif

uniform vec3 uAmbient;  // scene ambient
uniform float uDistanceScale;

#ifdef LR_OUTPUT_GBUFFER
layout(location = 0) out vec4 oGBuffer0;  // encodeGBuffer's g0 .. g3 (gbuffer.glsl)
layout(location = 1) out vec4 oGBuffer1;
layout(location = 2) out vec4 oGBuffer2;
layout(location = 3) out vec4 oGBuffer3;
#ifdef LR_LIGHT_LINKING
layout(location = 4) out uint oLinkClass;  // the G-buffer's link target (Targets::gbufferLink)
#endif
#elif defined(LR_OUTPUT_DISPLAY)
uniform float uExposureScale;  // 2^EV
layout(location = 0) out vec4 oColor;  // sRGB-encoded display colour, alpha 1 (BLEND: premultiplied)
#else
layout(location = 0) out vec4 oColor;  // linear radiance, alpha 1 (coverage after the MSAA resolve;
                                       // BLEND: premultiplied by the base alpha)
#endif

void main() {
#ifdef LR_LIGHT_LINKING
    lrLinkClass = uLinkClass;  // the drawn part's lighting class (shadetypes.glsl)
#ifdef LR_OUTPUT_GBUFFER
    oLinkClass = uint(uLinkClass);
#endif
#endif
#if defined(LR_OUTPUT_GBUFFER) && defined(LR_ATTRIBUTE_GBUFFER)
    encodeAttributes(oGBuffer0, oGBuffer1, oGBuffer2, oGBuffer3);
#else
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
#endif
}
