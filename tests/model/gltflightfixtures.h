// Issue 39: glTF files for the light import tests (tst_gltfiesimport, tst_gltflightextrasimport): the test
// scene (tests/data/model/scene.gltf) with a rig's lights written by the export (core/gltflights.h,
// gltfrewrite.h), as JSON to edit and write, and the import's lights looked up by name.
#pragma once

#include "core/gltfrewrite.h"
#include "model/modelloader.h"
#include "support/files.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>

namespace lr::test {

// scene.gltf with `rig`'s lights as the export writes them (its own two lights replaced).
inline QJsonObject exportedScene(const Rig& rig) {
    const QByteArray source = lrtest::readFile(QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"));
    GltfAdditions additions;
    additions.lights = convertRigToGltf(rig, SceneFrame{}).lights;
    const GltfRewriteResult r = rewriteGltfJson(source, additions);
    return QJsonDocument::fromJson(r.json).object();
}

inline bool writeJson(const QString& path, const QJsonObject& root) {
    return lrtest::writeFile(path, QJsonDocument(root).toJson(QJsonDocument::Compact));
}

// The GLB of `root`: buffer 0's data: URI moves into the BIN chunk, followed (4-byte aligned) by `extra`,
// whose offset in buffer 0 is *extraOffset.
inline QByteArray asGlb(QJsonObject root, const QByteArray& extra, qint64* extraOffset) {
    QJsonArray buffers = root.value(QStringLiteral("buffers")).toArray();
    QJsonObject buffer = buffers[0].toObject();
    const QString uri = buffer.take(QStringLiteral("uri")).toString();
    QByteArray data = QByteArray::fromBase64(uri.section(QLatin1Char(','), 1).toLatin1());
    data += QByteArray((4 - data.size() % 4) % 4, '\0');
    *extraOffset = data.size();
    data += extra;
    data += QByteArray((4 - data.size() % 4) % 4, '\0');
    buffer.insert(QStringLiteral("byteLength"), qint64(data.size()));
    buffers[0] = buffer;
    root.insert(QStringLiteral("buffers"), buffers);
    const quint32 length = qToLittleEndian(quint32(data.size()));
    const QByteArray bin =
        QByteArray(reinterpret_cast<const char*>(&length), 4) + QByteArray("BIN\0", 4) + data;
    return writeGlb(QJsonDocument(root).toJson(QJsonDocument::Compact), bin);
}

// The node of the light named `name` (the export names nodes after their lights), or -1.
inline int nodeNamed(const QJsonObject& root, const QString& name) {
    const QJsonArray nodes = root.value(QStringLiteral("nodes")).toArray();
    for (qsizetype i = 0; i < nodes.size(); ++i)
        if (nodes[i].toObject().value(QStringLiteral("name")).toString() == name) return int(i);
    return -1;
}

// root[path...] = value, for nested objects ("nodes" arrays by index).
inline void setIn(QJsonObject& root, const QStringList& path, const QJsonValue& value) {
    if (path.size() == 1) {
        root.insert(path[0], value);
        return;
    }
    bool isIndex = false;
    const int index = path[1].toInt(&isIndex);
    if (isIndex) {
        QJsonArray a = root.value(path[0]).toArray();
        QJsonObject o = a[index].toObject();
        if (path.size() == 2) {
            a[index] = value;
        } else {
            setIn(o, path.mid(2), value);
            a[index] = o;
        }
        root.insert(path[0], a);
        return;
    }
    QJsonObject o = root.value(path[0]).toObject();
    setIn(o, path.mid(1), value);
    root.insert(path[0], o);
}

inline const Light* lightNamed(const Model& m, const QString& name) {
    for (const Light& l : m.lights.lights)
        if (l.name == name) return &l;
    return nullptr;
}

// The warnings that contain every one of `parts`, joined (empty: none).
inline QString warningWith(const Model& m, const QStringList& parts) {
    QStringList out;
    for (const QString& w : m.warnings) {
        bool all = true;
        for (const QString& p : parts)
            all = all && w.contains(p);
        if (all) out << w;
    }
    return out.join(QLatin1Char('\n'));
}

} // namespace lr::test
