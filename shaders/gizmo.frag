// Gizmo fragments: parts hidden by the model (scene depth) are drawn faint, not dropped, so a light
// behind the model can still be found and picked. Point sprites draw the light icons:
// shape 0 point (disc), 1 spot (disc with a ring), 2 directional (sun with rays), 3 rim (hollow ring),
// 4 rect (square; also the size handles of a selected rect or disk light), 5 disk (disc in a square frame);
// +8: selected (white outline). Lines of shape 16 (kGridShape, gizmos.h) are the ground grid: hidden parts
// are dropped (the model occludes its ground) and the grid fades out with distance from the eye between
// uGridFade.x and uGridFade.y, as Blender's does. uHalo: the lines drawn dark, a pixel aside, under
// their own colour (pass_overlay.cpp), so a white gizmo stays visible on a bright environment; the
// icons have a dark rim of their own (a selected one a white ring inside it).
uniform sampler2D uSceneDepth;
uniform bool uHalo;
uniform bool uHasDepth;
uniform bool uPoints;
uniform vec2 uGridFade;

in vec4 vColor;
in float vDistance;
flat in int vShape;

out vec4 oColor;

void main() {
    vec4 c = vColor;
    if (uPoints) {
        vec2 p = gl_PointCoord * 2.0 - 1.0;
        float r = length(p);
        if (r > 1.0) discard;
        int shape = vShape & 7;
        bool selected = vShape >= 8;
        bool inside;
        if (shape == 2) {  // sun: disc and rays
            float angle = atan(p.y, p.x);
            inside = r < 0.45 || (r < 0.85 && abs(fract(angle * 8.0 / 6.2831853) - 0.5) > 0.32);
        } else if (shape == 3) {
            inside = r > 0.45 && r < 0.8;
        } else if (shape == 4 || shape == 5) {
            float box = max(abs(p.x), abs(p.y));
            inside = shape == 4 ? box < 0.55 : (r < 0.4 || (box > 0.5 && box < 0.62));
        } else if (shape == 1) {
            inside = r < 0.35 || (r > 0.55 && r < 0.8);
        } else {
            inside = r < 0.8;
        }
        if (inside) c = vec4(c.rgb, 1.0);
        else if (r > 0.8) c = selected && r < 0.92 ? vec4(1.0, 1.0, 1.0, 1.0) : vec4(0.0, 0.0, 0.0, 0.85);
        else c = vec4(0.0, 0.0, 0.0, 0.35);
    }
    bool grid = !uPoints && vShape == 16;
    if (uHalo) {
        if (grid) discard;
        c = vec4(0.0, 0.0, 0.0, 0.55 * c.a);
    }
    if (uHasDepth) {
        float sceneDepth = texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy), 0).r;
        if (gl_FragCoord.z > sceneDepth + 1e-6) {
            if (grid) discard;
            c.a *= 0.3;
        }
    }
    if (grid) c.a *= 1.0 - smoothstep(uGridFade.x, uGridFade.y, vDistance);
    oColor = c;
}
