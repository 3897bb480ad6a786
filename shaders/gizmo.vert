// Light gizmos and the grid: lines and point sprites in view space (built on the CPU in double precision
// each frame), drawn over the tone-mapped image.
layout(location = 0) in vec3 aPosition;  // view space
layout(location = 1) in vec4 aColor;     // display (sRGB-encoded) colour, straight alpha
layout(location = 2) in vec2 aPoint;     // point sprites: size in pixels, shape (+8 when selected)

uniform mat4 uProjection;
uniform vec2 uHaloOffset;  // the halo passes (gizmo.frag): this many NDC units aside; 0 otherwise

out vec4 vColor;
out float vDistance;  // from the eye
flat out int vShape;

void main() {
    gl_Position = uProjection * vec4(aPosition, 1.0);
    gl_Position.xy += uHaloOffset * gl_Position.w;
    vDistance = length(aPosition);
    gl_PointSize = aPoint.x;
    vColor = aColor;
    vShape = int(aPoint.y + 0.5);
}
