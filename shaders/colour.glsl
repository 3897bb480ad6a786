// Colour: tone mapping and sRGB encoding in GLSL 330, the twin of src/core/colour.h (same names, same
// guards), and the two clamps every shader file uses. Included first by every program that shades or
// displays (the tone-map pass includes only this file).
//
// The generator (src/render/shadergen.cpp) defines LR_TONEMAP_* and LR_TONE_MAP in the prelude.

const float kFloatMax = 3.402823466e+38;

// x clamped to [0, 1]; NaN -> 0.
float saturate(float x) { return x > 0.0 ? (x < 1.0 ? x : 1.0) : 0.0; }

// max(x, 0) that maps NaN to 0.
float positive(float x) { return x > 0.0 ? x : 0.0; }

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
