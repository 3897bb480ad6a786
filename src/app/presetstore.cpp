#include "presetstore.h"

#include "render/imagefile.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QStandardPaths>

namespace lr {

PresetStore::PresetStore(const QString& userDir, QObject* parent)
    : QObject(parent),
      m_userDir(userDir.isEmpty() ? QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) +
                                        QStringLiteral("/presets")
                                  : userDir) {}

QList<PresetEntry> PresetStore::presets() const {
    QList<PresetEntry> out;
    for (const QString& name : builtinPresetNames())
        out.append({name, builtinPresetPath(name), QString(), true});
    const QDir dir(m_userDir);
    const QFileInfoList files =
        dir.entryInfoList({QStringLiteral("*.json")}, QDir::Files, QDir::Name | QDir::IgnoreCase);
    for (const QFileInfo& f : files) {
        const QString png = dir.filePath(f.completeBaseName() + QStringLiteral(".png"));
        out.append(
            {f.completeBaseName(), f.absoluteFilePath(), QFileInfo::exists(png) ? png : QString(), false});
    }
    for (PresetEntry& e : out)
        if (const RigReadResult r = read(e); r.ok()) e.shading = r.rig->shading.model;
    return out;
}

RigReadResult PresetStore::read(const PresetEntry& entry) const {
    return entry.builtin ? readBuiltinPreset(entry.name) : readRigFile(entry.path);
}

QString PresetStore::fileBaseName(const QString& name) {
    QString base = name.trimmed();
    base.replace(QRegularExpression(QStringLiteral("[\\\\/:*?\"<>|\\x00-\\x1f]")), QStringLiteral("_"));
    if (base.startsWith(QLatin1Char('.'))) base.prepend(QLatin1Char('_'));
    return base.left(120);
}

QString PresetStore::save(const QString& name, const Rig& rig, const QImage& thumbnail) {
    const QString base = fileBaseName(name);
    if (base.isEmpty()) return tr("A preset needs a name.");
    if (!QDir().mkpath(m_userDir)) return tr("%1: cannot create the presets folder").arg(m_userDir);
    Rig named = rig;
    named.name = name.trimmed();
    const QString path = QDir(m_userDir).filePath(base + QStringLiteral(".json"));
    QString error;
    if (!saveRigFile(named, path, &error)) return error;
    const QString png = QDir(m_userDir).filePath(base + QStringLiteral(".png"));
    if (!thumbnail.isNull()) {
        if (const QString reason = writeImageAtomically(thumbnail, png, "png"); !reason.isEmpty()) {
            emit changed();
            return tr("%1: could not write the thumbnail (the preset itself was saved): %2").arg(png, reason);
        }
    }
    emit changed();
    return {};
}

QString PresetStore::remove(const PresetEntry& entry) {
    if (entry.builtin) return tr("%1 is a built-in preset and cannot be deleted").arg(entry.name);
    if (!QFile::remove(entry.path)) return tr("%1: could not delete the file").arg(entry.path);
    if (!entry.thumbnail.isEmpty()) QFile::remove(entry.thumbnail);
    emit changed();
    return {};
}

} // namespace lr
