// Image files, written the one atomic way (core/atomicwrite.h): the image is encoded to bytes in memory,
// then handed to writeFileAtomically, so a full disk, a cancel or a kill leaves any previous file as it was.
// Used for screenshots, preset thumbnails, the README screenshot, `lightrig render` and bench charts.
#pragma once

#include <QByteArray>
#include <QString>
#include <atomic>

class QImage;

namespace lr {

// format: "png" or "jpeg"/"jpg" (any case; JPEG at quality 92, alpha dropped); "" takes it from PATH's
// suffix. Empty bytes and *error set when the image cannot be encoded.
QByteArray encodeImage(const QImage& image, const QByteArray& format, QString* error);
QByteArray imageFormatOf(const QString& path); // "png", "jpeg", or the suffix in lower case
// "png" or "jpeg" when PATH's suffix (.png, .jpg, .jpeg, any case) names a format encodeImage writes; else
// "".
QByteArray writableImageFormatOf(const QString& path);

// "" when PATH holds the image; else the reason ("no space left on device", "cancelled"), PATH unchanged.
// Cancel as writeFileAtomically. Thread-safe.
QString writeImageAtomically(const QImage& image, const QString& path, const QByteArray& format = {},
                             const std::atomic<bool>* cancel = nullptr, bool* cancelled = nullptr);

} // namespace lr
