// glTF material extensions that Assimp 5.2.5's glTF importer drops (KHR_materials_emissive_strength) and
// the list of every material's extensions, read from the file's own JSON.
#include "importdetail.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace lr::detail {

namespace {

constexpr char kEmissiveStrength[] = "KHR_materials_emissive_strength";

} // namespace

GltfMaterialExtrasByName readGltfMaterialExtras(const QByteArray& json) {
    if (!json.contains("_materials_")) return {}; // the common case costs one search
    const QJsonDocument doc = QJsonDocument::fromJson(json);
    GltfMaterialExtrasByName out;
    for (const QJsonValue& v : doc.object().value(QLatin1String("materials")).toArray()) {
        const QJsonObject mat = v.toObject();
        GltfMaterialExtras e;
        const QJsonArray factor = mat.value(QLatin1String("emissiveFactor")).toArray();
        if (factor.size() == 3)
            for (int i = 0; i < 3; ++i)
                e.emissiveFactor[i] = float(factor[i].toDouble());
        const QJsonObject extensions = mat.value(QLatin1String("extensions")).toObject();
        const QJsonValue strength = extensions.value(QLatin1String(kEmissiveStrength))
                                        .toObject()
                                        .value(QLatin1String("emissiveStrength"));
        e.emissiveStrength = strength.isDouble() ? strength.toDouble() : 1.0;
        e.extensionCount = int(extensions.size());
        for (auto it = extensions.begin(); it != extensions.end(); ++it) {
            if (int(e.extensions.size()) >= kMaxMaterialExtensions) break;
            QString values =
                it.value().isObject()
                    ? QString::fromUtf8(QJsonDocument(it.value().toObject()).toJson(QJsonDocument::Compact))
                    : QStringLiteral("(not an object)");
            if (values.size() > kMaxExtensionValues)
                values = values.left(kMaxExtensionValues - 1) + QChar(0x2026);
            e.extensions.push_back({it.key(), values});
        }
        out.insert(mat.value(QLatin1String("name")).toString(), e);
    }
    return out;
}

QStringList readGltfVariantNames(const QByteArray& json) {
    if (!json.contains("KHR_materials_variants")) return {};
    const QJsonArray variants = QJsonDocument::fromJson(json)
                                    .object()
                                    .value(QLatin1String("extensions"))
                                    .toObject()
                                    .value(QLatin1String("KHR_materials_variants"))
                                    .toObject()
                                    .value(QLatin1String("variants"))
                                    .toArray();
    QStringList names;
    for (const QJsonValue& v : variants) {
        const QString name = v.toObject().value(QLatin1String("name")).toString();
        names << (name.isEmpty() ? QStringLiteral("variant %1").arg(names.size()) : name);
    }
    return names;
}

} // namespace lr::detail
