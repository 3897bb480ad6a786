#include "propertyfields.h"

namespace lr {

const QList<LightProperty>& propertyRows() {
    using P = LightProperty;
    static const QList<LightProperty> rows{P::Name,
                                           P::Type,
                                           P::Enabled,
                                           P::Color,
                                           P::Temperature,
                                           P::Intensity,
                                           P::Position,
                                           P::Direction,
                                           P::FalloffModel,
                                           P::FalloffRange,
                                           P::FalloffExponent,
                                           P::FalloffConstant,
                                           P::FalloffLinear,
                                           P::FalloffQuadratic,
                                           P::ConeModel,
                                           P::ConeInner,
                                           P::ConeOuter,
                                           P::ConeExponent,
                                           P::Diffuse,
                                           P::Specular,
                                           P::Ambient,
                                           P::RimExponent};
    return rows;
}

QString propertyFieldName(LightProperty property) {
    using P = LightProperty;
    switch (property) {
    case P::Name:
        return QStringLiteral("name");
    case P::Type:
        return QStringLiteral("type");
    case P::Enabled:
        return QStringLiteral("enabled");
    case P::Color:
        return QStringLiteral("color");
    case P::Intensity:
        return QStringLiteral("intensity");
    case P::Temperature:
        return QStringLiteral("temperature");
    case P::Position:
        return QStringLiteral("position");
    case P::Direction:
        return QStringLiteral("direction");
    case P::FalloffModel:
        return QStringLiteral("falloffModel");
    case P::FalloffRange:
        return QStringLiteral("falloffRange");
    case P::FalloffExponent:
        return QStringLiteral("falloffExponent");
    case P::FalloffConstant:
        return QStringLiteral("falloffConstant");
    case P::FalloffLinear:
        return QStringLiteral("falloffLinear");
    case P::FalloffQuadratic:
        return QStringLiteral("falloffQuadratic");
    case P::ConeModel:
        return QStringLiteral("coneModel");
    case P::ConeInner:
        return QStringLiteral("coneInner");
    case P::ConeOuter:
        return QStringLiteral("coneOuter");
    case P::ConeExponent:
        return QStringLiteral("coneExponent");
    case P::Diffuse:
        return QStringLiteral("diffuse");
    case P::Specular:
        return QStringLiteral("specular");
    case P::Ambient:
        return QStringLiteral("ambient");
    case P::RimExponent:
        return QStringLiteral("rimExponent");
    case P::Any:
        break;
    }
    return {};
}

bool propertyShown(const Light& light, LightProperty property) {
    using P = LightProperty;
    if (!lightPropertyApplies(light, property)) return false;
    const FalloffModel f = light.falloff.model;
    const ConeModel c = light.cone.model;
    switch (property) {
    case P::FalloffRange:
        return f != FalloffModel::None;
    case P::FalloffExponent:
        return f == FalloffModel::RangePower;
    case P::FalloffConstant:
    case P::FalloffLinear:
    case P::FalloffQuadratic:
        return f == FalloffModel::InversePolynomial;
    case P::ConeInner:
        return c == ConeModel::Smooth;
    case P::ConeExponent:
        return c == ConeModel::AnglePower || c == ConeModel::Smooth;
    default:
        return true;
    }
}

} // namespace lr
