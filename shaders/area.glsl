// Rect and disk lights in GLSL 330, the twin of src/core/lighting_area.h and lighting_area_poly.h: the
// polygon integrals, the classic area terms and the LTC lookup of the physically based ones. Compiled only
// where the rig has an area light (LR_HAS_LIGHT_RECT / LR_HAS_LIGHT_DISK); after shadetypes.glsl.
#ifdef LR_SHADING

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

#ifdef LR_BARN_DOORS
// The part of a rect P sees past its barn doors (core/barndoors.h windowLocal), in view units along its axes
// from its centre: (x0, x1, y0, y1), empty when x0 >= x1 or y0 >= y1; the whole rect without flaps.
vec4 barnWindow(ShadeLight l, vec3 P) {
    float hw = l.halfWidth, hh = l.halfHeight, d = l.barnDepth, e = l.barnExtent;
    vec4 whole = vec4(-hw, hw, -hh, hh);
    vec3 p = P - l.position;
    float pz = dot(p, l.direction);
    if (!(d > 0.0) || !(pz > 0.0)) return whole;
    float px = dot(p, l.axisX), py = dot(p, l.axisY);
    if (pz <= d) {  // between the emitter and the flaps' far edges: inside the walls or outside them
        float grow = e * (pz / d);
        return abs(px) <= hw + grow && abs(py) <= hh + grow ? whole : vec4(0.0);
    }
    float inv = 1.0 / (pz - d);
    float fx = (hw + e) * pz, fy = (hh + e) * pz;
    return vec4(max(-hw, (-fx - px * d) * inv), min(hw, (fx - px * d) * inv), max(-hh, (-fy - py * d) * inv),
                min(hh, (fy - py * d) * inv));
}
#endif

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
#ifdef LR_BARN_DOORS
        // Barn doors: the rectangle of the emitter P sees replaces it (nothing of it: nothing added).
        vec4 w = barnWindow(l, P);
        if (!(w.x < w.y) || !(w.z < w.w)) return o;
        vec3 ax = toLocal(f, l.axisX) * scale, ay = toLocal(f, l.axisY) * scale;
        vec3 p0 = cl + ax * w.x + ay * w.z, p1 = cl + ax * w.y + ay * w.z;
        vec3 p2 = cl + ax * w.y + ay * w.w, p3 = cl + ax * w.x + ay * w.w;
#else
        vec3 p0 = cl - xl - yl, p1 = cl + xl - yl, p2 = cl + xl + yl, p3 = cl - xl + yl;
#endif
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

// shadeAreaLightPbr's direct terms: diffuse = c_diff (1 − 0.04) (1 − w) D (per unit of colour), and the
// specular's LTC integral I × the lobe's norm n, split by Schlick's weight ws at the lobe's mean direction:
// specular = F0·scaleI + biasI with scaleI = (1 − ws)·n·I, biasI = ws·n·I.
struct AreaPbr {
    float diffuse;  // (1 − w)·D: × c_diff (1 − F0_dielectric)
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

#endif  // LR_SHADING
