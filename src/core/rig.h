// A light rig as the editor, the renderer and the file format see it. Plain data in double precision;
// angles are stored in degrees as in files (the formulas take radians), directions are unit length.
#pragma once

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

struct Light {
    QString name;
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

    // What its type uses (lighttypes.h).
    bool usesPosition() const { return traitsOf(type).usesPosition; }
    bool usesDirection() const { return traitsOf(type).usesDirection; }
    bool usesFalloff() const { return traitsOf(type).usesFalloff; }
    bool usesCone() const { return traitsOf(type).usesCone; }
    bool usesSurfaceModels() const { return traitsOf(type).usesSurfaceModels; } // diffuse, specular, ambient
    bool usesRimExponent() const { return traitsOf(type).usesRimExponent; }
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

struct Rig {
    QString name;
    RigSpace space = RigSpace::World;
    glm::dvec3 ambient{0.0};
    Shading shading;
    std::vector<Light> lights;
    bool operator==(const Rig&) const = default;
};

// A default-constructed light of the given type with sensible, valid parameters (used by "Add light").
Light makeLight(LightType type, const QString& name);

} // namespace lr
