// Environment images (issue 15; docs/architecture.md "Environments"): equirectangular OpenEXR (any
// compression OpenEXR 3 reads, DWAB included; channels R, G, B as float, or Y as grey; alpha ignored)
// and Radiance RGBE (.hdr, through stb_image), told apart by their first bytes, not their extension.
//
// A file from the user is untrusted: importEnvironmentIsolated decodes it in `lightrig import-worker`
// (isolatedimport.h: a crash, hang or allocation bomb ends the worker only) and checks the image it sends
// back (checkEnvironmentImage) before anything uses it. Bundled environments ("builtin:studio") are
// trusted and decoded in process.
//
// Refused with an error naming the file and the reason: a path that is not a regular file (a FIFO or a
// device such as /dev/zero: refused at once, never read), width or height above kMaxEnvironmentSide, more
// than kMaxEnvironmentTexels texels, a header claiming more data than the file holds or more texels than
// the file could plausibly hold (maxEnvironmentDecodedBytes: checked before any pixel memory is
// allocated), truncated or corrupt data, no colour channel. Accepted with one warning each: texels with
// NaN or infinite values (set to 0), texels brighter than kMaxEnvironmentRadiance (clamped to it: brighter
// values overflow to infinity when filtered), an image that is not 2:1 (equirectangular expects 2:1).
// Negative values (the ringing of lossy DWA/B44 compression around bright edges) are set to 0 silently
// unless one is larger than kNegativeTolerance × the image's mean value: then that is a warning too.
#pragma once

#include "core/environment.h"
#include "isolatedimport.h"

#include <QByteArrayView>
#include <QString>
#include <QStringList>
#include <algorithm>

namespace lr {

inline constexpr int kMaxEnvironmentSide = 16384;
inline constexpr qint64 kMaxEnvironmentTexels = 64ll << 20; // 64 Mpx (768 MiB as float RGB)
inline constexpr qint64 kMaxEnvironmentFileBytes = 2ll << 30;
// The brightest radiance kept (larger values are clamped with a warning). Far above any captured sun
// (~1e5 in relative units, 1.6e9 cd/m² absolute), far below where prefiltering's sums and the shader's
// 2^20 EV overflow a float (3.4e38): 1e35 in a texel turned the whole image black.
inline constexpr float kMaxEnvironmentRadiance = 1e10f;
inline constexpr double kNegativeTolerance = 0.01;
// Decoded bytes (float RGB, 12 a texel) allowed per byte of file, beyond kFreeEnvironmentBytes: real
// HDRIs decode to 12-64 bytes per byte (DWAB), RLE Radiance files to at most ~190; a 457-byte EXR header
// claiming 64 Mpx made the worker allocate 793 MB before it found the data missing.
inline constexpr qint64 kMaxEnvironmentExpansion = 256;
inline constexpr qint64 kFreeEnvironmentBytes = 16ll << 20;
inline qint64 maxEnvironmentDecodedBytes(qint64 fileBytes) {
    return kFreeEnvironmentBytes + kMaxEnvironmentExpansion * std::max<qint64>(fileBytes, 0);
}

struct EnvironmentDecodeResult {
    EnvironmentImage image; // every value finite and >= 0 when ok()
    QStringList warnings;   // each begins with the file's name: "sky.exr: 12 texels were ..."
    QString reason;         // why it failed, without the file: "truncated or corrupt OpenEXR (...)"
    QString error;          // "could not read <path as given>: <reason>"; empty when ok()
    bool ok() const { return error.isEmpty() && !image.isNull(); }
};

// Decodes a file's bytes in this process. `path` names the file in the error and warnings.
EnvironmentDecodeResult decodeEnvironment(QByteArrayView bytes, const QString& path);
// Why `path` cannot be an environment file before it is opened: "no such file", "not a regular file
// (...)"; empty when it may be one. (The parent's quick check; the worker checks again on its open file.)
QString environmentFileProblem(const QString& path);
// Reads and decodes a file in this process (the worker does this).
EnvironmentDecodeResult decodeEnvironmentFile(const QString& path);
// Decodes `path` in the import worker and validates the reply. Blocking; thread-safe.
EnvironmentDecodeResult importEnvironmentIsolated(const QString& path, const ImportLimits& limits = {});

// The bundled environments' names ("courtyard", "studio"), sorted, for "builtin:NAME"
// (kBuiltinEnvironmentPrefix) and the editor's chooser; and one of them decoded (in process).
QStringList builtinEnvironmentNames();
EnvironmentDecodeResult decodeBuiltinEnvironment(const QString& name);

// Empty when `image` is usable: sides within the limits, texels = width × height, every value finite,
// >= 0 and <= kMaxEnvironmentRadiance; else why not. The parent's check of a worker's reply.
QString checkEnvironmentImage(const EnvironmentImage& image);

// The worker's reply ('V' frame, importprotocol.h) and its parent-side reading (which checks sizes and
// every value; false with `why` on any inconsistency).
QByteArray encodeEnvironmentReply(const EnvironmentImage& image, const QStringList& warnings);
bool decodeEnvironmentReply(QByteArrayView payload, EnvironmentImage* image, QStringList* warnings,
                            QString* why);

} // namespace lr
