// Editable values of a rig (not of one of its lights), addressed by id, as QVariants: one row each in
// rigProperties() (its name, how to check, get and set it), read by ChangeRigValue, Document and the
// Render settings dock. Adding one: docs/architecture.md, "Where to add things".
//
// Value types: Name QString (<= kMaxRigNameLength characters); Space, SpecularModel, ViewerModel,
// ShadingModel, GroundMode the enum (or int index, or file name); Ambient glm::dvec3 linear (also QColor,
// sRGB); Shininess double > 0; GroundColor glm::dvec3 linear albedo, components 0 ... 1; Environment
// lr::Environment (editor/environmentvalue.h checks it).
#pragma once

#include "core/rig.h"

#include <QString>
#include <QVariant>
#include <span>

namespace lr {

// ShadingModel: classic or physically based (core/rig.h Shading::model); the classic-only values (specular
// model, viewer, shininess) stay editable but mean nothing under Pbr.
// GroundMode and GroundColor: the rig's ground plane (core/rig.h Ground; issue 14).
enum class RigProperty {
    Name,
    Space,
    Ambient,
    SpecularModel,
    ViewerModel,
    Shininess,
    ShadingModel,
    GroundMode,
    GroundColor,
    Environment, // issue 15: the whole lr::Environment (editor/environmentvalue.h checks it)
    Any
};
constexpr int kRigPropertyCount = int(RigProperty::Any);

// One row of the rig-property table.
struct RigPropertyInfo {
    RigProperty id;
    const char* name; // lower case, for messages and undo texts ("shininess")
    // Context-free check of type and range: empty when valid.
    QString (*check)(const RigPropertyInfo& row, const QVariant& value);
    QVariant (*get)(const Rig&);
    void (*set)(Rig&, const QVariant&); // a value that validated
};

// Every rig property, in RigProperty order.
std::span<const RigPropertyInfo> rigProperties();
// The row of a property; nullptr for Any (and anything out of range).
const RigPropertyInfo* rigPropertyInfo(RigProperty property);

// "shininess", "ground colour"; "rig" for Any.
QString rigPropertyName(RigProperty property);
QVariant rigValue(const Rig& rig, RigProperty property);
// Empty when valid, else a reason such as "shininess must be a finite number > 0 and <= 10000, got 0".
QString validateRigValue(RigProperty property, const QVariant& value);
void applyRigValue(Rig& rig, RigProperty property, const QVariant& value);

} // namespace lr
