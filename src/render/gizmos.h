// Light gizmos and the ground grid as view-space line and point-sprite vertices, built on the CPU in
// double precision each frame (a few thousand vertices at most). No GL here.
#pragma once

#include "core/ies.h"
#include "core/prepare.h"
#include "model/model.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

namespace lr::render {

struct GizmoVertex {
    glm::vec3 position{0.0f}; // view space
    glm::vec4 color{1.0f};    // display colour (sRGB-encoded), straight alpha
    // Point sprites: size in pixels, shape (GizmoShape, core/lighttypes.h; +8 selected). Lines: 0, or
    // kGridShape for the ground grid (depth-tested against the model, fading with distance).
    glm::vec2 point{0.0f};
};

constexpr float kGridShape = 16.0f;

struct GizmoGeometry {
    std::vector<GizmoVertex> lines;  // GL_LINES pairs
    std::vector<GizmoVertex> points; // GL_POINTS
};

struct GizmoOptions {
    bool lights = true;
    // The lights' loaded IES profiles, per rig light (scene/lightassets.h; nullptr or shorter: none): a
    // light with one draws its distribution's shape (iesOutline).
    const std::vector<std::shared_ptr<const IesProfile>>* ies = nullptr;
    bool grid = false;
    std::vector<int> selected; // light indices
    double iconPixels = 14.0;
    double nearClip = 0.0; // view-space distance in front of the eye; geometry nearer is clipped away
};

// Selected lights' lines (sRGB, opaque: a saturated amber no light colour is drawn in at full alpha) and
// how much larger their icon is.
inline const glm::vec4 kSelectedColor{1.0f, 0.66f, 0.0f, 1.0f};
constexpr double kSelectedIconScale = 1.8;

// Where a directional or rim light's gizmo is drawn (world): outside the bounding sphere, upstream.
glm::dvec3 directionalAnchor(const SceneFrame& frame, const glm::dvec3& direction);

// An area light's outline (world): a rect's four corners, centre ± x·width/2 ± y·height/2 on areaAxes
// (core/prepare.h) in the order (+x+y, -x+y, -x-y, +x-y), or a disk's rim as `diskSegments` points from +x
// towards +y. Sizes are rig units, scaled to the world as positions are (distanceScale). Empty for other
// types.
std::vector<glm::dvec3> areaOutline(const Rig& rig, const SceneFrame& frame, const Light& light,
                                    int diskSegments = 48);

// The size handles of an area light (drawn and dragged when it alone is selected): a rect's edge midpoints
// (±x: width, ±y: height), a disk's rim at ±x and ±y (radius). `axis` is the unit direction from the centre.
enum class AreaSize { Width, Height, Radius };
struct AreaHandle {
    glm::dvec3 position{0.0}; // world
    glm::dvec3 axis{1.0, 0.0, 0.0};
    AreaSize size = AreaSize::Width;
};
std::vector<AreaHandle> areaHandles(const Rig& rig, const SceneFrame& frame, const Light& light);
constexpr double kAreaHandlePixels = 9.0;

// An IES light's distribution as the gizmo draws it (gizmos_ies.cpp; world space): the photometric
// diagram's two planes, C0-C180 and C90-C270, each a closed curve of points `at + w(θ, φ) × length ×
// I(θ, φ) / peak` for θ = 0 … 180° in `steps` steps (w the direction the profile's angles name,
// core/iesshade.h); empty for a profile without light.
std::vector<std::vector<glm::dvec3>> iesOutline(const Light& light, const IesProfile& profile,
                                                const glm::dvec3& at, double length, int steps = 36);

GizmoGeometry buildGizmos(const Rig& rig, const SceneFrame& frame, const Bounds& bounds,
                          const glm::dmat4& view, const GizmoOptions& options);

} // namespace lr::render
