// What each light type is: one row per LightType, in enum order. Everything that used to switch on a type or
// count the types reads this table instead: which values a light uses (Light::uses*, the rig reader and
// writer, the editor's properties), whether a range can bound its reach (culling, clustered shading), its
// gizmo, its glTF counterpart, makeLight's defaults, its label and the bench's type list. Adding a type:
// docs/architecture.md, "Where to add things".
#pragma once

#include "types.h"

#include <QString>
#include <array>
#include <optional>

namespace lr {

// The viewport's point sprite for a light (shaders/gizmo.frag's shape index; +8 when selected).
enum class GizmoShape { Disc = 0, RingedDisc = 1, Sun = 2, HollowRing = 3, Square = 4, FramedDisc = 5 };

struct LightTypeTraits {
    LightType type;
    const char* label; // UI, translatable in context "lr::LightType": "Point"
    // Which values of a Light the type uses (the rest are kept but neither read, written nor shown).
    bool usesPosition;
    bool usesDirection; // where the light travels
    bool usesFalloff;
    bool usesCone;
    bool usesSurfaceModels; // diffuse, specular, ambient
    bool usesRimExponent;
    bool boundable;    // a falloff range can bound its reach (culling, clustered shading)
    bool castsShadows; // Light::shadow applies (a map of its own: perspective, orthographic or cube)
    // Area lights (issue 16): it emits from a surface (Light::area: one- or two-sided, its roll about its
    // direction; a shadow's softness comes from its size, not Shadow::size), a rectangle (width, height)
    // or a disk (radius).
    bool isArea;
    bool usesRectSize;
    bool usesDiskRadius;
    GizmoShape gizmo;      // its sprite
    bool alwaysShowsRange; // its range sphere is drawn also when it is not selected
    const char* gltfType;  // KHR_lights_punctual "type" (also Assimp's light source), nullptr when none
    // makeLight's defaults (position (2, 2, 2)): the direction before normalising, {0, 0, 0} meaning towards
    // the origin; a range-power falloff of this range (where it uses a falloff; the cone is Cone{}).
    std::array<double, 3> defaultDirection;
    double defaultRange;
    double benchIntensity; // summed intensity of a procedural bench rig of lights of this type
    // The unit of its intensity under physically based shading (KHR_lights_punctual: candela, lux; an area
    // light's luminance in nits), as the Properties dock shows it; nullptr: none (its term is classic).
    const char* pbrUnit;
};

inline constexpr std::array<LightTypeTraits, size_t(enumCount<LightType>())> kLightTypeTraits{{
    {.type = LightType::Point,
     .label = "Point",
     .usesPosition = true,
     .usesDirection = false,
     .usesFalloff = true,
     .usesCone = false,
     .usesSurfaceModels = true,
     .usesRimExponent = false,
     .boundable = true,
     .castsShadows = true,
     .isArea = false,
     .usesRectSize = false,
     .usesDiskRadius = false,
     .gizmo = GizmoShape::Disc,
     .alwaysShowsRange = true,
     .gltfType = "point",
     .defaultDirection = {0, 0, 0},
     .defaultRange = 8.0,
     .benchIntensity = 6.0,
     .pbrUnit = "cd"},
    {.type = LightType::Spot,
     .label = "Spot",
     .usesPosition = true,
     .usesDirection = true,
     .usesFalloff = true,
     .usesCone = true,
     .usesSurfaceModels = true,
     .usesRimExponent = false,
     .boundable = true,
     .castsShadows = true,
     .isArea = false,
     .usesRectSize = false,
     .usesDiskRadius = false,
     .gizmo = GizmoShape::RingedDisc,
     .alwaysShowsRange = false,
     .gltfType = "spot",
     .defaultDirection = {0, 0, 0},
     .defaultRange = 8.0,
     .benchIntensity = 6.0,
     .pbrUnit = "cd"},
    {.type = LightType::Directional,
     .label = "Directional",
     .usesPosition = false,
     .usesDirection = true,
     .usesFalloff = false,
     .usesCone = false,
     .usesSurfaceModels = true,
     .usesRimExponent = false,
     .boundable = false,
     .castsShadows = true,
     .isArea = false,
     .usesRectSize = false,
     .usesDiskRadius = false,
     .gizmo = GizmoShape::Sun,
     .alwaysShowsRange = false,
     .gltfType = "directional",
     .defaultDirection = {-1, -1, -1},
     .defaultRange = -1.0,
     .benchIntensity = 1.6,
     .pbrUnit = "lx"},
    {.type = LightType::Rim,
     .label = "Rim",
     .usesPosition = false,
     .usesDirection = true,
     .usesFalloff = false,
     .usesCone = false,
     .usesSurfaceModels = false,
     .usesRimExponent = true,
     .boundable = false,
     .castsShadows = false,
     .isArea = false,
     .usesRectSize = false,
     .usesDiskRadius = false,
     .gizmo = GizmoShape::HollowRing,
     .alwaysShowsRange = false,
     .gltfType = nullptr,
     .defaultDirection = {0, 0, -1},
     .defaultRange = -1.0,
     .benchIntensity = 0.8,
     .pbrUnit = nullptr},
    {.type = LightType::Rect,
     .label = "Rect",
     .usesPosition = true,
     .usesDirection = true,
     .usesFalloff = false,
     .usesCone = false,
     .usesSurfaceModels = true,
     .usesRimExponent = false,
     .boundable = false,
     .castsShadows = true,
     .isArea = true,
     .usesRectSize = true,
     .usesDiskRadius = false,
     .gizmo = GizmoShape::Square,
     .alwaysShowsRange = false,
     .gltfType = nullptr,
     .defaultDirection = {0, 0, 0},
     .defaultRange = -1.0,
     .benchIntensity = 20.0,
     .pbrUnit = "nits"},
    {.type = LightType::Disk,
     .label = "Disk",
     .usesPosition = true,
     .usesDirection = true,
     .usesFalloff = false,
     .usesCone = false,
     .usesSurfaceModels = true,
     .usesRimExponent = false,
     .boundable = false,
     .castsShadows = true,
     .isArea = true,
     .usesRectSize = false,
     .usesDiskRadius = true,
     .gizmo = GizmoShape::FramedDisc,
     .alwaysShowsRange = false,
     .gltfType = nullptr,
     .defaultDirection = {0, 0, 0},
     .defaultRange = -1.0,
     .benchIntensity = 25.0,
     .pbrUnit = "nits"},
}};

constexpr int kLightTypeCount = int(kLightTypeTraits.size());
// A missing row is value-initialised (type Point, no label) and fails here.
static_assert(
    [] {
        for (int i = 0; i < kLightTypeCount; ++i)
            if (int(kLightTypeTraits[size_t(i)].type) != i || !kLightTypeTraits[size_t(i)].label)
                return false;
        return true;
    }(),
    "kLightTypeTraits: one row per LightType, in enum order");
static_assert(kLightTypeCount <= 8, "RigFeatures::lightTypes holds one bit per type in 8 bits");

constexpr const LightTypeTraits& traitsOf(LightType type) {
    return kLightTypeTraits[size_t(type)];
}

// Every type, in enum order (Add actions, the bench suite).
constexpr std::array<LightType, kLightTypeCount> allLightTypes() {
    std::array<LightType, kLightTypeCount> out{};
    for (int i = 0; i < kLightTypeCount; ++i)
        out[size_t(i)] = LightType(i);
    return out;
}

// The translated label: "Point".
QString lightTypeLabel(LightType type);
// The file names of the types that have a trait, for messages: "point and spot", "spot".
QString lightTypesWith(bool LightTypeTraits::*trait);
// The type of a glTF (KHR_lights_punctual) light type name; nullopt when LightRig has none.
std::optional<LightType> lightTypeFromGltf(const QString& gltfType);

} // namespace lr
