// Environment images (issue 15; docs/architecture.md "Environments"): equirectangular OpenEXR (any
// compression OpenEXR 3 reads, DWAB included; channels R, G, B as float, or Y as grey; alpha ignored)
// and Radiance RGBE (.hdr, through stb_image), told apart by their first bytes, not their extension.
//
// A file from the user is untrusted: importEnvironmentIsolated decodes it in `lightrig import-worker`
// (isolatedimport.h: a crash, hang or allocation bomb ends the worker only) and checks the image it sends
// back (checkEnvironmentImage) before anything uses it. Bundled environments ("builtin:studio") are
// trusted and decoded in process.
//
// Refused with an error naming the file and the reason: width or height above kMaxEnvironmentSide,
// more than kMaxEnvironmentTexels texels, a header claiming more data than the file holds, truncated or
// corrupt data, no colour channel. Accepted with one warning each: texels with NaN, infinite or negative
// values (those values set to 0), an image that is not 2:1 (equirectangular expects 2:1).
#pragma once

#include "core/environment.h"
#include "isolatedimport.h"

#include <QByteArrayView>
#include <QString>
#include <QStringList>

namespace lr {

inline constexpr int kMaxEnvironmentSide = 16384;
inline constexpr qint64 kMaxEnvironmentTexels = 64ll << 20; // 64 Mpx (768 MiB as float RGB)
inline constexpr qint64 kMaxEnvironmentFileBytes = 2ll << 30;

struct EnvironmentDecodeResult {
    EnvironmentImage image; // every value finite and >= 0 when ok()
    QStringList warnings;   // each begins with the file's name: "sky.exr: 12 texels were ..."
    QString reason;         // why it failed, without the file: "truncated or corrupt OpenEXR (...)"
    QString error;          // "could not read <path as given>: <reason>"; empty when ok()
    bool ok() const { return error.isEmpty() && !image.isNull(); }
};

// Decodes a file's bytes in this process. `path` names the file in the error and warnings.
EnvironmentDecodeResult decodeEnvironment(QByteArrayView bytes, const QString& path);
// Reads and decodes a file in this process (the worker does this).
EnvironmentDecodeResult decodeEnvironmentFile(const QString& path);
// Decodes `path` in the import worker and validates the reply. Blocking; thread-safe.
EnvironmentDecodeResult importEnvironmentIsolated(const QString& path, const ImportLimits& limits = {});

// The bundled environments' names ("courtyard", "studio"), sorted, for "builtin:NAME"
// (kBuiltinEnvironmentPrefix) and the editor's chooser; and one of them decoded (in process).
QStringList builtinEnvironmentNames();
EnvironmentDecodeResult decodeBuiltinEnvironment(const QString& name);

// Empty when `image` is usable: sides within the limits, texels = width × height, every value finite
// and >= 0; else why not. The parent's check of a worker's reply.
QString checkEnvironmentImage(const EnvironmentImage& image);

// The worker's reply ('V' frame, importprotocol.h) and its parent-side reading (which checks sizes and
// every value; false with `why` on any inconsistency).
QByteArray encodeEnvironmentReply(const EnvironmentImage& image, const QStringList& warnings);
bool decodeEnvironmentReply(QByteArrayView payload, EnvironmentImage* image, QStringList* warnings,
                            QString* why);

} // namespace lr
