// Environment lighting (issue 15; docs/lighting-models.md "Environment"): what the rig's environment adds
// at a surface, approximating the definition above `struct Environment` in src/core/environment.h (the
// limit of one directional light per texel) with the prefiltered environment of src/render/environmentgl.h:
//   physically based  occlusion · (c_diff (1 − F0_dielectric) W · E(n)/π + L_spec(R, roughness) · (F0·A + B))
//                      (split sum; A, B, W from the table at (n·v, roughness), core/envbrdf.h);
//   classic            albedo · E(n)/π (Lambert; half-Lambert: the SH9 with the band weights 4/3, 1, 8/15)
//                      + ks · N_s · L_spec(R, roughness_s) (Phong / Blinn-Phong: the GGX level whose lobe
//                      matches the power, × the power lobe's integral N_s over π).
// E(n): the irradiance map in the exact tier, the SH9 in the balanced and fast tiers (per pixel in every
// tier). Everything × 2^EV (uEnvScale); the image is looked up in its own frame (uEnvFromView: view -> world
// -> R_y(−rotation)). Compiled only under LR_ENVIRONMENT (lit programs) or LR_ENVIRONMENT_BACKGROUND (the
// background pass): every other program's text is unchanged.
#if defined(LR_ENVIRONMENT) || defined(LR_ENVIRONMENT_BACKGROUND)

const float kEnvInvPi = 0.318309886183791;
const float kEnvRoughnessLods = 5.0;  // kSpecularLevels − 1: level k is GGX roughness k / 5

uniform sampler2D uEnvSpecular;  // the GGX chain, one mip level per roughness step
uniform mat3 uEnvFromView;       // view-space direction -> the image's own frame
uniform float uEnvScale;         // 2^intensity
uniform float uEnvMaxLod;        // the chain's last level

// core/environment.h equirectUv: u = atan2(d.z, d.x)/2π + 1/2, v = 1/2 − asin(d.y)/π (d unit, image frame;
// straight up or down the azimuth is 0 instead of atan(0, 0)).
vec2 envUv(vec3 d) {
    float azimuth = (d.x == 0.0 && d.z == 0.0) ? 0.0 : atan(d.z, d.x);
    return vec2(azimuth * (0.5 * kEnvInvPi) + 0.5, 0.5 - asin(clamp(d.y, -1.0, 1.0)) * kEnvInvPi);
}

// The environment's radiance (× 2^EV) towards view-space direction `dirView`, prefiltered at chain level
// `lod` (explicit: the azimuth's seam would make implicit derivatives pick the coarsest level).
vec3 envRadiance(vec3 dirView, float lod) {
    vec3 d = safeNormalize(uEnvFromView * dirView, vec3(0.0, 1.0, 0.0));
    float l = lod > 0.0 ? (lod < uEnvMaxLod ? lod : uEnvMaxLod) : 0.0;
    return uEnvScale * textureLod(uEnvSpecular, envUv(d), l).rgb;
}

#ifdef LR_ENVIRONMENT_BACKGROUND
// The sharp background (chain level 0) filtered with a cubic B-spline instead of bilinearly: magnified,
// a bilinear lookup's kinks at every texel border turn a bright edge into stair steps once tone mapped; the
// B-spline is smooth across texels (four bilinear taps, Sigg & Hadwiger 2005, GPU Gems 2 ch. 20).
vec3 envRadianceSmooth(vec3 dirView) {
    vec3 d = safeNormalize(uEnvFromView * dirView, vec3(0.0, 1.0, 0.0));
    vec2 size = vec2(textureSize(uEnvSpecular, 0));
    vec2 p = envUv(d) * size - 0.5;
    vec2 i = floor(p);
    vec2 f = p - i;
    vec2 f2 = f * f, f3 = f2 * f;
    vec2 w0 = (1.0 - 3.0 * f + 3.0 * f2 - f3) / 6.0;
    vec2 w1 = (4.0 - 6.0 * f2 + 3.0 * f3) / 6.0;
    vec2 w2 = (1.0 + 3.0 * f + 3.0 * f2 - 3.0 * f3) / 6.0;
    vec2 w3 = f3 / 6.0;
    vec2 g0 = w0 + w1, g1 = w2 + w3;
    vec2 h0 = (i - 0.5 + w1 / g0) / size;  // texel centres at (i + 0.5) / size
    vec2 h1 = (i + 1.5 + w3 / g1) / size;
    vec3 c = g0.y * (g0.x * textureLod(uEnvSpecular, vec2(h0.x, h0.y), 0.0).rgb +
                     g1.x * textureLod(uEnvSpecular, vec2(h1.x, h0.y), 0.0).rgb) +
             g1.y * (g0.x * textureLod(uEnvSpecular, vec2(h0.x, h1.y), 0.0).rgb +
                     g1.x * textureLod(uEnvSpecular, vec2(h1.x, h1.y), 0.0).rgb);
    return uEnvScale * c;
}
#endif

#endif

#if defined(LR_ENVIRONMENT) && defined(LR_SHADING)

uniform sampler2D uEnvIrradiance;  // E(n), equirectangular
uniform sampler2D uEnvDfg;         // (A, B, W) at (n·v, roughness)
uniform vec3 uEnvSh[9];            // irradiance SH9 (core/environment.h shBasis9's order)
uniform vec3 uEnvBands;            // per-band weights over the cosine lobe's: Lambert 1, half-Lambert 4/3, 1, 8/15
uniform float uEnvMapWeight;       // exact tier: 1 reads E from the map (Lambert), 0 from the SH9 (half-Lambert)

// Σ bands[l] · sh[i] · Y_i(d): the cosine lobe's irradiance, or another zonal kernel's by its band weights.
vec3 envSh(vec3 d, vec3 bands) {
    vec3 b0 = 0.282095 * uEnvSh[0];
    vec3 b1 = 0.488603 * (d.y * uEnvSh[1] + d.z * uEnvSh[2] + d.x * uEnvSh[3]);
    vec3 b2 = 1.092548 * (d.x * d.y * uEnvSh[4] + d.y * d.z * uEnvSh[5] + d.x * d.z * uEnvSh[7]) +
              0.315392 * (3.0 * d.z * d.z - 1.0) * uEnvSh[6] + 0.546274 * (d.x * d.x - d.y * d.y) * uEnvSh[8];
    vec3 e = bands.x * b0 + bands.y * b1 + bands.z * b2;
    return max(e, vec3(0.0));  // the truncated series can dip below 0 under a bright spot's opposite side
}

// The irradiance (× 2^EV) at view-space unit normal n: the map (exact tier, mapWeight 1) or the SH9.
vec3 envIrradiance(vec3 nView, vec3 bands, float mapWeight) {
    vec3 d = safeNormalize(uEnvFromView * nView, vec3(0.0, 1.0, 0.0));
    vec3 e = envSh(d, bands);
#ifdef LR_QUALITY_EXACT
    e = mix(e, textureLod(uEnvIrradiance, envUv(d), 0.0).rgb, mapWeight);
#endif
    return uEnvScale * e;
}

// What the environment adds at the surface (linear radiance), V the unit vector to the viewer.
vec3 shadeEnvironment(Surface s, vec3 V) {
    vec3 N = s.normal;
    float nDotV = dot(N, V);
    vec3 R = 2.0 * nDotV * N - V;  // reflect(−V, N)
#ifdef LR_PBR
    PbrSurface p = pbrSurface(s);
    float roughness = sqrt(p.alpha);  // clamped as the lights' lobe: [kMinRoughness, 1]
    float nv = nDotV > 1e-4 ? (nDotV < 1.0 ? nDotV : 1.0) : 1e-4;
    vec3 dfg = textureLod(uEnvDfg, vec2(nv, roughness), 0.0).rgb;
    vec3 diffuse = p.cDiff * ((1.0 - kDielectricF0) * dfg.b * kEnvInvPi) * envIrradiance(N, vec3(1.0), 1.0);
    // The split sum prefiltered its levels with N = V = R; a rough lobe's energy leans from R towards N.
    // Its dominant direction (Lagarde & de Rousiers 2014, "Moving Frostbite to PBR", listing 22, α = p.alpha).
    float smoothness = 1.0 - p.alpha;
    vec3 Rd = safeNormalize(mix(N, R, smoothness * (sqrt(smoothness) + p.alpha)), R);
    // Between two levels the lobe's width follows α = roughness², not roughness: blend linearly in α
    // (level k holds roughness k / kEnvRoughnessLods), so a nearly smooth surface takes little of the next,
    // far blurrier level.
    float rl = roughness * kEnvRoughnessLods;
    float k = floor(rl);
    float lod = k + (rl * rl - k * k) / (2.0 * k + 1.0);
    vec3 specular = envRadiance(Rd, lod) * (p.f0 * dfg.r + dfg.g);
    return saturate(s.occlusion) * (diffuse + specular);
#else
    vec3 diffuse = s.albedo * kEnvInvPi * envIrradiance(N, uEnvBands, uEnvMapWeight);
    float n = s.shininess > 0.0 ? s.shininess : 0.0;
#if LR_SPECULAR == LR_SPECULAR_PHONG
    // ∫_{r·ω>0} (r·ω)^n dω / π = 2/(n + 1); the Phong lobe about r ≈ a Blinn lobe of power 4n about n.
    float blinn = 4.0 * n;
    float lobe = 2.0 / (n + 1.0);
#else
    // ∫_{n·ω>0} (n·h)^n dω / π at v = n: 8/(n + 2) · (1 − 2^−(n+2)/2) (ω at twice h's angle).
    float blinn = n;
    float lobe = 8.0 / (n + 2.0) * (1.0 - exp2(-0.5 * (n + 2.0)));
#endif
    // Karis 2013: GGX α² ≈ 2/(Blinn power + 2); the chain's roughness is √α.
    float roughness = sqrt(sqrt(2.0 / (blinn + 2.0)));
    vec3 specular = s.specular * (lobe * envRadiance(R, roughness * kEnvRoughnessLods));
    return diffuse + specular;
#endif
}

#endif
