// Highlighted parts: a flat tint (display colour, straight alpha) blended over the image; where another
// surface hides the part (the resolved scene depth), a quarter of it, so a hidden part can still be seen.
uniform sampler2D uSceneDepth;
uniform vec4 uColor;

out vec4 oColor;

void main() {
    float sceneDepth = texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy), 0).r;
    bool hidden = gl_FragCoord.z > sceneDepth + 1e-6;
    oColor = vec4(uColor.rgb, hidden ? 0.25 * uColor.a : uColor.a);
}
