#include "editor/lightproperty.h"

#include "core/rigjson.h"

#include <QVector3D>
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

} // namespace

QString lightPropertyName(LightProperty p) {
    switch (p) {
    case LightProperty::Name:
        return QStringLiteral("name");
    case LightProperty::Type:
        return QStringLiteral("type");
    case LightProperty::Enabled:
        return QStringLiteral("on/off");
    case LightProperty::Color:
        return QStringLiteral("colour");
    case LightProperty::Intensity:
        return QStringLiteral("intensity");
    case LightProperty::Temperature:
        return QStringLiteral("temperature");
    case LightProperty::Position:
        return QStringLiteral("position");
    case LightProperty::Direction:
        return QStringLiteral("direction");
    case LightProperty::FalloffModel:
        return QStringLiteral("falloff model");
    case LightProperty::FalloffRange:
        return QStringLiteral("range");
    case LightProperty::FalloffExponent:
        return QStringLiteral("falloff exponent");
    case LightProperty::FalloffConstant:
        return QStringLiteral("constant attenuation");
    case LightProperty::FalloffLinear:
        return QStringLiteral("linear attenuation");
    case LightProperty::FalloffQuadratic:
        return QStringLiteral("quadratic attenuation");
    case LightProperty::ConeModel:
        return QStringLiteral("cone model");
    case LightProperty::ConeInner:
        return QStringLiteral("cone inner angle");
    case LightProperty::ConeOuter:
        return QStringLiteral("cone outer angle");
    case LightProperty::ConeExponent:
        return QStringLiteral("cone exponent");
    case LightProperty::Diffuse:
        return QStringLiteral("diffuse model");
    case LightProperty::Specular:
        return QStringLiteral("specular");
    case LightProperty::Ambient:
        return QStringLiteral("light ambient");
    case LightProperty::RimExponent:
        return QStringLiteral("rim exponent");
    case LightProperty::Any:
        break;
    }
    return QStringLiteral("light");
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
    case RigProperty::Any:
        break;
    }
    return QStringLiteral("rig");
}

bool lightPropertyApplies(const Light& l, LightProperty p) {
    switch (p) {
    case LightProperty::Position:
        return l.usesPosition();
    case LightProperty::Direction:
        return l.usesDirection();
    case LightProperty::FalloffModel:
    case LightProperty::FalloffRange:
    case LightProperty::FalloffExponent:
    case LightProperty::FalloffConstant:
    case LightProperty::FalloffLinear:
    case LightProperty::FalloffQuadratic:
        return l.usesFalloff();
    case LightProperty::ConeModel:
    case LightProperty::ConeInner:
    case LightProperty::ConeOuter:
    case LightProperty::ConeExponent:
        return l.usesCone();
    case LightProperty::Diffuse:
    case LightProperty::Specular:
    case LightProperty::Ambient:
        return l.usesSurfaceModels();
    case LightProperty::RimExponent:
        return l.type == LightType::Rim;
    case LightProperty::Any:
        return false;
    default:
        return true;
    }
}

QVariant lightValue(const Light& l, LightProperty p) {
    switch (p) {
    case LightProperty::Name:
        return l.name;
    case LightProperty::Type:
        return QVariant::fromValue(l.type);
    case LightProperty::Enabled:
        return l.enabled;
    case LightProperty::Color:
        return QVariant::fromValue(l.color);
    case LightProperty::Intensity:
        return l.intensity;
    case LightProperty::Temperature:
        return l.temperature ? QVariant(*l.temperature) : QVariant();
    case LightProperty::Position:
        return QVariant::fromValue(l.position);
    case LightProperty::Direction:
        return QVariant::fromValue(l.direction);
    case LightProperty::FalloffModel:
        return QVariant::fromValue(l.falloff.model);
    case LightProperty::FalloffRange:
        return l.falloff.hasRange() ? QVariant(l.falloff.range) : QVariant();
    case LightProperty::FalloffExponent:
        return l.falloff.exponent;
    case LightProperty::FalloffConstant:
        return l.falloff.constant;
    case LightProperty::FalloffLinear:
        return l.falloff.linear;
    case LightProperty::FalloffQuadratic:
        return l.falloff.quadratic;
    case LightProperty::ConeModel:
        return QVariant::fromValue(l.cone.model);
    case LightProperty::ConeInner:
        return l.cone.inner;
    case LightProperty::ConeOuter:
        return l.cone.outer;
    case LightProperty::ConeExponent:
        return l.cone.exponent;
    case LightProperty::Diffuse:
        return QVariant::fromValue(l.diffuse);
    case LightProperty::Specular:
        return l.specularIsColor ? QVariant::fromValue(l.specular) : QVariant(l.specular.x);
    case LightProperty::Ambient:
        return l.ambient ? QVariant::fromValue(*l.ambient) : QVariant();
    case LightProperty::RimExponent:
        return l.rimExponent;
    case LightProperty::Any:
        break;
    }
    return {};
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
    case RigProperty::Any:
        break;
    }
    return {};
}

QString validateLightValue(LightProperty p, const QVariant& v) {
    const QString what = lightPropertyName(p);
    switch (p) {
    case LightProperty::Name: {
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
    case LightProperty::Type:
        return checkEnum<LightType>(what, v);
    case LightProperty::Enabled:
        return v.metaType().id() == QMetaType::Bool ? QString()
                                                    : QStringLiteral("on/off must be true or false");
    case LightProperty::Color:
        return checkVec3(what, toVec3(v, true), 0.0, kMaxColorComponent);
    case LightProperty::Intensity:
        return checkRange(what, toDouble(v), 0.0, kMaxIntensity, false);
    case LightProperty::Temperature:
        if (isNone(v)) return {};
        return checkRange(QStringLiteral("temperature (kelvin)"), toDouble(v), kMinTemperature,
                          kMaxTemperature, false);
    case LightProperty::Position:
        return checkVec3(what, toVec3(v, false), -kMaxCoordinate, kMaxCoordinate);
    case LightProperty::Direction: {
        const auto d = toVec3(v, false);
        if (QString e = checkVec3(what, d, -kMaxCoordinate, kMaxCoordinate); !e.isEmpty()) return e;
        const double len = glm::length(*d);
        if (!(len > 1e-12) || !std::isfinite(len)) return QStringLiteral("direction must not be zero");
        return {};
    }
    case LightProperty::FalloffModel:
        return checkEnum<FalloffModel>(what, v);
    case LightProperty::FalloffRange:
        if (isNone(v)) return {};
        return checkRange(what, toDouble(v), 0.0, kMaxCoordinate, true);
    case LightProperty::FalloffExponent:
    case LightProperty::ConeExponent:
    case LightProperty::RimExponent:
        return checkRange(what, toDouble(v), 0.0, kMaxExponent, true);
    case LightProperty::FalloffConstant:
    case LightProperty::FalloffLinear:
    case LightProperty::FalloffQuadratic:
        return checkRange(what, toDouble(v), 0.0, kMaxPolynomialCoefficient, false);
    case LightProperty::ConeModel:
        return checkEnum<ConeModel>(what, v);
    case LightProperty::ConeInner:
    case LightProperty::ConeOuter:
        return checkRange(what + QStringLiteral(" (degrees)"), toDouble(v), 0.0, 90.0, true);
    case LightProperty::Diffuse:
        return checkEnum<DiffuseModel>(what, v);
    case LightProperty::Specular:
        if (auto c = toVec3(v, true))
            return checkVec3(QStringLiteral("specular colour"), c, 0.0, kMaxColorComponent);
        return checkRange(QStringLiteral("specular factor"), toDouble(v), 0.0, kMaxColorComponent, false);
    case LightProperty::Ambient:
        if (isNone(v)) return {};
        return checkVec3(what, toVec3(v, true), 0.0, kMaxColorComponent);
    case LightProperty::Any:
        break;
    }
    return QStringLiteral("not an editable light value");
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

QString validateRig(const Rig& r) {
    if (r.lights.size() > size_t(kMaxRigLights))
        return QStringLiteral("a rig holds at most %1 lights, got %2")
            .arg(kMaxRigLights)
            .arg(r.lights.size());
    for (int i = 0; i < kRigPropertyCount; ++i)
        if (QString e = validateRigValue(RigProperty(i), rigValue(r, RigProperty(i))); !e.isEmpty()) return e;
    for (const Light& l : r.lights)
        if (QString e = validateLight(l); !e.isEmpty()) return e;
    return {};
}

Light withLightValue(const Light& light, LightProperty p, const QVariant& v) {
    Light l = light;
    switch (p) {
    case LightProperty::Name:
        l.name = v.toString();
        break;
    case LightProperty::Type:
        if (auto t = toEnum<LightType>(v)) l.type = *t;
        break;
    case LightProperty::Enabled:
        l.enabled = v.toBool();
        break;
    case LightProperty::Color:
        if (auto c = toVec3(v, true)) l.color = *c;
        break;
    case LightProperty::Intensity:
        l.intensity = toDouble(v).value_or(l.intensity);
        break;
    case LightProperty::Temperature:
        l.temperature = toDouble(v);
        break;
    case LightProperty::Position:
        if (auto c = toVec3(v, false)) l.position = *c;
        break;
    case LightProperty::Direction:
        if (auto c = toVec3(v, false); c && glm::length(*c) > 0.0) l.direction = glm::normalize(*c);
        break;
    case LightProperty::FalloffModel:
        if (auto m = toEnum<FalloffModel>(v)) {
            l.falloff.model = *m;
            if (!rangeOptional(*m) && !l.falloff.hasRange()) l.falloff.range = 10.0;
            if (*m == FalloffModel::InversePolynomial &&
                !(l.falloff.constant > 0 || l.falloff.linear > 0 || l.falloff.quadratic > 0))
                l.falloff.constant = 1.0;
        }
        break;
    case LightProperty::FalloffRange:
        l.falloff.range = toDouble(v).value_or(-1.0);
        break;
    case LightProperty::FalloffExponent:
        l.falloff.exponent = toDouble(v).value_or(l.falloff.exponent);
        break;
    case LightProperty::FalloffConstant:
        l.falloff.constant = toDouble(v).value_or(l.falloff.constant);
        break;
    case LightProperty::FalloffLinear:
        l.falloff.linear = toDouble(v).value_or(l.falloff.linear);
        break;
    case LightProperty::FalloffQuadratic:
        l.falloff.quadratic = toDouble(v).value_or(l.falloff.quadratic);
        break;
    case LightProperty::ConeModel:
        if (auto m = toEnum<ConeModel>(v)) {
            l.cone.model = *m;
            l.cone.inner = std::min(l.cone.inner, l.cone.outer);
        }
        break;
    case LightProperty::ConeInner:
        l.cone.inner = toDouble(v).value_or(l.cone.inner);
        break;
    case LightProperty::ConeOuter:
        l.cone.outer = toDouble(v).value_or(l.cone.outer);
        // Only a smooth cone uses the inner angle; for the others it follows the outer angle down so that
        // switching to smooth later stays valid.
        if (l.cone.model != ConeModel::Smooth) l.cone.inner = std::min(l.cone.inner, l.cone.outer);
        break;
    case LightProperty::ConeExponent:
        l.cone.exponent = toDouble(v).value_or(l.cone.exponent);
        break;
    case LightProperty::Diffuse:
        if (auto m = toEnum<DiffuseModel>(v)) l.diffuse = *m;
        break;
    case LightProperty::Specular:
        if (auto c = toVec3(v, true)) {
            l.specular = *c;
            l.specularIsColor = true;
        } else if (auto f = toDouble(v)) {
            l.specular = glm::dvec3(*f);
            l.specularIsColor = false;
        }
        break;
    case LightProperty::Ambient:
        l.ambient = toVec3(v, true);
        break;
    case LightProperty::RimExponent:
        l.rimExponent = toDouble(v).value_or(l.rimExponent);
        break;
    case LightProperty::Any:
        break;
    }
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
