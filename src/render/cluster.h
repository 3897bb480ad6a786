// Clustered forward shading, CPU side: the view frustum is cut into screen tiles × exponential depth
// slices, and each light that can only reach a bounded region (a point or spot light whose falloff is
// exactly zero from its range on) is listed in the clusters its range sphere overlaps. Lights without a
// bound (directional, rim, falloff `none`, range-less inverse-square/polynomial) are evaluated everywhere.
// The fragment shader (shaders/cluster.glsl) finds its cluster from gl_FragCoord.xy and its view-space
// depth and loops over that cluster's lights only. The binning is conservative: a light is left out of a
// cluster only where its contribution is exactly zero, so the `exact` tier stays exact. No GL here.
#pragma once

#include "core/shade.h"

#include <cstdint>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <span>
#include <vector>

namespace lr::render {

struct ClusterGrid {
    int tilesX = 32, tilesY = 18, slices = 24;
    int count() const { return tilesX * tilesY * slices; }
    bool operator==(const ClusterGrid&) const = default;
};

// Where a prepared light can contribute: inside a view-space sphere, or everywhere (bounded == false).
struct LightBounds {
    bool bounded = false;
    glm::dvec3 center{0.0};
    double radius = 0.0; // view-space units, already widened for float evaluation on the GPU
};

// The sphere outside which shadeLight() returns exactly 0 for this light (distance in view units;
// the falloff sees d * distanceScale). Spot cones are bounded by their sphere.
LightBounds lightBounds(const lighting::ShadeLight<double>& light, double distanceScale);

// The frame the clusters are cut from: the projection used for drawing, the target size in pixels
// (gl_FragCoord's range), and the depth range the slices cover (view-space distances along -z).
struct ClusterView {
    glm::dmat4 projection{1.0};
    int width = 1, height = 1;
    double znear = 0.1, zfar = 100.0;
};

// The lookup the shader does (shaders/cluster.glsl clusterIndexAt), in double: the cluster of a fragment
// at window coordinates fragCoord (pixels, origin bottom-left) and view-space depth -z.
struct ClusterLookup {
    ClusterGrid grid;
    glm::dvec2 tileScale{0.0}; // tiles per pixel
    double znear = 0.1;
    double sliceScale = 1.0; // slices / log(zfar / znear)
    int tile(double fragX, double fragY, int* tx, int* ty) const;
    int slice(double depth) const;
    int index(const glm::dvec2& fragCoord, double depth) const;
};

ClusterLookup clusterLookup(const ClusterView& view, const ClusterGrid& grid = {});

struct ClusterData {
    ClusterGrid grid;
    ClusterLookup lookup;
    // indices[0, globalCount): lights evaluated everywhere; then each cluster's list. ranges holds
    // (offset into indices, count) per cluster, cluster id = (slice * tilesY + ty) * tilesX + tx.
    std::vector<std::uint32_t> indices;
    std::vector<std::uint32_t> ranges;
    int globalCount = 0;
    int boundedCount = 0;
    std::span<const std::uint32_t> cluster(int id) const {
        return {indices.data() + ranges[size_t(2 * id)], ranges[size_t(2 * id + 1)]};
    }
};

// The clusters a sphere may touch, as inclusive ranges [x0,x1]×[y0,y1]×[z0,z1] (conservative).
struct ClusterSpan {
    int x0 = 0, x1 = -1, y0 = 0, y1 = -1, z0 = 0, z1 = -1;
};
ClusterSpan sphereClusters(const glm::dvec3& center, double radius, const ClusterView& view,
                           const ClusterLookup& lookup);

// The grid for a target of width × height pixels: tiles of about kClusterTilePixels on a side (32 × 18 at
// 1280×720, 96 × 54 at 3840×2160), kClusterMaxTiles at most each way. A fixed 32 × 18 made a 4K tile 120
// pixels wide, and its list held far more lights than reach most of its pixels (issue 40: 4096 localised
// lights at 4K on the H100).
constexpr int kClusterTilePixels = 40;
constexpr int kClusterMaxTiles = 128;
// maxClusters: how many clusters the range buffer may hold (one texel each: GL_MAX_TEXTURE_BUFFER_SIZE, at
// least 65,536 in GL 3.3); fewer, larger tiles when the grid would hold more.
ClusterGrid clusterGridFor(int width, int height, long long maxClusters = 65536);

// Bins lights[i] (index i of the uploaded light buffer) into the grid.
ClusterData binLights(std::span<const LightBounds> lights, const ClusterView& view,
                      const ClusterGrid& grid = {});

// Whether clustering pays off: more than a few bounded lights.
constexpr int kClusterMinBoundedLights = 8;

} // namespace lr::render
