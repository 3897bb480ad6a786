// Writing an exported image without losing files (render/imagefile.h): it is replaced only by a complete
// image, and a cancel or a failure leaves any existing file byte for byte as it was. The export itself runs
// in the background: screenshotjob.h.
#pragma once

#include <QByteArray>
#include <QString>
#include <atomic>

class QImage;

namespace lr {

// Writes `image` to `path` as `format` ("PNG" or "JPEG", quality 92) atomically. When *cancel is set
// before the commit, nothing is written, *cancelled is set and the result is "cancelled". "" on success,
// else "PATH: could not write the image: reason". Thread-safe.
QString saveImageAtomically(const QImage& image, const QString& path, const QByteArray& format,
                            const std::atomic<bool>* cancel = nullptr, bool* cancelled = nullptr);

struct ScreenshotExportResult {
    QString error; // empty on success and when cancelled
    bool cancelled = false;
    int tiles = 0; // tiles rendered
    bool ok() const { return error.isEmpty() && !cancelled; }
};

} // namespace lr
