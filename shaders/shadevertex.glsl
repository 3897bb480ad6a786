// The fast tier in GLSL 330 (F1 and F1-PBR in docs/quality.md): shade.h's formulas evaluated at the
// vertices (shadeVertex, shadeVertexPbr) and finished per pixel (shadePixelPbr). Included only by the
// vertex-lit programs; after shade.glsl.
#ifdef LR_SHADING

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
    vec3 L;
    float attenuation;
    if (!lightArrival(l, P, N, st, L, attenuation)) return;
#ifdef LR_GOBO
    lrApplyGobo(l, L);
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
#ifdef LR_LIGHT_LINKING
            if (!lightLinked(l)) continue;  // to the loop's test
#endif
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
//   diffuse  = Σ attenuation·colour·(1 - F_d)·c_diff·cosTerm/π = c_diff·(1 - 0.04)·E,   E = Σ attenuation·colour·cosTerm·(1 - w)/π
// ((1 - F_d) = (1 - 0.04)(1 - w), the dielectric's Fresnel: lighting.h), so F0 and c_diff (base colour, metallic: textured) apply per pixel exactly;
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
    if (!lightArrival(l, s.position, s.normal, st, L, attenuation)) return;
#ifdef LR_GOBO
    lrApplyGobo(l, L);
#endif
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
#ifdef LR_LIGHT_LINKING
            if (!lightLinked(l)) continue;  // to the loop's test
#endif
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
    return pbrSceneAmbient(s, st, p) + p.cDiff * (1.0 - kDielectricF0) * E + p.f0 * (A - B) + B +
           p.cDiff * (ambient * occlusion) + added + s.emissive;
}
#endif  // LR_PBR
#endif  // LR_QUALITY_FAST

#endif  // LR_SHADING
