// Flattening Assimp's node hierarchy into world-space triangle meshes, in double, and dropping what
// would poison a frame: non-finite positions, out-of-range indices, zero-area triangles, bad normals.
#include "importdetail.h"

#include "core/rigjson.h"

#include <algorithm>
#include <array>
#include <assimp/scene.h>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <limits>
#include <unordered_map>
#include <utility>

namespace lr::detail {

glm::dmat4 toGlm(const aiMatrix4x4& m) {
    glm::dmat4 r(1.0);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            r[col][row] = double(m[unsigned(row)][col]);
    return r;
}

glm::dmat4 worldTransform(const aiNode* node) {
    glm::dmat4 m(1.0);
    for (int depth = 0; node && depth < 100000; node = node->mParent, ++depth)
        m = toGlm(node->mTransformation) * m;
    return m;
}

namespace {

constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
// A triangle whose edges e1, e2 satisfy |e1 x e2| <= kMinSine |e1| |e2| has no area worth drawing.
constexpr double kMinSine = 1e-10;

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Unit vector or nullopt-like false for zero, NaN or Inf.
bool normalizeInPlace(glm::dvec3& v) {
    if (!isFinite(v)) return false;
    const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (!(m > 0.0)) return false;
    v /= m;
    v /= std::sqrt(glm::dot(v, v));
    return true;
}

glm::dvec3 anyPerpendicular(const glm::dvec3& n) {
    const glm::dvec3 axis = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    glm::dvec3 t = glm::cross(axis, n);
    return normalizeInPlace(t) ? t : glm::dvec3(1, 0, 0);
}

struct Counts {
    std::size_t nonTriangles = 0, badIndices = 0, nonFinite = 0, farAway = 0, degenerate = 0,
                normalsFixed = 0;
};

// Vertex positions (after the node transforms) farther out than this are dropped with their triangles:
// the rig format's own limit on lengths (kMaxRigLength). A glTF node scale of 1e38 loaded "with 0
// warnings" into an empty view: the camera's framing overflowed.
constexpr double kMaxCoordinate = kMaxRigLength;
enum PositionState : char { kBadPosition = 0, kGoodPosition = 1, kFarPosition = 2 };

struct Instance {
    Mesh mesh;
    std::vector<glm::dvec3> world;
};

void addInstance(const aiMesh* am, const glm::dmat4& world, const QString& nodeName,
                 std::vector<Instance>& out, Counts& counts) {
    if (!am || !am->mVertices || am->mNumVertices == 0 || !am->mFaces) return;
    if (!(am->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) return; // points and lines: not drawn
    const std::uint32_t n = am->mNumVertices;
    const glm::dmat3 linear(world);
    const double det = glm::determinant(linear);
    const bool flip = det < 0.0;
    const glm::dmat3 normalMatrix = std::abs(det) > 0.0 ? glm::transpose(glm::inverse(linear)) : linear;

    std::vector<glm::dvec3> pos(n);
    std::vector<char> posOk(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        const aiVector3D& v = am->mVertices[i];
        pos[i] = glm::dvec3(world * glm::dvec4(v.x, v.y, v.z, 1.0));
        const glm::dvec3 a = glm::abs(pos[i]);
        posOk[i] = !isFinite(pos[i])                            ? kBadPosition
                   : std::max({a.x, a.y, a.z}) > kMaxCoordinate ? kFarPosition
                                                                : kGoodPosition;
    }

    std::vector<std::uint32_t> tri;
    tri.reserve(std::size_t(am->mNumFaces) * 3);
    for (unsigned f = 0; f < am->mNumFaces; ++f) {
        const aiFace& face = am->mFaces[f];
        if (face.mNumIndices != 3 || !face.mIndices) {
            counts.nonTriangles += face.mNumIndices >= 3;
            continue;
        }
        std::uint32_t a = face.mIndices[0], b = face.mIndices[1], c = face.mIndices[2];
        if (a >= n || b >= n || c >= n) {
            ++counts.badIndices;
            continue;
        }
        if (!posOk[a] || !posOk[b] || !posOk[c]) {
            ++counts.nonFinite;
            continue;
        }
        if (posOk[a] == kFarPosition || posOk[b] == kFarPosition || posOk[c] == kFarPosition) {
            ++counts.farAway;
            continue;
        }
        const glm::dvec3 e1 = pos[b] - pos[a], e2 = pos[c] - pos[a];
        if (!(glm::length(glm::cross(e1, e2)) > kMinSine * glm::length(e1) * glm::length(e2))) {
            ++counts.degenerate;
            continue;
        }
        if (flip) std::swap(b, c);
        tri.insert(tri.end(), {a, b, c});
    }
    if (tri.empty()) return;

    // Keep only the vertices the surviving triangles use.
    std::vector<std::uint32_t> remap(n, kUnused), order;
    order.reserve(n);
    for (std::uint32_t& idx : tri) {
        if (remap[idx] == kUnused) {
            remap[idx] = std::uint32_t(order.size());
            order.push_back(idx);
        }
        idx = remap[idx];
    }

    Instance inst;
    Mesh& mesh = inst.mesh;
    mesh.name = am->mName.length ? QString::fromUtf8(am->mName.C_Str()) : nodeName;
    mesh.node = nodeName;
    mesh.material = int(am->mMaterialIndex);
    mesh.indices = std::move(tri);
    const aiVector3D* uvs = am->mTextureCoords[0];
    const aiColor4D* colors = am->mColors[0];
    mesh.hasVertexColors = colors != nullptr;
    mesh.hasTangents = am->mTangents && am->mBitangents;
    mesh.vertices.resize(order.size());
    inst.world.resize(order.size());
    std::vector<glm::dvec3> normals(order.size());
    std::vector<char> normalOk(order.size(), 0);

    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::uint32_t i = order[k];
        Vertex& v = mesh.vertices[k];
        inst.world[k] = pos[i];
        if (am->mNormals) {
            const aiVector3D& an = am->mNormals[i];
            normals[k] = normalMatrix * glm::dvec3(an.x, an.y, an.z);
            normalOk[k] = normalizeInPlace(normals[k]);
        }
        if (uvs) {
            const glm::vec2 uv(uvs[i].x, 1.0f - uvs[i].y); // Assimp: bottom-left origin; ours: top-left
            v.uv = std::isfinite(uv.x) && std::isfinite(uv.y) ? uv : glm::vec2(0.0f);
        }
        if (colors) {
            const aiColor4D& c = colors[i];
            const glm::vec4 col(c.r, c.g, c.b, c.a);
            for (int j = 0; j < 4; ++j)
                v.color[j] = std::isfinite(col[j]) ? std::max(col[j], 0.0f) : 1.0f;
        }
    }

    // Recompute missing, zero or non-finite normals from the (area-weighted) faces around the vertex.
    std::size_t missing = 0;
    for (char ok : normalOk)
        missing += !ok;
    if (missing) {
        if (am->mNormals) counts.normalsFixed += missing;
        std::vector<glm::dvec3> sum(order.size(), glm::dvec3(0.0));
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
            const glm::dvec3 fn = glm::cross(inst.world[b] - inst.world[a], inst.world[c] - inst.world[a]);
            for (std::uint32_t idx : {a, b, c})
                if (!normalOk[idx]) sum[idx] += fn;
        }
        for (std::size_t k = 0; k < order.size(); ++k) {
            if (normalOk[k]) continue;
            normals[k] = sum[k];
            if (!normalizeInPlace(normals[k])) normals[k] = glm::dvec3(0.0, 0.0, 1.0);
        }
    }

    for (std::size_t k = 0; k < order.size(); ++k) {
        Vertex& v = mesh.vertices[k];
        const glm::dvec3& nrm = normals[k];
        v.normal = glm::vec3(nrm);
        if (!mesh.hasTangents) continue;
        const std::uint32_t i = order[k];
        const aiVector3D &at = am->mTangents[i], &ab = am->mBitangents[i];
        glm::dvec3 t = linear * glm::dvec3(at.x, at.y, at.z);
        const glm::dvec3 b = linear * glm::dvec3(ab.x, ab.y, ab.z);
        t -= nrm * glm::dot(nrm, t);
        if (!normalizeInPlace(t)) t = anyPerpendicular(nrm);
        const double w = glm::dot(glm::cross(nrm, t), b) < 0.0 ? -1.0 : 1.0;
        v.tangent = glm::vec4(glm::vec3(t), float(w));
    }
    out.push_back(std::move(inst));
}

QString plural(std::size_t n, const char* what) {
    return QStringLiteral("%1 %2%3").arg(n).arg(QLatin1String(what)).arg(n == 1 ? "" : "s");
}

} // namespace

bool convertMeshes(const aiScene* scene, const QString& displayName, Model& model,
                   const std::function<bool(double)>& keepGoing) {
    std::vector<Instance> instances;
    Counts counts;
    if (scene->mRootNode) {
        std::size_t totalRefs = 0, done = 0;
        std::vector<std::pair<const aiNode*, glm::dmat4>> stack{{scene->mRootNode, glm::dmat4(1.0)}};
        std::vector<std::pair<const aiNode*, glm::dmat4>> order;
        while (!stack.empty() && order.size() < 10'000'000) {
            auto [node, parent] = stack.back();
            stack.pop_back();
            const glm::dmat4 world = parent * toGlm(node->mTransformation);
            order.emplace_back(node, world);
            totalRefs += node->mNumMeshes;
            for (unsigned c = node->mNumChildren; c-- > 0;)
                if (node->mChildren && node->mChildren[c]) stack.emplace_back(node->mChildren[c], world);
        }
        for (const auto& [node, world] : order) {
            const QString nodeName = QString::fromUtf8(node->mName.C_Str());
            for (unsigned m = 0; m < node->mNumMeshes && node->mMeshes; ++m) {
                const unsigned index = node->mMeshes[m];
                if (index < scene->mNumMeshes)
                    addInstance(scene->mMeshes[index], world, nodeName, instances, counts);
                if (keepGoing && !keepGoing(double(++done) / double(totalRefs))) return false;
            }
        }
    }

    Bounds bounds;
    bounds.min = glm::dvec3(std::numeric_limits<double>::infinity());
    bounds.max = -bounds.min;
    for (const Instance& inst : instances)
        for (const glm::dvec3& p : inst.world) {
            bounds.min = glm::min(bounds.min, p);
            bounds.max = glm::max(bounds.max, p);
        }
    if (instances.empty()) bounds = Bounds{};
    model.bounds = bounds;
    model.origin = bounds.center();
    model.meshes.reserve(instances.size());
    for (Instance& inst : instances) {
        for (std::size_t k = 0; k < inst.world.size(); ++k)
            inst.mesh.vertices[k].position = glm::vec3(inst.world[k] - model.origin);
        model.meshes.push_back(std::move(inst.mesh));
    }

    const auto warn = [&](std::size_t n, const char* what, const char* why) {
        if (n)
            model.warnings
                << QStringLiteral("%1: %2 %3").arg(displayName, plural(n, what), QLatin1String(why));
    };
    warn(counts.nonFinite, "triangle", "with NaN or infinite vertex positions dropped");
    warn(counts.badIndices, "triangle", "with out-of-range vertex indices dropped");
    if (counts.farAway)
        model.warnings << QStringLiteral(
                              "%1: %2 with vertex positions beyond ±%3 (after the nodes' scales and "
                              "positions) dropped")
                              .arg(displayName, plural(counts.farAway, "triangle"))
                              .arg(kMaxCoordinate, 0, 'g', 3);
    warn(counts.degenerate, "zero-area triangle", "dropped");
    warn(counts.nonTriangles, "polygon", "that could not be triangulated dropped");
    warn(counts.normalsFixed, "zero-length or invalid normal", "recomputed from the faces");
    return true;
}

} // namespace lr::detail

namespace lr::detail {

qint64 coincidentVertexPairs(const aiScene* scene) {
    struct CellHash {
        std::size_t operator()(const std::array<qint64, 3>& c) const {
            return std::size_t(c[0] * 73856093ll ^ c[1] * 19349663ll ^ c[2] * 83492791ll);
        }
    };
    qint64 pairs = 0;
    std::unordered_map<std::array<qint64, 3>, qint64, CellHash> cells;
    for (unsigned m = 0; m < scene->mNumMeshes && scene->mMeshes; ++m) {
        const aiMesh* am = scene->mMeshes[m];
        if (!am || !am->mVertices) continue;
        glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
        for (unsigned i = 0; i < am->mNumVertices; ++i) {
            const glm::dvec3 p(am->mVertices[i].x, am->mVertices[i].y, am->mVertices[i].z);
            if (!isFinite(p)) continue;
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        // Assimp's smoothing epsilon (ComputePositionEpsilon); 0 when every vertex is at one point.
        const double cell = hi.x >= lo.x ? 1e-4 * glm::length(hi - lo) : 0.0;
        cells.clear();
        for (unsigned i = 0; i < am->mNumVertices; ++i) {
            const glm::dvec3 p(am->mVertices[i].x, am->mVertices[i].y, am->mVertices[i].z);
            if (!isFinite(p)) continue;
            std::array<qint64, 3> key{0, 0, 0};
            if (cell > 0.0 && std::isfinite(cell))
                for (int k = 0; k < 3; ++k)
                    key[k] = qint64(std::floor((p[k] - lo[k]) / cell));
            pairs += cells[key]++; // the new vertex pairs with every earlier one in its cell
            if (pairs > (qint64(1) << 60)) return pairs; // far past any limit; no overflow
        }
    }
    return pairs;
}

} // namespace lr::detail
