// The editor's value vocabulary: QVariants read as numbers, vectors, colours and enums, and the range
// checks whose messages the light and rig property tables give ("intensity must be a finite number between
// 0 and 1e+06, got -1"). Shared by lightproperty.cpp, lightproperty_rows.cpp and rigproperty.cpp.
#pragma once

#include "core/types.h"

#include <QColor>
#include <QMetaType>
#include <QString>
#include <QStringList>
#include <QVariant>
#include <glm/vec3.hpp>
#include <optional>

namespace lr {

// Linear RGB (HDR) <-> a displayable sRGB QColor (core/colour.h's transfer functions). HDR colours are
// scaled down by their largest component.
QColor displayColor(const glm::dvec3& linear);
glm::dvec3 linearFromDisplayColor(const QColor& color);

namespace propertyvalue {

QString num(double v);          // "%g" with 6 digits, as messages write numbers
bool isNone(const QVariant& v); // an invalid or null QVariant: "none"
// A number (any numeric type, or text that parses as one); nullopt for none and anything else.
std::optional<double> toDouble(const QVariant& v);
double number(const QVariant& v, double fallback);
// glm::dvec3 or QVector3D; with colorIsSrgb also a QColor, read as sRGB and converted to linear.
std::optional<glm::dvec3> toVec3(const QVariant& v, bool colorIsSrgb);
bool finite3(const glm::dvec3& v);

// The enum itself, its index as an integer, or its file name.
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

// "WHAT must be a finite number between LO and HI, got V" ("> LO and <= HI" when loOpen); empty when valid.
QString checkRange(const QString& what, const std::optional<double>& d, double lo, double hi, bool loOpen);
// "WHAT components must be between LO and HI, got V"; empty when valid.
QString checkVec3(const QString& what, const std::optional<glm::dvec3>& v, double lo, double hi);
template <typename E> QString checkEnum(const QString& what, const QVariant& v) {
    if (!toEnum<E>(v)) return QStringLiteral("%1 must be %2").arg(what, allowedNames<E>());
    return {};
}
// The enum's file names in index order (a combo box's items).
template <typename E> QStringList enumChoices() {
    QStringList out;
    for (int i = 0; i < enumCount<E>(); ++i)
        out << toString(E(i));
    return out;
}

} // namespace propertyvalue

} // namespace lr
