// The traced visibility of the double-precision reference (issue 14; docs/quality.md, "Shadows"): shadow
// rays against the model's triangles (and the ground plane's two, groundPlane() in src/model/ground.h),
// through Embree 3 (Debian's libembree-dev; the scene is embreescene.h's, which the path tracer shares).
// The scene is built once per reference job and is read-only afterwards, so the job's row tasks trace in
// parallel.
//
// Method, per surface point and casting light:
// - the ray origin is the point lifted along the geometric normal of the triangle the camera sees there
//   (the first hit on the eye's ray through the point) by kShadowRayEpsilon model radii;
// - a light of size (angle) 0 gets one ray to its centre (along its direction);
// - a point or spot light of size > 0 is a disk of diameter `size` (rig units scaled to world units as
//   positions are) facing the point; a directional light of angle > 0 a cone of that angular diameter;
//   both are sampled stratified and jittered (equal-area disk mapping). First a probe: kShadowRimSamples
//   rays to the emitter's rim and kShadowProbeSamples inside; when they all agree the point is fully lit
//   or fully shadowed, else kShadowSamples fresh rays decide.
// - an area light (rect, disk) is its own shape: the rect c ± hw·X ± hh·Y or the disk of its radius in
//   its plane (X, Y from areaAxes, world units as positions), sampled the same way (rect: jittered strata
//   of the rect, its perimeter for the rim; disk: the equal-area map, its circle); the fraction is of its
//   area. A point behind a one-sided emitter's plane gets 1: the light does not reach it, so nothing
//   shadows it (its shading is 0 there).
#pragma once

#include "core/lightlink.h"
#include "core/prepare.h"
#include "embreescene.h"
#include "model/model.h"

#include <QString>
#include <cstdint>
#include <memory>

namespace lr {

// The offset of a shadow ray's origin along the geometric normal, in model radii (Bounds::radius()).
inline constexpr double kShadowRayEpsilon = 1e-4;
// Rays of the probe (rim, and inside: a square number, strata n × n) and of the full estimate (square).
inline constexpr int kShadowRimSamples = 16;
inline constexpr int kShadowProbeSamples = 16;
inline constexpr int kShadowSamples = 256;

// A light's emitter as the shadow rays see it, world units.
struct ShadowEmitter {
    bool casts = false;       // Light::hasShadow()
    bool directional = false; // else a point or spot light at `position`
    glm::dvec3 position{0.0};
    glm::dvec3 toLight{0.0, 1.0, 0.0}; // directional: unit, towards the light (against its direction)
    double radius = 0.0;               // point, spot: the emitter disk's radius
    double halfAngle = 0.0;            // directional: the cone's half-angle, radians
    // Area lights: the shape (None: not an area light), the unit in-plane axes and where it shines (world),
    // its half extents (world units; a disk's are both its radius), and whether both sides emit.
    enum class Area { None, Rect, Disk } area = Area::None;
    glm::dvec3 axisX{1.0, 0.0, 0.0}, axisY{0.0, 1.0, 0.0}, normal{0.0, -1.0, 0.0};
    double halfWidth = 0.0, halfHeight = 0.0;
    bool twoSided = false;
    // Shadow linking (core/lightlink.h): the light's shadowMask; its rays pass the parts whose shadow
    // class it lacks (EmbreeScene's part masks). All ones: every part casts.
    std::uint32_t shadowMask = kAllLinkClasses;
};

ShadowEmitter shadowEmitter(const Rig& rig, const SceneFrame& frame, const Light& light);

class ShadowTracer {
  public:
    // The model's triangles, plus the ground plane's when `ground`: the parts of scene/linkparts.h (the
    // model's meshes, then the ground as one part). `partMasks`: EmbreeScene's, per part (empty: none).
    // Check ok() (Embree can fail).
    ShadowTracer(const Model& model, bool ground, std::vector<std::uint32_t> partMasks = {});
    ~ShadowTracer();
    ShadowTracer(const ShadowTracer&) = delete;
    ShadowTracer& operator=(const ShadowTracer&) = delete;

    bool ok() const { return m_scene && m_scene->ok(); }
    QString error() const { return m_scene ? m_scene->error() : QString(); }
    double epsilon() const { return m_epsilon; } // world units
    std::int64_t triangles() const { return m_scene ? m_scene->triangles() : 0; }

    // The unit geometric normal of the triangle the eye sees at `point` (both world), turned towards the
    // eye; `fallback` when the eye's ray hits nothing near the point.
    glm::dvec3 geometricNormal(const glm::dvec3& eye, const glm::dvec3& point,
                               const glm::dvec3& fallback) const;
    // The same, and which part that triangle is of (its linking part; -1 when the eye's ray hits nothing
    // near the point).
    struct Seen {
        glm::dvec3 normal{0.0, 0.0, 1.0};
        int part = -1;
    };
    Seen surfaceSeen(const glm::dvec3& eye, const glm::dvec3& point, const glm::dvec3& fallback) const;
    // Whether the segment from `origin` along unit `dir` up to `distance` (may be infinite) hits a triangle
    // (of a part whose mask shares a bit with `mask`).
    bool occluded(const glm::dvec3& origin, const glm::dvec3& dir, double distance,
                  std::uint32_t mask = kAllLinkClasses) const;
    // The fraction of the emitter that `point` (on a surface of unit geometric normal `normal`) sees,
    // 0..1. `seed` decorrelates the jitter of neighbouring points; `samples` overrides kShadowSamples.
    double visibility(const glm::dvec3& point, const glm::dvec3& normal, const ShadowEmitter& emitter,
                      std::uint32_t seed, int samples = kShadowSamples) const;

  private:
    Model m_groundQuad; // the ground plane's two triangles, when asked for
    std::unique_ptr<EmbreeScene> m_scene;
    double m_epsilon = 0.0;
};

} // namespace lr
