// Analytic shadow scenes built in code for the traced reference's tests (issue 14): quads, boxes and a
// UV sphere in one Model, with its bounds (and so groundPlane() and the ray epsilon) from the triangles.
#pragma once

#include "model/model.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <initializer_list>

namespace lr::test {

class ShadowSceneBuilder {
  public:
    ShadowSceneBuilder() : m_model(makePlane(1.0)) { // one material, one mesh: emptied
        vertices().clear();
        indices().clear();
    }

    // A quad of corners a, b, c, d; its normal by the right-hand rule (the tracer is double-sided).
    ShadowSceneBuilder& quad(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c, glm::dvec3 d) {
        const std::uint32_t base = add({a, b, c, d}, glm::normalize(glm::cross(b - a, c - a)));
        indices().insert(indices().end(), {base, base + 1, base + 2, base, base + 2, base + 3});
        return *this;
    }
    // The horizontal square y = height, |x|, |z| <= half.
    ShadowSceneBuilder& floor(double height, double half) {
        return quad({-half, height, -half}, {-half, height, half}, {half, height, half},
                    {half, height, -half});
    }
    // The closed axis-aligned box [lo, hi].
    ShadowSceneBuilder& box(glm::dvec3 lo, glm::dvec3 hi) {
        const auto p = [&](int i) {
            return glm::dvec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
        };
        quad(p(0), p(1), p(3), p(2)); // z = lo
        quad(p(4), p(6), p(7), p(5)); // z = hi
        quad(p(0), p(4), p(5), p(1)); // y = lo
        quad(p(2), p(3), p(7), p(6)); // y = hi
        quad(p(0), p(2), p(6), p(4)); // x = lo
        quad(p(1), p(5), p(7), p(3)); // x = hi
        return *this;
    }
    // makeSphere's UV sphere (vertices on the sphere, so the mesh lies inside it).
    ShadowSceneBuilder& sphere(glm::dvec3 center, double radius, int segments, int rings) {
        const Model s = makeSphere(radius, segments, rings, center);
        const auto base = std::uint32_t(vertices().size());
        for (const Vertex& v : s.meshes.front().vertices)
            add({s.origin + glm::dvec3(v.position)}, glm::dvec3(v.normal));
        for (std::uint32_t i : s.meshes.front().indices)
            indices().push_back(base + i);
        return *this;
    }
    Model build() const { return m_model; }

  private:
    std::vector<Vertex>& vertices() { return m_model.meshes.front().vertices; }
    std::vector<std::uint32_t>& indices() { return m_model.meshes.front().indices; }
    std::uint32_t add(std::initializer_list<glm::dvec3> points, glm::dvec3 normal) {
        const auto base = std::uint32_t(vertices().size());
        for (const glm::dvec3& p : points) {
            if (vertices().empty()) m_model.bounds.min = m_model.bounds.max = p;
            m_model.bounds.min = glm::min(m_model.bounds.min, p);
            m_model.bounds.max = glm::max(m_model.bounds.max, p);
            Vertex v;
            v.position = glm::vec3(p - m_model.origin);
            v.normal = glm::vec3(normal);
            vertices().push_back(v);
        }
        return base;
    }
    Model m_model;
};

// The distance from `c` to the segment from p to q (or the ray from p along unit q when `ray`).
inline double distanceToSegment(glm::dvec3 c, glm::dvec3 p, glm::dvec3 q, bool ray = false) {
    if (ray) return glm::length(c - p - std::max(0.0, glm::dot(c - p, q)) * q);
    const glm::dvec3 d = q - p;
    const double t = std::clamp(glm::dot(c - p, d) / glm::dot(d, d), 0.0, 1.0);
    return glm::length(p + t * d - c);
}

} // namespace lr::test
