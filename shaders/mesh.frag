// Mesh fragment stage: builds the Surface (material, textures, normal map, double-sided flip) and either
// shades it with every uploaded light (LR_OUTPUT_RADIANCE: linear HDR radiance, alpha = coverage) or
// writes it to the G-buffer (LR_OUTPUT_GBUFFER) for the CPU double-precision reference.
in vec3 vPosition;
in vec3 vNormal;
#if defined(LR_BASE_COLOR_TEXTURE) || defined(LR_NORMAL_MAP) || defined(LR_EMISSIVE_TEXTURE)
in vec2 vUv;
#endif
#ifdef LR_NORMAL_MAP
in vec4 vTangent;
#endif
#ifdef LR_VERTEX_COLOR
in vec4 vColor;
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
#endif
#ifdef LR_EMISSIVE_TEXTURE
uniform sampler2D uEmissiveTex;  // sRGB
#endif

#ifdef LR_OUTPUT_GBUFFER
layout(location = 0) out vec4 oPosition;  // view space xyz, 1
layout(location = 1) out vec4 oNormal;    // view space unit normal as shaded, 1
layout(location = 2) out vec4 oAlbedo;    // linear rgb, alpha
layout(location = 3) out vec4 oSpecular;  // ks rgb, shininess
layout(location = 4) out vec4 oEmissive;  // linear rgb, 1
#else
layout(location = 0) out vec4 oColor;  // linear radiance, alpha 1 (coverage after the MSAA resolve)
#endif

Surface surfaceHere() {
    Surface s;
    s.position = vPosition;
    vec3 n = safeNormalize(vNormal, vec3(0.0, 0.0, 1.0));
#ifdef LR_NORMAL_MAP
    vec3 t = safeNormalize(vTangent.xyz - n * dot(n, vTangent.xyz), vec3(0.0));
    vec3 b = cross(n, t) * (vTangent.w < 0.0 ? -1.0 : 1.0);
    vec3 m = texture(uNormalTex, vUv).xyz * 2.0 - 1.0;
    n = safeNormalize(t * m.x + b * m.y + n * m.z, n);
#endif
#ifdef LR_DOUBLE_SIDED
    if (!gl_FrontFacing) n = -n;
#endif
    s.normal = n;
    vec4 base = uBaseColor;
#ifdef LR_BASE_COLOR_TEXTURE
    base *= texture(uBaseColorTex, vUv);
#endif
#ifdef LR_VERTEX_COLOR
    base *= vColor;
#endif
    s.albedo = base.rgb;
    s.specular = uSpecular;
    s.emissive = uEmissive;
#ifdef LR_EMISSIVE_TEXTURE
    s.emissive *= texture(uEmissiveTex, vUv).rgb;
#endif
    s.shininess = uShininess;
    return s;
}

void main() {
    Surface s = surfaceHere();
#ifdef LR_OUTPUT_GBUFFER
    oPosition = vec4(s.position, 1.0);
    oNormal = vec4(s.normal, 1.0);
    oAlbedo = vec4(s.albedo, 1.0);
    oSpecular = vec4(s.specular, s.shininess);
    oEmissive = vec4(s.emissive, 1.0);
#else
    ShadeSettings st;
    st.ambient = uAmbient;
    st.distanceScale = uDistanceScale;
    oColor = vec4(shadeSurface(s, st), 1.0);
#endif
}
