// Interaction proxies for dense models: while the user orbits, pans, dollies or drags a light, the viewport
// draws a simplified index buffer over the same vertices (meshoptimizer), and the full mesh again as soon as
// the motion stops. On a software rasteriser the cost of a frame of a 1M-triangle model is the serial
// per-triangle work (vertex shading, setup, binning), so a quarter of the triangles is about a quarter of
// the frame. Models under kLodMinTriangles are always drawn in full; the proxies are built on a worker
// thread after the upload, so they never delay the first frame.
#pragma once

#include "model/model.h"

#include <cstdint>
#include <vector>

namespace lr::render {

constexpr std::int64_t kLodMinTriangles = 300000;    // models with fewer triangles get no proxy
constexpr std::int64_t kLodTargetTriangles = 250000; // the proxy's triangle budget for the whole model

struct MeshLod {
    int mesh = -1;                      // index into Model::meshes
    std::vector<std::uint32_t> indices; // triangles over the mesh's own vertices
};

// One proxy per mesh that simplifies to fewer triangles (none when the model is small). Each mesh keeps its
// share of the budget; meshes meshoptimizer cannot reduce by at least a fifth keep their full index list.
std::vector<MeshLod> buildInteractionLods(const Model& model,
                                          std::int64_t targetTriangles = kLodTargetTriangles);

} // namespace lr::render
