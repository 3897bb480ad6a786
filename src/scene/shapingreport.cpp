#include "shapingreport.h"

#include "lightassets.h"

namespace lr {

QStringList shapingWarnings(const Rig& rig, bool pathTraced) {
    const LightAssets assets = loadLightAssets(rig);
    QStringList out = assets.errors;
    if (pathTraced) return out;
    for (size_t i = 0; i < rig.lights.size(); ++i) {
        const Light& l = rig.lights[i];
        if (!l.enabled) continue;
        QStringList what;
        if (assets.ies[i] && (l.type == LightType::Point || l.type == LightType::Spot))
            what << QStringLiteral("IES profile");
        if (assets.gobos[i] && l.type == LightType::Spot) what << QStringLiteral("gobo");
        if (!what.isEmpty())
            out << QStringLiteral("lights[%1] (%2): the raster tiers draw it without its %3 (not implemented "
                                  "yet; --quality path shapes it)")
                       .arg(i)
                       .arg(l.name, what.join(QStringLiteral(" and ")));
    }
    return out;
}

} // namespace lr
