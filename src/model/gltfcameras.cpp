#include "gltfcameras.h"

#include "core/gltfrewrite.h"

#include <QFile>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>
#include <algorithm>
#include <climits>

namespace lr {

QByteArray gltfJsonOf(const QString& file) {
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) return {};
    const QByteArray header = f.peek(20);
    if (header.startsWith("glTF")) {
        if (header.size() < 20 || header.mid(16, 4) != "JSON") return {};
        const quint32 length = qFromLittleEndian<quint32>(header.constData() + 12);
        if (qint64(length) > kMaxGltfJsonBytes || !f.seek(20)) return {};
        return f.read(qint64(length));
    }
    return f.size() > kMaxGltfJsonBytes ? QByteArray() : f.readAll();
}

void sortCamerasAsGltf(const QByteArray& json, std::vector<Camera>& cameras) {
    const QJsonDocument doc = QJsonDocument::fromJson(json);
    if (!doc.isObject() || cameras.size() < 2) return;
    // Node name (as Assimp names the node) -> camera index; -1 when two nodes of one name disagree.
    QHash<QString, int> indexOf;
    const auto note = [&](const QString& name, int camera) {
        const auto it = indexOf.constFind(name);
        indexOf.insert(name, it == indexOf.cend() || *it == camera ? camera : -1);
    };
    const QJsonArray nodes = doc.object().value(QStringLiteral("nodes")).toArray();
    for (qsizetype i = 0; i < nodes.size(); ++i) {
        const QJsonObject node = nodes[i].toObject();
        const QJsonValue camera = node.value(QStringLiteral("camera"));
        if (!camera.isDouble()) continue;
        const int index = camera.toInt(-1);
        if (index < 0) continue;
        const QString name = node.value(QStringLiteral("name")).toString();
        if (!name.isEmpty()) {
            note(name, index);
        } else {
            note(QStringLiteral("nodes[%1]").arg(i), index);
            note(QStringLiteral("nodes_%1").arg(i), index);
        }
    }
    const auto key = [&](const Camera& c) {
        const int index = indexOf.value(c.name, -1);
        return index < 0 ? INT_MAX : index;
    };
    std::stable_sort(cameras.begin(), cameras.end(),
                     [&](const Camera& a, const Camera& b) { return key(a) < key(b); });
}

} // namespace lr
