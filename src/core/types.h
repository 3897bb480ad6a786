// The vocabulary of LightRig's lighting model: light types and the per-light formula choices.
// Each enum has a stable file name (used in rig JSON, GLSL #defines and the UI) via toString/fromString.
#pragma once

#include <QString>
#include <array>
#include <optional>

namespace lr {

// Rect and Disk are area lights (issue 16): a one- or two-sided emitting rectangle or disk of uniform
// radiance (rig.h, AreaShape; lighting_area.h defines what they add).
enum class LightType { Point, Spot, Directional, Rim, Rect, Disk };
enum class FalloffModel { None, RangePower, InversePolynomial, RangeQuadratic, InverseSquare };
enum class ConeModel { AnglePower, Smooth, Hard };
enum class DiffuseModel { Lambert, HalfLambert };
enum class SpecularModel { Phong, BlinnPhong };
enum class ViewerModel { Local, Infinite };
enum class RigSpace { World, Model };
enum class ToneMap { Clamp, Reinhard, Aces, Neutral, Agx };
// Classic: the design documents' diffuse/specular models. Pbr: the glTF 2.0 metal-rough BRDF (Appendix B)
// with KHR_lights_punctual units (docs/lighting-models.md, "Physically based shading").
enum class ShadingModel { Classic, Pbr };
// The rig's optional ground plane under the model (issue 14): none, a visible grey plane, or a shadow
// catcher (invisible except for the shadows it receives; in a transparent image they are its alpha).
enum class GroundMode { Off, Visible, Catcher };
// The rig's environment lighting (issue 15): none, an equirectangular HDR image (.hdr / .exr), or the
// built-in procedural studio (a floor/sky gradient and softboxes the rig stores).
enum class EnvironmentSource { None, Image, Studio };
// What the environment shows behind the model: itself, itself blurred, or the view's background colour
// (as without an environment). A transparent image has alpha 0 there in every mode.
enum class EnvironmentBackground { Visible, Blurred, Color };

template <typename E> struct EnumNames; // specialised below: static constexpr std::array names

#define LR_ENUM_NAMES(E, ...)                                                                                \
    template <> struct EnumNames<E> { static constexpr std::array names{__VA_ARGS__}; };
LR_ENUM_NAMES(LightType, "point", "spot", "directional", "rim", "rect", "disk")
LR_ENUM_NAMES(FalloffModel, "none", "range-power", "inverse-polynomial", "range-quadratic", "inverse-square")
LR_ENUM_NAMES(ConeModel, "angle-power", "smooth", "hard")
LR_ENUM_NAMES(DiffuseModel, "lambert", "half-lambert")
LR_ENUM_NAMES(SpecularModel, "phong", "blinn-phong")
LR_ENUM_NAMES(ViewerModel, "local", "infinite")
LR_ENUM_NAMES(RigSpace, "world", "model")
LR_ENUM_NAMES(ToneMap, "clamp", "reinhard", "aces", "neutral", "agx")
LR_ENUM_NAMES(ShadingModel, "classic", "pbr")
LR_ENUM_NAMES(GroundMode, "off", "visible", "catcher")
LR_ENUM_NAMES(EnvironmentSource, "none", "image", "studio")
LR_ENUM_NAMES(EnvironmentBackground, "visible", "blurred", "color")
#undef LR_ENUM_NAMES

template <typename E>
concept NamedEnum = requires {
    EnumNames<E>::names;
};

template <NamedEnum E> constexpr int enumCount() {
    return int(EnumNames<E>::names.size());
}

template <NamedEnum E> QString toString(E value) {
    return QString::fromLatin1(EnumNames<E>::names[size_t(value)]);
}

template <NamedEnum E> std::optional<E> fromString(const QString& name) {
    const auto& names = EnumNames<E>::names;
    for (size_t i = 0; i < names.size(); ++i)
        if (name == QLatin1String(names[i])) return E(i);
    return std::nullopt;
}

// "a", "b" or "c" — for error messages listing the accepted names.
template <NamedEnum E> QString allowedNames() {
    QString out;
    const auto& names = EnumNames<E>::names;
    for (size_t i = 0; i < names.size(); ++i) {
        if (i) out += (i + 1 == names.size()) ? QStringLiteral(" or ") : QStringLiteral(", ");
        out += QLatin1Char('"') + QLatin1String(names[i]) + QLatin1Char('"');
    }
    return out;
}

} // namespace lr
