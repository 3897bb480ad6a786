// The one Embree 3 scene builder (Debian's libembree-dev) of LightRig: triangle meshes of models in world
// units, one Embree geometry per mesh, relative to an origin (the scene's centre) so that float keeps its
// precision far from the world's origin. The traced shadow reference (referencetrace.h) and the path
// tracer (src/trace) both build their scenes here. Built once, read-only afterwards: any number of threads
// trace it at once. Embree stays PRIVATE to lightrig_scene: its handles are opaque here.
#pragma once

#include "model/model.h"

#include <QString>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

namespace lr {

// What a ray hit: the geometry (EmbreeScene::Part index), the triangle in its mesh, the barycentrics of
// vertices 1 and 2 (Embree's u, v), the distance along the ray (unit direction: world units) and the
// triangle's geometric normal (world, unit, as the triangle winds: not turned towards the ray).
struct EmbreeHit {
    bool hit = false;
    std::uint32_t part = 0, triangle = 0;
    double u = 0.0, v = 0.0, t = 0.0;
    glm::dvec3 normal{0.0, 0.0, 1.0};
};

class EmbreeScene {
  public:
    // Which mesh of which model a geometry is.
    struct Part {
        const Model* model = nullptr;
        int mesh = 0;
    };
    // Every mesh of every model (their vertices are relative to Model::origin, world units), in order:
    // the geometry ids are indices into parts(). The models must outlive the scene. Check ok().
    EmbreeScene(const std::vector<const Model*>& models, const glm::dvec3& origin);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    bool ok() const { return m_scene != nullptr; }
    QString error() const { return m_error; }
    std::int64_t triangles() const { return m_triangles; }
    const std::vector<Part>& parts() const { return m_parts; }
    const glm::dvec3& origin() const { return m_origin; }

    // Whether the segment from `origin` along unit `dir` between tnear and `distance` (may be infinite)
    // hits a triangle.
    bool occluded(const glm::dvec3& origin, const glm::dvec3& dir, double distance, double tnear = 0.0) const;
    // The closest hit of the ray within [tnear, tfar] (world; tfar may be infinite).
    EmbreeHit intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tnear, double tfar) const;

  private:
    void* m_device = nullptr; // RTCDevice
    void* m_scene = nullptr;  // RTCScene
    glm::dvec3 m_origin{0.0};
    std::vector<Part> m_parts;
    std::int64_t m_triangles = 0;
    QString m_error;
};

} // namespace lr
