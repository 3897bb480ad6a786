// From a Rig (file units, degrees, world or model space) to ShadeLights in view space.
#pragma once

#include "rig.h"
#include "shade.h"

#include <glm/mat4x4.hpp>
#include <vector>

namespace lr {

// Where a rig in `model` space is anchored: the model's bounding sphere (world units).
struct SceneFrame {
    glm::dvec3 center{0.0};
    double radius = 1.0;
};

// Position of a rig point in world units.
glm::dvec3 rigToWorld(const Rig& rig, const SceneFrame& frame, const glm::dvec3& p);
// Inverse of rigToWorld (for gizmo drags).
glm::dvec3 worldToRig(const Rig& rig, const SceneFrame& frame, const glm::dvec3& p);
// Multiplier from world distances to the rig's distance units (1 / radius in model space).
double distanceScale(const Rig& rig, const SceneFrame& frame);

// Whether a light can add anything to a sphere (world units): false for disabled lights and for point
// and spot lights whose range ends before the sphere. Used to skip lights, never to approximate them.
bool lightReaches(const Rig& rig, const SceneFrame& frame, const Light& light, const glm::dvec3& center,
                  double radius);

// An area light's in-plane axes (unit, x × y = -direction) in the rig's (and the world's) orientation:
// with roll 0, x = direction × world +Y (horizontal) and y = x × direction (up); where the direction is
// vertical (within 1e-6), x is world +X. `roll` (degrees) turns both right-handedly about the direction
// (counter-clockwise as seen from the lit side).
struct AreaAxes {
    glm::dvec3 x{1.0, 0.0, 0.0};
    glm::dvec3 y{0.0, 1.0, 0.0};
};
AreaAxes areaAxes(const glm::dvec3& direction, double rollDegrees);

// One light in view space (view = world -> view matrix, double precision).
lighting::ShadeLight<double> prepareLight(const Rig& rig, const SceneFrame& frame, const glm::dmat4& view,
                                          const Light& light);

// Enabled lights, in rig order (solo/mute applied by the caller through `enabled`).
std::vector<lighting::ShadeLight<double>> prepareLights(const Rig& rig, const SceneFrame& frame,
                                                        const glm::dmat4& view);

lighting::ShadeSettings<double> prepareSettings(const Rig& rig, const SceneFrame& frame);

// Linear RGB of a black body at `kelvin` (clamped to 1000..40000), normalised so its largest component is 1.
glm::dvec3 temperatureToRgb(double kelvin);

template <typename T> lighting::ShadeLight<T> castLight(const lighting::ShadeLight<double>& l) {
    lighting::ShadeLight<T> o;
    o.type = l.type;
    o.position = lighting::Vec3<T>(l.position);
    o.direction = lighting::Vec3<T>(l.direction);
    o.color = lighting::Vec3<T>(l.color);
    o.specular = lighting::Vec3<T>(l.specular);
    o.ambient = lighting::Vec3<T>(l.ambient);
    o.falloff = l.falloff;
    o.range = T(l.range), o.falloffExponent = T(l.falloffExponent);
    o.constant = T(l.constant), o.linear = T(l.linear), o.quadratic = T(l.quadratic);
    o.cone = l.cone;
    o.cosInner = T(l.cosInner), o.cosOuter = T(l.cosOuter), o.outer = T(l.outer);
    o.coneExponent = T(l.coneExponent);
    o.diffuse = l.diffuse;
    o.rimExponent = T(l.rimExponent);
    o.axisX = lighting::Vec3<T>(l.axisX);
    o.axisY = lighting::Vec3<T>(l.axisY);
    o.halfWidth = T(l.halfWidth), o.halfHeight = T(l.halfHeight);
    o.twoSided = l.twoSided;
    o.barnDepth = T(l.barnDepth), o.barnExtent = T(l.barnExtent);
    o.gobo = l.gobo, o.goboHalf = T(l.goboHalf);
    o.ies = l.ies, o.iesScale = T(l.iesScale);
    o.iesNadir = lighting::Vec3<T>(l.iesNadir);
    o.iesX = lighting::Vec3<T>(l.iesX), o.iesY = lighting::Vec3<T>(l.iesY);
    return o;
}

} // namespace lr
