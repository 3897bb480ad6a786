#include "environmentloader.h"

#include "envprefilter.h"
#include "model/environmentdecode.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QtConcurrent/QtConcurrentRun>

namespace lr {

QString resolveEnvironmentFile(const QString& file, const QString& rigFolder) {
    if (file.startsWith(QLatin1String(kBuiltinEnvironmentPrefix)) || file.isEmpty()) return file;
    if (QFileInfo(file).isAbsolute()) return QDir::cleanPath(file);
    return QDir::cleanPath(
        QDir(rigFolder.isEmpty() ? QDir::currentPath() : rigFolder).absoluteFilePath(file));
}

EnvironmentLoad::EnvironmentLoad(const Environment& spec, const QString& rigFolder)
    : m_spec(spec), m_rigFolder(rigFolder) {}

QFuture<EnvironmentLoadResult> EnvironmentLoad::start() {
    if (!m_future.isValid())
        m_future = QtConcurrent::run(
            [spec = m_spec, folder = m_rigFolder] { return loadEnvironment(spec, folder); });
    return m_future;
}

EnvironmentLoadResult EnvironmentLoad::result() {
    return start().result();
}

std::shared_ptr<const LoadedEnvironment> EnvironmentLoad::loaded() const {
    return m_future.isValid() && m_future.isFinished() ? m_future.result().environment : nullptr;
}

std::shared_ptr<const LoadedEnvironment> loadedEnvironment(const std::shared_ptr<EnvironmentLoad>& load,
                                                           std::shared_ptr<const LoadedEnvironment> loaded) {
    return load ? load->loaded() : loaded;
}

bool environmentServes(const LoadedEnvironment& loaded, const Environment& spec, const QString& rigFolder) {
    return loaded.spec.sameRadiance(spec) && (spec.source != EnvironmentSource::Image ||
                                              loaded.source == resolveEnvironmentFile(spec.file, rigFolder));
}

EnvironmentLoadResult loadEnvironment(const Environment& spec, const QString& rigFolder) {
    EnvironmentLoadResult r;
    if (spec.source == EnvironmentSource::None) return r;
    auto env = std::make_shared<LoadedEnvironment>();
    env->spec = spec;
    if (spec.source == EnvironmentSource::Studio) {
        env->source = QStringLiteral("studio");
        env->image = environment::renderStudio(spec.studio);
    } else {
        const QString& written = spec.file;
        if (written.isEmpty()) {
            r.error = QStringLiteral("could not read the environment image: the rig names no file");
            return r;
        }
        const QString prefix = QLatin1String(kBuiltinEnvironmentPrefix);
        env->source = resolveEnvironmentFile(written, rigFolder);
        QElapsedTimer timer;
        timer.start();
        EnvironmentDecodeResult decoded = written.startsWith(prefix)
                                              ? decodeBuiltinEnvironment(written.mid(prefix.size()))
                                              : importEnvironmentIsolated(env->source);
        env->decodeSeconds = double(timer.nsecsElapsed()) * 1e-9;
        if (!decoded.ok()) {
            const QString where =
                env->source == written ? written : QStringLiteral("%1 (%2)").arg(written, env->source);
            r.error = QStringLiteral("could not read %1: %2")
                          .arg(where, decoded.reason.isEmpty() ? decoded.error : decoded.reason);
            return r;
        }
        env->image = std::move(decoded.image);
        env->warnings = decoded.warnings;
    }
    environment::applySpots(&env->image, spec.spots);
    env->prefiltered = prefilterEnvironment(env->image);
    r.environment = std::move(env);
    return r;
}

} // namespace lr
