// The light-property rows of an IES profile (issue 39, docs/light-shaping.md "IES profiles"): its file
// (empty: none), multiplier, level and rotation, on point and spot lights (the types with a falloff), and a
// point light's nadir (its direction, which a spot edits in its Direction row). The file is checked as the
// rig reader checks "ies.file"; the others are shown only while the light has a profile.
#include "core/rigjson.h"
#include "editor/lightproperty.h"
#include "editor/lightproperty_parts.h"
#include "editor/propertyvalue.h"

#include <QCoreApplication>
#include <cmath>
#include <glm/geometric.hpp>

namespace lr {

namespace {

using P = LightProperty;
using K = LightValueKind;
using T = LightTypeTraits;
using propertyvalue::number;

QString checkFile(const LightPropertyInfo&, const QVariant& v) {
    if (v.metaType().id() != QMetaType::QString) return QStringLiteral("the IES file must be a file name");
    const QString s = v.toString();
    if (s.size() > kMaxEnvironmentPathLength)
        return QStringLiteral("the IES file name must be at most %1 characters")
            .arg(kMaxEnvironmentPathLength);
    if (s.contains(QChar(0))) return QStringLiteral("the IES file name must not contain a NUL character");
    return {};
}

QString checkLevel(const LightPropertyInfo&, const QVariant& v) {
    const std::optional<double> d = propertyvalue::toDouble(v); // NaN and infinities are neither
    return d && (*d == 0.0 || *d == 1.0) ? QString()
                                         : QStringLiteral("the IES level must be 0 (profile) or 1 (light)");
}

QStringList levelChoices() {
    return {QCoreApplication::translate("lr::LightProperty", "profile's candela"),
            QCoreApplication::translate("lr::LightProperty", "light's intensity")};
}

bool hasProfile(const Light& l) {
    return l.ies.has_value();
}

const LightPropertyInfo kIesRows[] = {
    {.id = P::IesFile,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "IES profile"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&IES profile"),
     .key = "iesFile",
     .jsonField = "ies.file",
     .kind = K::Text,
     .usedBy = &T::usesFalloff,
     .check = checkFile,
     .get = [](const Light& l) { return QVariant(l.ies ? l.ies->file : QString()); },
     .set =
         [](Light& l, const QVariant& v) {
             const QString file = v.toString().trimmed();
             if (file.isEmpty()) {
                 l.ies.reset();
                 return;
             }
             IesSpec s = l.ies.value_or(IesSpec{});
             s.file = file;
             s.resolved.clear(); // Document::renderRig resolves it against the rig's folder
             l.ies = s;
         }},
    {.id = P::IesMultiplier,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "IES multiplier"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "IES &multiplier"),
     .key = "iesMultiplier",
     .jsonField = "ies.multiplier",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxRigIntensity,
     .usedBy = &T::usesFalloff,
     .shown = hasProfile,
     .get = [](const Light& l) { return QVariant(l.ies ? l.ies->multiplier : 1.0); },
     .set =
         [](Light& l, const QVariant& v) {
             if (l.ies) l.ies->multiplier = number(v, l.ies->multiplier);
         }},
    {.id = P::IesLevel,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "IES level"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "IES &level from"),
     .key = "iesLevel",
     .jsonField = "ies.level",
     .kind = K::Enum,
     .usedBy = &T::usesFalloff,
     .shown = hasProfile,
     .check = checkLevel,
     .choices = levelChoices,
     .get = [](const Light& l) { return QVariant(int(l.ies ? l.ies->level : IesLevel::Light)); },
     .set =
         [](Light& l, const QVariant& v) {
             if (l.ies) l.ies->level = number(v, 1.0) == 0.0 ? IesLevel::Profile : IesLevel::Light;
         }},
    {.id = P::IesRotation,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "IES rotation"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "IES rota&tion"),
     .key = "iesRotation",
     .jsonField = "ies.rotation",
     .kind = K::Number,
     .min = 0.0,
     .max = 360.0,
     .unit = "degrees",
     .suffix = "°",
     .usedBy = &T::usesFalloff,
     .shown = hasProfile,
     .get = [](const Light& l) { return QVariant(l.ies ? l.ies->rotation : 0.0); },
     .set =
         [](Light& l, const QVariant& v) {
             if (l.ies) l.ies->rotation = normalizedEnvironmentRotation(number(v, l.ies->rotation));
         }},
    {.id = P::IesNadir,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "IES nadir"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "IES &nadir"),
     .key = "iesNadir",
     .jsonField = "direction",
     .kind = K::Vector,
     .min = -kMaxCoordinate,
     .max = kMaxCoordinate,
     .usedBy = &T::usesFalloff,
     .unless = &T::usesDirection, // a spot's nadir is its Direction row
     .shown = hasProfile,
     .check = checkDirection,
     .get = [](const Light& l) { return QVariant::fromValue(l.direction); },
     .set =
         [](Light& l, const QVariant& v) {
             if (auto d = propertyvalue::toVec3(v, false); d && glm::length(*d) > 0.0)
                 l.direction = glm::normalize(*d);
         }},
};

} // namespace

std::span<const LightPropertyInfo> iesLightProperties() {
    return kIesRows;
}

} // namespace lr
