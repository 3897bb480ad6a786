// The background kept by BackgroundPass (pass_background.cpp), copied texel for texel where no surface was
// drawn (the same depth test as background.frag): the values the environment lookup wrote into it.
uniform sampler2D uBackgroundCache;

out vec4 oColor;

void main() {
    oColor = texelFetch(uBackgroundCache, ivec2(gl_FragCoord.xy), 0);
}
