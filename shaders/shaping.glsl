// IES profiles and gobos in GLSL 330, the twin of src/core/ies.h (iesCandelaToward) and src/core/gobo.h
// (gobo::tint) as the raster reads them (src/render/lightshapinggl.h: the profiles resampled on a grid,
// the images as they are). Only in programs that shade a rig with either (LR_IES, LR_GOBO); after
// shadetypes.glsl.
#ifdef LR_SHADING

#ifdef LR_IES
uniform sampler2DArray uIes;  // I / peak: s = horizontal angle / 360 (wraps), t = vertical angle / 180

// The attenuation factor of the light's profile toward w (unit, from the light): iesScale × I(θ, φ) as
// core's lightArrival applies it; 1 for a light without one. θ = acos(w·nadir), φ = atan2(w·y, w·x) with
// y = x × nadir (φ = 0 where both vanish, as core), both in degrees.
float lrIes(ShadeLight l, vec3 w) {
    if (l.iesLayer < 0) return 1.0;
    float theta = degrees(acos(clamp(dot(w, l.iesNadir), -1.0, 1.0)));
    float px = dot(w, l.iesX), py = dot(w, cross(l.iesX, l.iesNadir));
    float phi = (px == 0.0 && py == 0.0) ? 0.0 : degrees(atan(py, px));
    phi = phi < 0.0 ? phi + 360.0 : phi;
    // Grid nodes at texel centres: vertical j × LR_IES_STEP_V, horizontal i × LR_IES_STEP_H.
    vec2 st = vec2((phi / LR_IES_STEP_H + 0.5) / float(LR_IES_GRID_H), (theta / LR_IES_STEP_V + 0.5) / float(LR_IES_GRID_V));
    return l.iesScale * texture(uIes, vec3(st, float(l.iesLayer))).r;
}
#endif

#ifdef LR_GOBO
uniform sampler2DArray uGobos;  // RGB transmission, each image in its layer's corner, row 0 its top

// The gobo's tint for L (surface to light): 1 without one; black behind the light and outside the square
// |x|, |y| <= h; inside, the image bilinear between texel centres, clamped to its own edge texels.
vec3 lrGoboTint(ShadeLight l, vec3 L) {
    if (l.goboLayer < 0) return vec3(1.0);
    vec3 w = -L;
    float c = dot(w, l.direction);
    if (!(c > 0.0) || !(l.goboHalf > 0.0)) return vec3(0.0);
    vec2 xy = vec2(dot(w, l.goboX), dot(w, l.goboY)) / (c * l.goboHalf);
    if (!(abs(xy.x) <= 1.0 && abs(xy.y) <= 1.0)) return vec3(0.0);
    vec2 uv = vec2(xy.x + 1.0, 1.0 - xy.y) * 0.5;
    vec2 texel = clamp(uv * l.goboSize, vec2(0.5), l.goboSize - 0.5);
    return texture(uGobos, vec3(texel * l.goboInvArray, float(l.goboLayer))).rgb;
}

// The light as the surface sees it through its gobo: core multiplies the light's whole contribution
// (direct and its own ambient term) by the tint, which is the same as tinting its three colours.
void lrApplyGobo(inout ShadeLight l, vec3 L) {
    vec3 t = lrGoboTint(l, L);
    l.color *= t;
    l.specular *= t;
    l.ambient *= t;
}
#endif

#endif  // LR_SHADING
