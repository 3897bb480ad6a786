#include "lightshaping.h"

#include "rig.h"

#include <QDir>
#include <QFileInfo>

namespace lr {

QString resolveRigRelative(const QString& file, const QString& rigFolder) {
    if (file.isEmpty()) return {};
    if (QFileInfo(file).isAbsolute()) return QDir::cleanPath(file);
    const QString folder = rigFolder.isEmpty() ? QDir::currentPath() : rigFolder;
    return QDir::cleanPath(QDir(folder).absoluteFilePath(file));
}

void resolveLightFiles(Rig& rig, const QString& rigFolder) {
    for (Light& light : rig.lights) {
        if (light.ies) light.ies->resolved = resolveRigRelative(light.ies->file, rigFolder);
        if (light.gobo) light.gobo->resolved = resolveRigRelative(light.gobo->file, rigFolder);
    }
}

} // namespace lr
