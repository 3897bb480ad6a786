// A light rig as the editor, the renderer and the file format see it. Plain data in double precision;
// angles are stored in degrees as in files (the formulas take radians), directions are unit length.
#pragma once

#include "environment.h"
#include "lightlink.h"
#include "lightshaping.h"
#include "lighttypes.h"
#include "types.h"

#include <QString>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

namespace lr {

struct Falloff {
    FalloffModel model = FalloffModel::None;
    double range =
        -1.0; // < 0: no range (only for inverse-polynomial and inverse-square, where it is optional)
    double exponent = 2.0;                                // range-power
    double constant = 1.0, linear = 0.0, quadratic = 0.0; // inverse-polynomial
    bool hasRange() const { return range >= 0.0; }
    bool operator==(const Falloff&) const = default;
};

struct Cone {
    ConeModel model = ConeModel::Smooth;
    double inner = 20.0;   // degrees, half-angle from the axis (smooth only)
    double outer = 35.0;   // degrees, half-angle from the axis
    double exponent = 1.0; // angle-power and smooth
    bool operator==(const Cone&) const = default;
};

// A light's shadow (issue 14; docs/rig-format.md "shadow"). Only types whose traits say castsShadows use it.
// Bias and normal offset are in shadow-map texels (scale-free: a texel's footprint at the receiver), the
// softness comes from the emitter's physical size: 0 is a hard shadow in every tier.
struct Shadow {
    bool enabled = false;
    int resolution =
        1024;          // map texels per side (per cube face for a point light): 256 ... 4096, a power of 2
    double bias = 1.0; // depth bias, texels along the light's direction: 0 ... 16
    double normalOffset = 1.0; // the receiver moved along its normal, texels: 0 ... 16
    double size = 0.0;         // point and spot: the emitter's diameter in rig units (>= 0)
    double angle = 0.0;        // directional: the emitter's angular diameter in degrees, 0 ... 10 (sun 0.53)
    bool operator==(const Shadow&) const = default;
};

// An area light's emitter (issue 16; docs/rig-format.md "area"): a rectangle (width × height) or a disk
// (radius) centred on Light::position, facing Light::direction (the side it emits from; both sides when
// twoSided), rotated by `roll` degrees about that direction. Its in-plane axes are areaAxes() (prepare.h):
// with roll 0 the width runs horizontally (perpendicular to world +Y and the direction) and the height
// runs up. Sizes are in rig units (scaled with the model in a model-space rig). Its intensity is the
// emitting face's radiance: nits (cd/m²) under physically based shading, as three.js's RectAreaLight;
// lighting_area.h defines what it adds under either shading.
struct AreaShape {
    double width = 1.0;  // rect, >= 0
    double height = 1.0; // rect, >= 0
    double radius = 0.5; // disk, >= 0
    double roll = 0.0;   // degrees, -180 ... 180
    bool twoSided = false;
    bool operator==(const AreaShape&) const = default;
};

// At most this many lights cast shadows at once (one map each; a point light's six faces count as one
// light): the rig reader refuses more, the editor says so instead of enabling another.
inline constexpr int kMaxShadowCasters = 16;

struct Light {
    QString name;
    // The light group it renders into (issue 37, core/lightgroups.h): lights with the same group share one
    // per-group image; empty: a group of its own, named after the light.
    QString group;
    LightType type = LightType::Point;
    bool enabled = true;
    glm::dvec3 color{1.0};
    double intensity = 1.0;
    std::optional<double> temperature;            // kelvin, tints color
    glm::dvec3 position{0.0};                     // usesPosition()
    glm::dvec3 direction{0.0, -1.0, 0.0};         // usesDirection(): where the light travels
    Falloff falloff;                              // usesFalloff()
    Cone cone;                                    // usesCone()
    DiffuseModel diffuse = DiffuseModel::Lambert; // usesSurfaceModels()
    bool specularIsColor = false;                 // file wrote an RGB colour rather than a factor
    glm::dvec3 specular{1.0};                     // factor f is stored as (f, f, f)
    std::optional<glm::dvec3> ambient;            // usesSurfaceModels()
    double rimExponent = 1.3;                     // usesRimExponent()
    Shadow shadow;                                // castsShadows()
    AreaShape area;                               // isArea()
    LightLink link; // which parts it lights and which cast its shadow (core/lightlink.h; format version 3)
    // Shaping (issue 39, core/lightshaping.h): an IES profile (point, spot), a gobo (spot), barn doors
    // (rect).
    std::optional<IesSpec> ies;
    std::optional<GoboSpec> gobo;
    std::optional<BarnDoors> barnDoors;

    // What its type uses (lighttypes.h).
    bool usesPosition() const { return traitsOf(type).usesPosition; }
    bool usesDirection() const { return traitsOf(type).usesDirection; }
    bool usesFalloff() const { return traitsOf(type).usesFalloff; }
    bool usesCone() const { return traitsOf(type).usesCone; }
    bool usesSurfaceModels() const { return traitsOf(type).usesSurfaceModels; } // diffuse, specular, ambient
    bool usesRimExponent() const { return traitsOf(type).usesRimExponent; }
    bool castsShadows() const { return traitsOf(type).castsShadows; }
    bool isArea() const { return traitsOf(type).isArea; } // rect, disk: Light::area
    // Whether this light casts a shadow now: enabled, of a type that can, with its shadow on.
    bool hasShadow() const { return enabled && castsShadows() && shadow.enabled; }
    // The colour actually emitted: color tinted by temperature (if any), linear RGB.
    glm::dvec3 effectiveColor() const;
    bool operator==(const Light&) const = default;
};

struct Shading {
    ShadingModel model = ShadingModel::Classic;
    // Classic only (kept, neither read nor written, under Pbr):
    SpecularModel specular = SpecularModel::Phong;
    ViewerModel viewer = ViewerModel::Local;
    double shininess = 32.0; // used when the material has none
    bool operator==(const Shading&) const = default;
};

// The ground plane under the model (issue 14): horizontal (normal +Y in the rig's world), at the model's
// lowest point, as wide as kGroundExtent model radii around the model's centre.
struct Ground {
    GroundMode mode = GroundMode::Off;
    glm::dvec3 color{0.8}; // linear albedo of a visible ground (a catcher shows only its shadows)
    bool operator==(const Ground&) const = default;
};
inline constexpr double kGroundExtent = 10.0;

// A camera view saved with the rig (docs/rig-format.md "view" and "views", issue 41): where the eye is,
// what it looks at, the up hint and the vertical field of view, in world units (as the viewport's camera).
// A bookmark has a name; the rig's own "view" (the camera when it was saved) has none.
struct RigView {
    QString name;
    glm::dvec3 eye{0.0, 0.0, 5.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double yfovDeg = 45.0;
    bool operator==(const RigView&) const = default;
};
constexpr int kMaxRigViews = 64; // named views in a rig

struct Rig {
    QString name;
    RigSpace space = RigSpace::World;
    glm::dvec3 ambient{0.0};
    Shading shading;
    Ground ground;
    Environment environment; // issue 15: none by default
    std::vector<Light> lights;
    std::optional<RigView> view; // the camera as the rig was last saved (restored on open)
    std::vector<RigView> views;  // named view bookmarks, names unique
    bool operator==(const Rig&) const = default;
};

// Every light's IES and gobo file resolved against the rig's folder (IesSpec::resolved): readRigFile does it
// with the file's folder; whoever sets a file (the editor) or moves a rig does it again.
void resolveLightFiles(Rig& rig, const QString& rigFolder);

// A default-constructed light of the given type with sensible, valid parameters (used by "Add light").
Light makeLight(LightType type, const QString& name);

} // namespace lr
