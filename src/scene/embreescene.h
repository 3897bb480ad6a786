// The one Embree 3 scene builder (Debian's libembree-dev) of LightRig: triangle meshes of models in world
// units, one Embree geometry per mesh, relative to an origin (the scene's centre) so that float keeps its
// precision far from the world's origin. The traced shadow reference (referencetrace.h) and the path
// tracer (src/trace) both build their scenes here. Built once, read-only afterwards: any number of threads
// trace it at once. Embree stays PRIVATE to lightrig_scene: its handles are opaque here.
//
// Shadow linking (issue 38, core/lightlink.h): a scene built with part masks gives geometry `part` the mask
// 1 << its shadow class, and a ray passed a mask (a light's shadowMask) hits only the geometries whose
// mask it shares; every other ray passes all ones and hits everything. Embree's ray masks do it where the
// device has them (RTC_DEVICE_PROPERTY_RAY_MASK_SUPPORTED; Debian's 3.13 has), else intersection and
// occlusion filter functions reject the hits (the same result, slower). Without part masks nothing is set.
#pragma once

#include "core/lightlink.h"
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
    // How part masks are applied: Auto uses the device's ray masks where it has them, else filters;
    // Filter always filters (tests compare the two).
    enum class MaskMethod { None, RayMask, Filter };
    // Every mesh of every model (their vertices are relative to Model::origin, world units), in order:
    // the geometry ids are indices into parts(). The models must outlive the scene. Check ok().
    // `partMasks`: per geometry (in that order; entries past the parts are ignored, missing ones are all
    // ones), or empty: no masks.
    EmbreeScene(const std::vector<const Model*>& models, const glm::dvec3& origin,
                std::vector<std::uint32_t> partMasks = {}, bool forceFilter = false);
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    bool ok() const { return m_scene != nullptr; }
    QString error() const { return m_error; }
    std::int64_t triangles() const { return m_triangles; }
    const std::vector<Part>& parts() const { return m_parts; }
    const glm::dvec3& origin() const { return m_origin; }
    MaskMethod maskMethod() const { return m_maskMethod; }
    // Per part: 1 << its shadow class under `links`; empty when they are inactive (no masks).
    static std::vector<std::uint32_t> shadowClassMasks(const LinkResolution& links);

    // Whether the segment from `origin` along unit `dir` between tnear and `distance` (may be infinite)
    // hits a triangle (of a part whose mask shares a bit with `mask`).
    bool occluded(const glm::dvec3& origin, const glm::dvec3& dir, double distance, double tnear = 0.0,
                  std::uint32_t mask = kAllLinkClasses) const;
    // The closest hit of the ray within [tnear, tfar] (world; tfar may be infinite).
    EmbreeHit intersect(const glm::dvec3& origin, const glm::dvec3& dir, double tnear, double tfar,
                        std::uint32_t mask = kAllLinkClasses) const;

  private:
    void* m_device = nullptr; // RTCDevice
    void* m_scene = nullptr;  // RTCScene
    glm::dvec3 m_origin{0.0};
    std::vector<Part> m_parts;
    std::vector<std::uint32_t> m_masks; // per geometry; the filters read theirs
    MaskMethod m_maskMethod = MaskMethod::None;
    std::int64_t m_triangles = 0;
    QString m_error;
};

} // namespace lr
