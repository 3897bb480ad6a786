// A light's IES profile as EXT_lights_ies (issue 39, docs/export.md; the extension: KhronosGroup/glTF,
// extensions/2.0/Vendor/EXT_lights_ies). The profile's vertical angle 0 maps to the node's -Z and the
// horizontal plane to its X/Y plane, horizontal angle 0 along +X and 90 along +Y; the instance's multiplier
// scales the file's candela and its colour tints them.
#include "gltflights.h"

#include "ies.h"
#include "iesshade.h"

#include <QFile>
#include <algorithm>
#include <glm/common.hpp>

namespace lr {

QJsonObject GltfIes::profileJson() const {
    return {{QStringLiteral("uri"),
             QStringLiteral("data:application/x-ies-lm-63;base64,") + QString::fromLatin1(file.toBase64())}};
}

std::vector<int> gltfLightIndices(const std::vector<GltfLight>& lights) {
    std::vector<int> out;
    int punctual = 0, ies = 0;
    for (const GltfLight& l : lights)
        out.push_back(l.ies ? ies++ : punctual++);
    return out;
}

void convertIes(const Light& l, const glm::dmat3& fileFromWorld, double unit, GltfLight& g,
                std::vector<LossyConversion>& losses) {
    const IesSpec& spec = *l.ies;
    const QString path = spec.resolved.isEmpty() ? spec.file : spec.resolved;
    QString error;
    QByteArray bytes;
    std::shared_ptr<const IesProfile> profile;
    QFile file(path);
    if (file.open(QIODevice::ReadOnly) && file.size() <= kMaxIesFileBytes) {
        bytes = file.readAll();
        profile = readIesData(bytes, path, &error);
    } else {
        error = QStringLiteral("%1: cannot read it").arg(path);
    }
    if (!profile) {
        losses.push_back({ExportLoss::Ies, l.name, QStringLiteral("not exported (%1)").arg(error)});
        return;
    }
    // g.intensity is the light's intensity × unit × m, m its colour's largest component (convertRigToGltf);
    // under level "profile" the intensity is not used, and the classic rule's unit still applies.
    const glm::dvec3 c = glm::max(l.effectiveColor(), glm::dvec3(0.0));
    const double m = std::max({c.x, c.y, c.z});
    GltfIes ies;
    ies.file = bytes;
    ies.color = g.color;
    ies.multiplier = spec.level == IesLevel::Profile
                         ? spec.multiplier * unit * m
                         : g.intensity * iesScale(spec, *profile); // × mult / peak
    g.ies = ies;
    const glm::dvec3 nadir = lighting::safeNormalize(l.direction, glm::dvec3(0.0, -1.0, 0.0));
    const AreaAxes axes = areaAxes(nadir, spec.rotation);
    g.rotation = lookRotation(fileFromWorld * nadir, fileFromWorld * axes.y); // +Y: horizontal angle 90
    QStringList lost;
    if (l.usesCone()) lost << QStringLiteral("its cone");
    if (l.usesFalloff() && l.falloff.hasRange()) lost << QStringLiteral("its range");
    losses.push_back(
        {ExportLoss::Ies, l.name,
         QStringLiteral("%1 (level %2%3)")
             .arg(spec.file,
                  spec.level == IesLevel::Profile ? QStringLiteral("profile") : QStringLiteral("light"),
                  lost.isEmpty() ? QString() : QStringLiteral("; without ") + lost.join(", "))});
}

} // namespace lr
