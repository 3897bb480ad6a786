// The light-property table (lightproperty.h, LightPropertyInfo): one row per LightProperty, in the
// Properties dock's order, and the checks, choices and undo texts particular to some rows. The falloff rows
// take their limits and when they are shown from core/fallofftraits.h.
#include "core/fallofftraits.h"
#include "editor/lightproperty.h"
#include "editor/lightproperty_parts.h"
#include "editor/propertyvalue.h"

#include <QCoreApplication>
#include <cmath>
#include <glm/geometric.hpp>
#include <iterator>

namespace lr {

namespace {

using namespace propertyvalue;

template <typename E> QString enumCheck(const LightPropertyInfo& row, const QVariant& v) {
    return checkEnum<E>(row.displayName(), v);
}

QStringList lightTypeChoices() {
    QStringList out;
    for (const LightType t : allLightTypes())
        out << lightTypeLabel(t);
    return out;
}

QString checkName(const LightPropertyInfo&, const QVariant& v) {
    if (v.metaType().id() != QMetaType::QString) return QStringLiteral("name must be text");
    const QString s = v.toString();
    if (s.trimmed().isEmpty()) return QStringLiteral("name must not be empty");
    if (s.size() > kMaxLightNameLength)
        return QStringLiteral("name must be at most %1 characters, got %2")
            .arg(kMaxLightNameLength)
            .arg(s.size());
    for (const QChar c : s)
        if (c.category() == QChar::Other_Control)
            return QStringLiteral("name must not contain control characters");
    return {};
}

// A group name: text of at most kMaxLightNameLength characters without control characters; empty (after
// trimming) means the light is a group of its own.
QString checkGroup(const LightPropertyInfo&, const QVariant& v) {
    if (v.metaType().id() != QMetaType::QString) return QStringLiteral("group must be text");
    const QString s = v.toString().trimmed();
    if (s.size() > kMaxLightNameLength)
        return QStringLiteral("group must be at most %1 characters, got %2")
            .arg(kMaxLightNameLength)
            .arg(s.size());
    for (const QChar c : s)
        if (c.category() == QChar::Other_Control)
            return QStringLiteral("group must not contain control characters");
    return {};
}

QString undoGroup(const QString& lights, const QVariant& group) {
    const QString g = group.toString().trimmed();
    return g.isEmpty()
               ? QCoreApplication::translate("lr::ChangeLightValue", "Give %1 a group of its own").arg(lights)
               : QCoreApplication::translate("lr::ChangeLightValue", "Put %1 in group %2").arg(lights, g);
}

QString checkBool(const LightPropertyInfo& row, const QVariant& v) {
    return v.metaType().id() == QMetaType::Bool
               ? QString()
               : QStringLiteral("%1 must be true or false").arg(row.displayName());
}

QString checkSpecular(const LightPropertyInfo& row, const QVariant& v) {
    if (auto c = toVec3(v, true)) return checkVec3(QStringLiteral("specular colour"), c, row.min, row.max);
    return checkRange(QStringLiteral("specular factor"), toDouble(v), row.min, row.max, false);
}

QString undoRename(const QString& light, const QVariant& name) {
    return QCoreApplication::translate("lr::ChangeLightValue", "Rename %1 to %2").arg(light, name.toString());
}

QString undoSwitch(const QString& lights, const QVariant& on) {
    return on.toBool() ? QCoreApplication::translate("lr::ChangeLightValue", "Switch on %1").arg(lights)
                       : QCoreApplication::translate("lr::ChangeLightValue", "Switch off %1").arg(lights);
}

// The falloff rows read their limits and when they are shown from core/fallofftraits.h.
template <FalloffKey Key> bool falloffShown(const Light& l) {
    return falloffUses(l.falloff.model, Key);
}

template <FalloffKey Key> QVariant falloffValue(const Light& l) {
    return QVariant(l.falloff.*falloffField(Key).member);
}

template <FalloffKey Key> void setFalloffValue(Light& l, const QVariant& v) {
    double& value = l.falloff.*falloffField(Key).member;
    value = number(v, value);
}

// The row of a number of a falloff model (exponent, the inverse-polynomial terms).
template <FalloffKey Key>
LightPropertyInfo falloffRow(LightProperty id, const char* name, const char* label, const char* key,
                             const char* jsonField) {
    const FalloffField& field = falloffField(Key);
    return {.id = id,
            .name = name,
            .label = label,
            .key = key,
            .jsonField = jsonField,
            .kind = LightValueKind::Number,
            .min = field.min,
            .max = field.max,
            .minExclusive = field.minExclusive,
            .usedBy = &LightTypeTraits::usesFalloff,
            .shown = falloffShown<Key>,
            .get = falloffValue<Key>,
            .set = setFalloffValue<Key>};
}

bool shadowOn(const Light& l) {
    return l.shadow.enabled;
}

QString checkShadowResolution(const LightPropertyInfo& row, const QVariant& v) {
    const std::optional<double> d = toDouble(v);
    if (d && isShadowResolution(*d)) return {};
    return QStringLiteral("%1 must be a power of two between %2 and %3%4")
        .arg(row.displayName())
        .arg(kMinShadowResolution)
        .arg(kMaxShadowResolution)
        .arg(d ? QStringLiteral(", got %1").arg(num(*d)) : QString());
}

QString undoSwitchShadow(const QString& lights, const QVariant& on) {
    return on.toBool()
               ? QCoreApplication::translate("lr::ChangeLightValue", "Switch on the shadow of %1").arg(lights)
               : QCoreApplication::translate("lr::ChangeLightValue", "Switch off the shadow of %1")
                     .arg(lights);
}

using P = LightProperty;
using K = LightValueKind;
using T = LightTypeTraits;

// One row per property, in the Properties dock's order. The rig format's limits are in lightproperty.h.
const LightPropertyInfo kLightProperties[] = {
    {.id = P::Name,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "name"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Name"),
     .key = "name",
     .jsonField = "name",
     .kind = K::Text,
     .check = checkName,
     .get = [](const Light& l) { return QVariant(l.name); },
     .set = [](Light& l, const QVariant& v) { l.name = v.toString(); },
     .undoText = undoRename,
     .shownWith = P::Group, // a light without a group is a group named after it
     .uniquePerLight = true},
    // Issue 37 (core/lightgroups.h, docs/light-mixing.md): lights with one group share one image when a
    // render is split for mixing; empty, the light is a group of its own (named after it). Many lights at
    // once: select three and type "key".
    {.id = P::Group,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "group"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Group"),
     .key = "group",
     .jsonField = "group",
     .kind = K::Text,
     .check = checkGroup,
     .get = [](const Light& l) { return QVariant(l.group); },
     .set = [](Light& l, const QVariant& v) { l.group = v.toString().trimmed(); },
     .undoText = undoGroup},
    {.id = P::Type,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "type"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Type"),
     .key = "type",
     .jsonField = "type",
     .kind = K::Enum,
     .check = enumCheck<LightType>,
     .choices = lightTypeChoices,
     .get = [](const Light& l) { return QVariant::fromValue(l.type); },
     .set = [](Light& l, const QVariant& v) { l.type = toEnum<LightType>(v).value_or(l.type); },
     .deliberateForMany = true},
    {.id = P::Enabled,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "on/off"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Enabled"),
     .tableLabel = QT_TRANSLATE_NOOP("lr::LightProperty", "On"),
     .key = "enabled",
     .jsonField = "enabled",
     .kind = K::Bool,
     .check = checkBool,
     .get = [](const Light& l) { return QVariant(l.enabled); },
     .set = [](Light& l, const QVariant& v) { l.enabled = v.toBool(); },
     .undoText = undoSwitch},
    {.id = P::Color,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "colour"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Colour"),
     .key = "color",
     .jsonField = "color",
     .kind = K::Color,
     .min = 0.0,
     .max = kMaxColorComponent,
     .get = [](const Light& l) { return QVariant::fromValue(l.color); },
     .set = [](Light& l, const QVariant& v) { l.color = toVec3(v, true).value_or(l.color); }},
    {.id = P::Temperature,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "temperature"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Te&mperature"),
     .key = "temperature",
     .jsonField = "temperature",
     .kind = K::OptionalNumber,
     .min = kMinTemperature,
     .max = kMaxTemperature,
     .unit = "kelvin",
     .suffix = " K",
     .get = [](const Light& l) { return l.temperature ? QVariant(*l.temperature) : QVariant(); },
     .set = [](Light& l, const QVariant& v) { l.temperature = toDouble(v); },
     .shownWith = P::Color},
    {.id = P::Intensity,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "intensity"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Intensity"),
     .key = "intensity",
     .jsonField = "intensity",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxIntensity,
     .get = [](const Light& l) { return QVariant(l.intensity); },
     .set = [](Light& l, const QVariant& v) { l.intensity = number(v, l.intensity); }},
    {.id = P::Position,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "position"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Position"),
     .key = "position",
     .jsonField = "position",
     .kind = K::Vector,
     .min = -kMaxCoordinate,
     .max = kMaxCoordinate,
     .usedBy = &T::usesPosition,
     .get = [](const Light& l) { return QVariant::fromValue(l.position); },
     .set = [](Light& l, const QVariant& v) { l.position = toVec3(v, false).value_or(l.position); }},
    {.id = P::Direction,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "direction"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Direction"),
     .key = "direction",
     .jsonField = "direction",
     .kind = K::Vector,
     .min = -kMaxCoordinate,
     .max = kMaxCoordinate,
     .usedBy = &T::usesDirection,
     .check = checkDirection,
     .get = [](const Light& l) { return QVariant::fromValue(l.direction); },
     .set =
         [](Light& l, const QVariant& v) {
             if (auto c = toVec3(v, false); c && glm::length(*c) > 0.0) l.direction = glm::normalize(*c);
         }},
    {.id = P::FalloffModel,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "falloff model"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Falloff"),
     .key = "falloffModel",
     .jsonField = "falloff.model",
     .kind = K::Enum,
     .usedBy = &T::usesFalloff,
     .check = enumCheck<FalloffModel>,
     .choices = enumChoices<FalloffModel>,
     .get = [](const Light& l) { return QVariant::fromValue(l.falloff.model); },
     .set =
         [](Light& l, const QVariant& v) {
             const auto m = toEnum<FalloffModel>(v);
             if (!m) return;
             l.falloff.model = *m;
             // A model that needs a range gets one; one that needs a positive coefficient gets one.
             const FalloffTraits& t = falloffTraitsOf(*m);
             if (t.range == RangeRule::Required && !l.falloff.hasRange()) l.falloff.range = 10.0;
             if (t.needsPositiveTerm &&
                 !(l.falloff.constant > 0 || l.falloff.linear > 0 || l.falloff.quadratic > 0))
                 l.falloff.constant = 1.0;
         },
     .shownWith = P::FalloffRange},
    {.id = P::FalloffRange,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "range"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Range"),
     .key = "falloffRange",
     .jsonField = "falloff.range",
     .kind = K::OptionalNumber,
     .min = falloffField(FalloffKey::Range).min,
     .max = falloffField(FalloffKey::Range).max,
     .minExclusive = falloffField(FalloffKey::Range).minExclusive,
     .usedBy = &T::usesFalloff,
     .shown = falloffShown<FalloffKey::Range>,
     .get = [](const Light& l) { return l.falloff.hasRange() ? QVariant(l.falloff.range) : QVariant(); },
     .set = [](Light& l, const QVariant& v) { l.falloff.range = toDouble(v).value_or(-1.0); }},
    falloffRow<FalloffKey::Exponent>(
        P::FalloffExponent, QT_TRANSLATE_NOOP("lr::LightProperty", "falloff exponent"),
        QT_TRANSLATE_NOOP("lr::LightProperty", "Falloff e&xponent"), "falloffExponent", "falloff.exponent"),
    falloffRow<FalloffKey::Constant>(
        P::FalloffConstant, QT_TRANSLATE_NOOP("lr::LightProperty", "constant attenuation"),
        QT_TRANSLATE_NOOP("lr::LightProperty", "Consta&nt"), "falloffConstant", "falloff.constant"),
    falloffRow<FalloffKey::Linear>(
        P::FalloffLinear, QT_TRANSLATE_NOOP("lr::LightProperty", "linear attenuation"),
        QT_TRANSLATE_NOOP("lr::LightProperty", "&Linear"), "falloffLinear", "falloff.linear"),
    falloffRow<FalloffKey::Quadratic>(
        P::FalloffQuadratic, QT_TRANSLATE_NOOP("lr::LightProperty", "quadratic attenuation"),
        QT_TRANSLATE_NOOP("lr::LightProperty", "&Quadratic"), "falloffQuadratic", "falloff.quadratic"),
    {.id = P::ConeModel,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "cone model"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "C&one"),
     .key = "coneModel",
     .jsonField = "cone.model",
     .kind = K::Enum,
     .usedBy = &T::usesCone,
     .check = enumCheck<ConeModel>,
     .choices = enumChoices<ConeModel>,
     .get = [](const Light& l) { return QVariant::fromValue(l.cone.model); },
     .set =
         [](Light& l, const QVariant& v) {
             if (auto m = toEnum<ConeModel>(v)) {
                 l.cone.model = *m;
                 l.cone.inner = std::min(l.cone.inner, l.cone.outer);
             }
         }},
    {.id = P::ConeInner,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "cone inner angle"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Inner an&gle"),
     .key = "coneInner",
     .jsonField = "cone.inner",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxConeAngle,
     .minExclusive = true,
     .unit = "degrees",
     .suffix = "°",
     .usedBy = &T::usesCone,
     .shown = [](const Light& l) { return l.cone.model == ConeModel::Smooth; },
     .get = [](const Light& l) { return QVariant(l.cone.inner); },
     .set = [](Light& l, const QVariant& v) { l.cone.inner = number(v, l.cone.inner); }},
    {.id = P::ConeOuter,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "cone outer angle"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "O&uter angle"),
     .key = "coneOuter",
     .jsonField = "cone.outer",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxConeAngle,
     .minExclusive = true,
     .unit = "degrees",
     .suffix = "°",
     .usedBy = &T::usesCone,
     .get = [](const Light& l) { return QVariant(l.cone.outer); },
     .set =
         [](Light& l, const QVariant& v) {
             l.cone.outer = number(v, l.cone.outer);
             // Only a smooth cone uses the inner angle; for the others it follows the outer angle down so
             // that switching to smooth later stays valid.
             if (l.cone.model != ConeModel::Smooth) l.cone.inner = std::min(l.cone.inner, l.cone.outer);
         }},
    {.id = P::ConeExponent,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "cone exponent"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Cone exponen&t"),
     .key = "coneExponent",
     .jsonField = "cone.exponent",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxExponent,
     .minExclusive = true,
     .usedBy = &T::usesCone,
     .shown = [](const Light& l) { return l.cone.model != ConeModel::Hard; },
     .get = [](const Light& l) { return QVariant(l.cone.exponent); },
     .set = [](Light& l, const QVariant& v) { l.cone.exponent = number(v, l.cone.exponent); }},
    {.id = P::Diffuse,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "diffuse model"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Di&ffuse"),
     .key = "diffuse",
     .jsonField = "diffuse",
     .kind = K::Enum,
     .usedBy = &T::usesSurfaceModels,
     .check = enumCheck<DiffuseModel>,
     .choices = enumChoices<DiffuseModel>,
     .get = [](const Light& l) { return QVariant::fromValue(l.diffuse); },
     .set = [](Light& l, const QVariant& v) { l.diffuse = toEnum<DiffuseModel>(v).value_or(l.diffuse); }},
    {.id = P::Specular,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "specular"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Specular"),
     .key = "specular",
     .jsonField = "specular",
     .kind = K::FactorOrColor,
     .min = 0.0,
     .max = kMaxColorComponent,
     .usedBy = &T::usesSurfaceModels,
     .check = checkSpecular,
     .get =
         [](const Light& l) {
             return l.specularIsColor ? QVariant::fromValue(l.specular) : QVariant(l.specular.x);
         },
     .set =
         [](Light& l, const QVariant& v) {
             if (auto c = toVec3(v, true)) {
                 l.specular = *c;
                 l.specularIsColor = true;
             } else if (auto f = toDouble(v)) {
                 l.specular = glm::dvec3(*f);
                 l.specularIsColor = false;
             }
         }},
    {.id = P::Ambient,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "light ambient"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Ambient"),
     .key = "ambient",
     .jsonField = "ambient",
     .kind = K::OptionalColor,
     .min = 0.0,
     .max = kMaxColorComponent,
     .usedBy = &T::usesSurfaceModels,
     .get = [](const Light& l) { return l.ambient ? QVariant::fromValue(*l.ambient) : QVariant(); },
     .set = [](Light& l, const QVariant& v) { l.ambient = toVec3(v, true); }},
    {.id = P::RimExponent,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "rim exponent"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Rim e&xponent"),
     .key = "rimExponent",
     .jsonField = "exponent",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxExponent,
     .minExclusive = true,
     .usedBy = &T::usesRimExponent,
     .get = [](const Light& l) { return QVariant(l.rimExponent); },
     .set = [](Light& l, const QVariant& v) { l.rimExponent = number(v, l.rimExponent); }},
    // An area light's emitter (issue 16; core/rig.h AreaShape, docs/rig-format.md "area").
    {.id = P::AreaWidth,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "width"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Width"),
     .key = "areaWidth",
     .jsonField = "area.width",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxAreaSize,
     .unit = "rig units",
     .usedBy = &T::usesRectSize,
     .get = [](const Light& l) { return QVariant(l.area.width); },
     .set = [](Light& l, const QVariant& v) { l.area.width = number(v, l.area.width); }},
    {.id = P::AreaHeight,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "height"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Height"),
     .key = "areaHeight",
     .jsonField = "area.height",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxAreaSize,
     .unit = "rig units",
     .usedBy = &T::usesRectSize,
     .get = [](const Light& l) { return QVariant(l.area.height); },
     .set = [](Light& l, const QVariant& v) { l.area.height = number(v, l.area.height); }},
    {.id = P::AreaRadius,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "radius"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Radi&us"),
     .key = "areaRadius",
     .jsonField = "area.radius",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxAreaSize,
     .unit = "rig units",
     .usedBy = &T::usesDiskRadius,
     .get = [](const Light& l) { return QVariant(l.area.radius); },
     .set = [](Light& l, const QVariant& v) { l.area.radius = number(v, l.area.radius); }},
    {.id = P::AreaRoll,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "roll"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Ro&ll"),
     .key = "areaRoll",
     .jsonField = "area.roll",
     .kind = K::Number,
     .min = -180.0,
     .max = 180.0,
     .unit = "degrees",
     .suffix = "°",
     .usedBy = &T::isArea,
     .get = [](const Light& l) { return QVariant(l.area.roll); },
     .set = [](Light& l, const QVariant& v) { l.area.roll = number(v, l.area.roll); }},
    {.id = P::AreaTwoSided,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "two-sided"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Tw&o-sided"),
     .key = "areaTwoSided",
     .jsonField = "area.twoSided",
     .kind = K::Bool,
     .usedBy = &T::isArea,
     .check = checkBool,
     .get = [](const Light& l) { return QVariant(l.area.twoSided); },
     .set = [](Light& l, const QVariant& v) { l.area.twoSided = v.toBool(); }},
    // The shadow (issue 14; docs/rig-format.md "shadow"): its details are shown while it is switched on.
    {.id = P::ShadowEnabled,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "shadow"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Shado&w"),
     .tableLabel = QT_TRANSLATE_NOOP("lr::LightProperty", "Shadow"),
     .key = "shadowEnabled",
     .jsonField = "shadow.enabled",
     .kind = K::Bool,
     .usedBy = &T::castsShadows,
     .check = checkBool,
     .get = [](const Light& l) { return QVariant(l.shadow.enabled); },
     .set = [](Light& l, const QVariant& v) { l.shadow.enabled = v.toBool(); },
     .undoText = undoSwitchShadow},
    {.id = P::ShadowResolution,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "shadow resolution"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Shadow resolution"),
     .key = "shadowResolution",
     .jsonField = "shadow.resolution",
     .kind = K::Number,
     .min = kMinShadowResolution,
     .max = kMaxShadowResolution,
     .unit = "texels per side",
     .suffix = " texels",
     .usedBy = &T::castsShadows,
     .shown = shadowOn,
     .check = checkShadowResolution,
     .get = [](const Light& l) { return QVariant(l.shadow.resolution); },
     .set = [](Light& l, const QVariant& v) { l.shadow.resolution = int(number(v, l.shadow.resolution)); },
     .shownWith = P::ShadowEnabled}, // the Shadow column's tooltip names it
    {.id = P::ShadowBias,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "shadow bias"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Shadow bias"),
     .key = "shadowBias",
     .jsonField = "shadow.bias",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxShadowBias,
     .unit = "texels",
     .usedBy = &T::castsShadows,
     .shown = shadowOn,
     .get = [](const Light& l) { return QVariant(l.shadow.bias); },
     .set = [](Light& l, const QVariant& v) { l.shadow.bias = number(v, l.shadow.bias); }},
    {.id = P::ShadowNormalOffset,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "shadow normal offset"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Normal offset"),
     .key = "shadowNormalOffset",
     .jsonField = "shadow.normalOffset",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxShadowBias,
     .unit = "texels",
     .usedBy = &T::castsShadows,
     .shown = shadowOn,
     .get = [](const Light& l) { return QVariant(l.shadow.normalOffset); },
     .set = [](Light& l, const QVariant& v) { l.shadow.normalOffset = number(v, l.shadow.normalOffset); }},
    {.id = P::ShadowSize,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "emitter size"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Emitter si&ze"),
     .key = "shadowSize",
     .jsonField = "shadow.size",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxShadowSize,
     .unit = "diameter in the rig's units",
     .usedBy = &T::usesPosition, // every type with a position casts shadows (static_assert below)
     .unless = &T::isArea,       // an area light's shadow is as soft as its own size makes it
     .shown = shadowOn,
     .get = [](const Light& l) { return QVariant(l.shadow.size); },
     .set = [](Light& l, const QVariant& v) { l.shadow.size = number(v, l.shadow.size); }},
    {.id = P::ShadowAngle,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "emitter angle"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Emitter an&gle"),
     .key = "shadowAngle",
     .jsonField = "shadow.angle",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxShadowAngle,
     .unit = "degrees",
     .suffix = "°",
     .usedBy = &T::castsShadows,
     .unless = &T::usesPosition, // lights at infinity: directional
     .shown = shadowOn,
     .get = [](const Light& l) { return QVariant(l.shadow.angle); },
     .set = [](Light& l, const QVariant& v) { l.shadow.angle = number(v, l.shadow.angle); }},
};
static_assert(
    [] {
        for (const LightTypeTraits& t : kLightTypeTraits)
            if (t.usesPosition && !t.castsShadows) return false;
        return true;
    }(),
    "the emitter size row applies to the types with a position: they must all cast shadows");
static_assert(std::size(kLightProperties) + 1 + kGoboLightPropertyCount + 3 + 5 ==
                  size_t(kLightPropertyCount), // + link, gobo, barn doors, IES
              "one row per LightProperty");

} // namespace

QString checkDirection(const LightPropertyInfo& row, const QVariant& v) {
    const auto d = propertyvalue::toVec3(v, false);
    if (QString e = propertyvalue::checkVec3(row.displayName(), d, row.min, row.max); !e.isEmpty()) return e;
    const double len = glm::length(*d);
    if (!(len > 1e-12) || !std::isfinite(len))
        return QStringLiteral("%1 must not be zero").arg(row.displayName());
    return {};
}

std::span<const LightPropertyInfo> valueLightProperties() { // all but Link (lightproperty_link.cpp)
    return kLightProperties;
}

} // namespace lr
