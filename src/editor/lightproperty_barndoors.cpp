// The light-property rows of a rect light's barn doors (issue 39; core/barndoors.h): whether it has them,
// their angle (UE5's: 0 = straight out, 90 = in the emitter's plane) and their length. Checked as the rig
// reader checks a "barnDoors" object (docs/rig-format.md), so a saved rig always loads again.
#include "core/barndoors.h"
#include "core/rigjson.h"
#include "editor/lightproperty.h"
#include "editor/lightproperty_parts.h"

#include <array>

namespace lr {

namespace {

using P = LightProperty;
using K = LightValueKind;
using T = LightTypeTraits;

QString checkBool(const LightPropertyInfo& row, const QVariant& v) {
    return v.metaType().id() == QMetaType::Bool
               ? QString()
               : QStringLiteral("%1 must be true or false").arg(row.displayName());
}

bool hasDoors(const Light& l) {
    return l.barnDoors.has_value();
}

double number(const QVariant& v, double fallback) {
    bool ok = false;
    const double d = v.toDouble(&ok);
    return ok ? d : fallback;
}

const std::array<LightPropertyInfo, 3> kRows = {{
    {.id = P::BarnDoors,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "barn doors"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Barn doors"),
     .key = "barnDoors",
     .jsonField = "barnDoors",
     .kind = K::Bool,
     .usedBy = &T::usesRectSize,
     .check = checkBool,
     .get = [](const Light& l) { return QVariant(l.barnDoors.has_value()); },
     .set =
         [](Light& l, const QVariant& v) {
             if (!v.toBool())
                 l.barnDoors.reset();
             else if (!l.barnDoors)
                 l.barnDoors = BarnDoors{};
         }},
    {.id = P::BarnDoorAngle,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "barn door angle"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Barn door angle"),
     .key = "barnDoorAngle",
     .jsonField = "barnDoors.angle",
     .kind = K::Number,
     .min = 0.0,
     .max = barndoors::kMaxAngle,
     .unit = "degrees",
     .suffix = "°",
     .usedBy = &T::usesRectSize,
     .shown = hasDoors,
     .get = [](const Light& l) { return QVariant(l.barnDoors.value_or(BarnDoors{}).angle); },
     .set =
         [](Light& l, const QVariant& v) {
             BarnDoors b = l.barnDoors.value_or(BarnDoors{});
             b.angle = number(v, b.angle);
             l.barnDoors = b;
         }},
    {.id = P::BarnDoorLength,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "barn door length"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Barn door length"),
     .key = "barnDoorLength",
     .jsonField = "barnDoors.length",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxRigLength,
     .unit = "rig units",
     .usedBy = &T::usesRectSize,
     .shown = hasDoors,
     .get = [](const Light& l) { return QVariant(l.barnDoors.value_or(BarnDoors{}).length); },
     .set =
         [](Light& l, const QVariant& v) {
             BarnDoors b = l.barnDoors.value_or(BarnDoors{});
             b.length = number(v, b.length);
             l.barnDoors = b;
         }},
}};

} // namespace

std::span<const LightPropertyInfo> barnDoorLightProperties() {
    return kRows;
}

} // namespace lr
