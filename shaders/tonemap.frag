// Output pass: resolved HDR radiance (coverage in alpha) -> exposure -> tone map -> sRGB, over the
// background colour or with straight alpha when the background is transparent. Per channel, exactly
// lighting::toneMap and lighting::linearToSrgb.
uniform sampler2D uHdr;
uniform float uExposureScale;  // 2^EV
uniform vec3 uBackground;  // linear
uniform bool uTransparent;

out vec4 oColor;

vec3 mapped(vec3 radiance) {  // displayEncode() without the encoding: composited before it
    return toneMapRgb(LR_TONE_MAP, radiance * uExposureScale);
}

vec3 encode(vec3 c) { return vec3(linearToSrgb(c.r), linearToSrgb(c.g), linearToSrgb(c.b)); }

void main() {
    vec4 c = texelFetch(uHdr, ivec2(gl_FragCoord.xy), 0);
    float a = saturate(c.a);
    // The scene was cleared to zero: an MSAA edge pixel holds coverage * radiance. Un-premultiply,
    // tone map, then composite (tone mapping a blend of surface and nothing would darken edges).
    vec3 m = a > 0.0 ? mapped(c.rgb / a) : vec3(0.0);
    if (uTransparent)
        oColor = vec4(encode(m), a);
    else
        oColor = vec4(encode(m * a + uBackground * (1.0 - a)), 1.0);
}
