#include "screenshotexport.h"

#include "render/imagefile.h"

namespace lr {

QString saveImageAtomically(const QImage& image, const QString& path, const QByteArray& format,
                            const std::atomic<bool>* cancel, bool* cancelled) {
    const QString reason = writeImageAtomically(image, path, format, cancel, cancelled);
    if (reason.isEmpty() || (cancelled && *cancelled)) return reason;
    return QStringLiteral("%1: could not write the image: %2").arg(path, reason);
}

} // namespace lr
