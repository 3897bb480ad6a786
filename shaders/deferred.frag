// Deferred lighting pass: one full-screen triangle, depth-tested against the G-buffer's depth so only
// covered pixels run. Every covered pixel is shaded once with whole 4x4 blocks of work, where the forward
// pass would shade the partial blocks of every small triangle (a software rasteriser's main waste).
// Same Surface values (RGBA32F, exact), same shadeSurface(): the same radiance as the forward path.
// LR_ATTRIBUTE_GBUFFER: the G-buffer holds the fragment's attributes instead (surface.glsl), and this pass
// builds the Surface with the material's textures, so the texture reads too run once per pixel in whole
// blocks instead of in every small triangle's partial ones.
// LR_OUTPUT_GBUFFER (with LR_ATTRIBUTE_GBUFFER): no shading; the Surface is written out (the kept surfaces).
uniform sampler2D uGBuffer0;  // decodeGBuffer's g0 .. g3 (gbuffer.glsl, generated from src/render/gbuffer.h)
uniform sampler2D uGBuffer1;
uniform sampler2D uGBuffer2;
uniform sampler2D uGBuffer3;
#ifdef LR_LIGHT_LINKING
uniform usampler2D uGBufferLink;  // each pixel's lighting class, as the G-pass wrote it (Targets::gbufferLink)
#endif
uniform vec3 uAmbient;
uniform float uDistanceScale;
#ifdef LR_OUTPUT_DISPLAY
uniform float uExposureScale;
#endif

#ifdef LR_OUTPUT_GBUFFER
// LR_ATTRIBUTE_GBUFFER and LR_OUTPUT_GBUFFER: the kept surfaces (pass_lighting.cpp). Each pixel's Surface,
// built from its attributes and its material's textures, is written in the Surface G-buffer's layout
// (encodeGBuffer) for the frames that shade it again under a still camera.
layout(location = 0) out vec4 oGBuffer0;
layout(location = 1) out vec4 oGBuffer1;
layout(location = 2) out vec4 oGBuffer2;
layout(location = 3) out vec4 oGBuffer3;
#else
layout(location = 0) out vec4 oColor;
#endif

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
#ifdef LR_ATTRIBUTE_GBUFFER
    decodeAttributes(texelFetch(uGBuffer0, p, 0), texelFetch(uGBuffer1, p, 0), texelFetch(uGBuffer2, p, 0),
                     texelFetch(uGBuffer3, p, 0));
    Surface s = surfaceHere();
#else
    Surface s = decodeGBuffer(texelFetch(uGBuffer0, p, 0), texelFetch(uGBuffer1, p, 0),
                              texelFetch(uGBuffer2, p, 0), texelFetch(uGBuffer3, p, 0));
#endif
#ifdef LR_OUTPUT_GBUFFER
    vec4 g0, g1, g2, g3;
    encodeGBuffer(s, g0, g1, g2, g3);
    oGBuffer0 = g0;
    oGBuffer1 = g1;
    oGBuffer2 = g2;
    oGBuffer3 = g3;
#else
#ifdef LR_LIGHT_LINKING
    lrLinkClass = int(texelFetch(uGBufferLink, p, 0).r);
#endif
    ShadeSettings st;
    st.ambient = uAmbient;
    st.distanceScale = uDistanceScale;
#ifdef LR_CLUSTERED
    vec3 radiance = shadeSurfaceClustered(s, st, gl_FragCoord.xy);
#else
    vec3 radiance = shadeSurface(s, st);
#endif
#ifdef LR_ENVIRONMENT
    radiance += shadeEnvironment(s, viewVector(st, s.position));  // environment.glsl
#endif
#ifdef LR_OUTPUT_DISPLAY
    oColor = vec4(displayEncode(radiance, uExposureScale, LR_TONE_MAP), 1.0);
#else
    oColor = vec4(radiance, 1.0);
#endif
#endif
}
