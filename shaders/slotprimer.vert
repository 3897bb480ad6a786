// The sampler-slot primer (pass_geometry.cpp primeSamplerSlots): every vertex at one point, so its
// triangle covers no pixel; the draw only binds state.
void main() {
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
