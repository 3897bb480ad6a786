#include "lightgroups.h"

#include <QHash>

namespace lr {

namespace {

const char* const kReserved[] = {"environment", "emissive", "ambient", "background"};

bool reserved(const QString& name) {
    for (const char* r : kReserved)
        if (name.compare(QLatin1String(r), Qt::CaseInsensitive) == 0) return true;
    return false;
}

} // namespace

QString lightGroupName(const Light& light, int index) {
    if (!light.group.trimmed().isEmpty()) return light.group;
    if (!light.name.trimmed().isEmpty()) return light.name;
    return QStringLiteral("light %1").arg(index + 1);
}

std::vector<LightGroup> lightGroups(const Rig& rig, const LightGroupScene& scene) {
    std::vector<LightGroup> groups;
    QHash<QString, size_t> byName;
    for (size_t i = 0; i < rig.lights.size(); ++i) {
        const Light& l = rig.lights[i];
        if (!l.enabled || (!scene.includeRims && l.type == LightType::Rim)) continue;
        QString name = lightGroupName(l, int(i));
        if (reserved(name)) name += QStringLiteral(" (lights)");
        const auto it = byName.constFind(name);
        if (it != byName.constEnd()) {
            groups[*it].lights.push_back(int(i));
            continue;
        }
        byName.insert(name, groups.size());
        groups.push_back({name, LightGroupKind::Lights, {int(i)}});
    }
    if (!rig.environment.isNone())
        groups.push_back({QStringLiteral("environment"), LightGroupKind::Environment, {}});
    if (scene.hasEmissive) groups.push_back({QStringLiteral("emissive"), LightGroupKind::Emissive, {}});
    if (rig.ambient != glm::dvec3(0.0))
        groups.push_back({QStringLiteral("ambient"), LightGroupKind::Ambient, {}});
    if (scene.alwaysBackground)
        groups.push_back({QStringLiteral("background"), LightGroupKind::Background, {}});
    return groups;
}

std::vector<int> groupOfLights(const Rig& rig, const std::vector<LightGroup>& groups) {
    std::vector<int> of(rig.lights.size(), -1);
    for (size_t g = 0; g < groups.size(); ++g)
        for (int i : groups[g].lights)
            if (i >= 0 && size_t(i) < of.size()) of[size_t(i)] = int(g);
    return of;
}

QStringList groupNames(const std::vector<LightGroup>& groups) {
    QStringList names;
    for (const LightGroup& g : groups)
        names << g.name;
    return names;
}

} // namespace lr
