// An EXT_lights_ies profile's bytes (issue 39, docs/export.md "Import"): from lights[i].uri (a data: URI or
// a file relative to the glTF, under the model folder's rule) or lights[i].bufferView (a GLB's BIN chunk, or
// a buffer's data: URI or file), checked by the strict LM-63 reader (core/ies.h) here, in the import worker,
// where the rest of the untrusted file is decoded. A profile the file embeds has no file of its own for
// IesSpec::file to name: it is written once into a content-addressed cache, <folder>/<sha256>.ies.
#include "importdetail.h"

#include "core/atomicwrite.h"
#include "core/ies.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QStandardPaths>
#include <QUrl>
#include <cmath>
#include <utility>

namespace lr::detail {

namespace {

struct Bytes {
    QByteArray data;
    QString error; // set: no data
};

Bytes fail(const QString& why) {
    return {{}, why};
}

// The bytes of a "data:[type][;base64],..." URI (glTF's are base64), at most `maxBytes` decoded.
Bytes decodeDataUri(const QString& uri, qint64 maxUriBytes, qint64 maxBytes) {
    if (uri.size() > maxUriBytes)
        return fail(
            QStringLiteral("a data: URI of %1 characters; at most %2").arg(uri.size()).arg(maxUriBytes));
    const qsizetype comma = uri.indexOf(QLatin1Char(','));
    if (comma < 0) return fail(QStringLiteral("a data: URI without a comma before its data"));
    if (!uri.left(comma).endsWith(QLatin1String(";base64")))
        return fail(QStringLiteral("a data: URI that is not base64 (glTF's data: URIs are)"));
    if (qint64(uri.size() - comma - 1) / 4 * 3 > maxBytes)
        return fail(QStringLiteral("a data: URI of over %1 bytes (the IES reader's limit)").arg(maxBytes));
    auto decoded = QByteArray::fromBase64Encoding(uri.mid(comma + 1).toLatin1(),
                                                  QByteArray::AbortOnBase64DecodingErrors);
    if (!decoded) return fail(QStringLiteral("a data: URI whose base64 does not decode"));
    return {std::move(*decoded), {}};
}

// A relative file URI (percent-encoded) as an absolute path inside the model's folder, or why not.
QString resolveFileUri(const QString& uri, const ModelFolder& folder, QString* error) {
    if (const qsizetype colon = uri.indexOf(QLatin1Char(':'));
        colon > 1 && !uri.left(colon).contains(QLatin1Char('/'))) {
        *error = QStringLiteral("\"%1\": only data: URIs and relative file paths are read").arg(uri.left(64));
        return {};
    }
    QString refusal;
    const QString path = folder.resolve(QUrl::fromPercentEncoding(uri.toUtf8()), &refusal);
    if (path.isEmpty()) *error = refusal;
    return path;
}

// `length` bytes at `offset` of a file, or why not.
Bytes readSlice(const QString& path, qint64 offset, qint64 length) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return fail(QStringLiteral("%1: cannot read it (%2)").arg(path, f.errorString()));
    if (offset < 0 || length < 0 || offset > f.size() || length > f.size() - offset)
        return fail(QStringLiteral("%1: bytes %2 to %3 lie beyond its %4 bytes")
                        .arg(path)
                        .arg(offset)
                        .arg(offset + length)
                        .arg(f.size()));
    if (!f.seek(offset)) return fail(QStringLiteral("%1: cannot seek to byte %2").arg(path).arg(offset));
    QByteArray data = f.read(length);
    if (data.size() != length) return fail(QStringLiteral("%1: cut short").arg(path));
    return {std::move(data), {}};
}

// A GLB's BIN chunk: where it starts in the file and its length (-1 when there is none).
std::pair<qint64, qint64> glbBinChunk(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {0, -1};
    const QByteArray header = f.read(20);
    if (header.size() < 20 || !header.startsWith("glTF")) return {0, -1};
    const qint64 at = 20 + ((qint64(glbU32(header, 12)) + 3) & ~qint64(3));
    if (!f.seek(at)) return {0, -1};
    const QByteArray chunk = f.read(8);
    if (chunk.size() < 8 || chunk.mid(4, 4) != QByteArray("BIN\0", 4)) return {0, -1};
    return {at + 8, qint64(glbU32(chunk, 0))};
}

// A non-negative integer, `fallback` when absent, -1 when it is something else.
qint64 integer(const QJsonValue& v, qint64 fallback) {
    if (v.isUndefined()) return fallback;
    const double d = v.toDouble(-1.0);
    return v.isDouble() && d >= 0.0 && d <= 9e15 && d == std::floor(d) ? qint64(d) : -1;
}

qint64 integer(const QJsonObject& o, const char* key, qint64 fallback) {
    return integer(o.value(QLatin1String(key)), fallback);
}

// lights[i].bufferView: a slice of a buffer (the GLB's BIN chunk, a data: URI, or a file).
Bytes bufferViewBytes(const QJsonObject& root, const QJsonValue& index, const ModelFolder& folder,
                      qint64 maxDataUriBytes, QString* field) {
    const QJsonArray views = root.value(QLatin1String("bufferViews")).toArray();
    const qint64 v = integer(index, -1);
    if (v < 0 || v >= views.size())
        return fail(QStringLiteral("no such buffer view (the file has %1)").arg(views.size()));
    const QJsonObject view = views[v].toObject();
    const qint64 b = integer(view, "buffer", -1), offset = integer(view, "byteOffset", 0),
                 length = integer(view, "byteLength", -1);
    *field = QStringLiteral("bufferViews[%1]").arg(v);
    const QJsonArray buffers = root.value(QLatin1String("buffers")).toArray();
    if (b < 0 || b >= buffers.size() || offset < 0 || length < 0)
        return fail(QStringLiteral("needs a buffer of the file, a byteOffset and a byteLength"));
    if (length > kMaxIesFileBytes)
        return fail(QStringLiteral("%1 bytes; an IES file has at most %2").arg(length).arg(kMaxIesFileBytes));
    const QJsonValue uri = buffers[b].toObject().value(QLatin1String("uri"));
    if (!uri.isString()) {
        const auto [start, size] = glbBinChunk(folder.modelFile());
        if (b != 0 || size < 0)
            return fail(QStringLiteral("buffers[%1] has no uri and is not a GLB's BIN chunk").arg(b));
        if (offset > size || length > size - offset)
            return fail(QStringLiteral("bytes %1 to %2 lie beyond the BIN chunk's %3")
                            .arg(offset)
                            .arg(offset + length)
                            .arg(size));
        return readSlice(folder.modelFile(), start + offset, length);
    }
    const QString u = uri.toString();
    if (u.startsWith(QLatin1String("data:"))) {
        Bytes all = decodeDataUri(u, maxDataUriBytes, maxDataUriBytes);
        if (!all.error.isEmpty()) return fail(QStringLiteral("buffers[%1]: %2").arg(b).arg(all.error));
        if (offset > all.data.size() || length > all.data.size() - offset)
            return fail(QStringLiteral("bytes %1 to %2 lie beyond buffers[%3]'s %4")
                            .arg(offset)
                            .arg(offset + length)
                            .arg(b)
                            .arg(all.data.size()));
        return {all.data.mid(offset, length), {}};
    }
    QString error;
    const QString path = resolveFileUri(u, folder, &error);
    if (path.isEmpty()) return fail(QStringLiteral("buffers[%1].uri: %2").arg(b).arg(error));
    return readSlice(path, offset, length);
}

} // namespace

QString iesCacheFolder() {
    const QString configured = qEnvironmentVariable("LIGHTRIG_IES_CACHE");
    if (!configured.isEmpty()) return QDir::cleanPath(QDir(configured).absolutePath());
    // Not AppDataLocation: the worker and the editor have different organisation names, so that would be two
    // folders; this one is the same for every process.
    return QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation) +
           QStringLiteral("/lightrig/ies");
}

QString cacheIesProfile(const QByteArray& bytes, QString* error) {
    const QString folder = iesCacheFolder();
    const QString hash =
        QString::fromLatin1(QCryptographicHash::hash(bytes, QCryptographicHash::Sha256).toHex());
    const QString path = folder + QLatin1Char('/') + hash + QStringLiteral(".ies");
    if (QFile existing(path);
        existing.size() == bytes.size() && existing.open(QIODevice::ReadOnly) && existing.readAll() == bytes)
        return path; // already there, written by an earlier import
    if (!QDir().mkpath(folder)) {
        *error = QStringLiteral("cannot create the IES cache folder %1").arg(folder);
        return {};
    }
    if (const QString why = writeFileAtomically(path, bytes); !why.isEmpty()) {
        *error = QStringLiteral("cannot write %1: %2").arg(path, why);
        return {};
    }
    return path;
}

GltfIesProfile readGltfIesProfile(const QJsonObject& root, int index, const ModelFolder& folder,
                                  qint64 maxDataUriBytes) {
    GltfIesProfile out;
    const QString at = QStringLiteral("extensions.EXT_lights_ies.lights[%1]").arg(index);
    const QJsonArray lights = root.value(QLatin1String("extensions"))
                                  .toObject()
                                  .value(QLatin1String("EXT_lights_ies"))
                                  .toObject()
                                  .value(QLatin1String("lights"))
                                  .toArray();
    if (index < 0 || index >= lights.size()) {
        out.field = at;
        out.error = QStringLiteral("no such profile (the file has %1)").arg(lights.size());
        return out;
    }
    const QJsonObject light = lights[index].toObject();
    const QJsonValue uri = light.value(QLatin1String("uri")), view = light.value(QLatin1String("bufferView"));
    Bytes bytes;
    QString name = QStringLiteral("embedded profile"), file; // file: a profile that is a file of its own
    if (uri.isString() && uri.toString().startsWith(QLatin1String("data:"))) {
        out.field = at + QStringLiteral(".uri");
        bytes = decodeDataUri(uri.toString(), maxDataUriBytes, kMaxIesFileBytes);
    } else if (uri.isString()) {
        out.field = at + QStringLiteral(".uri");
        file = resolveFileUri(uri.toString(), folder, &bytes.error);
        if (!file.isEmpty()) {
            name = file;
            const QFileInfo info(file);
            if (!info.isFile())
                bytes.error = QStringLiteral("%1: no such file").arg(file);
            else if (info.size() > kMaxIesFileBytes)
                bytes.error = QStringLiteral("%1: %2 bytes; an IES file has at most %3")
                                  .arg(file)
                                  .arg(info.size())
                                  .arg(kMaxIesFileBytes);
            else
                bytes = readSlice(file, 0, info.size());
        }
    } else if (!view.isUndefined()) {
        out.field = at + QStringLiteral(".bufferView");
        QString viewField;
        bytes = bufferViewBytes(root, view, folder, maxDataUriBytes, &viewField);
        if (!bytes.error.isEmpty() && !viewField.isEmpty())
            bytes.error = viewField + QStringLiteral(": ") + bytes.error;
    } else {
        out.field = at;
        bytes.error = QStringLiteral("has neither a uri nor a bufferView");
    }
    if (!bytes.error.isEmpty()) {
        out.error = bytes.error;
        return out;
    }
    QString error;
    if (!readIesData(bytes.data, name, &error)) {
        out.error = error;
        return out;
    }
    out.file = file.isEmpty() ? cacheIesProfile(bytes.data, &out.error) : file;
    return out;
}

} // namespace lr::detail
