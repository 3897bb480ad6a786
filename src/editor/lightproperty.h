// Editable values of a light and of a rig, addressed by id, as QVariants: one vocabulary shared by the undo
// commands, the light table model and the properties dock. Values are validated here, with the rig format's
// ranges (docs/rig-format.md), before any command is created: nothing invalid, NaN, Inf or out of range is
// ever stored.
//
// Everything the editor knows about a light property is one row of a table (lightProperties(),
// LightPropertyInfo: its name and label, JSON field, kind, limits, unit, which light types use it, when the
// Properties dock shows it, how to get and set it, its undo text). Validation, the Properties dock, the light
// table's columns and the undo texts all read that row; adding a property is adding a row
// (docs/architecture.md, "Where to add things").
//
// Value types (what lightValue() returns and what validate/apply accept):
//   Name                 QString (non-empty after trimming, <= kMaxLightNameLength characters)
//   Group                QString (<= kMaxLightNameLength characters, stored trimmed; empty: the light is a
//                          group of its own, core/lightgroups.h lightGroupName)
//   Type                 lr::LightType (also accepts int index or the file name, e.g. "spot")
//   Enabled              bool
//   Color, Position,     glm::dvec3 (also accepts QVector3D; Color also accepts QColor, read as sRGB and
//   Direction              converted to linear). Direction must be non-zero and is normalised when applied.
//   Ambient              glm::dvec3, or an invalid QVariant for "none"
//   Temperature          double kelvin, or an invalid QVariant for "none"
//   Specular             double factor f (stored as (f,f,f)), or glm::dvec3 colour (specularIsColor)
//   FalloffModel, ConeModel, Diffuse   the enum (or int index, or file name)
//   FalloffRange         double > 0, or an invalid QVariant for "no range" (inverse-polynomial,
//   inverse-square)
//   ShadowEnabled        bool
//   ShadowResolution     int (also a whole double), a power of two 256 ... 4096
//   AreaTwoSided         bool
//   Link                 lr::LightLink (names checked as the rig reader checks them; no name twice in a
//                          list)
//   everything else      double
// Enums from types.h. The rig's own values are editor/rigproperty.h's; the conversions of QVariants and
// displayColor are editor/propertyvalue.h's. (Qt 6 needs no Q_DECLARE_METATYPE for glm::dvec3 in a
// QVariant; declaring it here would clash with earlier implicit uses.)
#pragma once

#include "core/rig.h"
#include "core/rigjson.h"
#include "editor/propertyvalue.h"

#include <QColor>
#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QVariant>
#include <glm/vec3.hpp>
#include <span>

namespace lr {

enum class LightProperty {
    Name,
    Group, // issue 37: the light group it renders into (core/lightgroups.h); "" = its own
    Type,
    Enabled,
    Color,
    Intensity,
    Temperature,
    Position,
    Direction,
    FalloffModel,
    FalloffRange,
    FalloffExponent,
    FalloffConstant,
    FalloffLinear,
    FalloffQuadratic,
    ConeModel,
    ConeInner,
    ConeOuter,
    ConeExponent,
    Diffuse,
    Specular,
    Ambient,
    RimExponent,
    ShadowEnabled, // shadow.enabled ... shadow.angle: types whose traits say castsShadows
    ShadowResolution,
    ShadowBias,
    ShadowNormalOffset,
    ShadowSize,   // point and spot: the emitter's diameter in rig units
    ShadowAngle,  // directional: the emitter's angular diameter in degrees
    AreaWidth,    // rect (issue 16; core/rig.h AreaShape): rig units, >= 0
    AreaHeight,   // rect
    AreaRadius,   // disk
    AreaRoll,     // rect and disk: degrees about the direction, -180 ... 180
    AreaTwoSided, // rect and disk: bool
    // Barn doors (issue 39; core/barndoors.h), rect only: whether it has them (bool), their angle (degrees,
    // 0 ... 90; UE5's: 0 straight out, 90 in the emitter's plane) and their length (rig units, >= 0).
    BarnDoors,
    BarnDoorAngle,
    BarnDoorLength,
    Link,          // issue 38: which parts it lights and which cast its shadow (editor/linkedit.h)
    GoboFile,      // issue 39, spot: the gobo's image (core/lightshaping.h GoboSpec); "" = no gobo
    GoboScale,     // spot with a gobo: 0.01 ... 100 × the cone's width
    GoboRotation,  // spot with a gobo: degrees about the axis, -360 ... 360
    IesFile,       // issue 39 (lightproperty_ies.cpp): point and spot; QString, "" = no profile
    IesMultiplier, // double 0 ... 1e6 (shown with a profile)
    IesLevel,      // int: 0 the profile's candela, 1 the light's intensity
    IesRotation,   // double degrees, 0 ... 360
    IesNadir,      // point with a profile: its nadir, the light's direction (glm::dvec3, not zero)
    Any            // not a property: "several or all values of the light changed" (in RigChange only)
};
constexpr int kLightPropertyCount = int(LightProperty::Any);

// Limits the editor enforces: the rig format's own (core/rigjson.h), so a saved rig always loads again.
constexpr int kMaxLightNameLength = kMaxRigNameLength;  // characters
constexpr double kMaxColorComponent = kMaxRigIntensity; // linear RGB, HDR allowed; also specular, ambient
constexpr double kMaxIntensity = kMaxRigIntensity;
constexpr double kMinTemperature = 1000.0, kMaxTemperature = 40000.0; // kelvin
constexpr double kMaxCoordinate = kMaxRigLength;                      // |position component|, range
constexpr double kMaxExponent = kMaxRigExponent; // falloff, cone and rim exponents (all > 0)
constexpr double kMaxPolynomialCoefficient = kMaxRigLength;
constexpr double kMaxShininess = kMaxRigExponent; // > 0
constexpr double kMaxConeAngle = 90.0;            // degrees, half-angle; > 0
constexpr double kMaxShadowSize = kMaxRigLength;  // a point or spot light's emitter diameter; >= 0
constexpr double kMaxAreaSize = kMaxRigLength;    // an area light's width, height, radius; >= 0

// How a property's value is held and edited (the Properties dock picks a default editor widget per kind).
enum class LightValueKind {
    Text,           // QString
    Enum,           // an enum from types.h (choices() lists its items in index order)
    Bool,           // bool
    Number,         // double in [min, max] ((min, max] when minExclusive)
    OptionalNumber, // a Number, or an invalid QVariant for "none"
    Color,          // glm::dvec3 linear RGB, components in [min, max]
    OptionalColor,  // a Color, or an invalid QVariant for "none"
    Vector,         // glm::dvec3, components in [min, max]
    FactorOrColor,  // a Number factor or a Color (specular)
    Link,           // lr::LightLink (core/lightlink.h): the Properties dock's Linking section edits it
};

// One row of the light-property table.
struct LightPropertyInfo {
    LightProperty id;
    const char* name;  // lower case, for messages and undo texts ("cone outer angle"); translatable
    const char* label; // the dock's label with its mnemonic ("O&uter angle"); translatable
    const char* tableLabel = nullptr; // the light table's column header when not `label` ("On")
    const char* key;                  // stable identifier: the dock's field object name, tests ("coneOuter")
    const char* jsonField;            // where the rig file keeps it, relative to the light ("cone.outer")
    LightValueKind kind;
    double min = 0.0, max = 0.0; // Number, Color, Vector kinds
    bool minExclusive = false;
    const char* unit = nullptr;   // named in range messages: "cone inner angle (degrees) must be ..."
    const char* suffix = nullptr; // shown after the number ("°", " K")
    // The light types that use it (a LightTypeTraits flag); nullptr: every type. Commands skip lights
    // where a property does not apply.
    bool LightTypeTraits::*usedBy = nullptr;
    // ... except the types that have this trait too (a directional light's shadow angle: castsShadows
    // unless usesPosition); nullptr: no exception.
    bool LightTypeTraits::*unless = nullptr;
    // Shown by the dock only when this also holds (the light's models use it); nullptr: whenever it applies.
    bool (*shown)(const Light&) = nullptr;
    // Its own context-free check; nullptr: the check of its kind and limits.
    QString (*check)(const LightPropertyInfo& row, const QVariant& value) = nullptr;
    QStringList (*choices)() = nullptr; // Enum: item texts in index order
    QVariant (*get)(const Light&) = nullptr;
    void (*set)(Light&, const QVariant&) = nullptr; // a value that validated; keeps the light consistent
    // The undo text for `lights` ("Key" or "3 lights") set to value; nullptr: "Change NAME of LIGHTS".
    QString (*undoText)(const QString& lights, const QVariant& value) = nullptr;
    // Other displays that change with it (Temperature tints the colour swatch; the falloff model decides
    // whether there is a range); Any: none.
    LightProperty shownWith = LightProperty::Any;
    bool uniquePerLight = false;    // no two lights share a value (names): never set on several at once
    bool deliberateForMany = false; // changing several lights at once must be a deliberate act (type)

    QString displayName() const;
    QString displayLabel() const;
    bool applies(const Light& light) const;
    bool isShown(const Light& light) const; // applies and `shown`
};

// Every light property, in the Properties dock's order.
std::span<const LightPropertyInfo> lightProperties();
// The row of a property; nullptr for Any (and anything out of range).
const LightPropertyInfo* lightPropertyInfo(LightProperty property);

// Human-readable name for undo texts and messages: "intensity", "cone outer angle".
QString lightPropertyName(LightProperty property);

// Whether the property means anything for this light (its row's usedBy flag of the light's type). Commands
// only touch lights where the property applies.
bool lightPropertyApplies(const Light& light, LightProperty property);

// The light's current value, in the types listed above.
QVariant lightValue(const Light& light, LightProperty property);

// Context-free check of type and range: empty string when valid, else a reason such as
// "intensity must be a finite number between 0 and 1e+06, got -1".
QString validateLightValue(LightProperty property, const QVariant& value);
// Also checks the light's other values (a smooth cone's inner <= outer, "no range" only for the falloff
// models that allow it, at least one positive inverse-polynomial coefficient).
QString validateLightValue(const Light& light, LightProperty property, const QVariant& value);
// "N lights would cast shadows; at most 16 can ...": empty when `casters` is within kMaxShadowCasters.
QString checkShadowCasterCount(int casters);
// Every value of a light / a rig (used for rigs that come from elsewhere: presets, model imports); a rig
// also within kMaxShadowCasters.
QString validateLight(const Light& light);
QString validateRig(const Rig& rig);

// Returns the light with the value applied (call only with a value that validated for this light). Keeps the
// light consistent: a falloff model that needs a range gets one, a cone's inner angle follows its outer angle
// down, a direction is normalised.
Light withLightValue(const Light& light, LightProperty property, const QVariant& value);

} // namespace lr
