#include "lod.h"

#include <algorithm>
#include <cstddef>
#include <meshoptimizer.h>

namespace lr::render {

namespace {

// Relative to the mesh's extent: 2% keeps silhouettes recognisable for navigation.
constexpr float kTargetError = 0.02f;

std::vector<std::uint32_t> simplify(const Mesh& mesh, std::size_t count, std::size_t targetIndices) {
    const float* positions = &mesh.vertices.front().position.x;
    std::vector<std::uint32_t> out(count);
    std::size_t n = meshopt_simplify(out.data(), mesh.indices.data(), count, positions, mesh.vertices.size(),
                                     sizeof(Vertex), targetIndices, kTargetError, 0, nullptr);
    // Seams (split normals or UVs) lock borders and can stop the topology-preserving pass early: then the
    // sloppy one, which only needs positions.
    if (n > targetIndices + targetIndices / 2)
        n = meshopt_simplifySloppy(out.data(), mesh.indices.data(), count, positions, mesh.vertices.size(),
                                   sizeof(Vertex), targetIndices, kTargetError, nullptr);
    out.resize(n - n % 3);
    meshopt_optimizeVertexCache(out.data(), out.data(), out.size(), mesh.vertices.size());
    return out;
}

} // namespace

std::vector<MeshLod> buildInteractionLods(const Model& model, std::int64_t targetTriangles) {
    std::vector<MeshLod> lods;
    const auto total = std::int64_t(model.triangleCount());
    if (total < kLodMinTriangles || total <= targetTriangles || targetTriangles <= 0) return lods;
    const double share = double(targetTriangles) / double(total);
    for (std::size_t i = 0; i < model.meshes.size(); ++i) {
        const Mesh& mesh = model.meshes[i];
        const std::size_t count = mesh.indices.size() / 3 * 3;
        if (mesh.vertices.empty() || count < 3 * 64) continue; // too small to matter
        const auto target = std::max<std::size_t>(3, std::size_t(double(count / 3) * share) * 3);
        std::vector<std::uint32_t> indices = simplify(mesh, count, target);
        if (indices.size() < 3 || indices.size() * 5 > count * 4) continue; // not worth a second buffer
        lods.push_back({int(i), std::move(indices)});
    }
    return lods;
}

} // namespace lr::render
