// Clustered forward shading (src/render/cluster.h bins the lights on the CPU). Included after
// shade.glsl when the feature key asks for it (LR_CLUSTERED): the fragment finds its cluster from
// gl_FragCoord.xy (screen tile) and its view-space depth (exponential slice), then shades the lights
// evaluated everywhere (directional, rim, unbounded falloffs) and those listed for its cluster, in the
// buffer's order. Lights left out of a cluster contribute exactly zero there (their falloff is 0 beyond
// their range), so the sum equals shadeSurface()'s.
#if defined(LR_SHADING) && defined(LR_CLUSTERED)

uniform usamplerBuffer uClusterRanges;   // RG32UI per cluster: offset into uClusterIndices, count
uniform usamplerBuffer uClusterIndices;  // R32UI: [0, uGlobalLightCount) everywhere, then per-cluster lists
uniform int uGlobalLightCount;
uniform ivec3 uClusterGrid;         // tiles x, tiles y, depth slices
uniform vec2 uClusterTileScale;     // tiles per pixel
uniform float uClusterNear;         // view-space depth where slice 0 begins
uniform float uClusterSliceScale;   // slices / log(far / near)

// The cluster of this fragment: mirrors ClusterLookup::index (cluster.cpp).
int clusterIndexAt(vec2 fragCoord, float depth) {
    int tx = clamp(int(floor(fragCoord.x * uClusterTileScale.x)), 0, uClusterGrid.x - 1);
    int ty = clamp(int(floor(fragCoord.y * uClusterTileScale.y)), 0, uClusterGrid.y - 1);
    int slice = 0;
    if (depth > uClusterNear)
        slice = clamp(int(floor(log(depth / uClusterNear) * uClusterSliceScale)), 0, uClusterGrid.z - 1);
    return (slice * uClusterGrid.y + ty) * uClusterGrid.x + tx;
}

// shadeSurface() over the global lights and this fragment's cluster only.
// Under LR_PBR the same sum with shadeLightPbr() and the physically based scene ambient.
vec3 shadeSurfaceClustered(Surface s, ShadeSettings st, vec2 fragCoord) {
    vec3 V = viewVector(st, s.position);
#ifdef LR_PBR
    PbrSurface p = pbrSurfaceLit(s, V);
    vec3 sum = pbrSceneAmbient(s, st, p);
#define lrShadeClustered(l) shadeLightPbr(l, s, st, V, p)
#else
    vec3 sum = st.ambient * s.albedo;
#define lrShadeClustered(l) shadeLight(l, s, st, V)
#endif
#if defined(LR_HAS_SURFACE_LIGHTS) || defined(LR_HAS_LIGHT_RIM)
    if (uGlobalLightCount > 0) {  // do-while: see shadeSurface (shade.glsl)
        int i = 0;
        do {
#ifdef LR_LIGHT_LINKING
            ShadeLight l = loadLight(int(texelFetch(uClusterIndices, i).r));
            if (lightLinked(l)) sum += lrShadeClustered(l);
#else
            sum += lrShadeClustered(loadLight(int(texelFetch(uClusterIndices, i).r)));
#endif
        } while (++i < uGlobalLightCount);
    }
    uvec2 range = texelFetch(uClusterRanges, clusterIndexAt(fragCoord, -s.position.z)).rg;
    if (range.y > 0u) {
        uint k = 0u;
        do {
#ifdef LR_LIGHT_LINKING
            ShadeLight l = loadLight(int(texelFetch(uClusterIndices, int(range.x + k)).r));
            if (lightLinked(l)) sum += lrShadeClustered(l);
#else
            sum += lrShadeClustered(loadLight(int(texelFetch(uClusterIndices, int(range.x + k)).r)));
#endif
        } while (++k < range.y);
    }
#endif
    return sum + s.emissive;
}

#endif
