// Analytic models for render tests and fallbacks: exact unit normals, counter-clockwise triangles seen
// from outside, UV (0, 0) at the image's top-left, tangents along +u with glTF handedness.
#include "model.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace lr {

namespace {

Model withOneMaterial(const char* meshName, const glm::dvec3& center, double halfExtent) {
    Model model;
    model.origin = center;
    model.bounds.min = center - glm::dvec3(halfExtent);
    model.bounds.max = center + glm::dvec3(halfExtent);
    Material material;
    material.name = QStringLiteral("default");
    model.materials.push_back(material);
    Mesh mesh;
    mesh.name = QString::fromLatin1(meshName);
    mesh.hasTangents = true;
    model.meshes.push_back(mesh);
    return model;
}

} // namespace

Model makeSphere(double radius, int segments, int rings, const glm::dvec3& center) {
    radius = std::isfinite(radius) && radius > 0.0 ? radius : 1.0;
    segments = std::clamp(segments, 3, 4096);
    rings = std::clamp(rings, 2, 4096);
    Model model = withOneMaterial("sphere", center, radius);
    Mesh& mesh = model.meshes.front();
    const double pi = std::numbers::pi;
    // theta from the +Y pole (v = 0, the image's top) to the -Y pole; phi around +Y, 0 facing +Z.
    for (int i = 0; i <= rings; ++i) {
        const double theta = pi * double(i) / double(rings);
        for (int j = 0; j <= segments; ++j) {
            const double phi = 2.0 * pi * double(j) / double(segments);
            const glm::dvec3 n(std::sin(theta) * std::sin(phi), std::cos(theta),
                               std::sin(theta) * std::cos(phi));
            const glm::dvec3 t(std::cos(phi), 0.0, -std::sin(phi)); // d/dphi, i.e. +u
            const glm::dvec3 up(-std::cos(theta) * std::sin(phi), std::sin(theta),
                                -std::cos(theta) * std::cos(phi));
            const bool pole =
                i == 0 || i == rings; // up is undefined there: the u direction's handedness holds
            const double w = pole || glm::dot(glm::cross(n, t), up) >= 0.0 ? 1.0 : -1.0;
            Vertex v;
            v.position = glm::vec3(radius * n);
            v.normal = glm::vec3(glm::normalize(n));
            v.uv = glm::vec2(float(double(j) / segments), float(double(i) / rings));
            v.tangent = glm::vec4(glm::vec3(t), float(w));
            mesh.vertices.push_back(v);
        }
    }
    const auto at = [&](int i, int j) { return std::uint32_t(i * (segments + 1) + j); };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < segments; ++j) {
            const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            if (i != rings - 1) mesh.indices.insert(mesh.indices.end(), {a, b, c}); // not at the -Y pole
            if (i != 0) mesh.indices.insert(mesh.indices.end(), {a, c, d});         // not at the +Y pole
        }
    }
    return model;
}

Model makePlane(double halfSize, const glm::dvec3& center) {
    halfSize = std::isfinite(halfSize) && halfSize > 0.0 ? halfSize : 1.0;
    Model model = withOneMaterial("plane", center, halfSize);
    model.bounds.min.z = model.bounds.max.z = center.z;
    Mesh& mesh = model.meshes.front();
    const float h = float(halfSize);
    const glm::vec2 corners[4] = {{-1, 1}, {-1, -1}, {1, -1}, {1, 1}}; // top-left, then counter-clockwise
    for (const glm::vec2& c : corners) {
        Vertex v;
        v.position = glm::vec3(c.x * h, c.y * h, 0.0f);
        v.normal = glm::vec3(0.0f, 0.0f, 1.0f);
        v.uv = glm::vec2(0.5f * (c.x + 1.0f), 0.5f * (1.0f - c.y));
        v.tangent = glm::vec4(1.0f, 0.0f, 0.0f, 1.0f);
        mesh.vertices.push_back(v);
    }
    mesh.indices = {0, 1, 2, 0, 2, 3};
    return model;
}

} // namespace lr
