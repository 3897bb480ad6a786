// The sampler-slot primer (pass_geometry.cpp primeSamplerSlots): reads each of the first 20 sampler slots
// (all at texture unit 0, the renderer's 1x1 slot texture), so that Mesa binds the same sampler state into
// each of them before the lit passes. Never shades a pixel (slotprimer.vert).
uniform sampler2D uSlots[20];

out vec4 oColor;

void main() {
    vec4 s = vec4(0.0);
    s += texelFetch(uSlots[0], ivec2(0), 0);
    s += texelFetch(uSlots[1], ivec2(0), 0);
    s += texelFetch(uSlots[2], ivec2(0), 0);
    s += texelFetch(uSlots[3], ivec2(0), 0);
    s += texelFetch(uSlots[4], ivec2(0), 0);
    s += texelFetch(uSlots[5], ivec2(0), 0);
    s += texelFetch(uSlots[6], ivec2(0), 0);
    s += texelFetch(uSlots[7], ivec2(0), 0);
    s += texelFetch(uSlots[8], ivec2(0), 0);
    s += texelFetch(uSlots[9], ivec2(0), 0);
    s += texelFetch(uSlots[10], ivec2(0), 0);
    s += texelFetch(uSlots[11], ivec2(0), 0);
    s += texelFetch(uSlots[12], ivec2(0), 0);
    s += texelFetch(uSlots[13], ivec2(0), 0);
    s += texelFetch(uSlots[14], ivec2(0), 0);
    s += texelFetch(uSlots[15], ivec2(0), 0);
    s += texelFetch(uSlots[16], ivec2(0), 0);
    s += texelFetch(uSlots[17], ivec2(0), 0);
    s += texelFetch(uSlots[18], ivec2(0), 0);
    s += texelFetch(uSlots[19], ivec2(0), 0);
    oColor = s;
}
