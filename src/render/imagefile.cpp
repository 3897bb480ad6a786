#include "imagefile.h"

#include "core/atomicwrite.h"

#include <QBuffer>
#include <QFileInfo>
#include <QImage>
#include <QImageWriter>

namespace lr {

QByteArray imageFormatOf(const QString& path) {
    const QByteArray suffix = QFileInfo(path).suffix().toLower().toLatin1();
    return suffix == "jpg" ? QByteArrayLiteral("jpeg") : suffix;
}

QByteArray writableImageFormatOf(const QString& path) {
    const QByteArray f = imageFormatOf(path);
    return f == "png" || f == "jpeg" ? f : QByteArray();
}

QByteArray encodeImage(const QImage& image, const QByteArray& format, QString* error) {
    const QByteArray f = format.toLower() == "jpg" ? QByteArrayLiteral("jpeg") : format.toLower();
    if (image.isNull()) {
        *error = QStringLiteral("there is no image to write");
        return {};
    }
    QByteArray bytes;
    QBuffer buffer(&bytes);
    buffer.open(QIODevice::WriteOnly);
    QImageWriter writer(&buffer, f);
    const bool jpeg = f == "jpeg";
    if (jpeg) writer.setQuality(92);
    if (!writer.write(jpeg ? image.convertToFormat(QImage::Format_RGB888) : image)) {
        *error = writer.errorString();
        if (writer.error() == QImageWriter::UnsupportedFormatError)
            *error = QStringLiteral("cannot write images as \"%1\"").arg(QString::fromLatin1(f));
        return {};
    }
    return bytes;
}

QString writeImageAtomically(const QImage& image, const QString& path, const QByteArray& format,
                             const std::atomic<bool>* cancel, bool* cancelled) {
    if (cancelled) *cancelled = false;
    if (cancel && cancel->load()) { // before the (long) encoding
        if (cancelled) *cancelled = true;
        return QStringLiteral("cancelled");
    }
    QString error;
    const QByteArray bytes = encodeImage(image, format.isEmpty() ? imageFormatOf(path) : format, &error);
    if (bytes.isEmpty()) return error;
    return writeFileAtomically(path, bytes, cancel, cancelled);
}

} // namespace lr
