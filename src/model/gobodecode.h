// Decoding a gobo's image (issue 39; docs/light-shaping.md "Gobos"): PNG or OpenEXR, told apart by their
// first bytes, decoded in the isolated import worker (`lightrig import-worker`, request kind "gobo";
// model/isolatedimport.h: a crash, hang or allocation bomb ends the worker only) because the file is
// untrusted. The worker sends the image back as an environment image's 'V' frame (importprotocol.h), and
// the parent checks every value and size before anything uses it.
//
// The image is the gobo's transmission: linear RGB in [0, 1]. PNG values are sRGB-encoded (8 or 16 bits,
// grey, palette or colour; alpha is ignored) and converted to linear; OpenEXR values are linear (R, G, B
// or Y, as environmentdecode.h reads them), clamped to [0, 1] with a warning when any lie outside.
// Refused, with "PATH: reason": not a regular file, larger than kMaxGoboFileBytes, not PNG or OpenEXR,
// a side above kMaxGoboSide (core/gobo.h), truncated or corrupt data, and what the worker cannot do
// (crash, memory or time limits).
#pragma once

#include "core/gobo.h"
#include "environmentdecode.h"

#include <QString>
#include <memory>

namespace lr {

inline constexpr qint64 kMaxGoboFileBytes = 256ll << 20;
// The worker's address space and time for one gobo (enough for the largest image, 4096² from a 256 MiB file).
inline constexpr qint64 kGoboWorkerMemory = 2ll << 30;
inline constexpr int kGoboWorkerTimeoutMs = 60'000;

// In this process (the worker's side, and tests): the image as an EnvironmentImage (texels = linear RGB
// transmission), or `error` set ("PATH: reason"). Warnings begin with the file's name.
EnvironmentDecodeResult decodeGoboBytes(QByteArrayView bytes, const QString& path);
EnvironmentDecodeResult decodeGoboFile(const QString& path);

// Empty when `image` is a usable gobo (sides within kMaxGoboSide, every value in [0, 1]); else why not.
QString checkGoboImage(const EnvironmentImage& image);

// Decodes `path` in the import worker and validates the reply. nullptr with *error ("PATH: reason")
// when the file is not a usable image. Blocking; thread-safe.
std::shared_ptr<const GoboImage> decodeGoboImage(const QString& path, QString* error);

} // namespace lr
