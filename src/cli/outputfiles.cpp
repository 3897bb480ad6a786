#include "outputfiles.h"

#include "core/atomicwrite.h"
#include "render/imagefile.h"

#include <QDir>
#include <QFileInfo>

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

bool writeOutputFile(const QString& path, const QByteArray& data, QString* error) {
    const QString reason = writeFileAtomically(path, data);
    return reason.isEmpty() || cannotWrite(path, reason, error);
}

bool writeOutputImage(const QImage& image, const QString& path, const QByteArray& format, QString* error) {
    const QString reason = writeImageAtomically(image, path, format);
    return reason.isEmpty() || cannotWrite(path, reason, error);
}

} // namespace lr::cli
