// Mesh vertex stage: positions relative to Model::origin, transformed to view space with a model-view
// matrix built in double precision on the CPU (precision holds far from the world origin). In the fast
// quality tier it also lights the vertex (the shading files and shadevertex.glsl are then compiled into this stage too).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec4 aTangent;
layout(location = 4) in vec4 aColor;

uniform mat4 uModelView;
uniform mat3 uNormalMatrix;
uniform mat4 uProjection;

out vec3 vPosition;  // view space
out vec3 vNormal;    // view space, not normalised
#if defined(LR_BASE_COLOR_TEXTURE) || defined(LR_NORMAL_MAP) || defined(LR_EMISSIVE_TEXTURE) || \
    defined(LR_METAL_ROUGH_TEXTURE) || defined(LR_OCCLUSION_TEXTURE)
out vec2 vUv;
#endif
#ifdef LR_NORMAL_MAP
out vec4 vTangent;  // view space xyz, handedness w
#endif
#ifdef LR_VERTEX_COLOR
out vec4 vColor;
#endif
#ifdef LR_QUALITY_FAST
// Fast tier (F1, Gouraud): the lighting at this vertex (shadevertex.glsl shadeVertex), interpolated.
uniform vec3 uAmbient;
uniform float uDistanceScale;
uniform float uShininess;
out vec3 vLitDiffuse;   // multiplies the albedo
out vec3 vLitSpecular;  // multiplies ks
out vec3 vLitAdded;     // rim lights
#ifdef LR_PBR
// PBR: vLitSpecular = A, vLitDiffuse = E of shadevertex.glsl's split (shadeVertexPbr), and these two.
uniform float uRoughness;
#ifdef LR_METAL_ROUGH_TEXTURE
uniform sampler2D uMetalRoughTex;
#endif
out vec3 vLitFresnel;
out vec3 vLitAmbient;
#endif
#endif

void main() {
    vec4 p = uModelView * vec4(aPosition, 1.0);
    vPosition = p.xyz;
    vNormal = uNormalMatrix * aNormal;
#if defined(LR_BASE_COLOR_TEXTURE) || defined(LR_NORMAL_MAP) || defined(LR_EMISSIVE_TEXTURE) || \
    defined(LR_METAL_ROUGH_TEXTURE) || defined(LR_OCCLUSION_TEXTURE)
    vUv = aUv;
#endif
#ifdef LR_NORMAL_MAP
    vTangent = vec4(mat3(uModelView) * aTangent.xyz, aTangent.w);
#endif
#ifdef LR_VERTEX_COLOR
    vColor = aColor;
#endif
#ifdef LR_QUALITY_FAST
#ifdef LR_LIGHT_LINKING
    lrLinkClass = uLinkClass;  // the drawn part's (shadetypes.glsl)
#endif
    vec3 n = safeNormalize(vNormal, vec3(0.0, 0.0, 1.0));  // the vertex normal: normal maps are not used
#ifdef LR_DOUBLE_SIDED
    if (dot(n, p.xyz) > 0.0) n = -n;  // no gl_FrontFacing at a vertex: light the side facing the eye
#endif
    ShadeSettings st;
    st.ambient = uAmbient;
    st.distanceScale = uDistanceScale;
#ifdef LR_PBR
    float roughness = uRoughness;
#ifdef LR_METAL_ROUGH_TEXTURE
    // The roughness around the vertex: the mip level about 128 texels across (a vertex spans many texels
    // of a full-resolution map; level 0 would alias).
    float lod = max(0.0, log2(float(max(textureSize(uMetalRoughTex, 0).x, textureSize(uMetalRoughTex, 0).y))) - 7.0);
    roughness *= textureLod(uMetalRoughTex, aUv, lod).g;
#endif
    VertexLightPbr lit = shadeVertexPbr(p.xyz, n, roughness, st);
    vLitSpecular = lit.specular;
    vLitFresnel = lit.fresnel;
    vLitDiffuse = lit.diffuse;
    vLitAmbient = lit.ambient;
    vLitAdded = lit.added;
#else
    VertexLight lit = shadeVertex(p.xyz, n, uShininess, st);
    vLitDiffuse = lit.diffuse;
    vLitSpecular = lit.specular;
    vLitAdded = lit.added;
#endif
#endif
    gl_Position = uProjection * p;
}
