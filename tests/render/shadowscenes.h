// Analytic scenes for the shadow tests (tst_shadows.cpp, tst_shadowshapes.cpp): meshes built here, the
// ground from the model's bounds (src/model/ground.h), and the probes: world points projected to pixels
// with the renderer's own camera, so no pixel position is hard-coded.
#pragma once

#include "core/rig.h"
#include "model/ground.h"
#include "model/model.h"
#include "render/floatimage.h"
#include "render/renderer.h"
#include "scene/camera.h"

#include <QPoint>
#include <QSize>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <memory>
#include <optional>

namespace lr::test {

// Appends `part`'s meshes (and its material, one per mesh) to `into`, positions relative to its origin.
inline void appendMeshes(Model& into, const Model& part) {
    for (Mesh mesh : part.meshes) {
        for (Vertex& v : mesh.vertices)
            v.position = glm::vec3(glm::dvec3(v.position) + part.origin - into.origin);
        into.materials.push_back(part.materials[size_t(std::max(0, mesh.material))]);
        mesh.material = int(into.materials.size()) - 1;
        into.meshes.push_back(std::move(mesh));
    }
}

inline void recomputeBounds(Model& m) {
    bool first = true;
    for (const Mesh& mesh : m.meshes) {
        for (const Vertex& v : mesh.vertices) {
            const glm::dvec3 p = glm::dvec3(v.position) + m.origin;
            m.bounds.min = first ? p : glm::min(m.bounds.min, p);
            m.bounds.max = first ? p : glm::max(m.bounds.max, p);
            first = false;
        }
    }
}

// A horizontal square (normal +Y) of half-size h at `center`, counter-clockwise seen from above.
inline Model horizontalQuad(double h, const glm::dvec3& center) {
    Model m = makePlane(h, center); // its material and bounds; the vertices are replaced
    Mesh& mesh = m.meshes.front();
    mesh.vertices.clear();
    const glm::vec2 corners[4] = {{-1, -1}, {-1, 1}, {1, 1}, {1, -1}}; // (x, z)
    for (const glm::vec2& c : corners) {
        Vertex v;
        v.position = glm::vec3(c.x * float(h), 0.0f, c.y * float(h));
        v.normal = glm::vec3(0.0f, 1.0f, 0.0f);
        mesh.vertices.push_back(v);
    }
    mesh.indices = {0, 1, 2, 0, 2, 3};
    recomputeBounds(m);
    return m;
}

// An axis-aligned cube of half-size h resting on y = 0 (its base centre at the origin), flat normals.
inline Model restingCube(double h) {
    Model m = makePlane(h); // material
    m.origin = glm::dvec3(0.0);
    Mesh& mesh = m.meshes.front();
    mesh.vertices.clear();
    mesh.indices.clear();
    const float s = float(h);
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (const glm::vec3& n : normals) {
        // Two axes spanning the face with a × b = n: counter-clockwise seen from outside.
        const glm::vec3 a = std::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
        const glm::vec3 b = glm::cross(n, a);
        const auto base = std::uint32_t(mesh.vertices.size());
        const glm::vec2 corners[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const glm::vec2& c : corners) {
            Vertex v;
            v.position = (n + a * c.x + b * c.y) * s + glm::vec3(0.0f, s, 0.0f);
            v.normal = n;
            mesh.vertices.push_back(v);
        }
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    recomputeBounds(m);
    return m;
}

// A sphere of radius 0.5 centred 1 above the ground at y = 0 (a small foot quad far off sets the ground).
inline std::shared_ptr<Model> floatingSphere() {
    auto m = std::make_shared<Model>(makeSphere(0.5, 64, 32, glm::dvec3(0.0, 1.0, 0.0)));
    m->materials[0].baseColor = {0.7f, 0.7f, 0.7f, 1.0f};
    appendMeshes(*m, horizontalQuad(0.02, glm::dvec3(1.0, 0.0, -1.0)));
    recomputeBounds(*m);
    return m;
}

// A view camera looking down at the ground from the front.
inline ViewCamera groundCamera(double height = 4.0, double back = 4.0) {
    ViewCamera c;
    c.eye = {0.0, height, back};
    c.target = {0.0, 0.3, 0.0};
    c.yfovDeg = 50.0;
    return c;
}

// The pixel (image order, top row 0) a world point lands on; nullopt outside the image or behind.
inline std::optional<QPoint> projectToPixel(const Renderer& r, const ViewCamera& cam, QSize size,
                                            const glm::dvec3& p) {
    const ViewCamera c = r.effectiveCamera(cam);
    const glm::dvec4 h = c.projection(double(size.width()) / size.height()) * c.view() * glm::dvec4(p, 1.0);
    if (!(h.w > 0.0)) return std::nullopt;
    const double x = (h.x / h.w * 0.5 + 0.5) * size.width(), y = (0.5 - h.y / h.w * 0.5) * size.height();
    if (x < 0 || y < 0 || x >= size.width() || y >= size.height()) return std::nullopt;
    return QPoint(int(x), int(y));
}

// The world point on the horizontal plane y = height that pixel (x, y) sees (through its centre).
inline std::optional<glm::dvec3> pixelOnPlane(const Renderer& r, const ViewCamera& cam, QSize size, int x,
                                              int y, double height) {
    const ViewCamera c = r.effectiveCamera(cam);
    const glm::dmat4 inv = glm::inverse(c.projection(double(size.width()) / size.height()) * c.view());
    const double nx = (x + 0.5) / size.width() * 2.0 - 1.0, ny = 1.0 - (y + 0.5) / size.height() * 2.0;
    const glm::dvec4 a = inv * glm::dvec4(nx, ny, -1.0, 1.0), b = inv * glm::dvec4(nx, ny, 1.0, 1.0);
    const glm::dvec3 p0 = glm::dvec3(a) / a.w, p1 = glm::dvec3(b) / b.w;
    const double t = (height - p0.y) / (p1.y - p0.y);
    if (!(t > 0.0 && std::isfinite(t))) return std::nullopt;
    return p0 + t * (p1 - p0);
}

inline double luminance(const glm::vec4& c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

} // namespace lr::test
