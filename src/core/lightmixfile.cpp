#include "lightmixfile.h"

#include "atomicwrite.h"
#include "rigjson.h"

#include <QFile>
#include <QFileInfo>

namespace lr {

namespace {
LightMixReadResult failed(const QString& path, const QString& reason) {
    LightMixReadResult r;
    r.errors << QStringLiteral("%1: %2").arg(path, reason);
    return r;
}
} // namespace

LightMixReadResult readLightMixFile(const QString& path, const QStringList& known) {
    const QFileInfo info(path);
    if (info.isDir()) return failed(path, QStringLiteral("is a directory, not a mix file"));
    // A FIFO would block the read: mix files are regular files, as rig files are.
    if (info.exists() && !info.isFile())
        return failed(path, QStringLiteral("is not a regular file (a FIFO, socket or device)"));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return failed(path, QStringLiteral("cannot open: %1").arg(file.errorString()));
    if (file.size() > kMaxRigFileBytes)
        return failed(
            path,
            QStringLiteral("is %1 bytes; a mix file has at most %2").arg(file.size()).arg(kMaxRigFileBytes));
    const QByteArray data = file.read(kMaxRigFileBytes + 1);
    if (file.error() != QFileDevice::NoError)
        return failed(path, QStringLiteral("cannot read: %1").arg(file.errorString()));
    return readLightMix(data, path, known);
}

QString writeLightMixFile(const QString& path, const LightMix& mix) {
    const QString reason = writeFileAtomically(path, writeLightMix(mix));
    return reason.isEmpty() ? QString() : QStringLiteral("%1: not saved: %2").arg(path, reason);
}

} // namespace lr
