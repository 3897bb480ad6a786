// Whole-surface shading in GLSL 330, the twin of src/core/shade.h: the viewer, one light's contribution
// (shadeLight classic, lightArrival + shadeLightPbr physically based) and shadeSurface's sum over the
// lights. After shadetypes.glsl and area.glsl; shadows.glsl (lrShadow) follows it.
#ifdef LR_SHADING

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

#ifdef LR_HAS_SURFACE_LIGHTS
// The direction to a light and its attenuation (falloff × cone; 1 for a directional light) at the surface
// point P with normal N; false when the light adds nothing there (shade.h lightArrival). One definition for
// both shadings and every tier: the tiers differ only in how L and d are computed.
// LR_ARRIVAL_INVERSESQRT: L and d from one inversesqrt, without branches; exact where 1e-15 < |toLight| <
// 1e15, and outside it L falls back to N and d to 0 or the largest float. Physically based keys use it in
// every tier unless LR_FAR_LIGHTS (the renderer compiles it only when no positional light can be 1e15 from
// a visible surface: LightSet::update bounds it; below 1e-15 the light is on the surface, since float
// positions of a visible surface beyond the near plane cannot differ by less unless they are equal);
// classic keys use it in the balanced tier (B4). Otherwise L = safeNormalize (rescaled first, exact at any
// distance) and |toLight| = dot(toLight, L): no squared intermediate to overflow or underflow.
#if (defined(LR_PBR) && !defined(LR_FAR_LIGHTS)) || (!defined(LR_PBR) && defined(LR_B4))
#define LR_ARRIVAL_INVERSESQRT 1
#endif
bool lightArrival(ShadeLight l, vec3 P, vec3 N, ShadeSettings st, out vec3 L, out float attenuation) {
    L = -l.direction;
    attenuation = 1.0;
#ifdef LR_HAS_POSITIONAL
    if (lightTypeOf(l) != LR_LIGHT_DIRECTIONAL) {
        vec3 toLight = l.position - P;
#ifdef LR_B3
        // B3 early-out: beyond a bounded falloff's range (squared distances, before any sqrt) the light
        // adds exactly zero.
        float d2 = dot(toLight, toLight);
        if (l.range > 1e-18 && lightIsBounded(l) && d2 * (st.distanceScale * st.distanceScale) >= l.range * l.range)
            return false;
#endif
#ifdef LR_ARRIVAL_INVERSESQRT
        float t2 = dot(toLight, toLight);
        float inv = inversesqrt(t2);
        bool inRange = t2 > 1e-30 && t2 < 1e30;
        L = inRange ? toLight * inv : N;
        float d = (inRange ? t2 * inv : (!(t2 <= 1.0) ? kFloatMax : 0.0)) * st.distanceScale;
#else
        L = safeNormalize(toLight, N);  // a light on the surface shines along the normal
        float d = dot(toLight, L) * st.distanceScale;
#endif
        d = abs(d) <= kFloatMax ? d : kFloatMax;  // an overflowing distance: every falloff gives its limit
#ifdef LR_HAS_LIGHT_SPOT
        float cosTheta = dot(-L, l.direction);
#ifdef LR_B3
        // ... and outside the cone (cosine space, before the falloff and the cone are evaluated).
        if (lightTypeOf(l) == LR_LIGHT_SPOT && cosTheta < l.cosOuter) return false;
#endif
#endif
        attenuation = evalFalloff(l, d);
#ifdef LR_HAS_LIGHT_SPOT
        if (lightTypeOf(l) == LR_LIGHT_SPOT) attenuation *= evalCone(l, cosTheta);
#endif
#ifdef LR_IES
        attenuation *= lrIes(l, -L);  // 1 for a light without a profile
#endif
        return attenuation > 0.0;
    }
#endif
    return true;
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
    vec3 L;
    float attenuation;
    if (!lightArrival(l, s.position, N, st, L, attenuation)) return vec3(0.0);
#ifdef LR_GOBO
    lrApplyGobo(l, L);
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
    vec3 direct = l.color * (p.cDiff * ((1.0 - kDielectricF0) * a.diffuse)) + l.specular * (p.f0 * a.scaleI + vec3(a.biasI));
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
    bool arrives = lightArrival(l, s.position, s.normal, st, L, attenuation);
#ifdef LR_GOBO
    lrApplyGobo(l, L);
#endif
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
#ifdef LR_LIGHT_LINKING
            ShadeLight l = loadLight(i);
            if (lightLinked(l)) sum += shadeLightPbr(l, s, st, V, p);
#else
            sum += shadeLightPbr(loadLight(i), s, st, V, p);
#endif
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
#ifdef LR_LIGHT_LINKING
            ShadeLight l = loadLight(i);
            if (lightLinked(l)) sum += shadeLight(l, s, st, V);
#else
            sum += shadeLight(loadLight(i), s, st, V);
#endif
        } while (++i < uLightCount);
    }
#endif
    return sum + s.emissive;
#endif
}

#endif  // LR_SHADING
