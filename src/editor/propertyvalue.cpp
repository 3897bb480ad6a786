#include "editor/propertyvalue.h"

#include "core/colour.h"

#include <QVector3D>
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

namespace lr {

namespace propertyvalue {

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

double number(const QVariant& v, double fallback) {
    return toDouble(v).value_or(fallback);
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

bool finite3(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

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

} // namespace propertyvalue

QColor displayColor(const glm::dvec3& linear) {
    glm::dvec3 c = propertyvalue::finite3(linear) ? glm::max(linear, glm::dvec3(0.0)) : glm::dvec3(0.0);
    const double m = std::max({c.x, c.y, c.z});
    if (m > 1.0) c /= m;
    return QColor::fromRgbF(float(colour::linearToSrgb(c.x)), float(colour::linearToSrgb(c.y)),
                            float(colour::linearToSrgb(c.z)));
}

glm::dvec3 linearFromDisplayColor(const QColor& color) {
    const QColor c = color.toRgb();
    return colour::srgbToLinear(glm::dvec3(c.redF(), c.greenF(), c.blueF()));
}

} // namespace lr
