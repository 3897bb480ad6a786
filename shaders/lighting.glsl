// LightRig lighting formulas in GLSL 330: the exact twin of src/core/lighting.h (same function names,
// same guards, same order of operations). Keep the two files in step. Needs colour.glsl (saturate,
// positive, kFloatMax). The whole-surface shading is in shadetypes.glsl, area.glsl, shade.glsl and
// shadevertex.glsl, the twins of shadetypes.h, lighting_area.h, shade.h and shade.h's fast tier.
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
//   LR_LIGHT_TEXELS: RGBA32F texels per light in the light buffer (layout in shadetypes.glsl, loadLight);
//   LR_QUALITY_EXACT / LR_QUALITY_BALANCED / LR_QUALITY_FAST: the quality tier (docs/quality.md);
//   LR_SHININESS_INT + powShininessInt(): balanced tier, the material's shininess is this integer;
//   LR_PBR: the rig is physically based (the glTF BRDF block, shadeLightPbr); with it
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

// The diffuse lobe's weight 1 - F_dielectric, (1 - 0.04)(1 - w): the specification's mix (lighting.h).
float dielectricDiffuseWeight(float w) { return (1.0 - kDielectricF0) * (1.0 - w); }

// One light's two lobes per unit of light: diffuse = (1 - F_dielectric) c_diff / π · cosTerm,
// specular = F D V · N·L.
PbrLobes pbrLobes(vec3 N, vec3 L, vec3 V, vec3 cDiff, vec3 f0, float alpha, float cosTerm) {
    PbrLobes o;
    // H from two unit vectors (lighting.h): |L + V| <= 2 cannot overflow, so one inversesqrt (lighting.h
    // divides by the square root: the same to rounding); L = -V (or a NaN): H = N.
    vec3 h = L + V;
    float hh = dot(h, h);
    vec3 H = hh > 1e-12 ? h * inversesqrt(hh) : N;
    float w = schlickWeight(dot(V, H));
    vec3 F = f0 + (vec3(1.0) - f0) * w;
    o.diffuse = cDiff * (dielectricDiffuseWeight(w) * cosTerm * kInvPi);
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
