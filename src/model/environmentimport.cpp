// Environment images through the import worker (the parent's side; the worker's is
// cli/importworker.cpp), the worker's reply format, and the bundled environments.
#include "environmentdecode.h"

#include "importprotocol.h"
#include "isolatedworker.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <cmath>
#include <cstring>

namespace lr {

namespace {

namespace ip = importprotocol;

const QString kBuiltinFolder = QStringLiteral(":/resources/environments");

} // namespace

QByteArray encodeEnvironmentReply(const EnvironmentImage& image, const QStringList& warnings) {
    const QByteArray text = warnings.join(QLatin1Char('\n')).toUtf8().left(ip::kMaxErrorBytes);
    const quint32 header[3] = {quint32(image.width), quint32(image.height), quint32(text.size())};
    QByteArray out;
    out.reserve(ip::kEnvironmentHeaderSize + text.size() +
                qsizetype(image.texels.size() * sizeof(glm::vec3)));
    out.append(reinterpret_cast<const char*>(header), sizeof header);
    out.append(text);
    out.append(reinterpret_cast<const char*>(image.texels.data()),
               qsizetype(image.texels.size() * sizeof(glm::vec3)));
    return out;
}

bool decodeEnvironmentReply(QByteArrayView payload, EnvironmentImage* image, QStringList* warnings,
                            QString* why) {
    quint32 header[3];
    if (payload.size() < qsizetype(sizeof header)) {
        *why = QStringLiteral("an environment reply of %1 bytes").arg(payload.size());
        return false;
    }
    std::memcpy(header, payload.data(), sizeof header);
    const qint64 w = header[0], h = header[1], textBytes = header[2];
    if (w < 1 || h < 1 || w > kMaxEnvironmentSide || h > kMaxEnvironmentSide ||
        w * h > kMaxEnvironmentTexels || textBytes > ip::kMaxErrorBytes) {
        *why = QStringLiteral("an environment of %1×%2 texels with %3 bytes of warnings")
                   .arg(w)
                   .arg(h)
                   .arg(textBytes);
        return false;
    }
    const qint64 texelBytes = w * h * qint64(sizeof(glm::vec3));
    if (payload.size() != qint64(sizeof header) + textBytes + texelBytes) {
        *why = QStringLiteral("%1 bytes for an environment of %2×%3 texels (%4 expected)")
                   .arg(payload.size())
                   .arg(w)
                   .arg(h)
                   .arg(qint64(sizeof header) + textBytes + texelBytes);
        return false;
    }
    EnvironmentImage decoded;
    decoded.width = int(w);
    decoded.height = int(h);
    decoded.texels.resize(size_t(w * h));
    std::memcpy(decoded.texels.data(), payload.data() + sizeof header + textBytes, size_t(texelBytes));
    if (QString problem = checkEnvironmentImage(decoded); !problem.isEmpty()) {
        *why = problem;
        return false;
    }
    const QString text = QString::fromUtf8(payload.data() + sizeof header, qsizetype(textBytes));
    *warnings = text.isEmpty() ? QStringList() : text.split(QLatin1Char('\n'));
    *image = std::move(decoded);
    return true;
}

EnvironmentDecodeResult importEnvironmentIsolated(const QString& path, const ImportLimits& limits) {
    EnvironmentDecodeResult r;
    if (QString problem = environmentFileProblem(path); !problem.isEmpty()) { // a FIFO: no worker waits on it
        r.reason = problem;
        r.error = QStringLiteral("could not read %1: %2").arg(path, problem);
        return r;
    }
    const auto keepGoing = [&limits](double) { return !(limits.cancel && limits.cancel->load()); };
    QJsonObject request;
    request.insert(QStringLiteral("kind"), QStringLiteral("environment"));
    request.insert(QStringLiteral("path"), path);
    const qint64 maxBytes = ip::kEnvironmentHeaderSize + ip::kMaxErrorBytes + kMaxEnvironmentTexels * 12;
    isolated::WorkerOutcome run =
        isolated::runWorker(request, limits, -1, keepGoing, maxBytes, BudgetKind::Environment);
    if (!run.ok() && run.fromWorker) {
        // The worker's own message, "could not read PATH: REASON"; keep the reason alone too.
        r.error = run.failure;
        const QString prefix = QStringLiteral("could not read %1: ").arg(path);
        r.reason = r.error.startsWith(prefix) ? r.error.mid(prefix.size()) : r.error;
        return r;
    }
    QString why;
    if (!run.ok())
        r.reason = run.failure;
    else if (run.type != ip::kEnvironment)
        r.reason = QStringLiteral("the importer sent a malformed reply (a reply of type '%1' to an "
                                  "environment request)")
                       .arg(QLatin1Char(run.type));
    else if (!decodeEnvironmentReply(run.payload, &r.image, &r.warnings, &why))
        r.reason = QStringLiteral("the importer sent a malformed reply (%1)").arg(why);
    if (!r.reason.isEmpty()) {
        r.image = {};
        r.warnings.clear();
        r.error = QStringLiteral("could not read %1: %2").arg(path, r.reason);
    }
    return r;
}

QStringList builtinEnvironmentNames() {
    QStringList names;
    for (const QFileInfo& f :
         QDir(kBuiltinFolder).entryInfoList({QStringLiteral("*.exr")}, QDir::Files, QDir::Name))
        names << f.completeBaseName();
    return names;
}

EnvironmentDecodeResult decodeBuiltinEnvironment(const QString& name) {
    const QString written = QLatin1String(kBuiltinEnvironmentPrefix) + name;
    QFile file(kBuiltinFolder + QLatin1Char('/') + name + QStringLiteral(".exr"));
    if (name.contains(QLatin1Char('/')) || !file.open(QIODevice::ReadOnly)) {
        EnvironmentDecodeResult r;
        r.reason = QStringLiteral("no bundled environment is called \"%1\" (there are: %2)")
                       .arg(name, builtinEnvironmentNames().join(QStringLiteral(", ")));
        r.error = QStringLiteral("could not read %1: %2").arg(written, r.reason);
        return r;
    }
    return decodeEnvironment(file.readAll(), written);
}

} // namespace lr
