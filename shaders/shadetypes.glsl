// The shading inputs in GLSL 330, the twin of src/core/shadetypes.h: a light as the shaders read it from
// the light buffer (ShadeLight, loadLight), the surface (Surface), the frame's settings (ShadeSettings),
// and each light's falloff and cone by its model. Only in programs that shade (LR_SHADING); after
// colour.glsl and lighting.glsl.
#ifdef LR_SHADING

// ---- whole-surface shading (shade.h) ----

struct ShadeLight {
    int type;
    vec3 position;   // view space (point, spot)
    vec3 direction;  // view space, unit: where the light travels (spot, directional, rim)
    vec3 color;      // effective colour * intensity
    vec3 specular;   // Sc * intensity
    vec3 ambient;    // Ac * intensity
    int falloff;
    float range, falloffExponent, constant, linear, quadratic;
    int cone;
    float cosInner, cosOuter, outer, coneExponent;  // outer in radians
    int diffuse;
    float rimExponent;
#if defined(LR_HAS_LIGHT_RECT) || defined(LR_HAS_LIGHT_DISK)
    // Area lights: in-plane axes (unit, axisX × axisY = -direction), half extents; position = centre.
    vec3 axisX, axisY;
    float halfWidth, halfHeight;
    bool twoSided;
#ifdef LR_BARN_DOORS
    float barnDepth, barnExtent;  // a rect's barn doors (core/barndoors.h): depth 0: none
#endif
#endif
#ifdef LR_SHADOWS
    int shadow;  // its shadow slot + 1 (shadows.glsl), 0: it casts none
#endif
#ifdef LR_LIGHT_LINKING
    uint litMask;  // bit c: it lights the parts of lighting class c (core/lightlink.h)
#endif
#ifdef LR_IES
    // An IES profile (core/iesshade.h; shaping.glsl lrIes): its layer in uIes (-1: none), the photometric
    // nadir and horizontal angle 0's axis (view space, unit; angle 90 along iesX × iesNadir), the scale.
    int iesLayer;
    vec3 iesNadir, iesX;
    float iesScale;
#endif
#ifdef LR_GOBO
    // A spot's gobo (core/gobo.h; shaping.glsl lrGoboTint): its layer in uGobos (-1: none), its axes (view
    // space), half extent, size in texels and 1 / the array's size.
    int goboLayer;
    vec3 goboX, goboY;
    float goboHalf;
    vec2 goboSize, goboInvArray;
#endif
};

struct Surface {
    vec3 position;  // view space
    vec3 normal;    // view space, unit
    vec3 albedo;
    vec3 specular;  // material specular colour (ks)
    vec3 emissive;
    float shininess;  // classic
#ifdef LR_PBR
    // Physically based: albedo is the base colour; occlusion scales ambient light only. Declared only under
    // LR_PBR, so a classic program's text is exactly what it was.
    float metallic, roughness, occlusion;
#endif
};

struct ShadeSettings {
    vec3 ambient;
    float distanceScale;  // 1 / bounding radius for rigs in model space, else 1
};

#ifdef LR_SHADOWS
// The share of the light that reaches the surface, L pointing to the light (shaders/shadows.glsl).
// `needed`: false where the caller's result does not depend on it (the light adds nothing there), which
// lets whole blocks of such pixels skip most of the filter; the value is then unspecified.
float lrShadow(ShadeLight l, Surface s, vec3 L, bool needed);
#endif

// Compile-time constants where the scene has a single value: the branches on them fold away.
#ifdef LR_ONLY_LIGHT
#define lightTypeOf(l) LR_ONLY_LIGHT
#else
#define lightTypeOf(l) (l).type
#endif
#ifdef LR_ONLY_FALLOFF
#define falloffOf(l) LR_ONLY_FALLOFF
#else
#define falloffOf(l) (l).falloff
#endif
#ifdef LR_ONLY_CONE
#define coneOf(l) LR_ONLY_CONE
#else
#define coneOf(l) (l).cone
#endif
#ifdef LR_ONLY_DIFFUSE
#define diffuseOf(l) LR_ONLY_DIFFUSE
#else
#define diffuseOf(l) (l).diffuse
#endif

#if defined(LR_HAS_LIGHT_POINT) || defined(LR_HAS_LIGHT_SPOT)
#define LR_HAS_POSITIONAL 1
#endif
#if defined(LR_HAS_LIGHT_RECT) || defined(LR_HAS_LIGHT_DISK)
#define LR_HAS_AREA 1
#define lightIsArea(l) (lightTypeOf(l) == LR_LIGHT_RECT || lightTypeOf(l) == LR_LIGHT_DISK)
#endif
#if defined(LR_HAS_POSITIONAL) || defined(LR_HAS_LIGHT_DIRECTIONAL) || defined(LR_HAS_AREA)
#define LR_HAS_SURFACE_LIGHTS 1
#endif

uniform samplerBuffer uLights;  // LR_LIGHT_TEXELS RGBA32F texels per light, view space
uniform int uLightCount;

// Texel layout (src/render/lightpack.cpp packLight writes it), ordered so that the common lights read
// few texels (a point light with one falloff model reads 0-2; texelFetch is costly on software GL):
//   0: position.xyz, range        1: color.xyz, type          2: specular.xyz, falloff
//   3: direction.xyz, falloffExponent                        4: ambient.xyz, diffuse
//   5: constant, linear, quadratic, cone                      6: cosInner, cosOuter, outer, coneExponent
//   7: rimExponent, halfWidth, halfHeight, twoSided
//   8 (LR_LIGHT_LINKING only, LR_LIGHT_TEXELS 9): litMask's low 16 bits, its high 16 bits, 0, 0
//   LR_IES_TEXEL + 0, 1 (LR_IES only): iesNadir.xyz, iesLayer; iesX.xyz, iesScale
//   LR_GOBO_TEXEL + 0, 1, 2 (LR_GOBO only): goboX.xyz, goboLayer; goboY.xyz, goboHalf; goboSize, goboInvArray
//   (shadergen.h lightTexelLayout places them; lightpack.h packIesTexels, packGoboTexels write them)
// Area lights (no falloff, no cone) reuse texels 5 and 6: 5: axisX.xyz, cone   6: axisY.xyz, coneExponent.
// A rect light (LR_BARN_DOORS) carries its barn doors' depth in 7.x and their extent in 3.w.
// Unused fields are never read: the compiler drops their fetches.
ShadeLight loadLight(int index) {
    int base = index * LR_LIGHT_TEXELS;
    vec4 t0 = texelFetch(uLights, base + 0);
    vec4 t1 = texelFetch(uLights, base + 1);
    vec4 t2 = texelFetch(uLights, base + 2);
    vec4 t3 = texelFetch(uLights, base + 3);
    vec4 t4 = texelFetch(uLights, base + 4);
    vec4 t5 = texelFetch(uLights, base + 5);
    vec4 t6 = texelFetch(uLights, base + 6);
    vec4 t7 = texelFetch(uLights, base + 7);
    ShadeLight l;
    l.position = t0.xyz;
    l.range = t0.w;
    l.color = t1.xyz;
#ifdef LR_SHADOWS
    int typeAndShadow = int(t1.w);  // type + LR_SHADOW_SLOT_SCALE × (shadow slot + 1)
    l.type = typeAndShadow % LR_SHADOW_SLOT_SCALE;
    l.shadow = typeAndShadow / LR_SHADOW_SLOT_SCALE;
#else
    l.type = int(t1.w);
#endif
    l.specular = t2.xyz;
    l.falloff = int(t2.w);
    l.direction = t3.xyz;
    l.falloffExponent = t3.w;
    l.ambient = t4.xyz;
    l.diffuse = int(t4.w);
    l.constant = t5.x;
    l.linear = t5.y;
    l.quadratic = t5.z;
    l.cone = int(t5.w);
    l.cosInner = t6.x;
    l.cosOuter = t6.y;
    l.outer = t6.z;
    l.coneExponent = t6.w;
    l.rimExponent = t7.x;
#ifdef LR_HAS_AREA
    l.axisX = t5.xyz;
    l.axisY = t6.xyz;
    l.halfWidth = t7.y;
    l.halfHeight = t7.z;
    l.twoSided = t7.w > 0.5;
#ifdef LR_BARN_DOORS
    l.barnDepth = t7.x;   // a rect's rim-exponent slot
    l.barnExtent = t3.w;  // its falloff-exponent slot
#endif
#endif
#ifdef LR_LIGHT_LINKING
    vec4 t8 = texelFetch(uLights, base + 8);
    l.litMask = uint(t8.x) | (uint(t8.y) << 16);
#endif
#ifdef LR_IES
    vec4 i0 = texelFetch(uLights, base + LR_IES_TEXEL);
    vec4 i1 = texelFetch(uLights, base + LR_IES_TEXEL + 1);
    l.iesNadir = i0.xyz;
    l.iesLayer = int(i0.w);
    l.iesX = i1.xyz;
    l.iesScale = i1.w;
#endif
#ifdef LR_GOBO
    vec4 g0 = texelFetch(uLights, base + LR_GOBO_TEXEL);
    vec4 g1 = texelFetch(uLights, base + LR_GOBO_TEXEL + 1);
    vec4 g2 = texelFetch(uLights, base + LR_GOBO_TEXEL + 2);
    l.goboX = g0.xyz;
    l.goboLayer = int(g0.w);
    l.goboY = g1.xyz;
    l.goboHalf = g1.w;
    l.goboSize = g2.xy;
    l.goboInvArray = g2.zw;
#endif
    return l;
}

#ifdef LR_LIGHT_LINKING
// Light linking (issue 38; docs/light-linking.md): the shaded part's lighting class. Forward and per
// vertex it is the draw's (uLinkClass, set per draw by MeshPass::drawMeshes); the deferred lighting pass
// reads the pixel's from the G-buffer's link target. Each main() that shades sets lrLinkClass first.
uniform int uLinkClass;
int lrLinkClass = 0;

// Whether light l lights the part being shaded: where it does not, it adds nothing (diffuse, specular, its
// own ambient term; a rim light its rim), and the shading loops skip it before any of its work.
bool lightLinked(ShadeLight l) {
    return ((l.litMask >> uint(lrLinkClass)) & 1u) != 0u;
}
#endif

float evalFalloff(ShadeLight l, float d) {
    int m = falloffOf(l);
#ifdef LR_HAS_FALLOFF_NONE
    if (m == LR_FALLOFF_NONE) return 1.0;
#endif
#ifdef LR_HAS_FALLOFF_RANGE_POWER
    if (m == LR_FALLOFF_RANGE_POWER) return falloffRangePower(d, l.range, l.falloffExponent);
#endif
#ifdef LR_HAS_FALLOFF_INVERSE_POLYNOMIAL
    if (m == LR_FALLOFF_INVERSE_POLYNOMIAL)
        return falloffInversePolynomial(d, l.constant, l.linear, l.quadratic, l.range);
#endif
#ifdef LR_HAS_FALLOFF_RANGE_QUADRATIC
    if (m == LR_FALLOFF_RANGE_QUADRATIC) return falloffRangeQuadratic(d, l.range);
#endif
#ifdef LR_HAS_FALLOFF_INVERSE_SQUARE
    if (m == LR_FALLOFF_INVERSE_SQUARE) return falloffInverseSquare(d, l.range);
#endif
    return 0.0;
}

float evalCone(ShadeLight l, float cosTheta) {
    int m = coneOf(l);
#ifdef LR_HAS_CONE_ANGLE_POWER
    if (m == LR_CONE_ANGLE_POWER) return coneAnglePower(cosTheta, l.outer, l.coneExponent);
#endif
#ifdef LR_HAS_CONE_SMOOTH
    if (m == LR_CONE_SMOOTH) return coneSmooth(cosTheta, l.cosInner, l.cosOuter, l.coneExponent);
#endif
#ifdef LR_HAS_CONE_HARD
    if (m == LR_CONE_HARD) return coneHard(cosTheta, l.cosOuter);
#endif
    return 0.0;
}

#ifdef LR_B3
// Whether the light's falloff is exactly zero at d >= range (a required range always, an optional one when
// the light has it, i.e. range >= 0): LR_FALLOFF_BOUNDED comes from core/fallofftraits.h's table.
bool lightIsBounded(ShadeLight l) {
    int m = falloffOf(l);
    return LR_FALLOFF_BOUNDED(m, l.range);
}
#endif

#endif  // LR_SHADING
