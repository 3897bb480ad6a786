// The environment behind the model (pass_background.cpp): a full-screen triangle on the far plane, drawn
// where no surface was (depth test LEQUAL against the cleared depth 1). Each pixel looks up the
// environment along its view ray: Visible at the chain's level 0 (B-spline filtered: no stair steps when
// magnified), Blurred at lod = blur · 5 (a GGX roughness). The same exposure, tone map and encoding as
// every lit fragment of the frame.
uniform mat4 uViewFromClip;  // the inverse of the frame's (tile's) projection
uniform vec2 uTargetSize;    // pixels
uniform float uBackgroundLod;
#ifdef LR_OUTPUT_DISPLAY
uniform float uExposureScale;
#endif

out vec4 oColor;

void main() {
    vec2 ndc = gl_FragCoord.xy / uTargetSize * 2.0 - 1.0;
    // The ray through the pixel: near point to far point (perspective and orthographic alike).
    vec4 nearPoint = uViewFromClip * vec4(ndc, -1.0, 1.0);
    vec4 farPoint = uViewFromClip * vec4(ndc, 1.0, 1.0);
    vec3 ray = farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w;
    vec3 dir = safeNormalize(ray, vec3(0.0, 0.0, -1.0));
    vec3 radiance = uBackgroundLod > 0.0 ? envRadiance(dir, uBackgroundLod) : envRadianceSmooth(dir);
#ifdef LR_OUTPUT_DISPLAY
    oColor = vec4(displayEncode(radiance, uExposureScale, LR_TONE_MAP), 1.0);
#else
    oColor = vec4(radiance, 1.0);
#endif
}
