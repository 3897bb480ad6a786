#include "lightassets.h"

#include "model/gobodecode.h"

#include <QDateTime>
#include <QFileInfo>
#include <QMutex>
#include <map>
#include <tuple>

namespace lr {

namespace {

// Key: the path, its size and modification time (an edited file is read again).
using FileKey = std::tuple<QString, qint64, qint64>;

FileKey keyOf(const QString& path) {
    const QFileInfo info(path);
    return {path, info.exists() ? info.size() : -1,
            info.exists() ? info.lastModified().toMSecsSinceEpoch() : -1};
}

template <typename T, typename Load>
std::shared_ptr<const T> cached(std::map<FileKey, std::shared_ptr<const T>>& cache, const QString& path,
                                Load load, QString* error) {
    static QMutex mutex;
    const FileKey key = keyOf(path);
    {
        QMutexLocker lock(&mutex);
        if (auto it = cache.find(key); it != cache.end()) return it->second;
    }
    std::shared_ptr<const T> value = load(path, error);
    if (value) {
        QMutexLocker lock(&mutex);
        cache[key] = value;
    }
    return value;
}

QString pathOf(const QString& file, const QString& resolved) {
    return resolved.isEmpty() ? file : resolved;
}

} // namespace

bool LightAssets::anyIes() const {
    for (const auto& p : ies)
        if (p) return true;
    return false;
}

bool LightAssets::anyGobo() const {
    for (const auto& g : gobos)
        if (g) return true;
    return false;
}

LightAssets loadLightAssets(const Rig& rig) {
    static std::map<FileKey, std::shared_ptr<const IesProfile>> iesCache;
    static std::map<FileKey, std::shared_ptr<const GoboImage>> goboCache;
    LightAssets a;
    a.ies.resize(rig.lights.size());
    a.gobos.resize(rig.lights.size());
    for (size_t i = 0; i < rig.lights.size(); ++i) {
        const Light& l = rig.lights[i];
        QString error;
        if (l.ies) {
            a.ies[i] = cached(iesCache, pathOf(l.ies->file, l.ies->resolved), readIesFile, &error);
            if (!a.ies[i]) a.errors << QStringLiteral("lights[%1].ies.file: %2").arg(i).arg(error);
        }
        if (l.gobo) {
            error.clear();
            a.gobos[i] = cached(goboCache, pathOf(l.gobo->file, l.gobo->resolved), decodeGoboImage, &error);
            if (!a.gobos[i]) a.errors << QStringLiteral("lights[%1].gobo.file: %2").arg(i).arg(error);
        }
    }
    return a;
}

bool sameLightFiles(const Rig& a, const Rig& b) {
    if (a.lights.size() != b.lights.size()) return false;
    for (size_t i = 0; i < a.lights.size(); ++i) {
        const Light& x = a.lights[i];
        const Light& y = b.lights[i];
        const auto iesPath = [](const Light& l) {
            return l.ies ? pathOf(l.ies->file, l.ies->resolved) : QString();
        };
        const auto goboPath = [](const Light& l) {
            return l.gobo ? pathOf(l.gobo->file, l.gobo->resolved) : QString();
        };
        if (bool(x.ies) != bool(y.ies) || bool(x.gobo) != bool(y.gobo) || iesPath(x) != iesPath(y) ||
            goboPath(x) != goboPath(y))
            return false;
    }
    return true;
}

} // namespace lr
