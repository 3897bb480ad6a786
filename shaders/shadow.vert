// Shadow-map depth pass (src/render/shadowmaps.cpp): model positions (relative to Model::origin) to the
// light's clip space, uLightMatrix built in double precision on the CPU.
layout(location = 0) in vec3 aPosition;
uniform mat4 uLightMatrix;

void main() { gl_Position = uLightMatrix * vec4(aPosition, 1.0); }
