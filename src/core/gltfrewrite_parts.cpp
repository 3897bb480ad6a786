// GLB chunks, the lights-only file and file URIs (gltfrewrite.h); the JSON rewrite is gltfrewrite.cpp.
#include "gltfrewrite.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QRegularExpression>
#include <QUrl>
#include <QtEndian>

namespace lr {

namespace {

constexpr quint32 kGlbMagic = 0x46546C67; // "glTF"
constexpr quint32 kChunkJson = 0x4E4F534A;
constexpr quint32 kChunkBin = 0x004E4942;
const QString kExt = QStringLiteral("KHR_lights_punctual");

quint32 u32(const QByteArray& d, qsizetype at) {
    return qFromLittleEndian<quint32>(d.constData() + at);
}

void putU32(QByteArray& d, quint32 v) {
    char b[4];
    qToLittleEndian(v, b);
    d.append(b, 4);
}

} // namespace

bool isGlb(const QByteArray& data) {
    return data.size() >= 4 && u32(data, 0) == kGlbMagic;
}

std::optional<GlbParts> parseGlb(const QByteArray& d, QString* error) {
    auto fail = [&](const QString& why) {
        *error = why;
        return std::nullopt;
    };
    if (d.size() < 20) return fail(QStringLiteral("too short for a GLB (%1 bytes)").arg(d.size()));
    if (u32(d, 0) != kGlbMagic) return fail(QStringLiteral("not a GLB (no \"glTF\" magic)"));
    if (u32(d, 4) != 2) return fail(QStringLiteral("GLB version %1; only version 2 is read").arg(u32(d, 4)));
    if (u32(d, 8) != quint64(d.size()))
        return fail(
            QStringLiteral("the header claims %1 bytes but the file has %2").arg(u32(d, 8)).arg(d.size()));
    const quint64 jsonLength = u32(d, 12);
    if (u32(d, 16) != kChunkJson) return fail(QStringLiteral("the first chunk is not JSON"));
    if (20 + jsonLength > quint64(d.size()))
        return fail(QStringLiteral("the JSON chunk claims %1 bytes but %2 remain")
                        .arg(jsonLength)
                        .arg(d.size() - 20));
    if (qint64(jsonLength) > kMaxGltfJsonBytes)
        return fail(QStringLiteral("the JSON chunk is %1 bytes; at most %2 are read")
                        .arg(jsonLength)
                        .arg(kMaxGltfJsonBytes));
    GlbParts parts;
    parts.json = d.mid(20, qsizetype(jsonLength));
    const qsizetype restAt = 20 + qsizetype(jsonLength);
    parts.rest = d.mid(restAt);
    for (qsizetype at = restAt; at < d.size();) {
        if (d.size() - at < 8) return fail(QStringLiteral("a chunk header at byte %1 is cut off").arg(at));
        const quint64 length = u32(d, at);
        if (at + 8 + length > quint64(d.size()))
            return fail(QStringLiteral("the chunk at byte %1 claims %2 bytes but %3 remain")
                            .arg(at)
                            .arg(length)
                            .arg(d.size() - at - 8));
        if (u32(d, at + 4) == kChunkJson)
            return fail(QStringLiteral("a second JSON chunk at byte %1").arg(at));
        if (u32(d, at + 4) == kChunkBin) {
            if (at != restAt) return fail(QStringLiteral("the BIN chunk is not the second chunk"));
            parts.bin = d.mid(at + 8, qsizetype(length));
            parts.hasBin = true;
        }
        at += 8 + qsizetype(length);
    }
    return parts;
}

QByteArray writeGlb(const QByteArray& json, const QByteArray& rest) {
    QByteArray padded = json;
    while (padded.size() % 4)
        padded += ' ';
    QByteArray out;
    putU32(out, kGlbMagic);
    putU32(out, 2);
    putU32(out, quint32(12 + 8 + padded.size() + rest.size()));
    putU32(out, quint32(padded.size()));
    putU32(out, kChunkJson);
    return out + padded + rest;
}

QByteArray lightsOnlyGltfJson(const GltfAdditions& add) {
    QJsonObject root{
        {QStringLiteral("asset"), QJsonObject{{QStringLiteral("version"), QStringLiteral("2.0")},
                                              {QStringLiteral("generator"), QStringLiteral("LightRig")}}},
        {QStringLiteral("scene"), 0}};
    QJsonArray nodes, lights, profiles, sceneNodes;
    const std::vector<int> indices = gltfLightIndices(add.lights);
    for (size_t i = 0; i < add.lights.size(); ++i) {
        const GltfLight& l = add.lights[i];
        nodes.append(l.nodeJson(indices[i]));
        l.ies ? profiles.append(l.ies->profileJson()) : lights.append(l.lightJson());
        sceneNodes.append(int(i));
    }
    QJsonObject scene;
    if (!nodes.isEmpty()) {
        scene.insert(QStringLiteral("nodes"), sceneNodes);
        root.insert(QStringLiteral("nodes"), nodes);
        QJsonArray used;
        QJsonObject extensions;
        if (!lights.isEmpty()) {
            used.append(kExt);
            extensions.insert(kExt, QJsonObject{{QStringLiteral("lights"), lights}});
        }
        if (!profiles.isEmpty()) { // issue 39
            used.append(QStringLiteral("EXT_lights_ies"));
            extensions.insert(QStringLiteral("EXT_lights_ies"),
                              QJsonObject{{QStringLiteral("lights"), profiles}});
        }
        root.insert(QStringLiteral("extensionsUsed"), used);
        root.insert(QStringLiteral("extensions"), extensions);
    }
    root.insert(QStringLiteral("scenes"), QJsonArray{scene});
    if (!add.note.isEmpty())
        root.insert(QStringLiteral("extras"), QJsonObject{{QStringLiteral("lightrig"), add.note}});
    return QJsonDocument(root).toJson(QJsonDocument::Compact);
}

QString rebaseUri(const QString& uri, const QString& sourceFolder, const QString& outputFolder,
                  QString* problem) {
    if (problem) problem->clear();
    static const QRegularExpression drive(QStringLiteral("^[A-Za-z]:[\\\\/]"));
    const bool windowsDrive = drive.match(uri).hasMatch();
    const QUrl url(uri);
    if (uri.startsWith(QLatin1String("data:")) || (!url.scheme().isEmpty() && !windowsDrive)) return uri;
    // Windows separators: `.\tex.png` names tex.png (percent-encoded, the backslash stayed in the name).
    QString path = QUrl::fromPercentEncoding(uri.toUtf8()).replace(QLatin1Char('\\'), QLatin1Char('/'));
    const QDir source(sourceFolder);
    if (windowsDrive) {
        // Another machine's absolute path: the file of that name beside the model, when there is one.
        const QString name = path.section(QLatin1Char('/'), -1);
        if (name.isEmpty() || !QFileInfo::exists(source.absoluteFilePath(name))) {
            if (problem)
                *problem =
                    QStringLiteral("a Windows drive path, and no file %1 lies beside the model; viewers "
                                   "will not find it")
                        .arg(name);
            return uri;
        }
        path = name;
    }
    const QString file = QDir::cleanPath(source.absoluteFilePath(path));
    if (problem && !QFileInfo::exists(file))
        *problem = QStringLiteral("no such file beside the model (%1); viewers will not find it").arg(file);
    if (uri.startsWith(QLatin1Char('/'))) return uri;
    const bool sameFolder = QDir(sourceFolder).absolutePath() == QDir(outputFolder).absolutePath();
    if (sameFolder && !windowsDrive && !uri.contains(QLatin1Char('\\'))) return uri; // byte for byte
    const QString moved = QDir(outputFolder).relativeFilePath(file);
    return QString::fromUtf8(QUrl::toPercentEncoding(moved, "/"));
}

QStringList externalUris(const QByteArray& json) {
    QStringList out;
    const QJsonObject root = QJsonDocument::fromJson(json).object();
    for (const char* key : {"buffers", "images"})
        for (const QJsonValue& v : root.value(QLatin1String(key)).toArray()) {
            const QString uri = v.toObject().value(QStringLiteral("uri")).toString();
            if (!uri.isEmpty() && !uri.startsWith(QLatin1String("data:"))) out << uri;
        }
    return out;
}

} // namespace lr
