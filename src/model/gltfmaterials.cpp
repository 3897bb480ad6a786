// glTF material extensions that Assimp 5.2.5's glTF importer drops (KHR_materials_emissive_strength),
// read from the file's own JSON. preflight() has already checked the GLB header's lengths against the file.
#include "importdetail.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace lr::detail {

namespace {

constexpr char kEmissiveStrength[] = "KHR_materials_emissive_strength";

// The JSON text of a .gltf, or of a GLB's JSON chunk (read alone: the binary chunk can be large).
QByteArray gltfJson(QFile& file) {
    const QByteArray header = file.peek(20);
    if (!header.startsWith("glTF")) return file.readAll();
    const qint64 length = glbJsonLength(header, file.size());
    if (length <= 0 || !file.seek(20)) return {};
    return file.read(length);
}

} // namespace

GltfMaterialExtrasByName readGltfMaterialExtras(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    const QByteArray json = gltfJson(file);
    if (!json.contains(kEmissiveStrength)) return {}; // the common case costs one search
    const QJsonDocument doc = QJsonDocument::fromJson(json);
    GltfMaterialExtrasByName out;
    for (const QJsonValue& v : doc.object().value(QLatin1String("materials")).toArray()) {
        const QJsonObject mat = v.toObject();
        GltfMaterialExtras e;
        const QJsonArray factor = mat.value(QLatin1String("emissiveFactor")).toArray();
        if (factor.size() == 3)
            for (int i = 0; i < 3; ++i)
                e.emissiveFactor[i] = float(factor[i].toDouble());
        const QJsonValue strength = mat.value(QLatin1String("extensions"))
                                        .toObject()
                                        .value(QLatin1String(kEmissiveStrength))
                                        .toObject()
                                        .value(QLatin1String("emissiveStrength"));
        e.emissiveStrength = strength.isDouble() ? strength.toDouble() : 1.0;
        out.insert(mat.value(QLatin1String("name")).toString(), e);
    }
    return out;
}

} // namespace lr::detail
