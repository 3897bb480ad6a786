// Viewport picking and drag geometry on the CPU, independent of GL and widgets (unit-testable):
// project points to the screen, cast rays, pick the nearest light gizmo within a pixel radius, hit the
// model's triangles, and turn mouse motion into world-space moves and cone angles.
// Screen coordinates are widget pixels, origin top-left, y down.
#pragma once

#include <QPointF>
#include <QSizeF>
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

namespace lr {

struct Model;

struct Ray {
    glm::dvec3 origin{0.0};
    glm::dvec3 direction{0.0, 0.0, -1.0}; // unit
    glm::dvec3 at(double t) const { return origin + t * direction; }
};

class ScreenProjector {
  public:
    ScreenProjector() = default;
    ScreenProjector(const glm::dmat4& view, const glm::dmat4& projection, const QSizeF& size);

    // Screen position of a world point; nullopt when it is behind the camera (or at its plane).
    std::optional<QPointF> project(const glm::dvec3& world) const;
    // World-space ray through a screen position: from the eye (perspective) or the near plane (orthographic).
    Ray ray(const QPointF& screen) const;
    // Unit world-space direction the camera looks along.
    glm::dvec3 viewDirection() const;
    glm::dvec3 eye() const;
    bool isOrthographic() const;
    // View-space depth (distance along the view direction) of a world point.
    double depth(const glm::dvec3& world) const;
    // World units per screen pixel (vertically) at a view depth.
    double worldPerPixel(double depth) const;
    const QSizeF& size() const { return m_size; }

  private:
    glm::dmat4 m_view{1.0}, m_proj{1.0}, m_inverseViewProj{1.0}, m_inverseView{1.0};
    QSizeF m_size{1.0, 1.0};
};

// Index of the anchor nearest to `screen` within maxPixels (ties: nearer the camera), or -1.
int pickNearest(const ScreenProjector& projector, const std::vector<glm::dvec3>& anchors,
                const QPointF& screen, double maxPixels);

// Ray parameter of the intersection with a plane (point, normal), or nullopt when parallel/behind.
std::optional<double> intersectPlane(const Ray& ray, const glm::dvec3& point, const glm::dvec3& normal);

// Nearest hit of the ray with the model's triangles (world space), or nullopt.
std::optional<glm::dvec3> intersectModel(const Model& model, const Ray& ray);
// The same hit with the surface normal there (world, unit, turned to face the ray's origin): the shading
// normal, i.e. the triangle's vertex normals interpolated at the hit (what the renderer lights, before any
// normal map), or the triangle's geometric normal where the vertex normals are degenerate.
struct ModelHit {
    glm::dvec3 point{0.0};
    glm::dvec3 normal{0.0, 0.0, 1.0};
    std::size_t mesh = 0; // index into Model::meshes: the part light linking names (scene/linkparts.h)
};
std::optional<ModelHit> intersectModelWithNormal(const Model& model, const Ray& ray);

// Mirror direction of `incident` (travelling towards the surface) about the unit normal `normal`.
glm::dvec3 mirrorDirection(const glm::dvec3& incident, const glm::dvec3& normal);

// Parameter t of the point origin + t * axis (axis unit) nearest to the ray (the closest points of two
// lines), or nullopt when the ray runs (nearly) along the axis.
std::optional<double> closestOnAxis(const Ray& ray, const glm::dvec3& origin, const glm::dvec3& axis);

// Whether `screen` lies inside the projected polygon (even-odd rule), or within maxPixels of its edges.
// False when any corner is behind the camera.
bool hitsPolygon(const ScreenProjector& projector, const std::vector<glm::dvec3>& polygon,
                 const QPointF& screen, double maxPixels);

// Moves `start` so that it follows the mouse from `from` to `to` in the plane through `start` facing
// the camera. Returns `start` when the plane cannot be hit.
glm::dvec3 dragInViewPlane(const ScreenProjector& projector, const glm::dvec3& start, const QPointF& from,
                           const QPointF& to);
// Moves `start` along the line of sight through it (so it stays under the cursor): dragging up pushes it
// away from the camera, `unitsPerPixel` world units a pixel.
glm::dvec3 dragAlongViewAxis(const ScreenProjector& projector, const glm::dvec3& start, const QPointF& from,
                             const QPointF& to, double unitsPerPixel);

// Points on a spot's outer cone rim (world) at `length` along the axis, for picking its edge.
std::vector<glm::dvec3> coneRim(const glm::dvec3& apex, const glm::dvec3& axis, double outerDegrees,
                                double length, int segments = 32);
// Distance in pixels from `screen` to the projected rim polygon (infinity when none is visible).
double distanceToConeRim(const ScreenProjector& projector, const std::vector<glm::dvec3>& rim,
                         const QPointF& screen);
// The half-angle (degrees, 0..90) of the cone whose edge passes under the mouse. Seen from the side, the
// cursor ray meets the plane through the axis that faces the camera best and the angle is between the axis
// and apex→hit; seen along the axis (|axis·view| > 0.5), the ray meets the disc perpendicular to the axis at
// `rimDistance` from the apex and the angle is atan(radius / rimDistance).
std::optional<double> coneAngleUnderCursor(const ScreenProjector& projector, const glm::dvec3& apex,
                                           const glm::dvec3& axis, const QPointF& screen, double rimDistance);

} // namespace lr
