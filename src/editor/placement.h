// Where "Add light" puts a new light: relative to the model, whatever its size. A new point or spot light
// sits on a sphere of kPlacementDistance bounding radii around the model's centre (the distance the studio
// presets use in model space), on the viewer's side and above, so it lights what the user is looking at;
// a spot and a directional light face the model's centre; a point or spot light's range is kPlacementRange
// radii, so it reaches all of the model. Successive lights walk around the viewer's side (they do not stack).
// A new area light (rect, disk; issue 16) is placed like a spot, faces the model's centre and is a softbox
// about the model's size: a rect kAreaPlacementSize radii square, a disk of that diameter.
// Positions, ranges and sizes are written in the rig's own space (world units, or radii in model space).
#pragma once

#include "core/prepare.h"
#include "core/rig.h"

#include <QString>
#include <glm/vec3.hpp>

namespace lr {

class Document;

constexpr double kPlacementDistance = 3.0;    // bounding radii from the model's centre
constexpr double kMinPlacementDistance = 1.6; // pulled in no closer than this to land in view
constexpr double kPlacementRange = 8.0;       // bounding radii
constexpr double kAreaPlacementSize = 1.0;    // a new rect's width and height, a new disk's diameter: radii

// What the placement needs to know about the scene and the view (world units).
struct PlacementView {
    SceneFrame frame;                       // the model's bounding sphere
    glm::dvec3 towardViewer{0.0, 0.0, 1.0}; // from the model towards the camera (need not be unit length)
    glm::dvec3 up{0.0, 1.0, 0.0};           // the camera's up
    // The camera's frustum, when known (the editor's view): a new light that would land outside it is pulled
    // in along its direction from the model's centre, no closer than kMinPlacementDistance radii, so that it
    // shows without the camera moving (issue 41: adding a light moved the camera, outside undo).
    bool hasCamera = false;
    glm::dvec3 eye{0.0, 0.0, 5.0};
    glm::dvec3 forward{0.0, 0.0, -1.0}; // unit, eye -> target
    double tanHalfFovY = 0.41421356;    // tan(yfov / 2)
    double aspect = 1.0;                // width / height
};

// Under physically based shading (rig.shading.model == Pbr) a new light is KHR_lights_punctual-like: an
// inverse-square falloff with the range window, a smooth cone of exponent 2 for spots, Lambert, and an
// intensity in candela (point, spot: kPbrPlacementIlluminance × distance², the distance from the model's
// centre in the rig's units) or lux (directional: kPbrPlacementIlluminance), so that a light placed as
// below lights a mid-grey model at about the level a classic default light does (docs/rig-format.md).
// Candela past the format's limit (kMaxRigIntensity: a world-space rig around a model over ~200 units
// across) are clamped to it: the light stays valid, the model is lit less.
// An area light gets the luminance (nits) that gives kPbrPlacementIlluminance at a point `distance` in front
// of its centre, facing it (areaIrradianceFactor), clamped to the format's limit. Under classic shading a
// new area light gets the intensity whose light at the model's centre equals a classic directional light of
// intensity kClassicAreaPlacementLevel head on (lighting_area.h: (1/π) × the same factor × intensity).
constexpr double kPbrPlacementIlluminance = 2.0; // lux at the model's centre
constexpr double kClassicAreaPlacementLevel = 1.0;
void makePhysicallyBased(Light& light, double distance);

// The irradiance an area light of unit radiance gives at a point `distance` (rig units) in front of its
// centre on its axis, facing it: the cosine-weighted solid angle ∫cos θ dω of the emitter (closed forms for
// the rectangle and the disk; about area / distance² when small). 0 for other types or an empty emitter.
double areaIrradianceFactor(const Light& light, double distance);

// makeLight(type, name) moved, aimed and scaled for the model. `index` picks the spot around the viewer's
// side (0, 1, 2, ...: the number of lights already in the rig gives successive lights different places).
Light placeNewLight(const Rig& rig, LightType type, const QString& name, const PlacementView& view,
                    int index);

// Appends placeNewLight(type, a unique name like "Spot 2") to the document as one undo step ("Add spot
// light") and selects it; false and *error when refused (the rig is full).
bool addPlacedLight(Document* document, LightType type, const PlacementView& view, QString* error = nullptr);

} // namespace lr
