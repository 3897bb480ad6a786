// LightRig lighting formulas in GLSL 330: the exact twin of src/core/lighting.h and src/core/shade.h
// (same function names, same guards, same order of operations). Keep the three files in step.
//
// Conventions: right-handed OpenGL view space (eye at the origin looking down -Z); L = unit vector
// surface->light, d = distance, N = unit normal, V = unit vector to the eye; angles in radians.
// Guards: no formula relies on max(NaN, 0); pow/acos get arguments inside their domains; normalising a
// zero vector returns a fallback.
//
// The program generator (src/render/shadergen.cpp) prepends the #version line, the enum values
// (LR_LIGHT_POINT, LR_FALLOFF_RANGE_POWER, ...) and the features the scene uses:
//   LR_HAS_LIGHT_<TYPE>, LR_HAS_FALLOFF_<MODEL>, LR_HAS_CONE_<MODEL>, LR_HAS_DIFFUSE_<MODEL>: present;
//   LR_ONLY_LIGHT / LR_ONLY_FALLOFF / LR_ONLY_CONE / LR_ONLY_DIFFUSE: the single value when only one is;
//   LR_SPECULAR, LR_VIEWER: the rig's models; LR_HAS_LIGHT_AMBIENT: some light has an ambient colour;
//   LR_LIGHT_TEXELS: RGBA32F texels per light in the light buffer (layout in loadLight below);
//   LR_QUALITY_EXACT / LR_QUALITY_BALANCED / LR_QUALITY_FAST: the quality tier (docs/quality.md);
//   LR_SHININESS_INT + powShininessInt(): balanced tier, the material's shininess is this integer;
//   LR_PBR: the rig is physically based (the glTF BRDF block, lightArrival, shadeLightPbr); with it
//   LR_METAL_ROUGH_TEXTURE / LR_OCCLUSION_TEXTURE (mesh.frag) and the BRDF's approximations LR_B5, LR_B6;
//   LR_SHADOWS: some light casts (shadows.glsl); LR_SHADOW_CATCHER: the ground's catcher (mesh.frag).
// Code for absent features is not compiled, so a scene pays only for what it uses.
//
// Quality tiers change how the formulas are evaluated, never what they are. Exact: the functions below
// as written. Balanced: lrPow/lrAcos/powSpecular swap safePow, safeAcos and the specular power for the
// cheaper evaluations of the "balanced tier" block, and shadeLight() rejects lights outside their range
// or cone before normalising (B1-B4 in docs/quality.md). Fast: shadeVertex() at the vertices (Gouraud),
// interpolated, the albedo and ks applied per pixel; under LR_PBR shadeVertexPbr() sums the split
// A, B, E at the vertices and shadePixelPbr() applies F0 and c_diff per pixel (docs/quality.md, F1-PBR).

const float kMinDenominator = 1e-4;  // floor of d^2 and of the inverse-polynomial denominator
const float kMinConeWidth = 1e-7;    // narrowest smooth-cone width treated as a smooth edge
const float kFloatMax = 3.402823466e+38;

// x clamped to [0, 1]; NaN -> 0.
float saturate(float x) { return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0; }

// max(x, 0) that maps NaN to 0.
float positive(float x) { return x > 0.0 ? x : 0.0; }

// pow(base, exponent) for base >= 0 (negative or NaN base -> 0) and exponent >= 0 (else treated as 0).
float safePow(float base, float exponent) {
    if (!(exponent > 0.0)) return 1.0;
    if (!(base > 0.0)) return 0.0;
    return pow(base, exponent);
}

// acos with its argument clamped into [-1, 1]. The built-in acos of some drivers (Mesa among them) is a
// low-order fit with errors near 1e-4 rad; this is Abramowitz & Stegun 4.4.46, |error| <= 2e-8 rad.
float safeAcos(float c) {
    float x = c > -1.0 ? (c < 1.0 ? c : 1.0) : -1.0;
    float a = abs(x);
    float p = -0.0012624911;
    p = p * a + 0.0066700901;
    p = p * a - 0.0170881256;
    p = p * a + 0.0308918810;
    p = p * a - 0.0501743046;
    p = p * a + 0.0889789874;
    p = p * a - 0.2145988016;
    p = p * a + 1.5707963050;
    float r = sqrt(1.0 - a) * p;
    return x < 0.0 ? 3.14159265358979 - r : r;
}

// v / |v| at any magnitude (denormal to huge components); zero, NaN or Inf -> fallback. lighting.h's
// safeNormalize divides by the largest component first; here v is scaled by a power of two (exact) when
// |v|² would leave the normal floats, then normalised with one inversesqrt: the same to rounding, at two
// divisions' cost instead of seven, and written with selects (llvmpipe runs both sides of a branch).
vec3 safeNormalize(vec3 v, vec3 fallback) {
    float t2 = dot(v, v);
    vec3 w = v * (t2 > 1e30 ? 7.888609052210118e-31 : (t2 < 1e-30 ? 1.2676506002282294e30 : 1.0));  // 2^∓100
    float w2 = dot(w, w);
    return w2 > 0.0 && w2 <= kFloatMax ? w * inversesqrt(w2) : fallback;
}

// The balanced tier's approximations LR_B1 ... LR_B4 are defined by the generator (shadergen.cpp): B1, B2
// and B4 by default; LIGHTRIG_BALANCED=b1,b3 in the environment picks others, for measuring each alone.

#ifdef LR_QUALITY_BALANCED
// ---- balanced tier: cheaper evaluations, each measured in docs/quality.md ----

// B1 poly-acos: Abramowitz & Stegun 4.4.45 (four terms), |error| <= 6.8e-5 rad; near cos = 1 the error is
// relative (5e-5 of the angle), so narrow cones keep their shape. Used by the angle-power cone only.
float acosBalanced(float c) {
    float x = c > -1.0 ? (c < 1.0 ? c : 1.0) : -1.0;
    float a = abs(x);
    float p = ((-0.0187293 * a + 0.0742610) * a - 0.2121144) * a + 1.5707288;
    float r = sqrt(1.0 - a) * p;
    return x < 0.0 ? 3.14159265358979 - r : r;
}

// B2 integer shininess: see powSpecular below (the chain of products is generated per variant).
#endif
#ifdef LR_B1
#define lrAcos acosBalanced
#else
#define lrAcos safeAcos
#endif
#define lrPow safePow

// The specular power x^shininess. B2: with an integer shininess known when the variant is built
// (LR_SHININESS_INT, balanced only), x^n by repeated squaring, the generated chain of products
// powShininessInt() (at most 2·log2(n) multiplications instead of pow's exp2(n·log2 x); as accurate or
// more). A runtime test of the exponent would not help on a SIMD rasteriser (llvmpipe evaluates both sides
// of a branch under a mask), hence the specialisation. Per-light exponents (falloff, cone, rim) keep pow.
#if defined(LR_SHININESS_INT) && defined(LR_B2)
float powSpecular(float base, float shininess) { return base > 0.0 ? powShininessInt(base) : 0.0; }
#else
float powSpecular(float base, float shininess) { return lrPow(base, shininess); }
#endif

// ---- distance falloff a(d); range < 0 means "no range" where the range is optional ----

float falloffRangePower(float d, float range, float exponent) {
    if (!(d < range)) return 0.0;
    float t = 1.0 - d / range;
    if (!(t > 1e-6)) return 0.0; // kRangeEdge: the last 1e-6 of the range is 0, as in double
    return lrPow(saturate(t), exponent);
}

// Written with selects rather than early returns (here and in the PBR path below): llvmpipe evaluates
// both sides of a branch under a mask anyway, and a return inside an inlined function becomes a flag that
// guards everything after it. The values are those of the branching form for every input, NaN included.
float rangeWindow(float d, float range) {
    float r = d / range, r2 = r * r;
    float w = saturate(1.0 - r2 * r2);
    return range < 0.0 ? 1.0 : (d < range ? w * w : 0.0);
}

float falloffInversePolynomial(float d, float constant, float linear, float quadratic, float range) {
    float w = rangeWindow(d, range);
    if (!(w > 0.0)) return 0.0;
    float denom = constant + linear * d + quadratic * d * d;
    if (!(denom > kMinDenominator)) denom = kMinDenominator;
    return w / denom;
}

float falloffRangeQuadratic(float d, float range) {
    if (!(d < range)) return 0.0;
    float r = d / range;
    return saturate(1.0 - r * r);
}

float falloffInverseSquare(float d, float range) {
    float w = rangeWindow(d, range);
    float d2 = d * d;
    d2 = d2 > kMinDenominator ? d2 : kMinDenominator;
    return w > 0.0 ? w / d2 : 0.0;
}

// ---- spot cone s(cos(theta)), cos(theta) = dot(-L, spotDirection) ----

float coneAnglePower(float cosTheta, float outer, float exponent) {
    float theta = lrAcos(cosTheta);
    if (!(theta < outer)) return 0.0;
    return lrPow(saturate(1.0 - theta / outer), exponent);
}

float coneHard(float cosTheta, float cosOuter) { return cosTheta >= cosOuter ? 1.0 : 0.0; }

// A width below kMinConeWidth (inner = outer, or a cone too narrow for float) is exactly the hard cone.
float coneSmooth(float cosTheta, float cosInner, float cosOuter, float exponent) {
    float width = cosInner - cosOuter;
    if (!(width > kMinConeWidth)) return coneHard(cosTheta, cosOuter);
    if (!(cosTheta > cosOuter)) return 0.0;
    return lrPow(saturate((cosTheta - cosOuter) / width), exponent);
}

// ---- surface terms ----

// Saturated above too: float N·L of unit vectors exceeds 1 by an ulp or two.
float diffuseLambert(float nDotL) { return saturate(nDotL); }

float diffuseHalfLambert(float nDotL) {
    float h = saturate(nDotL * 0.5 + 0.5);
    return h * h;
}

float specularPhong(vec3 N, vec3 L, vec3 V, float shininess) {
    vec3 R = 2.0 * dot(N, L) * N - L;  // reflect(-L, N)
    return powSpecular(saturate(dot(R, V)), shininess);
}

float specularBlinnPhong(vec3 N, vec3 L, vec3 V, float shininess) {
    vec3 H = safeNormalize(L + V, N);
    return powSpecular(saturate(dot(N, H)), shininess);
}

float rimTerm(vec3 direction, vec3 N, vec3 V, float exponent) {
    float p1 = 1.0 - saturate(dot(direction, N));
    float p2 = 1.0 - saturate(dot(N, V));
    return lrPow(p1 * p2, exponent);
}

#ifdef LR_PBR
// ---- physically based BRDF (glTF 2.0 Appendix B): lighting.h's PBR block ----
// Balanced-tier approximations, each a variant bit measured in docs/quality.md: LR_B5 Schlick's power as
// a spherical Gaussian (three.js), LR_B6 Filament's fast visibility.

const float kPi = 3.14159265358979;
const float kInvPi = 0.318309886183791;  // float(1 / kPi), as T(1.0 / kPi) in shade.h
const float kMinRoughness = 0.0525;
const float kMinNDotV = 1e-5;
const float kDielectricF0 = 0.04;

// α = max(roughness, kMinRoughness)²; roughness above 1 or NaN -> 1.
float pbrAlpha(float roughness) {
    float r = roughness > kMinRoughness ? (roughness < 1.0 ? roughness : 1.0)
                                        : (roughness <= kMinRoughness ? kMinRoughness : 1.0);
    return r * r;
}

// D(h) = α² / (π ((N·H)² (α² - 1) + 1)²) for N·H > 0, the bracket as (N·H)² α² + |N×H|² (Lagrange).
float ggxDistribution(vec3 N, vec3 H, float alpha) {
    float nDotH = dot(N, H);
    vec3 c = cross(N, H);
    float a2 = alpha * alpha;
    float k = nDotH * nDotH * a2 + dot(c, c);
    return nDotH > 0.0 ? a2 / (kPi * k * k) : 0.0;
}

// Height-correlated Smith visibility; LR_B6: Filament's 0.5 / mix(2 N·L N·V, N·L + N·V, α).
float smithVisibility(float nDotL, float nDotV, float alpha) {
#ifdef LR_B6
    float denom = mix(2.0 * nDotL * nDotV, nDotL + nDotV, alpha);
    return denom > 0.0 ? 0.5 / denom : 0.0;
#else
    float a2 = alpha * alpha;
    float gv = nDotL * sqrt(nDotV * nDotV * (1.0 - a2) + a2);
    float gl = nDotV * sqrt(nDotL * nDotL * (1.0 - a2) + a2);
    float denom = gv + gl;
    return denom > 0.0 ? 0.5 / denom : 0.0;
#endif
}

// The Schlick weight (1 - |V·H|)^5; LR_B5: exp2((-5.55473 x - 6.98316) x), x = |V·H| (three.js F_Schlick).
float schlickWeight(float vDotH) {
    float x = saturate(abs(vDotH));
#ifdef LR_B5
    return exp2((-5.55473 * x - 6.98316) * x);
#else
    float m = 1.0 - x;
    float m2 = m * m;
    return m2 * m2 * m;
#endif
}

vec3 fresnelSchlick(vec3 f0, float vDotH) { return f0 + (vec3(1.0) - f0) * schlickWeight(vDotH); }

vec3 pbrBaseColor(vec3 b) { return vec3(positive(b.r), positive(b.g), positive(b.b)); }
vec3 pbrDiffuseColor(vec3 baseColor, float metallic) { return pbrBaseColor(baseColor) * (1.0 - saturate(metallic)); }
vec3 pbrF0(vec3 baseColor, float metallic) {
    float m = saturate(metallic);
    return vec3(kDielectricF0) * (1.0 - m) + pbrBaseColor(baseColor) * m;
}

struct PbrLobes {
    vec3 diffuse;
    vec3 specular;
};

// One light's two lobes per unit of light: diffuse = (1 - F) c_diff / π · cosTerm, specular = F D V · N·L.
PbrLobes pbrLobes(vec3 N, vec3 L, vec3 V, vec3 cDiff, vec3 f0, float alpha, float cosTerm) {
    PbrLobes o;
    // H from two unit vectors (lighting.h): |L + V| <= 2 cannot overflow, so one inversesqrt (lighting.h
    // divides by the square root: the same to rounding); L = -V (or a NaN): H = N.
    vec3 h = L + V;
    float hh = dot(h, h);
    vec3 H = hh > 1e-12 ? h * inversesqrt(hh) : N;
    vec3 F = fresnelSchlick(f0, dot(V, H));
    o.diffuse = (vec3(1.0) - F) * cDiff * (cosTerm * kInvPi);
    float nDotL = dot(N, L);
    float nDotV = abs(dot(N, V));
    nDotV = nDotV > kMinNDotV ? nDotV : kMinNDotV;
    float nl = nDotL < 1.0 ? nDotL : 1.0;
    float specular = ggxDistribution(N, H, alpha) * smithVisibility(nl, nDotV, alpha) * nl;
    // no specular from behind (a wrapped diffuse may still light it)
    o.specular = nDotL > 0.0 ? F * specular : vec3(0.0);
    return o;
}
#endif  // LR_PBR

// ---- tone mapping and output encoding ----

float toneMap(int op, float x) {
    if (!(x > 0.0)) return 0.0;
    if (op == LR_TONEMAP_CLAMP) return saturate(x);
    if (op == LR_TONEMAP_REINHARD) return x < kFloatMax ? x / (1.0 + x) : 1.0;
    if (op == LR_TONEMAP_ACES) {  // Narkowicz 2015 fit
        if (!(x < 1e6)) return 1.0;
        return saturate((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14));
    }
    return 0.0;
}

// Khronos PBR Neutral (three.js NeutralToneMapping): colour.h toneMapNeutral.
vec3 toneMapNeutral(vec3 c) {
    const float startCompression = 0.8 - 0.04;
    const float desaturation = 0.15;
    float x = min(c.r, min(c.g, c.b));
    float offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
    c -= offset;
    float peak = max(c.r, max(c.g, c.b));
    if (peak < startCompression) return c;
    const float d = 1.0 - startCompression;
    float newPeak = 1.0 - d * d / (peak + d - startCompression);
    c *= newPeak / peak;
    float g = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return mix(c, vec3(newPeak), g);
}

// AgX as three.js r187 / Filament evaluate it: colour.h toneMapAgx.
vec3 toneMapAgx(vec3 c) {
    const mat3 srgbToRec2020 = mat3(vec3(0.6274, 0.0691, 0.0164), vec3(0.3293, 0.9195, 0.0880),
                                    vec3(0.0433, 0.0113, 0.8956));
    const mat3 rec2020ToSrgb = mat3(vec3(1.6605, -0.1246, -0.0182), vec3(-0.5876, 1.1329, -0.1006),
                                    vec3(-0.0728, -0.0083, 1.1187));
    const mat3 inset = mat3(vec3(0.856627153315983, 0.137318972929847, 0.11189821299995),
                            vec3(0.0951212405381588, 0.761241990602591, 0.0767994186031903),
                            vec3(0.0482516061458583, 0.101439036467562, 0.811302368396859));
    const mat3 outset = mat3(vec3(1.1271005818144368, -0.1413297634984383, -0.14132976349843826),
                             vec3(-0.11060664309660323, 1.157823702216272, -0.11060664309660294),
                             vec3(-0.016493938717834573, -0.016493938717834257, 1.2519364065950405));
    const float minEv = -12.47393, maxEv = 4.026069;
    c = inset * (srgbToRec2020 * c);
    vec3 x = clamp((log2(max(c, vec3(1e-10))) - minEv) / (maxEv - minEv), 0.0, 1.0);
    vec3 x2 = x * x, x4 = x2 * x2;
    c = 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
    c = rec2020ToSrgb * pow(max(outset * c, vec3(0.0)), vec3(2.2));
    return vec3(saturate(c.r), saturate(c.g), saturate(c.b));
}

// An exposed colour into [0, 1]^3 (colour.h toneMapRgb): per channel, or on the colour (Neutral, AgX).
vec3 toneMapRgb(int op, vec3 x) {
    if (op != LR_TONEMAP_NEUTRAL && op != LR_TONEMAP_AGX) return vec3(toneMap(op, x.r), toneMap(op, x.g), toneMap(op, x.b));
    vec3 c = vec3(x.r > 0.0 ? min(x.r, 1e6) : 0.0, x.g > 0.0 ? min(x.g, 1e6) : 0.0, x.b > 0.0 ? min(x.b, 1e6) : 0.0);
    c = op == LR_TONEMAP_NEUTRAL ? toneMapNeutral(c) : toneMapAgx(c);
    return vec3(saturate(c.r), saturate(c.g), saturate(c.b));
}

float linearToSrgb(float x) {
    x = saturate(x);
    return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

float srgbToLinear(float x) {
    x = saturate(x);
    return x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4);
}

// Exposure (scale = 2^EV), tone map and sRGB encoding of linear radiance, per channel: what every output
// path applies (the display paths per fragment, tonemap.frag after a float target).
// `op` is a compile-time constant where it is called (LR_TONE_MAP, FeatureKey::toneMap), so only that
// operator's code is compiled: llvmpipe would run every operator's branch for every pixel.
vec3 displayEncode(vec3 radiance, float exposureScale, int op) {
    vec3 m = toneMapRgb(op, radiance * exposureScale);
    return vec3(linearToSrgb(m.r), linearToSrgb(m.g), linearToSrgb(m.b));
}

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
#endif
#ifdef LR_SHADOWS
    int shadow;  // its shadow slot + 1 (shadows.glsl), 0: it casts none
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
// Area lights (no falloff, no cone) reuse texels 5 and 6: 5: axisX.xyz, cone   6: axisY.xyz, coneExponent.
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
#endif
    return l;
}

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
// Whether the light's falloff is exactly zero at d >= range (range-power and range-quadratic always,
// the inverse falloffs when they have a range, i.e. range >= 0).
bool lightIsBounded(ShadeLight l) {
    int m = falloffOf(l);
    return m == LR_FALLOFF_RANGE_POWER || m == LR_FALLOFF_RANGE_QUADRATIC ||
           ((m == LR_FALLOFF_INVERSE_POLYNOMIAL || m == LR_FALLOFF_INVERSE_SQUARE) && l.range >= 0.0);
}
#endif

#if defined(LR_HAS_LIGHT_RECT) || defined(LR_HAS_LIGHT_DISK)
// ---- area lights (rect, disk): src/core/lighting_area.h and lighting_area_poly.h ----
// Polygon integrals in a local frame whose z is the clipping hemisphere's pole; the LTC table (core/ltc.h)
// as a 2-layer RGBA32F array (layer 0: M⁻¹'s m00, m02, m20, m22 with m11 = 1; layer 1: scale, bias),
// bilinear by texelFetch so that the filtering is float exact (a GPU's filter weights have 8 bits).
const int kDiskVertices = 8;
const float kDiskRadiusScale = 1.0539;
const int kLtcSize = 64;
#ifndef LR_PBR
const float kPi = 3.14159265358979;
const float kInvPi = 0.318309886183791;
const float kMinRoughness = 0.0525;
#endif
uniform sampler2DArray uLtc;

// Powers of two near 1/x and 1/√x for finite x > 0 (x = 0 gives 2^127 and 2^64: the clip below then scales a
// zero vector), from the exponent bits: no division and no square root, which llvmpipe pays in full (the
// edge integrals below need lengths near 1, not exactly 1).
float pow2Inverse(float x) { return intBitsToFloat((254 << 23) - (floatBitsToInt(x) & 0x7f800000)); }
float pow2InverseSqrt(float x) {
    int e = ((floatBitsToInt(x) >> 23) & 0xff) - 127;
    return intBitsToFloat((127 - (e >> 1)) << 23);
}

// θ / |a × b| for an edge with |a × b|² = cc and a · b = d, θ = atan2(|a × b|, a · b) in [0, π] (exact at any
// angle, no acos); 1 or 0 for a point (its a × b is zero). The arctangent on [0, 1] is Abramowitz & Stegun
// 4.4.49 (|error| ≤ 2e-8, below float's rounding; GLSL's two-argument atan handles every quadrant and cost
// half an area light), and one division serves both min/max and 1/|a × b|.
float edgeFactor(float cc, float d) {
    float s = sqrt(cc);
    float ad = abs(d);
    float m = max(s, ad);
    float q = 1.0 / max(m * s, 1e-36);
    float r = min(s, ad) * s * q;
    float r2 = r * r;
    float p = r * (0.9999993329 + r2 * (-0.3332985605 + r2 * (0.1994653599 + r2 * (-0.1390853351 +
              r2 * (0.0964200441 + r2 * (-0.0559098861 + r2 * (0.0218612288 + r2 * -0.0040540580)))))));
    float t = s > ad ? 1.57079632679490 - p : p;
    float theta = d < 0.0 ? 3.14159265358979 - t : t;
    return cc > 1e-36 ? theta * m * q : (d > 0.0 ? 1.0 : 0.0);
}

// The edge a→b's share of 2 ∫ ω dω: θ · normalize(a × b), zero for a point; the same at any length of a and
// b: the emitter's corners are scaled together to lengths near 1, and the points the clips and M⁻¹ make of
// them stay within a few orders of magnitude of that.
vec3 edgeIntegral(vec3 a, vec3 b) {
    vec3 c = cross(a, b);
    return c * edgeFactor(dot(c, c), dot(a, b));
}

vec3 unitOrPole(vec3 p) { return safeNormalize(p, vec3(0.0, 0.0, 1.0)); }

// The polygons stream past edge by edge and are clipped on the fly (lighting_area_poly.h clipHorizon gives
// the same polygons): no array of vertices, which llvmpipe keeps in memory and indexes lane by lane. A
// convex polygon leaves the half-space z > 0 once and comes back once; the closing edge along the plane
// joins the two points (both zero when it never crosses, an edge of length zero).
struct Clipper {
    vec3 sum;      // 2 ∫ ω dω over the edges' kept parts so far
    vec3 exitP;    // where the boundary went below z = 0
    vec3 entryP;   // where it came back
    bool crossed;  // whether it did (the closing edge costs nothing where no pixel's polygon crosses)
};

Clipper clipperStart() { return Clipper(vec3(0.0), vec3(0.0), vec3(0.0), false); }

// The part of a→b with z > 0 as s0→s1 (one point twice when none), noting a crossing.
void keptPart(inout Clipper c, vec3 a, vec3 b, out vec3 s0, out vec3 s1) {
    bool aUp = a.z > 0.0, bUp = b.z > 0.0;
    bool crosses = aUp != bUp;
    // a.z b − b.z a, oriented, lies on the segment's ray through the plane; scaled by a power of two near
    // 1 / (|a.z| + |b.z|) (exponent bits, no division) so that its length stays near the corners'.
    float pow2 = pow2Inverse(abs(a.z) + abs(b.z));
    vec3 x = (a.z * b - b.z * a) * (aUp ? pow2 : -pow2);
    x.z = 0.0;
    s0 = aUp ? a : x;
    s1 = bUp ? b : x;
    c.exitP = aUp && !bUp ? x : c.exitP;
    c.entryP = bUp && !aUp ? x : c.entryP;
    c.crossed = c.crossed || crosses;
}

void clipEdge(inout Clipper c, vec3 a, vec3 b) {
    vec3 s0, s1;
    keptPart(c, a, b, s0, s1);
    c.sum += edgeIntegral(s0, s1);
}

// ∫ ω dω over the clipped polygon: its z is π × the clipped form factor, signed by the winding.
vec3 clipperEnd(Clipper c) {
    // The closing edge lies in the plane z = 0: its a × b is (0, 0, cz).
    vec3 a = c.exitP, b = c.entryP;
    float cz = a.x * b.y - a.y * b.x;
    if (c.crossed) c.sum.z += cz * edgeFactor(cz * cz, a.x * b.x + a.y * b.y);
    return c.sum * 0.5;
}

// The emitter's polygon (local frame) through both clips: its part above the horizon, and that part mapped
// by A (the LTC's M⁻¹, or Phong's scaled frame about R) and clipped again, the lobe's polygon. full (the
// half-Lambert wrap only): the unclipped polygon's vector and its signed solid angle (a fan from vertex 0).
struct AreaStream {
    Clipper horizon;
    Clipper lobe;
    mat3 A;
    bool diffuse;  // whether the part above the horizon is integrated (not for a metal: c_diff = 0)
    bool full;
    vec3 fullSum;
    float omega;
};

struct AreaSums {
    vec3 clipped;  // ∫ ω dω over the part above the horizon
    vec3 lobe;     // ∫ ω dω over A·(that part), clipped to z > 0
    vec3 full;     // ∫ ω dω over the whole polygon (with full)
    float omega;   // its solid angle (with full)
};

void feedEdge(inout AreaStream s, vec3 a, vec3 b) {
    vec3 s0, s1;
    keptPart(s.horizon, a, b, s0, s1);
    if (s.diffuse) s.horizon.sum += edgeIntegral(s0, s1);
    clipEdge(s.lobe, s.A * s0, s.A * s1);
    if (s.full) s.fullSum += edgeIntegral(a, b);
}

// The signed solid angle of the triangle o, a, b (Van Oosterom & Strackee).
float triangleSolidAngle(vec3 o, vec3 a, vec3 b) {
    o = unitOrPole(o);
    a = unitOrPole(a);
    b = unitOrPole(b);
    return 2.0 * atan(dot(o, cross(a, b)), 1.0 + dot(o, a) + dot(a, b) + dot(b, o));
}

void feedFan(inout AreaStream s, vec3 o, vec3 a, vec3 b) {
    if (s.full) s.omega += triangleSolidAngle(o, a, b);
}

struct Frame {
    vec3 t1, t2, n;
};

vec3 toLocal(Frame f, vec3 v) { return vec3(dot(v, f.t1), dot(v, f.t2), dot(v, f.n)); }

Frame frameAround(vec3 n, vec3 towards) {
    vec3 any = abs(n.x) < 0.9 ? vec3(0.0, -n.z, n.y) : vec3(n.z, 0.0, -n.x);
    Frame f;
    f.t1 = safeNormalize(towards - n * dot(n, towards), safeNormalize(any, vec3(1.0, 0.0, 0.0)));
    f.t2 = cross(n, f.t1);
    f.n = n;
    return f;
}

// Streams the emitter at P in the frame f: a rect's four corners, or a disk as the equal-area octagon.
AreaSums areaSums(ShadeLight l, vec3 P, Frame f, mat3 A, bool diffuse, bool full) {
    AreaStream s;
    s.horizon = clipperStart();
    s.lobe = s.horizon;
    s.A = A;
    s.diffuse = diffuse || full;
    s.full = full;
    s.fullSum = vec3(0.0);
    s.omega = 0.0;
    AreaSums o;
    o.clipped = o.lobe = o.full = vec3(0.0);
    o.omega = 0.0;
    vec3 c = l.position - P;
    // The centre and half axes in the local frame (a disk's octagon on the circle of the equal-area radius).
    bool disk = lightTypeOf(l) == LR_LIGHT_DISK;
    float halfX = disk ? l.halfWidth * kDiskRadiusScale : l.halfWidth;
    vec3 cl = toLocal(f, c), xl = toLocal(f, l.axisX * halfX);
    vec3 yl = toLocal(f, l.axisY * (disk ? halfX : l.halfHeight));
    // Wholly below the horizon, nothing is left of it but for the half-Lambert wrap.
    if (!full && cl.z + abs(xl.z) + abs(yl.z) <= 0.0) return o;
    // One scale for all the corners (the edge integrals are the same at any length) keeps them near 1.
    float size2 = dot(cl, cl) + dot(xl, xl) + dot(yl, yl);
    float scale = size2 > 0.0 && size2 <= kFloatMax ? pow2InverseSqrt(size2) : 1.0;
    cl *= scale;
    xl *= scale;
    yl *= scale;
#ifdef LR_HAS_LIGHT_DISK
    if (lightTypeOf(l) == LR_LIGHT_DISK) {
        vec3 first = cl + xl;
        vec3 prev = first;
        for (int i = 1; i <= kDiskVertices; ++i) {
            float a = (2.0 * kPi / float(kDiskVertices)) * float(i);
            vec3 cur = i < kDiskVertices ? cl + xl * cos(a) + yl * sin(a) : first;
            feedEdge(s, prev, cur);
            if (i >= 2 && i < kDiskVertices) feedFan(s, first, prev, cur);
            prev = cur;
        }
    } else
#endif
    {
        vec3 p0 = cl - xl - yl, p1 = cl + xl - yl, p2 = cl + xl + yl, p3 = cl - xl + yl;
        feedEdge(s, p0, p1);
        feedEdge(s, p1, p2);
        feedEdge(s, p2, p3);
        feedEdge(s, p3, p0);
        feedFan(s, p0, p1, p2);
        feedFan(s, p0, p2, p3);
    }
    // The first clip's closing edge along the horizon is an edge of the lobe's polygon too.
    if (s.horizon.crossed) clipEdge(s.lobe, A * s.horizon.exitP, A * s.horizon.entryP);
    o.clipped = s.diffuse ? clipperEnd(s.horizon) : vec3(0.0);
    o.lobe = clipperEnd(s.lobe);
    o.full = s.fullSum * 0.5;
    o.omega = abs(s.omega);
    return o;
}

bool facesEmitter(ShadeLight l, vec3 P) {
    float side = dot(P - l.position, l.direction);
    return l.twoSided ? (side > 0.0 || side < 0.0) : side > 0.0;
}

vec3 emitterToward(ShadeLight l, vec3 P) { return dot(P - l.position, l.direction) > 0.0 ? -l.direction : l.direction; }

// (1/π) ∫ ((1 + cos)/2)² dω over the unclipped polygon, cos² as its mean squared (lighting_area.h).
float halfLambertIntegral(AreaSums a, vec3 toward) {
    float cosSum = dot(a.full, toward) < 0.0 ? -a.full.z : a.full.z;
    return a.omega > 0.0 ? positive(a.omega + 2.0 * cosSum + cosSum * cosSum / a.omega) * (0.25 * kInvPi) : 0.0;
}

// The diffuse integral of the light's model over the emitter (form factor or half-Lambert wrap).
float areaDiffuse(ShadeLight l, AreaSums a, vec3 toward) {
    return diffuseOf(l) == LR_DIFFUSE_LAMBERT ? abs(a.clipped.z) * kInvPi : halfLambertIntegral(a, toward);
}

#ifndef LR_PBR
// shadeAreaLight's direct terms split (diffuse per unit of colour·albedo, specular per unit of Sc·ks). The
// specular: (1/π) ∫ (R·ω)^n dω over the clipped polygon, as the LTC diag(s, s, 1) around R, s² = 2/(n + 1).
vec2 areaClassic(ShadeLight l, vec3 P, vec3 N, float shininess, vec3 V) {
    if (!facesEmitter(l, P)) return vec2(0.0);
    Frame f = frameAround(N, V);
    vec3 R = safeNormalize(2.0 * dot(N, V) * N - V, N);
#if LR_SPECULAR == LR_SPECULAR_PHONG
    float e = positive(shininess);
#else
    float e = positive(shininess * 0.25);
#endif
    float invS = sqrt((e + 1.0) * 0.5);
    Frame r = frameAround(R, f.n);
    // Local (surface frame) → R's frame, scaled across R.
    mat3 toR = transpose(mat3(r.t1 * invS, r.t2 * invS, r.n)) * mat3(f.t1, f.t2, f.n);
    AreaSums a = areaSums(l, P, f, toR, true, diffuseOf(l) != LR_DIFFUSE_LAMBERT);
    float D = areaDiffuse(l, a, toLocal(f, emitterToward(l, P)));
    float S = abs(a.lobe.z) * kInvPi * (2.0 / (e + 1.0));
    return vec2(D, S);
}
#else
// The LTC table at (α, N·V), bilinear (ltc.h lookup). It depends on the surface, not on the light: looked up
// once per surface (PbrSurface), so that a pixel under sixteen softboxes fetches its eight texels once.
struct LtcSample {
    vec4 minv;     // M⁻¹'s m00, m02, m20, m22
    vec2 fresnel;  // scale, bias
    Frame frame;   // the local frame: N, and V in its xz plane
    vec3 Vl;       // V in it
};

LtcSample ltcLookup(float alpha, vec3 N, vec3 V) {
    float nDotV = abs(dot(N, V));
    nDotV = nDotV > kMinNDotV ? nDotV : kMinNDotV;
    float u = saturate((sqrt(positive(alpha)) - kMinRoughness) / (1.0 - kMinRoughness));
    float v = sqrt(saturate(1.0 - nDotV));
    float x = u * float(kLtcSize - 1), y = v * float(kLtcSize - 1);
    int i0 = min(int(x), kLtcSize - 2), j0 = min(int(y), kLtcSize - 2);
    float fx = x - float(i0), fy = y - float(j0);
    vec4 a0 = texelFetch(uLtc, ivec3(i0, j0, 0), 0), a1 = texelFetch(uLtc, ivec3(i0 + 1, j0, 0), 0);
    vec4 a2 = texelFetch(uLtc, ivec3(i0, j0 + 1, 0), 0), a3 = texelFetch(uLtc, ivec3(i0 + 1, j0 + 1, 0), 0);
    vec4 b0 = texelFetch(uLtc, ivec3(i0, j0, 1), 0), b1 = texelFetch(uLtc, ivec3(i0 + 1, j0, 1), 0);
    vec4 b2 = texelFetch(uLtc, ivec3(i0, j0 + 1, 1), 0), b3 = texelFetch(uLtc, ivec3(i0 + 1, j0 + 1, 1), 0);
    vec4 at = a0 + (a1 - a0) * fx, ab = a2 + (a3 - a2) * fx;
    vec4 bt = b0 + (b1 - b0) * fx, bb = b2 + (b3 - b2) * fx;
    LtcSample o;
    o.minv = at + (ab - at) * fy;
    o.fresnel = (bt + (bb - bt) * fy).xy;
    o.frame = frameAround(N, V);
    o.Vl = toLocal(o.frame, V);
    return o;
}

// Schlick's weight at the half vector of V and the direction of m: V·H = sqrt((1 + V·m/|m|) / 2), the pole
// for m = 0.
float schlickToward(vec3 m, vec3 V) {
    float mm = dot(m, m);
    float c = mm > 1e-30 ? dot(m, V) / sqrt(mm) : V.z;
    return schlickWeight(sqrt(saturate(0.5 + 0.5 * c)));
}

// shadeAreaLightPbr's direct terms: diffuse = c_diff (1 − F0) (1 − w) D (per unit of colour), and the
// specular's LTC integral I × the lobe's norm n, split by Schlick's weight ws at the lobe's mean direction:
// specular = F0·scaleI + biasI with scaleI = (1 − ws)·n·I, biasI = ws·n·I.
struct AreaPbr {
    float diffuse;  // (1 − w)·D: × c_diff (1 − F0)
    float scaleI;   // (1 − ws)·n·I: × F0
    float biasI;    // ws·n·I
};

AreaPbr areaPbr(ShadeLight l, vec3 P, vec3 N, vec3 V, LtcSample ltc, bool diffuse) {
    AreaPbr o;
    o.diffuse = 0.0;
    o.scaleI = 0.0;
    o.biasI = 0.0;
    if (!facesEmitter(l, P)) return o;
    Frame f = ltc.frame;
    vec4 k = ltc.minv;
    // The polygon clipped to the surface's horizon (the BRDF is zero below), then transformed by M⁻¹.
    mat3 minv = mat3(vec3(k.x, 0.0, k.z), vec3(0.0, 1.0, 0.0), vec3(k.y, 0.0, k.w));
    AreaSums a = areaSums(l, P, f, minv, diffuse, diffuseOf(l) != LR_DIFFUSE_LAMBERT);
    vec3 toward = toLocal(f, emitterToward(l, P));
    float D = areaDiffuse(l, a, toward);
    vec3 Vl = ltc.Vl;
    float w = schlickToward(dot(a.clipped, toward) < 0.0 ? -a.clipped : a.clipped, Vl);
    o.diffuse = (1.0 - w) * D;
    // The lobe's norm × Schlick's Fresnel at its mean direction over the light: the LTC polygon's vector
    // taken back through M (M⁻¹'s xz block inverted, m11 = 1; lighting_area.h lobeMeanDirection).
    float I = abs(a.lobe.z) * kInvPi;
    vec3 e = a.lobe.z < 0.0 ? -a.lobe : a.lobe;
    float det = k.x * k.w - k.y * k.z;
    float ws = schlickToward(vec3(k.w * e.x - k.y * e.z, e.y * det, k.x * e.z - k.z * e.x), Vl);
    float normI = (ltc.fresnel.x + ltc.fresnel.y) * I;
    o.scaleI = (1.0 - ws) * normI;
    o.biasI = ws * normI;
    return o;
}
#endif
#endif

// The viewer as the rig asks, in every tier. LR_FAST_INFINITE_VIEWER (measuring only): the fast tier with
// Direct3D's default infinite viewer (F2 in docs/quality.md, measured and dropped).
vec3 viewVector(ShadeSettings s, vec3 P) {
    const vec3 infinite = vec3(0.0, 0.0, 1.0);
#if LR_VIEWER == LR_VIEWER_LOCAL && !defined(LR_FAST_INFINITE_VIEWER)
    return safeNormalize(-P, infinite);
#else
    return infinite;
#endif
}

#if defined(LR_HAS_AREA) && !defined(LR_PBR)
// What an area light adds, classic (lighting_area.h shadeAreaLight); the shadow as for the other lights,
// towards the emitter's centre.
vec3 shadeAreaLight(ShadeLight l, Surface s, ShadeSettings st, vec3 V) {
    vec2 ds = areaClassic(l, s.position, s.normal, s.shininess, V);
    vec3 direct = l.color * s.albedo * ds.x + l.specular * s.specular * ds.y;
#ifdef LR_SHADOWS
    direct *= lrShadow(l, s, safeNormalize(l.position - s.position, s.normal), true);
#endif
#ifdef LR_HAS_LIGHT_AMBIENT
    return direct + l.ambient * s.albedo;
#else
    return direct;
#endif
}
#endif

// Radiance one light adds at the surface (linear, HDR).
vec3 shadeLight(ShadeLight l, Surface s, ShadeSettings st, vec3 V) {
    vec3 N = s.normal;
#ifdef LR_HAS_LIGHT_RIM
    if (lightTypeOf(l) == LR_LIGHT_RIM) return l.color * rimTerm(l.direction, N, V, l.rimExponent);
#endif
#if defined(LR_HAS_AREA) && !defined(LR_PBR)
    if (lightIsArea(l)) return shadeAreaLight(l, s, st, V);
#endif
#ifdef LR_HAS_SURFACE_LIGHTS
    vec3 L = -l.direction;
    float attenuation = 1.0;
#ifdef LR_HAS_POSITIONAL
    if (lightTypeOf(l) != LR_LIGHT_DIRECTIONAL) {
        vec3 toLight = l.position - s.position;
#ifdef LR_B3
        // B3 early-out: beyond a bounded falloff's range (squared distances, before any sqrt) the light
        // adds exactly zero.
        float d2 = dot(toLight, toLight);
        if (l.range > 1e-18 && lightIsBounded(l) && d2 * (st.distanceScale * st.distanceScale) >= l.range * l.range)
            return vec3(0.0);
#endif
#ifdef LR_B4
        // B4 L and d from one inversesqrt, without branches. Outside 1e-15 < |toLight| < 1e15 (a light
        // within 1e-15 of the surface, or farther than rig files allow) L falls back to N and d to 0 or the
        // largest float, where the exact tier rescales first.
        float t2 = dot(toLight, toLight);
        float inv = inversesqrt(t2);
        bool inRange = t2 > 1e-30 && t2 < 1e30;
        L = inRange ? toLight * inv : N;
        float d = (inRange ? t2 * inv : (!(t2 <= 1.0) ? kFloatMax : 0.0)) * st.distanceScale;
        if (!(abs(d) <= kFloatMax)) d = kFloatMax;
#else
        L = safeNormalize(toLight, N);  // a light on the surface shines along the normal
        // |toLight| as dot(toLight, L): no squared intermediate to overflow or underflow, one sqrt fewer;
        // an overflowing distance becomes the largest float (every falloff then gives its limit).
        float d = dot(toLight, L) * st.distanceScale;
        if (!(abs(d) <= kFloatMax)) d = kFloatMax;
#endif
#ifdef LR_HAS_LIGHT_SPOT
        float cosTheta = dot(-L, l.direction);
#ifdef LR_B3
        // ... and outside the cone (cosine space, before the falloff and the cone are evaluated).
        if (lightTypeOf(l) == LR_LIGHT_SPOT && cosTheta < l.cosOuter) return vec3(0.0);
#endif
#endif
        attenuation = evalFalloff(l, d);
#ifdef LR_HAS_LIGHT_SPOT
        if (lightTypeOf(l) == LR_LIGHT_SPOT) attenuation *= evalCone(l, cosTheta);
#endif
        if (!(attenuation > 0.0)) return vec3(0.0);
    }
#endif
    float nDotL = dot(N, L);
    float D = diffuseOf(l) == LR_DIFFUSE_LAMBERT ? diffuseLambert(nDotL) : diffuseHalfLambert(nDotL);
    float S = 0.0;
#if LR_SPECULAR == LR_SPECULAR_PHONG
    if (nDotL > 0.0) S = specularPhong(N, L, V, s.shininess);
#else
    if (nDotL > 0.0) S = specularBlinnPhong(N, L, V, s.shininess);
#endif
#ifdef LR_SHADOWS
    // The shadow dims the light's direct terms, not its ambient one.
    float visibility = lrShadow(l, s, L, D > 0.0 || S > 0.0);
#ifdef LR_HAS_LIGHT_AMBIENT
    return attenuation * (visibility * (l.color * s.albedo * D + l.specular * s.specular * S) + l.ambient * s.albedo);
#else
    return attenuation * visibility * (l.color * s.albedo * D + l.specular * s.specular * S);
#endif
#else
#ifdef LR_HAS_LIGHT_AMBIENT
    return attenuation * (l.color * s.albedo * D + l.specular * s.specular * S + l.ambient * s.albedo);
#else
    return attenuation * (l.color * s.albedo * D + l.specular * s.specular * S);
#endif
#endif
#else
    return vec3(0.0);
#endif
}

#ifdef LR_PBR
// The direction to a light and its attenuation (falloff × cone; 1 for a directional light) at the surface;
// false when the light adds nothing there (shade.h lightArrival). The classic shadeLight() above inlines
// the same steps, except that its exact tier normalises with safeNormalize at any distance (classic keys
// carry no LR_FAR_LIGHTS bit); folding it into this function is left for when the classic path gets the
// bit too.
bool lightArrival(ShadeLight l, Surface s, ShadeSettings st, out vec3 L, out float attenuation) {
    vec3 N = s.normal;
    L = -l.direction;
    attenuation = 1.0;
#ifdef LR_HAS_POSITIONAL
    if (lightTypeOf(l) != LR_LIGHT_DIRECTIONAL) {
        vec3 toLight = l.position - s.position;
#ifdef LR_B3
        float d2 = dot(toLight, toLight);
        if (l.range > 1e-18 && lightIsBounded(l) && d2 * (st.distanceScale * st.distanceScale) >= l.range * l.range)
            return false;
#endif
#ifndef LR_FAR_LIGHTS
        // L and d from one inversesqrt (the classic B4, here in every tier). Exact where 1e-15 < |toLight|
        // < 1e15: the renderer compiles this only when no positional light can be 1e15 from a visible
        // surface (LightSet::update bounds it), and below 1e-15 the light is on the surface (float positions
        // of a visible surface, beyond the near plane, cannot differ by less unless they are equal): L = N,
        // d = 0, as safeNormalize.
        float t2 = dot(toLight, toLight);
        float inv = inversesqrt(t2);
        bool inRange = t2 > 1e-30 && t2 < 1e30;
        L = inRange ? toLight * inv : N;
        float d = (inRange ? t2 * inv : (!(t2 <= 1.0) ? kFloatMax : 0.0)) * st.distanceScale;
#else
        // LR_FAR_LIGHTS: rescaled first, exact at any distance.
        L = safeNormalize(toLight, N);  // a light on the surface shines along the normal
        float d = dot(toLight, L) * st.distanceScale;
#endif
        d = abs(d) <= kFloatMax ? d : kFloatMax;
#ifdef LR_HAS_LIGHT_SPOT
        float cosTheta = dot(-L, l.direction);
#ifdef LR_B3
        if (lightTypeOf(l) == LR_LIGHT_SPOT && cosTheta < l.cosOuter) return false;
#endif
#endif
        attenuation = evalFalloff(l, d);
#ifdef LR_HAS_LIGHT_SPOT
        if (lightTypeOf(l) == LR_LIGHT_SPOT) attenuation *= evalCone(l, cosTheta);
#endif
        return attenuation > 0.0;
    }
#endif
    return true;
}

// What shadeSurface() computes once per surface under PBR, before the lights.
struct PbrSurface {
    vec3 cDiff, f0;
    float alpha;
#ifdef LR_HAS_AREA
    LtcSample ltc;  // the area lights' LTC at this (α, N·V)
#endif
};

PbrSurface pbrSurface(Surface s) {
    PbrSurface p;
    p.cDiff = pbrDiffuseColor(s.albedo, s.metallic);
    p.f0 = pbrF0(s.albedo, s.metallic);
    p.alpha = pbrAlpha(s.roughness);
    return p;
}

// pbrSurface() with what the lights need of the viewer once per surface (the LTC lookup).
PbrSurface pbrSurfaceLit(Surface s, vec3 V) {
    PbrSurface p = pbrSurface(s);
#ifdef LR_HAS_AREA
    p.ltc = ltcLookup(p.alpha, s.normal, V);
#endif
    return p;
}

#ifdef LR_HAS_AREA
// What an area light adds under physically based shading (lighting_area.h shadeAreaLightPbr).
vec3 shadeAreaLightPbr(ShadeLight l, Surface s, ShadeSettings st, vec3 V, PbrSurface p) {
    AreaPbr a = areaPbr(l, s.position, s.normal, V, p.ltc, any(greaterThan(p.cDiff, vec3(0.0))));
    vec3 direct = l.color * (p.cDiff * (vec3(1.0) - p.f0) * a.diffuse) + l.specular * (p.f0 * a.scaleI + vec3(a.biasI));
#ifdef LR_SHADOWS
    direct *= lrShadow(l, s, safeNormalize(l.position - s.position, s.normal), true);
#endif
#ifdef LR_HAS_LIGHT_AMBIENT
    return direct + l.ambient * p.cDiff * (saturate(s.occlusion) * kInvPi);
#else
    return direct;
#endif
}
#endif

// Radiance one light adds under physically based shading (shade.h shadeLightPbr):
//   attenuation · (colour·intensity · diffuse lobe + Sc·intensity · specular lobe + Ac·intensity · c_diff/π);
// a rim light adds its classic term.
vec3 shadeLightPbr(ShadeLight l, Surface s, ShadeSettings st, vec3 V, PbrSurface p) {
    vec3 N = s.normal;
    vec3 cDiff = p.cDiff, f0 = p.f0;
    float alpha = p.alpha;
#ifdef LR_HAS_LIGHT_RIM
    if (lightTypeOf(l) == LR_LIGHT_RIM) return l.color * rimTerm(l.direction, N, V, l.rimExponent);
#endif
#ifdef LR_HAS_AREA
    if (lightIsArea(l)) return shadeAreaLightPbr(l, s, st, V, p);
#endif
#ifdef LR_HAS_SURFACE_LIGHTS
    vec3 L;
    float attenuation;
    bool arrives = lightArrival(l, s, st, L, attenuation);
    float nDotL = dot(N, L);
    float cosTerm = diffuseOf(l) == LR_DIFFUSE_LAMBERT ? diffuseLambert(nDotL) : diffuseHalfLambert(nDotL);
    PbrLobes f = pbrLobes(N, L, V, cDiff, f0, alpha, cosTerm);
#ifdef LR_SHADOWS
    // The shadow dims the light's direct lobes, not its ambient term (and is not sampled where the light
    // adds nothing).
    // Needed only where the light arrives with a direct lobe; elsewhere the result below is discarded or
    // multiplied by zero.
    float visibility = lrShadow(l, s, L, arrives && attenuation > 0.0 && (cosTerm > 0.0 || nDotL > 0.0));
#ifdef LR_HAS_LIGHT_AMBIENT
    vec3 radiance = attenuation * (visibility * (l.color * f.diffuse + l.specular * f.specular) +
                                   l.ambient * cDiff * (saturate(s.occlusion) * kInvPi));
#else
    vec3 radiance = attenuation * visibility * (l.color * f.diffuse + l.specular * f.specular);
#endif
#else
#ifdef LR_HAS_LIGHT_AMBIENT
    vec3 radiance = attenuation * (l.color * f.diffuse + l.specular * f.specular +
                                   l.ambient * cDiff * (saturate(s.occlusion) * kInvPi));
#else
    vec3 radiance = attenuation * (l.color * f.diffuse + l.specular * f.specular);
#endif
#endif
    return arrives ? radiance : vec3(0.0);
#else
    return vec3(0.0);
#endif
}

// The scene ambient: an irradiance (as three.js's AmbientLight) on the diffuse lobe, times the occlusion.
vec3 pbrSceneAmbient(Surface s, ShadeSettings st, PbrSurface p) {
    return st.ambient * p.cDiff * (saturate(s.occlusion) * kInvPi);
}
#endif  // LR_PBR

// Scene ambient + every light + emissive.
//
// Loops over a run-time count are written `if (n > 0) { int i = 0; do { ... } while (++i < n); }` here
// and in every shader: llvmpipe runs a block of pixels (or vertices) through a loop until none is left in
// it, and a `for` loop's test comes first in each pass, so the `for` form runs one more pass than the
// longest lane needs, with every lane masked off (measured: docs/performance.md, session 15).
vec3 shadeSurface(Surface s, ShadeSettings st) {
    vec3 V = viewVector(st, s.position);
#ifdef LR_PBR
    PbrSurface p = pbrSurfaceLit(s, V);
    vec3 sum = pbrSceneAmbient(s, st, p);
#if defined(LR_HAS_SURFACE_LIGHTS) || defined(LR_HAS_LIGHT_RIM)
    if (uLightCount > 0) {
        int i = 0;
        do {
            sum += shadeLightPbr(loadLight(i), s, st, V, p);
        } while (++i < uLightCount);
    }
#endif
    return sum + s.emissive;
#else
    vec3 sum = st.ambient * s.albedo;
#if defined(LR_HAS_SURFACE_LIGHTS) || defined(LR_HAS_LIGHT_RIM)
    if (uLightCount > 0) {
        int i = 0;
        do {
            sum += shadeLight(loadLight(i), s, st, V);
        } while (++i < uLightCount);
    }
#endif
    return sum + s.emissive;
#endif
}

#ifdef LR_QUALITY_FAST
// F1 Gouraud (Direct3D fixed function, design document 004): the lighting of shadeSurface() evaluated at
// the vertices and interpolated; the albedo and ks, textured per pixel, multiply it afterwards:
//   radiance = albedo · diffuse + ks · specular + added + emissive, where
//   diffuse = scene ambient + Σ attenuation·(colour·D + Ac), specular = Σ attenuation·Sc·S, added = Σ rim.
// Per light the same formulas and guards as shadeLight(), with the viewer V at the vertex.
struct VertexLight {
    vec3 diffuse;
    vec3 specular;
    vec3 added;
};

void shadeLightSplit(ShadeLight l, vec3 P, vec3 N, float shininess, ShadeSettings st, vec3 V, inout VertexLight o) {
#ifdef LR_HAS_LIGHT_RIM
    if (lightTypeOf(l) == LR_LIGHT_RIM) {
        o.added += l.color * rimTerm(l.direction, N, V, l.rimExponent);
        return;
    }
#endif
#if defined(LR_HAS_AREA) && !defined(LR_PBR)
    if (lightIsArea(l)) {  // the area integrals at the vertex, as every light in this tier
        vec2 ds = areaClassic(l, P, N, shininess, V);
#ifdef LR_HAS_LIGHT_AMBIENT
        o.diffuse += l.color * ds.x + l.ambient;
#else
        o.diffuse += l.color * ds.x;
#endif
        o.specular += l.specular * ds.y;
        return;
    }
#endif
#ifdef LR_HAS_SURFACE_LIGHTS
    vec3 L = -l.direction;
    float attenuation = 1.0;
#ifdef LR_HAS_POSITIONAL
    if (lightTypeOf(l) != LR_LIGHT_DIRECTIONAL) {
        vec3 toLight = l.position - P;
        L = safeNormalize(toLight, N);
        float d = dot(toLight, L) * st.distanceScale;
        if (!(abs(d) <= kFloatMax)) d = kFloatMax;
        attenuation = evalFalloff(l, d);
#ifdef LR_HAS_LIGHT_SPOT
        if (lightTypeOf(l) == LR_LIGHT_SPOT) attenuation *= evalCone(l, dot(-L, l.direction));
#endif
        if (!(attenuation > 0.0)) return;
    }
#endif
    float nDotL = dot(N, L);
    float D = diffuseOf(l) == LR_DIFFUSE_LAMBERT ? diffuseLambert(nDotL) : diffuseHalfLambert(nDotL);
    float S = 0.0;
#if LR_SPECULAR == LR_SPECULAR_PHONG
    if (nDotL > 0.0) S = specularPhong(N, L, V, shininess);
#else
    if (nDotL > 0.0) S = specularBlinnPhong(N, L, V, shininess);
#endif
#ifdef LR_HAS_LIGHT_AMBIENT
    o.diffuse += attenuation * (l.color * D + l.ambient);
#else
    o.diffuse += attenuation * (l.color * D);
#endif
    o.specular += attenuation * (l.specular * S);
#endif
}

VertexLight shadeVertex(vec3 P, vec3 N, float shininess, ShadeSettings st) {
    VertexLight o;
    o.diffuse = st.ambient;
    o.specular = vec3(0.0);
    o.added = vec3(0.0);
    vec3 V = viewVector(st, P);
#if defined(LR_HAS_SURFACE_LIGHTS) || defined(LR_HAS_LIGHT_RIM)
    if (uLightCount > 0) {
        int i = 0;
        do {
            ShadeLight l = loadLight(i);
#ifdef LR_SHADOWS
            if (l.shadow == 0)  // the casting lights are shaded per pixel (shadows.glsl shadeCastingLights)
#endif
                shadeLightSplit(l, P, N, shininess, st, V, o);
        } while (++i < uLightCount);
    }
#endif
    return o;
}

#ifdef LR_PBR
// F1 for physically based shading: the lights summed at the vertices in a split that keeps the material
// per pixel. With w = (1 - V·H)^5 (Schlick's weight, F = F0 (1 - w) + w) and per light
// a = attenuation·Sc·D·V·N·L (the specular lobe without F), the exact sums are
//   specular = Σ a·F = F0·(A - B) + B,         A = Σ a, B = Σ a·w
//   diffuse  = Σ attenuation·colour·(1 - F)·c_diff·cosTerm/π = c_diff·(1 - F0)·E,   E = Σ attenuation·colour·cosTerm·(1 - w)/π
// ((1 - F) = (1 - F0)(1 - w)), so F0 and c_diff (base colour, metallic: textured) apply per pixel exactly;
// what is per vertex is D·V and w, evaluated with the vertex normal (no normal map), the vertex's viewer
// and the roughness there (the factor × the metal-rough texture's coarse level), then interpolated.
struct VertexLightPbr {
    vec3 specular;  // A
    vec3 fresnel;   // B
    vec3 diffuse;   // E
    vec3 ambient;   // Σ attenuation·Ac/π: × c_diff·occlusion per pixel
    vec3 added;     // rim lights
};

void shadeLightSplitPbr(ShadeLight l, Surface s, ShadeSettings st, vec3 V, PbrSurface p, inout VertexLightPbr o) {
    float alpha = p.alpha;
    vec3 N = s.normal;
#ifdef LR_HAS_LIGHT_RIM
    if (lightTypeOf(l) == LR_LIGHT_RIM) {
        o.added += l.color * rimTerm(l.direction, N, V, l.rimExponent);
        return;
    }
#endif
#ifdef LR_HAS_AREA
    if (lightIsArea(l)) {  // specular = F0·scaleI + biasI = F0·(A − B) + B with A = scaleI + biasI, B = biasI
        AreaPbr a = areaPbr(l, s.position, N, V, p.ltc, true);  // the material comes per pixel
        o.specular += l.specular * (a.scaleI + a.biasI);
        o.fresnel += l.specular * a.biasI;
        o.diffuse += l.color * a.diffuse;
#ifdef LR_HAS_LIGHT_AMBIENT
        o.ambient += l.ambient * kInvPi;
#endif
        return;
    }
#endif
#ifdef LR_HAS_SURFACE_LIGHTS
    vec3 L;
    float attenuation;
    if (!lightArrival(l, s, st, L, attenuation)) return;
    float nDotL = dot(N, L);
    float cosTerm = diffuseOf(l) == LR_DIFFUSE_LAMBERT ? diffuseLambert(nDotL) : diffuseHalfLambert(nDotL);
    vec3 H = safeNormalize(L + V, N);
    float w = schlickWeight(dot(V, H));
    o.diffuse += attenuation * l.color * (cosTerm * kInvPi * (1.0 - w));
#ifdef LR_HAS_LIGHT_AMBIENT
    o.ambient += attenuation * l.ambient * kInvPi;
#endif
    if (!(nDotL > 0.0)) return;
    float nDotV = abs(dot(N, V));
    if (!(nDotV > kMinNDotV)) nDotV = kMinNDotV;
    float nl = nDotL < 1.0 ? nDotL : 1.0;
    vec3 a = attenuation * l.specular * (ggxDistribution(N, H, alpha) * smithVisibility(nl, nDotV, alpha) * nl);
    o.specular += a;
    o.fresnel += a * w;
#endif
}

VertexLightPbr shadeVertexPbr(vec3 P, vec3 N, float roughness, ShadeSettings st) {
    VertexLightPbr o;
    o.specular = vec3(0.0);
    o.fresnel = vec3(0.0);
    o.diffuse = vec3(0.0);
    o.ambient = vec3(0.0);
    o.added = vec3(0.0);
    Surface s;
    s.position = P;
    s.normal = N;
    vec3 V = viewVector(st, P);
    PbrSurface p;  // the vertex knows its roughness; the material's colours come per pixel (shadePixelPbr)
    p.cDiff = p.f0 = vec3(0.0);
    p.alpha = pbrAlpha(roughness);
#ifdef LR_HAS_AREA
    p.ltc = ltcLookup(p.alpha, N, V);
#endif
#if defined(LR_HAS_SURFACE_LIGHTS) || defined(LR_HAS_LIGHT_RIM)
    if (uLightCount > 0) {
        int i = 0;
        do {
            ShadeLight l = loadLight(i);
#ifdef LR_SHADOWS
            if (l.shadow == 0)  // as in shadeVertex
#endif
                shadeLightSplitPbr(l, s, st, V, p, o);
        } while (++i < uLightCount);
    }
#endif
    return o;
}

// The pixel's radiance from the interpolated sums and its own material (shadeSurface's terms).
vec3 shadePixelPbr(Surface s, ShadeSettings st, vec3 A, vec3 B, vec3 E, vec3 ambient, vec3 added) {
    PbrSurface p = pbrSurface(s);
    float occlusion = saturate(s.occlusion);
    return pbrSceneAmbient(s, st, p) + p.cDiff * (vec3(1.0) - p.f0) * E + p.f0 * (A - B) + B +
           p.cDiff * (ambient * occlusion) + added + s.emissive;
}
#endif  // LR_PBR
#endif  // LR_QUALITY_FAST

#endif  // LR_SHADING
