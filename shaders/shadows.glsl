// Shadows (docs/lighting-models.md "Shadows"; src/render/shadowmaps.h builds the maps and the records).
// Compiled only into programs whose rig has a casting light (LR_SHADOWS); otherwise this file is empty and
// a program's text is what it was before shadows. After shade.glsl, which calls lrShadow() (declared
// there) on the direct terms of every light that has a shadow slot.
//
// Each caster has LR_SHADOW_TEXELS vec4s in uShadowRecords (lightset.cpp; uniforms, as a texelFetch costs
// a software rasteriser much more), and its light's type texel says its slot (shadetypes.glsl loadLight):
//   0-3: the view -> light matrix (columns): light clip space (perspective, orthographic), or the
//        light-centred, world-aligned frame (cube: the face is chosen here)
//   4: layer, kind (0 perspective, 1 orthographic, 2 cube), near, far
//   5: texel scale (world size of a texel at distance 1, or anywhere for orthographic), bias (texels),
//      normal offset (texels), emitter (diameter in world units, or 2·tan(angle/2) for orthographic)
//   6: the light's index in uLights (-1: not uploaded), tan of the half-angle (perspective, cube),
//      resolution, 0
//   7: the blocker search's emitter (as 5.w; an area light's largest extent), PCSS's radius cap in texels
//      (kMaxFilterTexels, or shadowmaps.h kAreaFilterTexels for area lights), layers (a cube: 6, or 5 for a
//      one-sided area light, whose face 5 behind its plane is not drawn), 0
#if defined(LR_SHADING) && defined(LR_SHADOWS)

uniform sampler2DArrayShadow uShadowMaps;  // compare LEQUAL, bilinear: each tap is a 2×2 PCF
uniform sampler2DArray uShadowDepths;      // the same array, raw depths (PCSS's blocker search)
uniform int uShadowCount;
uniform vec4 uShadowRecords[LR_MAX_SHADOW_CASTERS * LR_SHADOW_TEXELS];

bool lrShadowsOn = true;  // the shadow catcher switches them off to measure the unshadowed light

const float kMaxFilterTexels = 24.0;  // PCSS's search and filter radius at most (the cube faces' margin)
                                      // for point, spot and directional lights; area lights: record 7.y

struct ShadowRecord {
    mat4 m;
    float layer;
    int kind;
    float znear, zfar;
    float texelScale, bias, normalOffset, emitter;
    float tanHalf, resolution;
    float searchEmitter, maxFilter, faces;
};

ShadowRecord loadShadow(int slot) {
    int base = slot * LR_SHADOW_TEXELS;
    ShadowRecord r;
    r.m = mat4(uShadowRecords[base], uShadowRecords[base + 1], uShadowRecords[base + 2], uShadowRecords[base + 3]);
    vec4 a = uShadowRecords[base + 4];
    vec4 b = uShadowRecords[base + 5];
    vec4 c = uShadowRecords[base + 6];
    vec4 e = uShadowRecords[base + 7];
    r.layer = a.x;
    r.kind = int(a.y);
    r.znear = a.z;
    r.zfar = a.w;
    r.texelScale = b.x;
    r.bias = b.y;
    r.normalOffset = b.z;
    r.emitter = b.w;
    r.tanHalf = c.y;
    r.resolution = c.z;
    r.searchEmitter = e.x;
    r.maxFilter = e.y;
    r.faces = e.z;
    return r;
}

// The cube faces (shadowmaps.cpp kFaces): the axis each looks along, its right and up vectors, in the
// cube's frame (world axes; an area light's own, +Z where it shines: the record's matrix turns into it).
const vec3 kFaceForward[6] = vec3[6](vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0), vec3(0, -1, 0),
                                     vec3(0, 0, 1), vec3(0, 0, -1));
const vec3 kFaceRight[6] = vec3[6](vec3(0, 0, 1), vec3(0, 0, -1), vec3(1, 0, 0), vec3(-1, 0, 0),
                                   vec3(-1, 0, 0), vec3(1, 0, 0));
const vec3 kFaceUp[6] = vec3[6](vec3(0, 1, 0), vec3(0, 1, 0), vec3(0, 0, 1), vec3(0, 0, 1), vec3(0, 1, 0),
                                vec3(0, 1, 0));

// A perspective map's depth (0..1) at distance t along its axis, and back.
float perspectiveDepth(ShadowRecord r, float t) {
    float n = r.znear, f = r.zfar;
    return 0.5 * ((f + n) / (f - n) - 2.0 * f * n / ((f - n) * max(t, 1e-30))) + 0.5;
}
float linearDepth(ShadowRecord r, float d) {
    if (r.kind == 1) return r.znear + d * (r.zfar - r.znear);
    float n = r.znear, f = r.zfar;
    return 2.0 * f * n / ((f + n) - (2.0 * d - 1.0) * (f - n));
}

struct ShadowCoord {
    vec3 uvLayer;  // map coordinates and layer
    float depth;   // the map's depth of the point (> 1 beyond the far plane)
    float dist;    // its distance along the light's axis (world units)
    bool valid;    // false behind a perspective map's eye
};

ShadowCoord shadowCoord(ShadowRecord r, vec3 P) {
    ShadowCoord c;
    c.valid = true;
#ifdef LR_SHADOW_CUBE  // some caster is a point light (shadergen.h RigFeatures::cubeShadows)
    if (r.kind == 2) {
        vec3 d = (r.m * vec4(P, 1.0)).xyz;
        vec3 a = abs(d);
        int face = a.x >= a.y && a.x >= a.z ? (d.x >= 0.0 ? 0 : 1) : (a.y >= a.z ? (d.y >= 0.0 ? 2 : 3) : (d.z >= 0.0 ? 4 : 5));
        float t = max(dot(kFaceForward[face], d), 1e-30);
        vec2 xy = vec2(dot(kFaceRight[face], d), dot(kFaceUp[face], d)) / (t * r.tanHalf);
        c.uvLayer = vec3(xy * 0.5 + 0.5, r.layer + float(face));
        c.depth = perspectiveDepth(r, t);
        c.dist = t;
        c.valid = float(face) < r.faces;  // behind a one-sided area light: no layer, and no light
        return c;
    }
#endif
    vec4 h = r.m * vec4(P, 1.0);
    c.valid = r.kind == 1 || h.w > 0.0;
    vec3 ndc = h.xyz / (r.kind == 1 ? 1.0 : max(h.w, 1e-30));
    c.uvLayer = vec3(ndc.xy * 0.5 + 0.5, r.layer);
    c.depth = ndc.z * 0.5 + 0.5;
    c.dist = r.kind == 1 ? r.znear + c.depth * (r.zfar - r.znear) : h.w;
    return c;
}

float shadowTap(vec3 uvLayer, float ref) { return texture(uShadowMaps, vec4(uvLayer, ref)); }

#if (defined(LR_QUALITY_BALANCED) || defined(LR_QUALITY_EXACT)) && defined(LR_SHADOW_SOFT)
const vec2 kPoisson[16] = vec2[16](
    vec2(-0.94201624, -0.39906216), vec2(0.94558609, -0.76890725), vec2(-0.094184101, -0.92938870),
    vec2(0.34495938, 0.29387760), vec2(-0.91588581, 0.45771432), vec2(-0.81544232, -0.87912464),
    vec2(-0.38277543, 0.27676845), vec2(0.97484398, 0.75648379), vec2(0.44323325, -0.97511554),
    vec2(0.53742981, -0.47373420), vec2(-0.26496911, -0.41893023), vec2(0.79197514, 0.19090188),
    vec2(-0.24188840, 0.99706507), vec2(-0.81409955, 0.91437590), vec2(0.19984126, 0.78641367),
    vec2(0.14383161, -0.14100790));

// The receiver plane's depth change per unit of map uv (receiver-plane depth bias, Isidoro 2006): two
// tangents of the surface (4 texels long) projected into the map; a filter tap at uv offset o then
// compares ref + dot(slope, o), the depth the receiver itself has there, so a wide kernel on a surface
// the light grazes does not shadow the surface with itself. Zero where the surface is edge-on to the map
// or the tangents leave the cube face.
vec2 receiverSlope(ShadowRecord r, vec3 P, vec3 N, ShadowCoord c, float texel) {
    vec3 t1 = safeNormalize(cross(N, abs(N.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)), vec3(1.0, 0.0, 0.0));
    vec3 t2 = cross(N, t1);
    ShadowCoord a = shadowCoord(r, P + t1 * (4.0 * texel)), b = shadowCoord(r, P + t2 * (4.0 * texel));
    vec2 du1 = a.uvLayer.xy - c.uvLayer.xy, du2 = b.uvLayer.xy - c.uvLayer.xy;
    float dd1 = a.depth - c.depth, dd2 = b.depth - c.depth;
    float det = du1.x * du2.y - du1.y * du2.x;
    if (!(abs(det) > 1e-14) || a.uvLayer.z != c.uvLayer.z || b.uvLayer.z != c.uvLayer.z) return vec2(0.0);
    return vec2(dd1 * du2.y - dd2 * du1.y, dd2 * du1.x - dd1 * du2.x) / det;
}

// One bilinear compare tap at uv offset o from the receiver, against the receiver plane's depth there.
float shadowTapAt(ShadowCoord c, float ref, vec2 slope, vec2 o) {
    return shadowTap(c.uvLayer + vec3(o, 0.0), min(ref + dot(slope, o), 1.0));
}

// Balanced: 3×3 bilinear compare taps a texel apart (a 4×4-texel tent), a row per pass of a loop that
// a block of pixels which needs none of them leaves after one (as shadowPcss below).
float shadowPcf3x3(ShadowCoord c, float ref, vec2 slope, float texelUv, bool needed) {
    float v = 0.0;
    int rows = needed ? 3 : 0, row = 0;
    do {
        float y = float(row - 1);
        v += shadowTapAt(c, ref, slope, vec2(-1.0, y) * texelUv);
        v += shadowTapAt(c, ref, slope, vec2(0.0, y) * texelUv);
        v += shadowTapAt(c, ref, slope, vec2(1.0, y) * texelUv);
    } while (++row < rows);
    return v / 9.0;
}

// kPoisson[4·g + k] (k a constant) for a group g that varies at run time: selects between constants,
// since llvmpipe reads an array indexed by a variable lane by lane, from memory.
#define LR_POISSON(g, k) ((g) == 0 ? kPoisson[k] : (g) == 1 ? kPoisson[4 + (k)] : (g) == 2 ? kPoisson[8 + (k)] : kPoisson[12 + (k)])

// One raw tap of PCSS's blocker search at uv offset o: a blocker adds its distance to sum and 1 to n.
void blockerTap(ShadowRecord r, ShadowCoord c, float ref, vec2 slope, vec2 o, inout float sum, inout float n) {
    float d = texture(uShadowDepths, c.uvLayer + vec3(o, 0.0)).r;
    if (d < ref + dot(slope, o)) {
        sum += linearDepth(r, d);
        n += 1.0;
    }
}

// Exact: percentage-closer soft shadows (Fernando 2005). The blockers' mean distance dB (8 raw taps) in the
// region of the map the emitter can see past; the penumbra's half-width at the receiver (distance dR) is
// emitter·(dR − dB)/(2·dB) (perspective; orthographic: emitter·(dR − dB)/2 with emitter = 2·tan(angle/2)),
// in texels of the receiver's footprint; then 16 bilinear compare taps over that radius.
//
// An area light's kernels reach kAreaFilterTexels: 16 taps that far apart would band, so its Poisson disk
// turns by a per-texel angle (interleaved gradient noise of the map position: noise instead of bands);
// other lights' turn is 0 (their kernels are exactly as before).
//
// The taps run in groups of four inside loops whose length is 0 where the result is not used (`needed`
// false) or known (no blocker: fully lit). A software rasteriser runs a whole block of pixels through a
// loop until none of them is left in it, so a block where no pixel needs the filter pays one group
// instead of all (docs/performance.md, session 15). The taps and their order are those of a plain loop.
float shadowPcss(ShadowRecord r, ShadowCoord c, float ref, vec2 slope, float texelUv, bool needed) {
    float dR = max(c.dist, 1e-30);
    float footprint = r.kind == 1 ? r.texelScale : r.texelScale * dR;  // world size of a texel here
    float reach = max(dR - r.znear, 0.0);
    float search = 0.5 * r.searchEmitter * reach / (r.kind == 1 ? footprint : r.znear * r.texelScale * dR);
    search = clamp(search, 1.0, r.maxFilter);
    vec2 cell = floor(c.uvLayer.xy * (4.0 * r.resolution));
    float turn = r.maxFilter > kMaxFilterTexels ? 6.2831853 * fract(52.9829189 * fract(dot(cell, vec2(0.06711056, 0.00583715)))) : 0.0;
    mat2 spin = mat2(cos(turn), sin(turn), -sin(turn), cos(turn));
    float sum = 0.0, n = 0.0;
    // 8 of the 16 points (the even ones; the mean blocker distance needs fewer), in two groups of four.
    float searchScale = search * texelUv;
    int groups = needed ? 2 : 0, g = 0;
    do {
        blockerTap(r, c, ref, slope, spin * LR_POISSON(2 * g, 0) * searchScale, sum, n);
        blockerTap(r, c, ref, slope, spin * LR_POISSON(2 * g, 2) * searchScale, sum, n);
        blockerTap(r, c, ref, slope, spin * LR_POISSON(2 * g + 1, 0) * searchScale, sum, n);
        blockerTap(r, c, ref, slope, spin * LR_POISSON(2 * g + 1, 2) * searchScale, sum, n);
    } while (++g < groups);
    float dB = max(sum / max(n, 1.0), 1e-30);
    float penumbra = 0.5 * r.emitter * max(dR - dB, 0.0) / (r.kind == 1 ? 1.0 : dB);  // world, half-width
    float radius = clamp(penumbra / footprint, 0.5, r.maxFilter);
    float v = 0.0;
    float filterScale = radius * texelUv;
    groups = needed && n > 0.0 ? 4 : 0;
    g = 0;
    do {
        v += shadowTapAt(c, ref, slope, spin * LR_POISSON(g, 0) * filterScale);
        v += shadowTapAt(c, ref, slope, spin * LR_POISSON(g, 1) * filterScale);
        v += shadowTapAt(c, ref, slope, spin * LR_POISSON(g, 2) * filterScale);
        v += shadowTapAt(c, ref, slope, spin * LR_POISSON(g, 3) * filterScale);
    } while (++g < groups);
    return n == 0.0 ? 1.0 : v / 16.0;
}
#endif

// The share of light l that reaches the surface (1: lit, 0: in shadow); L points to the light. The
// receiver moves off its surface by the normal offset (texels of its footprint, along the normal on the
// light's side: an effective depth bias of offset/cos θ, growing where the light grazes) and toward the
// light by the constant bias; glPolygonOffset adds the slope-scaled term when the map is drawn.
// An area light's map is centred on its emitter, so its caller passes L towards the centre.
float lrShadow(ShadeLight l, Surface s, vec3 L, bool needed) {
    if (!lrShadowsOn || l.shadow <= 0) return 1.0;
    ShadowRecord r = loadShadow(l.shadow - 1);
    ShadowCoord c0 = shadowCoord(r, s.position);
    if (!c0.valid) return 1.0;  // behind a spot's map: outside its cone
    float texel = r.kind == 1 ? r.texelScale : r.texelScale * max(c0.dist, 0.0);
    float nDotL = dot(s.normal, L);
    vec3 side = nDotL >= 0.0 ? s.normal : -s.normal;
    vec3 P = s.position + side * (r.normalOffset * texel) + L * (r.bias * texel);
    ShadowCoord c = shadowCoord(r, P);
    if (!c.valid) return 1.0;
    float ref = min(c.depth, 1.0);  // beyond the far plane: behind every occluder the map holds
    float texelUv = 1.0 / r.resolution;
    // Filters only where some caster has an extent (LR_SHADOW_SOFT): llvmpipe would run them for point
    // emitters too, whose result it then discards.
#if defined(LR_QUALITY_EXACT) && defined(LR_SHADOW_SOFT)
    if (r.emitter > 0.0) return shadowPcss(r, c, ref, receiverSlope(r, P, side, c, texel), texelUv, needed);
#elif defined(LR_QUALITY_BALANCED) && defined(LR_SHADOW_SOFT)
    if (r.emitter > 0.0) return shadowPcf3x3(c, ref, receiverSlope(r, P, side, c, texel), texelUv, needed);
#endif
    return shadowTap(c.uvLayer, ref);  // a point emitter, or the fast tier: one bilinear compare tap
}

#ifdef LR_QUALITY_FAST
// The fast tier lights the vertices with the lights that cast no shadow (shadevertex.glsl shadeVertex skips
// the others) and the casting lights here, per pixel, so a shadow keeps its shape on large triangles.
vec3 shadeCastingLights(Surface s, ShadeSettings st) {
    vec3 V = viewVector(st, s.position);
    vec3 sum = vec3(0.0);
#ifdef LR_PBR
    PbrSurface p = pbrSurfaceLit(s, V);
#endif
    if (uShadowCount > 0) {  // do-while: see shadeSurface (shade.glsl)
        int k = 0;
        do {
            int index = int(uShadowRecords[k * LR_SHADOW_TEXELS + 6].x);
            if (index >= 0) {
#ifdef LR_LIGHT_LINKING
                ShadeLight l = loadLight(index);
                if (lightLinked(l))
#ifdef LR_PBR
                    sum += shadeLightPbr(l, s, st, V, p);
#else
                    sum += shadeLight(l, s, st, V);
#endif
#else
#ifdef LR_PBR
                sum += shadeLightPbr(loadLight(index), s, st, V, p);
#else
                sum += shadeLight(loadLight(index), s, st, V);
#endif
#endif
            }
        } while (++k < uShadowCount);
    }
    return sum;
}
#endif

#endif
