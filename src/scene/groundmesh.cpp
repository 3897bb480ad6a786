#include "groundmesh.h"

#include <glm/common.hpp>

namespace lr::render {

Model groundModel(const GroundPlane& plane, const Ground& ground) {
    Model m;
    m.path = QStringLiteral("(ground)");
    const glm::dvec3 lo =
        glm::min(glm::min(plane.corners[0], plane.corners[1]), glm::min(plane.corners[2], plane.corners[3]));
    const glm::dvec3 hi =
        glm::max(glm::max(plane.corners[0], plane.corners[1]), glm::max(plane.corners[2], plane.corners[3]));
    m.origin = 0.5 * (lo + hi);
    m.bounds.min = lo;
    m.bounds.max = hi;
    Material mat;
    mat.name = QStringLiteral("ground");
    mat.baseColor = glm::vec4(glm::vec3(glm::clamp(ground.color, 0.0, 1.0)), 1.0f);
    mat.specular = glm::vec3(0.0f); // classic: Lambert only
    mat.shininess = 1.0f;
    mat.pbr = true;
    mat.metallic = 0.0f;
    mat.roughness = 1.0f;
    m.materials.push_back(mat);
    Mesh mesh;
    mesh.name = QStringLiteral("ground");
    mesh.material = 0;
    const int n = kGroundGridCells;
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            Vertex v;
            const glm::dvec3 p(lo.x + (hi.x - lo.x) * i / n, plane.height, lo.z + (hi.z - lo.z) * j / n);
            v.position = glm::vec3(p - m.origin);
            v.normal = glm::vec3(plane.normal);
            v.uv = glm::vec2(float(i) / n, float(j) / n);
            mesh.vertices.push_back(v);
        }
    }
    // Counter-clockwise seen from above (+Y): (x, z), (x, z + 1), (x + 1, z).
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const std::uint32_t a = std::uint32_t(j * (n + 1) + i), b = a + 1, c = a + std::uint32_t(n + 1),
                                d = c + 1;
            mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
        }
    }
    m.meshes.push_back(std::move(mesh));
    return m;
}

Bounds drawnBounds(const Bounds& model, const Ground& ground) {
    if (ground.mode == GroundMode::Off) return model;
    Bounds b = model;
    for (const glm::dvec3& c : groundPlane(model).corners) {
        b.min = glm::min(b.min, c);
        b.max = glm::max(b.max, c);
    }
    return b;
}

} // namespace lr::render
