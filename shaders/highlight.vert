// Highlighted parts (RenderSettings::highlightedParts, pass_overlay.cpp): a mesh's positions transformed
// exactly as mesh.vert transforms them, so its fragments meet the scene depth they were drawn with.
layout(location = 0) in vec3 aPosition;

uniform mat4 uModelView;
uniform mat4 uProjection;

void main() {
    vec4 p = uModelView * vec4(aPosition, 1.0);
    gl_Position = uProjection * p;
}
