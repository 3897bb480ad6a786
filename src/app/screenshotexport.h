// "Export screenshot" without freezing the editor and without losing files. The image is rendered tile by
// tile on the GUI thread (the GL context lives there) with a window-modal QProgressDialog that advances per
// tile and has Cancel; the event loop runs between tiles, so the window keeps repainting. The file is then
// encoded and written on a worker thread (render/imagefile.h): it is replaced only by a complete image, and
// a cancel (during the render or the writing) or a failure leaves any existing file byte for byte as it was.
#pragma once

#include <QByteArray>
#include <QString>
#include <atomic>

class QImage;
class QWidget;

namespace lr {

class Viewport;
struct ScreenshotOptions;

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

// Renders the viewport's screenshot as `options` say and writes it, with the progress dialog in front of
// `parent` (its object name "screenshotProgress", for tests). Returns when the file is written, the user
// cancelled, or it failed.
ScreenshotExportResult exportScreenshotWithProgress(QWidget* parent, Viewport* viewport,
                                                    const ScreenshotOptions& options);

} // namespace lr
