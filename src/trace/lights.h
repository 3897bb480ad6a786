// The emitters of a traced scene besides the environment (environmentmap.h): the rig's lights in world
// units, and the model's emissive triangles.
//   - Point and spot lights: core's lightArrival (falloff with KHR_lights_punctual's range window, cones)
//     and pbrLobes, the emitter a point for shading; its shadow ray goes to a uniform point of the disk
//     of diameter shadow.size facing the surface (0: the centre), so a point light's soft shadow is the
//     reference's visibility (scene/referencetrace.h) in expectation.
//   - Directional lights: the light's illuminance along its direction; the shadow ray leaves within the
//     cone of its angular size (shadow.angle), as the reference's.
//   - Rect and disk lights: Lambertian emitters of radiance colour × intensity from their front (or both)
//     sides, hit by BSDF rays too (MIS). A rect is sampled uniformly in the solid angle it subtends
//     (Ureña, Fajardo and King 2013, "An Area-Preserving Parametrization for Spherical Rectangles"), so a
//     large or near softbox costs no more noise than a small far one; a disk (no such closed form), and a
//     rect under 1e-4 sr, uniformly by area, the density converted to solid angle.
//   - Barn doors on a rect (core/barndoors.h): the part of the emitter a point sees is one rectangle,
//     sampled (and hit) as the emitter.
//   - Emissive triangles: chosen by emitted power (area × luminance of the emissive factor), a uniform
//     point in the triangle; both sides emit.
// Rim lights are not physical: the path tracer leaves them out (TraceScene::warnings says so).
#pragma once

#include "core/lightlink.h"
#include "core/shadetypes.h"
#include "scene/referencetrace.h"

#include <glm/vec2.hpp>
#include <vector>

namespace lr::trace {

struct TraceLight {
    lighting::ShadeLight<double> shade; // world space (prepareLight with the identity view)
    ShadowEmitter emitter;              // the shadow ray's target (referencetrace.h), world
    double area = 0.0;                  // rect, disk: world units²
    int group = 0;                      // its light group: an index into TraceScene::groups()
    // Light linking (core/lightlink.h LinkResolution::litMask): bit c when it lights the parts of
    // lighting class c (TraceScene::lights). Its shadow's is emitter.shadowMask.
    std::uint32_t litMask = kAllLinkClasses;
};

// Where the ray (unit dir) meets an area light's emitting side, at distance *t; false when it misses.
bool hitAreaLight(const TraceLight& light, const glm::dvec3& origin, const glm::dvec3& dir, double* t);
// A uniform point of the area light's shape from two uniform numbers.
glm::dvec3 sampleAreaLight(const TraceLight& light, double u1, double u2);

// A point of the area light for shading `from`, and its density per steradian (0: none to take).
struct AreaLightSample {
    glm::dvec3 point{0.0};
    double pdf = 0.0;
};
AreaLightSample sampleAreaLightFrom(const TraceLight& light, const glm::dvec3& from, double u1, double u2);
// The density per steradian with which sampleAreaLightFrom(light, from, …) draws the direction `dir`
// (unit) that meets the light at distance t.
double areaLightPdf(const TraceLight& light, const glm::dvec3& from, const glm::dvec3& dir, double t);
// Whether an area light emits towards `point` (its front side, or both sides when two-sided).
bool areaLightFaces(const TraceLight& light, const glm::dvec3& point);
// Whether the emitter's point `onEmitter` lights `from`: no barn-door flap between them (core/barndoors.h).
// hitAreaLight misses, and sampleAreaLightFrom samples only, the part of a rect its flaps leave visible.
bool areaLightSees(const TraceLight& light, const glm::dvec3& from, const glm::dvec3& onEmitter);

// A uniform point of a triangle from two uniform numbers, as barycentrics (b1, b2) of vertices 1 and 2.
glm::dvec2 sampleTriangle(double u1, double u2);

class EmissiveTriangles {
  public:
    struct Triangle {
        glm::dvec3 p0, p1, p2; // world
        std::uint32_t part = 0, triangle = 0;
        double area = 0.0;
    };
    // Adds a part's triangles (all of its mesh's, in order) with weight area × `luminance`.
    void add(std::uint32_t part, std::vector<Triangle> triangles, double luminance);
    void finish(std::size_t parts); // builds the CDF and the part -> first emitter index map
    bool empty() const { return m_triangles.empty() || !(m_total > 0.0); }
    // The chosen triangle and its probability.
    const Triangle& pick(double u, double* probability) const;
    // The density per unit area with which sampling picks a point of the triangle of `part` (its
    // probability / its area), 0 when it emits nothing.
    double areaDensity(std::uint32_t part, std::uint32_t triangle) const;
    std::size_t size() const { return m_triangles.size(); }

  private:
    std::vector<Triangle> m_triangles;
    std::vector<double> m_weight, m_cdf;
    std::vector<long> m_first; // per part: index of its first triangle, -1 none
    double m_total = 0.0;
};

} // namespace lr::trace
