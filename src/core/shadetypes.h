// What whole-surface shading works on: one light prepared in view space, the surface point and the rig's
// settings, templated on the scalar (shade.h evaluates them; lighting_area.h the area lights).
#pragma once

#include "ies.h"
#include "lighting.h"
#include "types.h"

namespace lr {
struct GoboImage;
}

namespace lr::lighting {

// One light prepared for evaluation: view-space geometry, intensity and temperature folded into colours,
// angles as cosines/radians. Built from a Light by prepareLights() (prepare.h).
template <typename T> struct ShadeLight {
    LightType type = LightType::Point;
    Vec3<T> position{0};         // view space (point, spot)
    Vec3<T> direction{0, 0, -1}; // view space, unit: where the light travels (spot, directional, rim)
    Vec3<T> color{1};            // effective colour × intensity
    Vec3<T> specular{1};         // Sc × intensity
    Vec3<T> ambient{0};          // Ac × intensity
    FalloffModel falloff = FalloffModel::None;
    T range = T(-1), falloffExponent = T(2), constant = T(1), linear = T(0), quadratic = T(0);
    ConeModel cone = ConeModel::Smooth;
    T cosInner = T(1), cosOuter = T(0), outer = T(1), coneExponent = T(1); // outer in radians
    DiffuseModel diffuse = DiffuseModel::Lambert;
    T rimExponent = T(1.3);
    // Area lights (rect, disk; issue 16): the emitter's in-plane axes (view space, unit; axisX × axisY =
    // -direction, prepare.h areaAxes) and half extents in view units (a disk: halfWidth = halfHeight = its
    // radius). `position` is its centre and `direction` its normal, the side it emits from.
    Vec3<T> axisX{1, 0, 0}, axisY{0, 1, 0};
    T halfWidth = T(0), halfHeight = T(0);
    bool twoSided = false;
    // A spot's gobo (issue 39, core/gobo.h): the image (not owned; nullptr: none), its half extent
    // h = tan(outer) × scale; axisX, axisY are then its frame (areaAxes(direction, gobo rotation)).
    const GoboImage* gobo = nullptr;
    T goboHalf = T(1);
    // Barn doors (rect; issue 39, core/barndoors.h): the flaps' far edge `barnDepth` in front of the emitter
    // and `barnExtent` outside its edges, view units; barnDepth 0: none.
    T barnDepth = T(0), barnExtent = T(0);
    // An IES profile (issue 39, core/iesshade.h; null: none, and nothing below is read): the attenuation is
    // scaled by iesScale × its candela toward the surface, in the photometric frame (view space, unit):
    // vertical angle 0 along iesNadir, horizontal 0 along iesX, 90 along iesY. Whoever fills it keeps the
    // profile alive.
    const IesProfile* ies = nullptr;
    Vec3<T> iesNadir{0, -1, 0}, iesX{1, 0, 0}, iesY{0, 0, 1};
    T iesScale = T(1);
};

template <typename T> struct Surface {
    Vec3<T> position{0};     // view space
    Vec3<T> normal{0, 0, 1}; // view space, unit
    Vec3<T> albedo{1};
    Vec3<T> specular{1}; // material specular colour (ks)
    Vec3<T> emissive{0};
    T shininess = T(32); // classic
    // Physically based (glTF metal-rough): albedo is the base colour; occlusion scales ambient light only.
    T metallic = T(0), roughness = T(1), occlusion = T(1);
};

template <typename T> struct ShadeSettings {
    ShadingModel model = ShadingModel::Classic;
    SpecularModel specular = SpecularModel::Phong;
    ViewerModel viewer = ViewerModel::Local;
    Vec3<T> ambient{0};
    T distanceScale = T(1); // 1 / bounding radius for rigs in model space, else 1
};

} // namespace lr::lighting
