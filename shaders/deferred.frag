// Deferred lighting pass: one full-screen triangle, depth-tested against the G-buffer's depth so only
// covered pixels run. Every covered pixel is shaded once with whole 4x4 blocks of work, where the forward
// pass would shade the partial blocks of every small triangle (a software rasteriser's main waste).
// Same Surface values (RGBA32F, exact), same shadeSurface(): the same radiance as the forward path.
uniform sampler2D uGBuffer0;  // position.xyz, shininess
uniform sampler2D uGBuffer1;  // normal.xyz, emissive.r
uniform sampler2D uGBuffer2;  // albedo.rgb, emissive.g
uniform sampler2D uGBuffer3;  // specular.rgb, emissive.b
uniform vec3 uAmbient;
uniform float uDistanceScale;
#ifdef LR_OUTPUT_DISPLAY
uniform float uExposureScale;
uniform int uToneMap;
#endif

out vec4 oColor;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 g0 = texelFetch(uGBuffer0, p, 0);
    vec4 g1 = texelFetch(uGBuffer1, p, 0);
    vec4 g2 = texelFetch(uGBuffer2, p, 0);
    vec4 g3 = texelFetch(uGBuffer3, p, 0);
    Surface s;
    s.position = g0.xyz;
    s.shininess = g0.w;
    s.normal = g1.xyz;
    s.albedo = g2.rgb;
    s.specular = g3.rgb;
    s.emissive = vec3(g1.w, g2.w, g3.w);
    ShadeSettings st;
    st.ambient = uAmbient;
    st.distanceScale = uDistanceScale;
#ifdef LR_CLUSTERED
    vec3 radiance = shadeSurfaceClustered(s, st, gl_FragCoord.xy);
#else
    vec3 radiance = shadeSurface(s, st);
#endif
#ifdef LR_OUTPUT_DISPLAY
    oColor = vec4(displayEncode(radiance, uExposureScale, uToneMap), 1.0);
#else
    oColor = vec4(radiance, 1.0);
#endif
}
