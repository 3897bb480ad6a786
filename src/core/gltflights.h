// A rig as glTF lights (issue 17, docs/export.md): every enabled point, spot and directional light becomes
// a KHR_lights_punctual light on a node of its own (a rect or disk light a spot or point light standing in
// for it, listed as a loss: glTF has no area lights), in glTF's frame (right-handed, +Y up, the model file's
// units, which glTF reads as metres), with the extension's semantics: candela for point and spot lights,
// lux for directional lights, inverse-square falloff with the smooth range window, spot cones as inner and
// outer half-angles in radians. What glTF cannot say is converted by a documented rule and listed, never
// silently: one LossyConversion per light and kind, described by the one table kExportLosses (the CLI
// prints them on stderr, the editor in a dialog). The rig's environment, ambient and ground, which glTF
// has no lights for, go into a note (`extras.lightrig`).
//
// Where a light lands: LightRig draws a world-space rig as is and a model-space rig through the model's
// bounding sphere (prepare.h, SceneFrame); `fileFromWorld` undoes a rotation the editor applied to the
// model (its up axis, model/upaxis.h), so the lights land in the file's own frame.
#pragma once

#include "prepare.h"
#include "rig.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <optional>
#include <vector>

namespace lr {

// Every kind of loss; one row each in kExportLosses.
enum class ExportLoss {
    ClassicUnits, // a classic rig's unitless intensities, read as candela / lux by the rule below
    Falloff,      // a falloff other than glTF's inverse-square
    Cone,         // a cone other than glTF's smooth cone of exponent 2
    HalfLambert,  // the half-Lambert diffuse wrap
    Specular,     // a specular factor or colour other than 1
    LightAmbient, // a light's own ambient term
    Rim,          // rim lights (no physical counterpart)
    Area,         // area emitters: a shadow's emitter size, the studio's softboxes
    AreaLight,    // rect and disk lights (issue 16): a spot (one-sided) or a point (two-sided) instead
    Shadow,       // shadow casting (KHR_lights_punctual lights carry none)
    Disabled,     // lights switched off (glTF lights have no switch)
    Ambient,      // the scene ambient (glTF has no ambient light)
    Environment,  // environment lighting (glTF has none)
    Ground,       // the ground plane or shadow catcher
    Link,         // light and shadow linking (issue 38): glTF has none
    Gobo,         // a spot's gobo (issue 39): glTF has no projected images
    BarnDoors,    // a rect light's barn doors (issue 39): glTF has none
    Ies,          // an IES profile (issue 39): EXT_lights_ies in place of the punctual light, or lost
    Count
};

struct ExportLossInfo {
    ExportLoss kind;
    const char* key;     // stable name ("falloff"), for tests and scripts
    const char* title;   // "Falloff"
    const char* written; // what the glTF holds instead
};

// One row per ExportLoss, in enum order.
extern const ExportLossInfo kExportLosses[int(ExportLoss::Count)];
const ExportLossInfo& exportLossInfo(ExportLoss kind);

struct LossyConversion {
    ExportLoss kind;
    QString subject; // the light's name ("Key"), or "rig"
    QString detail;  // what was there and what was written: "range-power (range 8): inverse-square ..."
    bool operator==(const LossyConversion&) const = default;
};
// One line: "Key: falloff range-power (range 8) → inverse-square, 12.6 cd at 3 m (...)".
QString describeLoss(const LossyConversion& loss);

// An IES profile on a light (issue 39, gltflights_ies.cpp): its node carries EXT_lights_ies in place of
// KHR_lights_punctual (a viewer reading both would light it twice).
struct GltfIes {
    QByteArray file;                 // the .ies file's bytes, written as a data: URI
    double multiplier = 1.0;         // × the file's candela (its candela multiplier applied by the reader)
    glm::dvec3 color{1.0};           // linear, largest component 1 (or all 0)
    QJsonObject profileJson() const; // the entry of extensions.EXT_lights_ies.lights
};

// One KHR_lights_punctual light (or EXT_lights_ies profile instance) and its node, in the file's frame.
struct GltfLight {
    QString name;
    QString type;              // "point", "spot", "directional"
    glm::dvec3 color{1.0};     // linear, largest component 1 (or all 0)
    double intensity = 0.0;    // candela (point, spot) or lux (directional)
    double range = -1.0;       // > 0, or < 0 for none
    double innerConeAngle = 0; // radians (spot)
    double outerConeAngle = 0; // radians (spot), > innerConeAngle, <= pi/2
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0}; // local -Z onto the light's direction
    QJsonObject link; // the rig's "link" (issue 38), written in the node's extras.lightrig.link; empty: none
    QJsonObject gobo; // the rig's "gobo" (issue 39), written in the node's extras.lightrig.gobo; empty: none
    // A rect's "barnDoors" (issue 39), written in the node's extras.lightrig.barnDoors; empty: none.
    QJsonObject barnDoors;
    std::optional<GltfIes> ies;    // issue 39: set, the node is an EXT_lights_ies instance
    QJsonObject lightJson() const; // the extension's light object
    // `lightIndex`: in KHR_lights_punctual's lights, or with `ies` in EXT_lights_ies's (gltfLightIndices).
    QJsonObject nodeJson(int lightIndex) const;
};

// Each light's index in its extension's array: KHR_lights_punctual's for lights without a profile,
// EXT_lights_ies's for lights with one, both in order.
std::vector<int> gltfLightIndices(const std::vector<GltfLight>& lights);

// Issue 39 (gltflights_ies.cpp): `l`'s IES profile onto `g` (colour and intensity already converted:
// `g.intensity` candela, `unit` the classic rule's factor), its node turned so that -Z is the profile's nadir
// and +X its horizontal angle 0; a file that does not read is a loss and leaves `g` as it is.
void convertIes(const Light& l, const glm::dmat3& fileFromWorld, double unit, GltfLight& g,
                std::vector<LossyConversion>& losses);

// A perspective camera and its node, in the file's frame.
struct GltfCamera {
    QString name;
    glm::dvec3 translation{0.0};
    glm::dquat rotation{1.0, 0.0, 0.0, 0.0}; // local -Z onto the view direction, +Y onto up
    double yfov = 0.785398;                  // radians
    double znear = 0.01, zfar = 1000.0;      // zfar <= znear: none (infinite)
    QJsonObject cameraJson() const;
    QJsonObject nodeJson(int cameraIndex) const;
};

struct GltfRigExport {
    std::vector<GltfLight> lights;
    std::vector<LossyConversion> losses;
    QJsonObject note; // extras.lightrig: the environment, ambient, ground and shading glTF cannot hold
};

// The rig's lights in the file's frame. `frame` is the model's bounding sphere in LightRig's world (the
// anchor of a model-space rig, and the reference distance of converted falloffs).
GltfRigExport convertRigToGltf(const Rig& rig, const SceneFrame& frame,
                               const glm::dmat3& fileFromWorld = glm::dmat3(1.0));

// A camera at `eye` looking along `forward` (LightRig's world), vertical field of view in degrees.
GltfCamera makeGltfCamera(const QString& name, const glm::dvec3& eye, const glm::dvec3& forward,
                          const glm::dvec3& up, double yfovDegrees, double znear, double zfar,
                          const glm::dmat3& fileFromWorld = glm::dmat3(1.0));

// The rotation taking -Z to `forward` and +Y as close to `up` as it can (any up when they are parallel).
glm::dquat lookRotation(const glm::dvec3& forward, const glm::dvec3& up);

// Classic intensity → physically based: a classic light of intensity 1 lights a white Lambert surface as
// a physically based one of π (candela or lux) does (the BRDF's 1/π).
inline constexpr double kClassicToPhysical = 3.14159265358979323846;

} // namespace lr
