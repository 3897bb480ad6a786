#include "lighttypes.h"

#include <QCoreApplication>
#include <QStringList>

namespace lr {

QString lightTypeLabel(LightType type) {
    return QCoreApplication::translate("lr::LightType", traitsOf(type).label);
}

QString lightTypesWith(bool LightTypeTraits::*trait) {
    QStringList names;
    for (const LightTypeTraits& t : kLightTypeTraits)
        if (t.*trait) names << toString(t.type);
    if (names.size() <= 1) return names.join(QString());
    const QString last = names.takeLast();
    return names.join(QStringLiteral(", ")) + QStringLiteral(" and ") + last;
}

std::optional<LightType> lightTypeFromGltf(const QString& gltfType) {
    for (const LightTypeTraits& t : kLightTypeTraits)
        if (t.gltfType && gltfType == QLatin1String(t.gltfType)) return t.type;
    return std::nullopt;
}

} // namespace lr
