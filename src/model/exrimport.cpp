// Multi-layer OpenEXR files through the import worker (the parent's side; the worker's is
// cli/importworker.cpp) and the worker's reply format.
//
// Reply (frame 'L'), every number a u32 in host order, every string its UTF-8 byte count then its bytes:
//   width, height, attribute count, layer count,
//   per attribute: name, value;  per layer: name, channel count, each channel's name;
//   then per layer, in that order: width × height × channels floats (ExrLayer::pixels).
#include "exrdecode.h"

#include "environmentdecode.h"
#include "importprotocol.h"
#include "isolatedworker.h"

#include <QFileInfo>
#include <QJsonObject>
#include <QSet>
#include <cstring>

namespace lr {

namespace {

namespace ip = importprotocol;

void putU32(QByteArray* out, quint32 v) {
    out->append(reinterpret_cast<const char*>(&v), sizeof v);
}

void putString(QByteArray* out, const QString& s) {
    const QByteArray utf8 = s.toUtf8();
    putU32(out, quint32(utf8.size()));
    out->append(utf8);
}

// Reads the reply front to back; every read checks what is left first.
class Reader {
  public:
    explicit Reader(QByteArrayView bytes) : m_bytes(bytes) {}
    bool u32(quint32* v) {
        if (left() < qsizetype(sizeof *v)) return false;
        std::memcpy(v, m_bytes.data() + m_pos, sizeof *v);
        m_pos += sizeof *v;
        return true;
    }
    bool string(QString* s) {
        quint32 n = 0;
        if (!u32(&n) || qint64(n) > left()) return false;
        *s = QString::fromUtf8(m_bytes.data() + m_pos, qsizetype(n));
        m_pos += n;
        return true;
    }
    qsizetype left() const { return m_bytes.size() - m_pos; }
    const char* here() const { return m_bytes.data() + m_pos; }
    void skip(qsizetype n) { m_pos += n; }

  private:
    QByteArrayView m_bytes;
    qsizetype m_pos = 0;
};

QString readReply(QByteArrayView payload, ExrFile* out) {
    Reader r(payload);
    quint32 w = 0, h = 0, attributeCount = 0, layerCount = 0;
    if (!r.u32(&w) || !r.u32(&h) || !r.u32(&attributeCount) || !r.u32(&layerCount))
        return QStringLiteral("a layers reply of %1 bytes").arg(payload.size());
    if (QString why = exrSizeProblem(w, h, 0); !why.isEmpty()) return why;
    if (layerCount < 1 || layerCount > quint32(kMaxExrChannels))
        return QStringLiteral("%1 layers").arg(layerCount);
    ExrFile file;
    file.width = int(w);
    file.height = int(h);
    QSet<QString> seen;
    for (quint32 i = 0; i < attributeCount; ++i) {
        QString name, value;
        if (!r.string(&name) || !r.string(&value)) return QStringLiteral("attribute %1 is cut short").arg(i);
        if (name.isEmpty() || seen.contains(name))
            return QStringLiteral("attribute %1 is named \"%2\" (empty or twice)").arg(i).arg(name);
        seen.insert(name);
        file.attributes.emplace_back(std::move(name), std::move(value));
    }
    seen.clear();
    int channels = 0;
    for (quint32 i = 0; i < layerCount; ++i) {
        ExrLayer& layer = file.layers.emplace_back();
        quint32 n = 0;
        if (!r.string(&layer.name) || !r.u32(&n)) return QStringLiteral("layer %1 is cut short").arg(i);
        if (seen.contains(layer.name)) return QStringLiteral("two layers named \"%1\"").arg(layer.name);
        seen.insert(layer.name);
        if (n < 1 || n > quint32(kMaxExrChannels - channels))
            return QStringLiteral("layer \"%1\" has %2 channels after %3")
                .arg(layer.name)
                .arg(n)
                .arg(channels);
        channels += int(n);
        for (quint32 c = 0; c < n; ++c) {
            QString name;
            if (!r.string(&name)) return QStringLiteral("layer \"%1\" is cut short").arg(layer.name);
            if (name.isEmpty() || layer.channels.contains(name))
                return QStringLiteral("layer \"%1\" has a channel named \"%2\" (empty or twice)")
                    .arg(layer.name, name);
            layer.channels << name;
        }
    }
    if (QString why = exrSizeProblem(w, h, channels); !why.isEmpty()) return why;
    const qint64 pixelBytes = qint64(w) * h * channels * qint64(sizeof(float));
    if (r.left() != pixelBytes)
        return QStringLiteral("%1 bytes of pixels for %2×%3 pixels of %4 channels (%5 expected)")
            .arg(r.left())
            .arg(w)
            .arg(h)
            .arg(channels)
            .arg(pixelBytes);
    for (ExrLayer& layer : file.layers) {
        layer.pixels.resize(size_t(w) * h * size_t(layer.channels.size()));
        const qsizetype bytes = qsizetype(layer.pixels.size() * sizeof(float));
        std::memcpy(layer.pixels.data(), r.here(), size_t(bytes));
        r.skip(bytes);
    }
    *out = std::move(file);
    return {};
}

} // namespace

QByteArray exrLayersReplyHead(const ExrFile& file) {
    QByteArray out;
    putU32(&out, quint32(file.width));
    putU32(&out, quint32(file.height));
    putU32(&out, quint32(file.attributes.size()));
    putU32(&out, quint32(file.layers.size()));
    for (const auto& [name, value] : file.attributes) {
        putString(&out, name);
        putString(&out, value);
    }
    for (const ExrLayer& layer : file.layers) {
        putString(&out, layer.name);
        putU32(&out, quint32(layer.channels.size()));
        for (const QString& c : layer.channels)
            putString(&out, c);
    }
    return out;
}

QByteArray encodeExrLayersReply(const ExrFile& file) {
    QByteArray out = exrLayersReplyHead(file);
    for (const ExrLayer& layer : file.layers)
        out.append(reinterpret_cast<const char*>(layer.pixels.data()),
                   qsizetype(layer.pixels.size() * sizeof(float)));
    return out;
}

bool decodeExrLayersReply(QByteArrayView payload, ExrFile* file, QString* why) {
    *why = readReply(payload, file);
    return why->isEmpty();
}

qint64 maxExrLayersReplyBytes(qint64 fileBytes) {
    // The pixels, and the names and attributes, which the file holds (each with a 4-byte count: at most a
    // few times the file's header).
    return maxExrDecodedBytes(fileBytes) + 4 * std::max<qint64>(fileBytes, 0) + (1 << 20);
}

std::optional<ExrFile> importExrLayersIsolated(const QString& path, QString* error,
                                               const ImportLimits& limits) {
    const auto fail = [&](const QString& reason) {
        *error = QStringLiteral("could not read %1: %2").arg(path, reason);
        return std::nullopt;
    };
    if (QString problem = environmentFileProblem(path); !problem.isEmpty()) return fail(problem);
    const auto keepGoing = [&limits](double) { return !(limits.cancel && limits.cancel->load()); };
    QJsonObject request;
    request.insert(QStringLiteral("kind"), QLatin1String(ip::kExrLayersKind));
    request.insert(QStringLiteral("path"), path);
    const qint64 fileBytes = QFileInfo(path).size();
    isolated::WorkerOutcome run = isolated::runWorker(
        request, limits, -1, keepGoing, maxExrLayersReplyBytes(fileBytes), BudgetKind::ExrLayers);
    if (!run.ok() && run.fromWorker) { // the worker's own message, "could not read PATH: REASON"
        *error = run.failure;
        return std::nullopt;
    }
    if (!run.ok()) return fail(run.failure);
    if (run.type != ip::kExrLayers)
        return fail(QStringLiteral("the importer sent a malformed reply (a reply of type '%1' to a layers "
                                   "request)")
                        .arg(QLatin1Char(run.type)));
    ExrFile file;
    QString why;
    if (!decodeExrLayersReply(run.payload, &file, &why))
        return fail(QStringLiteral("the importer sent a malformed reply (%1)").arg(why));
    return file;
}

} // namespace lr
