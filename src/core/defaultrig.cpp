#include "defaultrig.h"

#include "rigjson.h"

#include <QDir>
#include <QFileInfo>
#include <QtDebug>

namespace lr {

bool isClassicShowcase(const QString& modelPath) {
    QString p = modelPath;
    p.replace(QLatin1Char('\\'), QLatin1Char('/'));
    return p == QLatin1String(":/resources/models/suzanne/Suzanne.gltf") ||
           p.endsWith(QLatin1String("/resources/models/suzanne/Suzanne.gltf"));
}

std::optional<Rig> sampleRig(const QString& modelPath) {
    QString p = modelPath;
    p.replace(QLatin1Char('\\'), QLatin1Char('/'));
    if (!p.startsWith(QLatin1String(":/resources/models/")) &&
        !p.contains(QLatin1String("/resources/models/")))
        return std::nullopt;
    const QString rigPath = QFileInfo(p).dir().filePath(QStringLiteral("showcase.json"));
    if (!QFileInfo::exists(rigPath)) return std::nullopt;
    RigReadResult r = readRigFile(rigPath);
    if (!r.ok()) {
        qWarning().noquote() << "LightRig: the sample rig is unusable:" << r.errors.join(QLatin1Char('\n'));
        return std::nullopt;
    }
    return *r.rig;
}

ShadingModel defaultShadingFor(bool hasPbrMaterials, const QString& modelPath) {
    return hasPbrMaterials && !isClassicShowcase(modelPath) ? ShadingModel::Pbr : ShadingModel::Classic;
}

Rig withShading(Rig rig, ShadingModel model) {
    rig.shading.model = model;
    return rig;
}

Rig pbrDefaultRig() {
    RigReadResult r = readBuiltinPreset(QStringLiteral("pbr-three-point"));
    if (r.ok() && r.rig->shading.model == ShadingModel::Pbr) return *r.rig;
    qWarning().noquote() << "LightRig: the built-in physically based default rig is unusable, using the "
                            "default rig shaded physically based:"
                         << r.errors.join(QLatin1Char('\n'));
    return withShading(defaultRig(), ShadingModel::Pbr);
}

DefaultRigChoice chooseDefaultRig(bool hasPbrMaterials, const Rig& modelLights, const QString& modelPath,
                                  std::optional<ShadingModel> shadingOverride) {
    const ShadingModel shading = shadingOverride.value_or(defaultShadingFor(hasPbrMaterials, modelPath));
    DefaultRigChoice c;
    if (!modelLights.lights.empty()) {
        c.rig = withShading(modelLights, shading);
        c.source = QStringLiteral("the model's lights");
    } else if (auto sample = sampleRig(modelPath)) {
        c.rig = withShading(*sample, shading);
        c.source = QStringLiteral("the sample's rig");
    } else if (shading == ShadingModel::Pbr) {
        c.rig = pbrDefaultRig();
        c.source = QStringLiteral("the physically based default rig");
    } else {
        c.rig = defaultRig();
        c.source = QStringLiteral("the default rig");
    }
    return c;
}

} // namespace lr
