#include "editor/lightproperty.h"

#include "core/rigjson.h"
#include "editor/environmentvalue.h"

#include <QCoreApplication>
#include <QVector3D>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>

namespace lr {

namespace {

QString num(double v) {
    return QString::number(v, 'g', 6);
}

bool isNone(const QVariant& v) {
    return !v.isValid() || v.isNull();
}

std::optional<double> toDouble(const QVariant& v) {
    if (isNone(v)) return std::nullopt;
    switch (v.metaType().id()) {
    case QMetaType::Double:
    case QMetaType::Float:
    case QMetaType::Int:
    case QMetaType::UInt:
    case QMetaType::LongLong:
    case QMetaType::ULongLong:
        return v.toDouble();
    case QMetaType::QString: {
        bool ok = false;
        const double d = v.toString().trimmed().toDouble(&ok);
        if (ok) return d;
        return std::nullopt;
    }
    default:
        return std::nullopt;
    }
}

std::optional<glm::dvec3> toVec3(const QVariant& v, bool colorIsSrgb) {
    if (isNone(v)) return std::nullopt;
    if (v.metaType() == QMetaType::fromType<glm::dvec3>()) return v.value<glm::dvec3>();
    if (v.metaType() == QMetaType::fromType<QVector3D>()) {
        const QVector3D q = v.value<QVector3D>();
        return glm::dvec3(q.x(), q.y(), q.z());
    }
    if (colorIsSrgb && v.metaType() == QMetaType::fromType<QColor>()) {
        const QColor c = v.value<QColor>();
        if (!c.isValid()) return std::nullopt;
        return linearFromDisplayColor(c);
    }
    return std::nullopt;
}

template <typename E> std::optional<E> toEnum(const QVariant& v) {
    if (isNone(v)) return std::nullopt;
    if (v.metaType() == QMetaType::fromType<E>()) return v.value<E>();
    if (v.metaType().id() == QMetaType::QString) return fromString<E>(v.toString());
    if (v.metaType().id() == QMetaType::Int || v.metaType().id() == QMetaType::LongLong ||
        v.metaType().id() == QMetaType::UInt) {
        const qlonglong i = v.toLongLong();
        if (i >= 0 && i < enumCount<E>()) return E(int(i));
    }
    return std::nullopt;
}

bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// "NAME must be a finite number between LO and HI, got V" style checks.
QString checkRange(const QString& what, const std::optional<double>& d, double lo, double hi, bool loOpen) {
    const QString range = loOpen ? QStringLiteral("> %1 and <= %2").arg(num(lo), num(hi))
                                 : QStringLiteral("between %1 and %2").arg(num(lo), num(hi));
    if (!d) return QStringLiteral("%1 must be a number %2").arg(what, range);
    if (!std::isfinite(*d) || (loOpen ? *d <= lo : *d < lo) || *d > hi)
        return QStringLiteral("%1 must be a finite number %2, got %3").arg(what, range, num(*d));
    return {};
}

QString checkVec3(const QString& what, const std::optional<glm::dvec3>& v, double lo, double hi) {
    if (!v) return QStringLiteral("%1 must be three numbers").arg(what);
    if (!finite3(*v)) return QStringLiteral("%1 must be finite").arg(what);
    for (int i = 0; i < 3; ++i)
        if ((*v)[i] < lo || (*v)[i] > hi)
            return QStringLiteral("%1 components must be between %2 and %3, got %4")
                .arg(what, num(lo), num(hi), num((*v)[i]));
    return {};
}

template <typename E> QString checkEnum(const QString& what, const QVariant& v) {
    if (!toEnum<E>(v)) return QStringLiteral("%1 must be %2").arg(what, allowedNames<E>());
    return {};
}

bool rangeOptional(FalloffModel m) {
    return m == FalloffModel::InversePolynomial || m == FalloffModel::InverseSquare ||
           m == FalloffModel::None;
}

// ---- value conversions and checks used by the table's rows ----

double number(const QVariant& v, double fallback) {
    return toDouble(v).value_or(fallback);
}

template <typename E> QString enumCheck(const LightPropertyInfo& row, const QVariant& v) {
    return checkEnum<E>(row.displayName(), v);
}

template <typename E> QStringList enumChoices() {
    QStringList out;
    for (int i = 0; i < enumCount<E>(); ++i)
        out << toString(E(i));
    return out;
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

QString checkBool(const LightPropertyInfo& row, const QVariant& v) {
    return v.metaType().id() == QMetaType::Bool
               ? QString()
               : QStringLiteral("%1 must be true or false").arg(row.displayName());
}

QString checkDirection(const LightPropertyInfo& row, const QVariant& v) {
    const auto d = toVec3(v, false);
    if (QString e = checkVec3(row.displayName(), d, row.min, row.max); !e.isEmpty()) return e;
    const double len = glm::length(*d);
    if (!(len > 1e-12) || !std::isfinite(len)) return QStringLiteral("direction must not be zero");
    return {};
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

bool hasRangeModel(const Light& l) {
    return l.falloff.model != FalloffModel::None;
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
     .uniquePerLight = true},
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
             // A model that needs a range gets one; inverse-polynomial needs a positive coefficient.
             if (!rangeOptional(*m) && !l.falloff.hasRange()) l.falloff.range = 10.0;
             if (*m == FalloffModel::InversePolynomial &&
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
     .min = 0.0,
     .max = kMaxCoordinate,
     .minExclusive = true,
     .usedBy = &T::usesFalloff,
     .shown = hasRangeModel,
     .get = [](const Light& l) { return l.falloff.hasRange() ? QVariant(l.falloff.range) : QVariant(); },
     .set = [](Light& l, const QVariant& v) { l.falloff.range = toDouble(v).value_or(-1.0); }},
    {.id = P::FalloffExponent,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "falloff exponent"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Falloff e&xponent"),
     .key = "falloffExponent",
     .jsonField = "falloff.exponent",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxExponent,
     .minExclusive = true,
     .usedBy = &T::usesFalloff,
     .shown = [](const Light& l) { return l.falloff.model == FalloffModel::RangePower; },
     .get = [](const Light& l) { return QVariant(l.falloff.exponent); },
     .set = [](Light& l, const QVariant& v) { l.falloff.exponent = number(v, l.falloff.exponent); }},
    {.id = P::FalloffConstant,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "constant attenuation"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "Consta&nt"),
     .key = "falloffConstant",
     .jsonField = "falloff.constant",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxPolynomialCoefficient,
     .usedBy = &T::usesFalloff,
     .shown = [](const Light& l) { return l.falloff.model == FalloffModel::InversePolynomial; },
     .get = [](const Light& l) { return QVariant(l.falloff.constant); },
     .set = [](Light& l, const QVariant& v) { l.falloff.constant = number(v, l.falloff.constant); }},
    {.id = P::FalloffLinear,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "linear attenuation"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Linear"),
     .key = "falloffLinear",
     .jsonField = "falloff.linear",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxPolynomialCoefficient,
     .usedBy = &T::usesFalloff,
     .shown = [](const Light& l) { return l.falloff.model == FalloffModel::InversePolynomial; },
     .get = [](const Light& l) { return QVariant(l.falloff.linear); },
     .set = [](Light& l, const QVariant& v) { l.falloff.linear = number(v, l.falloff.linear); }},
    {.id = P::FalloffQuadratic,
     .name = QT_TRANSLATE_NOOP("lr::LightProperty", "quadratic attenuation"),
     .label = QT_TRANSLATE_NOOP("lr::LightProperty", "&Quadratic"),
     .key = "falloffQuadratic",
     .jsonField = "falloff.quadratic",
     .kind = K::Number,
     .min = 0.0,
     .max = kMaxPolynomialCoefficient,
     .usedBy = &T::usesFalloff,
     .shown = [](const Light& l) { return l.falloff.model == FalloffModel::InversePolynomial; },
     .get = [](const Light& l) { return QVariant(l.falloff.quadratic); },
     .set = [](Light& l, const QVariant& v) { l.falloff.quadratic = number(v, l.falloff.quadratic); }},
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
static_assert(std::size(kLightProperties) == size_t(kLightPropertyCount), "one row per LightProperty");

// Row index by id (the table is in display order, not enum order).
const std::array<int, kLightPropertyCount>& rowIndex() {
    static const std::array<int, kLightPropertyCount> index = [] {
        std::array<int, kLightPropertyCount> out{};
        out.fill(-1);
        for (int i = 0; i < kLightPropertyCount; ++i)
            out[size_t(kLightProperties[i].id)] = i;
        for (int i : out)
            Q_ASSERT_X(i >= 0, "kLightProperties", "a LightProperty has no row");
        return out;
    }();
    return index;
}

// The generic check of a row by its kind (rows with their own `check` use that instead).
QString checkByKind(const LightPropertyInfo& row, const QVariant& v) {
    QString what = row.displayName();
    if (row.unit) what += QStringLiteral(" (%1)").arg(QLatin1String(row.unit));
    switch (row.kind) {
    case K::OptionalNumber:
        if (isNone(v)) return {};
        [[fallthrough]];
    case K::Number:
        return checkRange(what, toDouble(v), row.min, row.max, row.minExclusive);
    case K::OptionalColor:
        if (isNone(v)) return {};
        [[fallthrough]];
    case K::Color:
        return checkVec3(what, toVec3(v, true), row.min, row.max);
    case K::Vector:
        return checkVec3(what, toVec3(v, false), row.min, row.max);
    default:
        return QStringLiteral("not an editable light value");
    }
}

} // namespace

QString LightPropertyInfo::displayName() const {
    return QCoreApplication::translate("lr::LightProperty", name);
}

QString LightPropertyInfo::displayLabel() const {
    return QCoreApplication::translate("lr::LightProperty", label);
}

bool LightPropertyInfo::applies(const Light& light) const {
    const LightTypeTraits& t = traitsOf(light.type);
    return (!usedBy || t.*usedBy) && (!unless || !(t.*unless));
}

bool LightPropertyInfo::isShown(const Light& light) const {
    return applies(light) && (!shown || shown(light));
}

std::span<const LightPropertyInfo> lightProperties() {
    return kLightProperties;
}

const LightPropertyInfo* lightPropertyInfo(LightProperty p) {
    if (int(p) < 0 || int(p) >= kLightPropertyCount) return nullptr;
    return &kLightProperties[rowIndex()[size_t(p)]];
}

QString lightPropertyName(LightProperty p) {
    const LightPropertyInfo* row = lightPropertyInfo(p);
    return row ? row->displayName() : QStringLiteral("light");
}

QString rigPropertyName(RigProperty p) {
    switch (p) {
    case RigProperty::Name:
        return QStringLiteral("rig name");
    case RigProperty::Space:
        return QStringLiteral("rig space");
    case RigProperty::Ambient:
        return QStringLiteral("ambient");
    case RigProperty::SpecularModel:
        return QStringLiteral("specular model");
    case RigProperty::ViewerModel:
        return QStringLiteral("viewer model");
    case RigProperty::Shininess:
        return QStringLiteral("shininess");
    case RigProperty::ShadingModel:
        return QStringLiteral("shading model");
    case RigProperty::GroundMode:
        return QStringLiteral("ground");
    case RigProperty::GroundColor:
        return QStringLiteral("ground colour");
    case RigProperty::Environment:
        return QStringLiteral("environment");
    case RigProperty::Any:
        break;
    }
    return QStringLiteral("rig");
}

bool lightPropertyApplies(const Light& l, LightProperty p) {
    const LightPropertyInfo* row = lightPropertyInfo(p);
    return row && row->applies(l);
}

QVariant lightValue(const Light& l, LightProperty p) {
    const LightPropertyInfo* row = lightPropertyInfo(p);
    return row ? row->get(l) : QVariant();
}

QVariant rigValue(const Rig& r, RigProperty p) {
    switch (p) {
    case RigProperty::Name:
        return r.name;
    case RigProperty::Space:
        return QVariant::fromValue(r.space);
    case RigProperty::Ambient:
        return QVariant::fromValue(r.ambient);
    case RigProperty::SpecularModel:
        return QVariant::fromValue(r.shading.specular);
    case RigProperty::ViewerModel:
        return QVariant::fromValue(r.shading.viewer);
    case RigProperty::Shininess:
        return r.shading.shininess;
    case RigProperty::ShadingModel:
        return QVariant::fromValue(r.shading.model);
    case RigProperty::GroundMode:
        return QVariant::fromValue(r.ground.mode);
    case RigProperty::GroundColor:
        return QVariant::fromValue(r.ground.color);
    case RigProperty::Environment:
        return QVariant::fromValue(r.environment);
    case RigProperty::Any:
        break;
    }
    return {};
}

QString validateLightValue(LightProperty p, const QVariant& v) {
    const LightPropertyInfo* row = lightPropertyInfo(p);
    if (!row) return QStringLiteral("not an editable light value");
    return row->check ? row->check(*row, v) : checkByKind(*row, v);
}

QString validateLightValue(const Light& l, LightProperty p, const QVariant& v) {
    if (QString e = validateLightValue(p, v); !e.isEmpty()) return e;
    // Checks against the light's other values, on the light as it would be after the change.
    const Light after = withLightValue(l, p, v);
    const Falloff& f = after.falloff;
    if (after.usesFalloff()) {
        if (!f.hasRange() && !rangeOptional(f.model))
            return QStringLiteral("the %1 falloff needs a range").arg(toString(f.model));
        if (f.model == FalloffModel::InversePolynomial &&
            !(f.constant > 0 || f.linear > 0 || f.quadratic > 0))
            return QStringLiteral(
                "at least one of the constant, linear and quadratic attenuation must be > 0");
    }
    if (after.usesCone() && after.cone.model == ConeModel::Smooth && after.cone.inner > after.cone.outer)
        return p == LightProperty::ConeInner
                   ? QStringLiteral("cone inner angle must be <= the outer angle (%1°), got %2")
                         .arg(num(after.cone.outer), num(after.cone.inner))
                   : QStringLiteral("cone outer angle must be >= the inner angle (%1°), got %2")
                         .arg(num(after.cone.inner), num(after.cone.outer));
    return {};
}

QString validateRigValue(RigProperty p, const QVariant& v) {
    switch (p) {
    case RigProperty::Name:
        if (v.metaType().id() != QMetaType::QString) return QStringLiteral("rig name must be text");
        if (v.toString().size() > kMaxLightNameLength)
            return QStringLiteral("rig name must be at most %1 characters").arg(kMaxLightNameLength);
        return {};
    case RigProperty::Space:
        return checkEnum<RigSpace>(rigPropertyName(p), v);
    case RigProperty::Ambient:
        return checkVec3(rigPropertyName(p), toVec3(v, true), 0.0, kMaxColorComponent);
    case RigProperty::SpecularModel:
        return checkEnum<SpecularModel>(rigPropertyName(p), v);
    case RigProperty::ViewerModel:
        return checkEnum<ViewerModel>(rigPropertyName(p), v);
    case RigProperty::Shininess:
        return checkRange(rigPropertyName(p), toDouble(v), 0.0, kMaxShininess, true);
    case RigProperty::ShadingModel:
        return checkEnum<ShadingModel>(rigPropertyName(p), v);
    case RigProperty::GroundMode:
        return checkEnum<GroundMode>(rigPropertyName(p), v);
    case RigProperty::GroundColor: // an albedo: what share of the light the ground reflects
        return checkVec3(rigPropertyName(p), toVec3(v, true), 0.0, 1.0);
    case RigProperty::Environment:
        if (v.metaType() != QMetaType::fromType<Environment>()) return QStringLiteral("not an environment");
        return validateEnvironment(v.value<Environment>());
    case RigProperty::Any:
        break;
    }
    return QStringLiteral("not an editable rig value");
}

QString validateLight(const Light& l) {
    for (int i = 0; i < kLightPropertyCount; ++i) {
        const auto p = LightProperty(i);
        // Names from files and model imports are taken as they are (the table shows them; edits are checked).
        if (p == LightProperty::Name) continue;
        if (!lightPropertyApplies(l, p) && p != LightProperty::Type) continue;
        if (QString e = validateLightValue(l, p, lightValue(l, p)); !e.isEmpty())
            return QStringLiteral("light \"%1\": %2").arg(l.name, e);
    }
    return {};
}

QString checkShadowCasterCount(int casters) {
    if (casters <= kMaxShadowCasters) return {};
    return QStringLiteral("%1 lights would cast shadows; at most %2 can (one shadow map each): switch off "
                          "another light's shadow first")
        .arg(casters)
        .arg(kMaxShadowCasters);
}

QString validateRig(const Rig& r) {
    if (r.lights.size() > size_t(kMaxRigLights))
        return QStringLiteral("a rig holds at most %1 lights, got %2")
            .arg(kMaxRigLights)
            .arg(r.lights.size());
    if (QString e = checkShadowCasterCount(shadowCasterCount(r.lights)); !e.isEmpty()) return e;
    for (int i = 0; i < kRigPropertyCount; ++i)
        if (QString e = validateRigValue(RigProperty(i), rigValue(r, RigProperty(i))); !e.isEmpty()) return e;
    for (const Light& l : r.lights)
        if (QString e = validateLight(l); !e.isEmpty()) return e;
    return {};
}

Light withLightValue(const Light& light, LightProperty p, const QVariant& v) {
    Light l = light;
    if (const LightPropertyInfo* row = lightPropertyInfo(p)) row->set(l, v);
    return l;
}

void applyRigValue(Rig& r, RigProperty p, const QVariant& v) {
    switch (p) {
    case RigProperty::Name:
        r.name = v.toString();
        break;
    case RigProperty::Space:
        if (auto s = toEnum<RigSpace>(v)) r.space = *s;
        break;
    case RigProperty::Ambient:
        if (auto c = toVec3(v, true)) r.ambient = *c;
        break;
    case RigProperty::SpecularModel:
        if (auto s = toEnum<SpecularModel>(v)) r.shading.specular = *s;
        break;
    case RigProperty::ViewerModel:
        if (auto s = toEnum<ViewerModel>(v)) r.shading.viewer = *s;
        break;
    case RigProperty::Shininess:
        r.shading.shininess = toDouble(v).value_or(r.shading.shininess);
        break;
    case RigProperty::ShadingModel:
        if (auto s = toEnum<ShadingModel>(v)) r.shading.model = *s;
        break;
    case RigProperty::GroundMode:
        if (auto m = toEnum<GroundMode>(v)) r.ground.mode = *m;
        break;
    case RigProperty::GroundColor:
        if (auto c = toVec3(v, true)) r.ground.color = *c;
        break;
    case RigProperty::Environment:
        r.environment = v.value<Environment>();
        break;
    case RigProperty::Any:
        break;
    }
}

namespace {
double toSrgb(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}
double toLinear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
} // namespace

QColor displayColor(const glm::dvec3& linear) {
    glm::dvec3 c = finite3(linear) ? glm::max(linear, glm::dvec3(0.0)) : glm::dvec3(0.0);
    const double m = std::max({c.x, c.y, c.z});
    if (m > 1.0) c /= m;
    return QColor::fromRgbF(float(toSrgb(c.x)), float(toSrgb(c.y)), float(toSrgb(c.z)));
}

glm::dvec3 linearFromDisplayColor(const QColor& color) {
    const QColor c = color.toRgb();
    return {toLinear(c.redF()), toLinear(c.greenF()), toLinear(c.blueF())};
}

} // namespace lr
