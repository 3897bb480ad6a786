// Invariants every loaded or built Model must satisfy, shared by the model tests and the import probe.
#pragma once

#include "model/model.h"

#include <QString>
#include <cmath>
#include <glm/geometric.hpp>

namespace lr::test {

inline bool finite3(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Empty when the model is safe to draw: finite values, unit normals and tangents, indices and material
// and texture references in range, decoded RGBA8888 textures, finite lights and cameras.
inline QString modelProblems(const Model& m) {
    if (m.materials.empty()) return QStringLiteral("no materials");
    if (m.meshes.empty()) return QStringLiteral("no meshes");
    for (const Mesh& mesh : m.meshes) {
        if (mesh.indices.empty() || mesh.indices.size() % 3)
            return QStringLiteral("index count not a multiple of 3");
        if (mesh.material < 0 || mesh.material >= int(m.materials.size()))
            return QStringLiteral("bad material index");
        for (std::uint32_t i : mesh.indices)
            if (i >= mesh.vertices.size()) return QStringLiteral("index out of range");
        for (const Vertex& v : mesh.vertices) {
            if (!finite3(v.position)) return QStringLiteral("non-finite position");
            if (!finite3(v.normal) || std::abs(glm::length(v.normal) - 1.0f) > 1e-3f)
                return QStringLiteral("normal not unit length");
            if (!std::isfinite(v.uv.x) || !std::isfinite(v.uv.y)) return QStringLiteral("non-finite uv");
            if (!finite3(glm::vec3(v.color)) || !std::isfinite(v.color.a))
                return QStringLiteral("non-finite colour");
            if (mesh.hasTangents) {
                const glm::vec3 t(v.tangent);
                if (!finite3(t) || std::abs(glm::length(t) - 1.0f) > 1e-3f)
                    return QStringLiteral("bad tangent");
                if (std::abs(glm::dot(t, v.normal)) > 1e-3f) return QStringLiteral("tangent not orthogonal");
                if (std::abs(v.tangent.w) != 1.0f) return QStringLiteral("tangent handedness not +-1");
            }
        }
    }
    const auto texOk = [&](int t) {
        return t == -1 || (t >= 0 && t < int(m.textures.size()) && !m.textures[size_t(t)].image.isNull() &&
                           m.textures[size_t(t)].image.format() == QImage::Format_RGBA8888);
    };
    for (const Material& mat : m.materials) {
        if (!texOk(mat.baseColorTexture) || !texOk(mat.normalTexture) || !texOk(mat.emissiveTexture) ||
            !texOk(mat.metallicRoughnessTexture) || !texOk(mat.occlusionTexture))
            return QStringLiteral("bad texture reference in material %1").arg(mat.name);
        for (float f : {mat.metallic, mat.roughness, mat.occlusionStrength, mat.alphaCutoff})
            if (!(f >= 0.0f && f <= 1.0f))
                return QStringLiteral("material factor outside [0, 1] in %1").arg(mat.name);
        if (!finite3(mat.emissive) || !std::isfinite(mat.normalScale))
            return QStringLiteral("non-finite emissive or normal scale in %1").arg(mat.name);
        for (const TextureTransform& t : {mat.baseColorTransform, mat.normalTransform, mat.emissiveTransform,
                                          mat.metallicRoughnessTransform, mat.occlusionTransform})
            if (!std::isfinite(t.offset.x) || !std::isfinite(t.offset.y) || !std::isfinite(t.rotation) ||
                !std::isfinite(t.scale.x) || !std::isfinite(t.scale.y))
                return QStringLiteral("non-finite texture transform in %1").arg(mat.name);
        for (int i = 0; i < 4; ++i)
            if (!std::isfinite(mat.baseColor[i]) || mat.baseColor[i] < 0.0f)
                return QStringLiteral("bad base colour");
    }
    for (const Light& l : m.lights.lights) {
        const auto ok = [](const glm::dvec3& v) {
            return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
        };
        if (!ok(l.position) || !ok(l.direction) || !ok(l.color) || !std::isfinite(l.intensity) ||
            l.intensity < 0)
            return QStringLiteral("bad light %1").arg(l.name);
        if (std::abs(glm::length(l.direction) - 1.0) > 1e-9)
            return QStringLiteral("light direction not unit");
    }
    for (const Camera& c : m.cameras) {
        if (std::abs(glm::length(c.forward) - 1.0) > 1e-9 || std::abs(glm::length(c.up) - 1.0) > 1e-9 ||
            std::abs(glm::dot(c.forward, c.up)) > 1e-9 || !(c.yfovDegrees > 0.0 && c.yfovDegrees < 180.0))
            return QStringLiteral("bad camera %1").arg(c.name);
    }
    return {};
}

// Triangles whose winding disagrees with the normals of their vertices (counter-clockwise seen from
// the side the normals point to is right).
inline std::size_t clockwiseTriangles(const Mesh& mesh) {
    std::size_t bad = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vertex &a = mesh.vertices[mesh.indices[t]], &b = mesh.vertices[mesh.indices[t + 1]],
                     &c = mesh.vertices[mesh.indices[t + 2]];
        const glm::vec3 face = glm::cross(b.position - a.position, c.position - a.position);
        bad += glm::dot(face, a.normal + b.normal + c.normal) <= 0.0f;
    }
    return bad;
}

// Triangles whose tangent frame disagrees with their UVs: the tangent must follow +u and
// w * cross(N, T) must point up in the image, i.e. towards -v (uv (0, 0) is the top-left texel).
inline std::size_t tangentFrameMismatches(const Mesh& mesh) {
    std::size_t bad = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vertex &a = mesh.vertices[mesh.indices[t]], &b = mesh.vertices[mesh.indices[t + 1]],
                     &c = mesh.vertices[mesh.indices[t + 2]];
        const glm::dvec3 e1 = glm::dvec3(b.position - a.position), e2 = glm::dvec3(c.position - a.position);
        const glm::dvec2 d1 = glm::dvec2(b.uv - a.uv), d2 = glm::dvec2(c.uv - a.uv);
        const double det = d1.x * d2.y - d2.x * d1.y;
        if (std::abs(det) < 1e-12) continue; // no UV area: no frame to compare
        const glm::dvec3 dPdu = (e1 * d2.y - e2 * d1.y) / det, dPdv = (e2 * d1.x - e1 * d2.x) / det;
        for (const Vertex* v : {&a, &b, &c}) {
            const glm::dvec3 n(v->normal), tan(v->tangent);
            const glm::dvec3 bitangent = double(v->tangent.w) * glm::cross(n, tan);
            if (!(glm::dot(tan, dPdu) > 0.0) || !(glm::dot(bitangent, -dPdv) > 0.0)) {
                ++bad;
                break;
            }
        }
    }
    return bad;
}

} // namespace lr::test
