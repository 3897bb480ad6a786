// A triangle covering the viewport, from gl_VertexID alone (no vertex buffer), on the far plane
// (window depth exactly 1): with depth test GL_GREATER it reaches only pixels a surface was drawn on.
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 1.0, 1.0);
}
