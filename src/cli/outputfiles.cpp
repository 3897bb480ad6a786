#include "outputfiles.h"

#include <QDir>
#include <QFileInfo>
#include <QImageWriter>
#include <QSaveFile>

namespace lr::cli {

namespace {

bool cannotWrite(const QString& path, const QString& reason, QString* error) {
    *error = QStringLiteral("cannot write %1: %2").arg(path, reason);
    return false;
}

} // namespace

bool checkOutputPath(const QString& path, QString* error) {
    const QFileInfo info(path);
    if (!info.absoluteDir().exists())
        return cannotWrite(path, QStringLiteral("the folder %1 does not exist").arg(info.absolutePath()),
                           error);
    if (info.isDir()) return cannotWrite(path, QStringLiteral("it is a folder"), error);
    return true;
}

bool writeFileAtomically(const QString& path, const QByteArray& data, QString* error) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) || file.write(data) != data.size() || !file.commit())
        return cannotWrite(path, file.errorString(), error);
    return true;
}

bool writeImageAtomically(const QImage& image, const QString& path, const QByteArray& format,
                          QString* error) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly)) return cannotWrite(path, file.errorString(), error);
    QImageWriter writer(&file, format);
    if (format == "jpeg") writer.setQuality(92);
    const QImage out = format == "jpeg" ? image.convertToFormat(QImage::Format_RGB888) : image;
    if (!writer.write(out)) {
        file.cancelWriting();
        return cannotWrite(path, writer.errorString(), error);
    }
    if (!file.commit()) return cannotWrite(path, file.errorString(), error);
    return true;
}

} // namespace lr::cli
