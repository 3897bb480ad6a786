#include "editor/rigproperty.h"

#include "core/rigjson.h"
#include "editor/environmentvalue.h"
#include "editor/propertyvalue.h"

#include <iterator>

namespace lr {

namespace {

using namespace propertyvalue;
using P = RigProperty;

QString displayName(const RigPropertyInfo& row) {
    return QString::fromLatin1(row.name);
}

template <typename E> QString enumCheck(const RigPropertyInfo& row, const QVariant& v) {
    return checkEnum<E>(displayName(row), v);
}

QString checkName(const RigPropertyInfo&, const QVariant& v) {
    if (v.metaType().id() != QMetaType::QString) return QStringLiteral("rig name must be text");
    if (v.toString().size() > kMaxRigNameLength)
        return QStringLiteral("rig name must be at most %1 characters").arg(kMaxRigNameLength);
    return {};
}

QString checkEnvironment(const RigPropertyInfo&, const QVariant& v) {
    if (v.metaType() != QMetaType::fromType<Environment>()) return QStringLiteral("not an environment");
    return validateEnvironment(v.value<Environment>());
}

// One row per property, in RigProperty order.
constexpr RigPropertyInfo kRigProperties[] = {
    {.id = P::Name,
     .name = "rig name",
     .check = checkName,
     .get = [](const Rig& r) { return QVariant(r.name); },
     .set = [](Rig& r, const QVariant& v) { r.name = v.toString(); }},
    {.id = P::Space,
     .name = "rig space",
     .check = enumCheck<RigSpace>,
     .get = [](const Rig& r) { return QVariant::fromValue(r.space); },
     .set = [](Rig& r, const QVariant& v) { r.space = toEnum<RigSpace>(v).value_or(r.space); }},
    {.id = P::Ambient,
     .name = "ambient",
     .check =
         [](const RigPropertyInfo& row, const QVariant& v) {
             return checkVec3(displayName(row), toVec3(v, true), 0.0, kMaxRigIntensity);
         },
     .get = [](const Rig& r) { return QVariant::fromValue(r.ambient); },
     .set = [](Rig& r, const QVariant& v) { r.ambient = toVec3(v, true).value_or(r.ambient); }},
    {.id = P::SpecularModel,
     .name = "specular model",
     .check = enumCheck<SpecularModel>,
     .get = [](const Rig& r) { return QVariant::fromValue(r.shading.specular); },
     .set =
         [](Rig& r, const QVariant& v) {
             r.shading.specular = toEnum<SpecularModel>(v).value_or(r.shading.specular);
         }},
    {.id = P::ViewerModel,
     .name = "viewer model",
     .check = enumCheck<ViewerModel>,
     .get = [](const Rig& r) { return QVariant::fromValue(r.shading.viewer); },
     .set = [](Rig& r,
               const QVariant& v) { r.shading.viewer = toEnum<ViewerModel>(v).value_or(r.shading.viewer); }},
    {.id = P::Shininess,
     .name = "shininess",
     .check =
         [](const RigPropertyInfo& row, const QVariant& v) {
             return checkRange(displayName(row), toDouble(v), 0.0, kMaxRigExponent, true);
         },
     .get = [](const Rig& r) { return QVariant(r.shading.shininess); },
     .set = [](Rig& r, const QVariant& v) { r.shading.shininess = number(v, r.shading.shininess); }},
    {.id = P::ShadingModel,
     .name = "shading model",
     .check = enumCheck<ShadingModel>,
     .get = [](const Rig& r) { return QVariant::fromValue(r.shading.model); },
     .set = [](Rig& r,
               const QVariant& v) { r.shading.model = toEnum<ShadingModel>(v).value_or(r.shading.model); }},
    {.id = P::GroundMode,
     .name = "ground",
     .check = enumCheck<GroundMode>,
     .get = [](const Rig& r) { return QVariant::fromValue(r.ground.mode); },
     .set = [](Rig& r, const QVariant& v) { r.ground.mode = toEnum<GroundMode>(v).value_or(r.ground.mode); }},
    {.id = P::GroundColor,
     .name = "ground colour",
     // an albedo: what share of the light the ground reflects
     .check = [](const RigPropertyInfo& row,
                 const QVariant& v) { return checkVec3(displayName(row), toVec3(v, true), 0.0, 1.0); },
     .get = [](const Rig& r) { return QVariant::fromValue(r.ground.color); },
     .set = [](Rig& r, const QVariant& v) { r.ground.color = toVec3(v, true).value_or(r.ground.color); }},
    {.id = P::Environment,
     .name = "environment",
     .check = checkEnvironment,
     .get = [](const Rig& r) { return QVariant::fromValue(r.environment); },
     .set = [](Rig& r, const QVariant& v) { r.environment = v.value<Environment>(); }},
};
static_assert(std::size(kRigProperties) == size_t(kRigPropertyCount), "one row per RigProperty");
static_assert(
    [] {
        for (int i = 0; i < kRigPropertyCount; ++i)
            if (int(kRigProperties[i].id) != i || !kRigProperties[i].name) return false;
        return true;
    }(),
    "kRigProperties: one row per RigProperty, in enum order");

} // namespace

std::span<const RigPropertyInfo> rigProperties() {
    return kRigProperties;
}

const RigPropertyInfo* rigPropertyInfo(RigProperty p) {
    if (int(p) < 0 || int(p) >= kRigPropertyCount) return nullptr;
    return &kRigProperties[int(p)];
}

QString rigPropertyName(RigProperty p) {
    const RigPropertyInfo* row = rigPropertyInfo(p);
    return row ? displayName(*row) : QStringLiteral("rig");
}

QVariant rigValue(const Rig& r, RigProperty p) {
    const RigPropertyInfo* row = rigPropertyInfo(p);
    return row ? row->get(r) : QVariant();
}

QString validateRigValue(RigProperty p, const QVariant& v) {
    const RigPropertyInfo* row = rigPropertyInfo(p);
    return row ? row->check(*row, v) : QStringLiteral("not an editable rig value");
}

void applyRigValue(Rig& r, RigProperty p, const QVariant& v) {
    if (const RigPropertyInfo* row = rigPropertyInfo(p)) row->set(r, v);
}

} // namespace lr
