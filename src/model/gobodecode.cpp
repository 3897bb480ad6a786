#include "gobodecode.h"

#include "exrio.h"
#include "importprotocol.h"
#include "isolatedworker.h"

#include "core/colour.h"

#include <QBuffer>
#include <QFileInfo>
#include <QImage>
#include <QImageReader>
#include <cmath>
#include <cstring>

namespace lr {

namespace {

namespace ip = importprotocol;

constexpr char kExrMagic[] = {0x76, 0x2f, 0x31, 0x01};
constexpr char kPngMagic[] = "\x89PNG\r\n\x1a\n";

QString sideProblem(qint64 w, qint64 h) {
    if (w <= 0 || h <= 0) return QStringLiteral("its size %1×%2 is empty").arg(w).arg(h);
    if (w > kMaxGoboSide || h > kMaxGoboSide)
        return QStringLiteral("%1×%2 texels is larger than the limit of %3 on a side for a gobo")
            .arg(w)
            .arg(h)
            .arg(kMaxGoboSide);
    return {};
}

// PNG through Qt's decoder, its size checked from the header before any pixel memory is allocated.
QString decodePng(QByteArrayView bytes, EnvironmentImage* image) {
    QByteArray copy = bytes.toByteArray();
    QBuffer buffer(&copy);
    buffer.open(QIODevice::ReadOnly);
    QImageReader reader(&buffer, "png");
    reader.setAllocationLimit(int((qint64(kMaxGoboSide) * kMaxGoboSide * 8) >> 20)); // MiB, RGBA64
    const QSize size = reader.size();
    if (!size.isValid()) return QStringLiteral("not a readable PNG (%1)").arg(reader.errorString());
    if (QString why = sideProblem(size.width(), size.height()); !why.isEmpty()) return why;
    QImage img;
    if (!reader.read(&img) || img.isNull())
        return QStringLiteral("truncated or corrupt PNG (%1)").arg(reader.errorString());
    if (img.size() != size) return QStringLiteral("its size does not match its header");
    img = img.convertToFormat(QImage::Format_RGBX64);
    image->width = img.width();
    image->height = img.height();
    image->texels.resize(size_t(img.width()) * size_t(img.height()));
    // sRGB-encoded levels to linear, through a table of the 65536 16-bit levels' values.
    std::vector<float> table(65536);
    for (int i = 0; i < 65536; ++i)
        table[size_t(i)] = float(colour::srgbToLinear(double(i) / 65535.0));
    for (int y = 0; y < img.height(); ++y) {
        const auto* row = reinterpret_cast<const quint16*>(img.constScanLine(y));
        for (int x = 0; x < img.width(); ++x)
            image->texels[size_t(y) * size_t(img.width()) + size_t(x)] =
                glm::vec3(table[row[4 * x]], table[row[4 * x + 1]], table[row[4 * x + 2]]);
    }
    return {};
}

} // namespace

EnvironmentDecodeResult decodeGoboBytes(QByteArrayView bytes, const QString& path) {
    EnvironmentDecodeResult r;
    const QString name = QFileInfo(path).fileName().isEmpty() ? path : QFileInfo(path).fileName();
    if (bytes.size() >= 4 && std::memcmp(bytes.data(), kExrMagic, 4) == 0) {
        // OpenEXR through the environment decoder (its limits, its sanitising), then the gobo's own.
        r = decodeEnvironment(bytes, path);
        r.warnings.removeIf([](const QString& w) { return w.contains(QLatin1String("equirectangular")); });
        if (r.ok()) r.reason = sideProblem(r.image.width, r.image.height);
        if (r.ok() && r.reason.isEmpty()) {
            qint64 clamped = 0;
            for (glm::vec3& t : r.image.texels)
                for (int c = 0; c < 3; ++c)
                    if (t[c] > 1.0f) {
                        t[c] = 1.0f;
                        ++clamped;
                    }
            if (clamped > 0)
                r.warnings << QStringLiteral("%1: %2 values were above 1 and were clamped to 1 (a gobo "
                                             "transmits at most all of the light)")
                                  .arg(name)
                                  .arg(clamped);
        }
    } else if (bytes.size() >= 8 && std::memcmp(bytes.data(), kPngMagic, 8) == 0) {
        try {
            r.reason = decodePng(bytes, &r.image);
        } catch (const std::bad_alloc&) {
            r.reason = QStringLiteral("out of memory decoding it");
        }
    } else {
        r.reason = QStringLiteral("not a PNG or OpenEXR image (unknown first bytes)");
    }
    if (!r.ok() || !r.reason.isEmpty()) {
        const QString prefix = QStringLiteral("could not read %1: ").arg(path);
        if (r.reason.isEmpty()) r.reason = r.error.startsWith(prefix) ? r.error.mid(prefix.size()) : r.error;
        r.image = {};
        r.warnings.clear();
        r.error = QStringLiteral("%1: %2").arg(path, r.reason);
    }
    return r;
}

EnvironmentDecodeResult decodeGoboFile(const QString& path) {
    exrio::UntrustedFile file;
    if (QString problem = file.open(path, kMaxGoboFileBytes); !problem.isEmpty()) {
        EnvironmentDecodeResult r;
        r.reason = problem;
        r.error = QStringLiteral("%1: %2").arg(path, problem);
        return r;
    }
    return decodeGoboBytes(file.bytes(), path);
}

QString checkGoboImage(const EnvironmentImage& image) {
    if (QString why = sideProblem(image.width, image.height); !why.isEmpty()) return why;
    if (image.texels.size() != size_t(image.width) * size_t(image.height))
        return QStringLiteral("%1 texels for %2×%3")
            .arg(image.texels.size())
            .arg(image.width)
            .arg(image.height);
    for (const glm::vec3& t : image.texels)
        for (int c = 0; c < 3; ++c)
            if (!(t[c] >= 0.0f && t[c] <= 1.0f))
                return QStringLiteral("a texel value %1 (not in [0, 1])").arg(double(t[c]));
    return {};
}

std::shared_ptr<const GoboImage> decodeGoboImage(const QString& path, QString* error) {
    const auto fail = [&](const QString& reason) {
        if (error) *error = QStringLiteral("%1: %2").arg(path, reason);
        return nullptr;
    };
    if (QString problem = environmentFileProblem(path); !problem.isEmpty()) return fail(problem);
    QJsonObject request;
    request.insert(QStringLiteral("kind"), QLatin1String(ip::kGoboKind));
    request.insert(QStringLiteral("path"), path);
    const qint64 maxBytes = ip::kEnvironmentHeaderSize + ip::kMaxErrorBytes +
                            qint64(kMaxGoboSide) * kMaxGoboSide * qint64(sizeof(glm::vec3));
    // Fixed limits, not scaled to the file: a 55 KB PNG of 4096² texels needs ~350 MiB resident (the
    // environment budget for that file, 544 MiB of address space, ran out).
    ImportLimits limits;
    limits.scaleWithInput = false;
    limits.memoryBytes = kGoboWorkerMemory;
    limits.timeoutMs = kGoboWorkerTimeoutMs;
    isolated::WorkerOutcome run = isolated::runWorker(
        request, limits, -1, [](double) { return true; }, maxBytes, BudgetKind::Environment);
    if (!run.ok()) {
        if (run.fromWorker) { // the worker's own "PATH: reason"
            if (error) *error = run.failure;
            return nullptr;
        }
        return fail(run.failure);
    }
    if (run.type != ip::kEnvironment)
        return fail(QStringLiteral("the importer sent a malformed reply (a reply of type '%1' to a gobo "
                                   "request)")
                        .arg(QLatin1Char(run.type)));
    EnvironmentImage image;
    QStringList warnings;
    QString why;
    if (!decodeEnvironmentReply(run.payload, &image, &warnings, &why))
        return fail(QStringLiteral("the importer sent a malformed reply (%1)").arg(why));
    if (QString problem = checkGoboImage(image); !problem.isEmpty())
        return fail(QStringLiteral("the importer sent a malformed reply (%1)").arg(problem));
    auto out = std::make_shared<GoboImage>();
    out->width = image.width;
    out->height = image.height;
    out->rgb.resize(image.texels.size() * 3);
    std::memcpy(out->rgb.data(), image.texels.data(), out->rgb.size() * sizeof(float));
    return out;
}

} // namespace lr
