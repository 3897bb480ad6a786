#include "environmentloader.h"

#include "envprefilter.h"

#include <QElapsedTimer>

namespace lr {

// PLACEHOLDER (issue 15 integration): the studio only; image decoding lands with the worker's codec.
EnvironmentLoadResult loadEnvironment(const Environment& spec, const QString& rigFolder) {
    Q_UNUSED(rigFolder);
    EnvironmentLoadResult r;
    if (spec.source == EnvironmentSource::None) return r;
    auto env = std::make_shared<LoadedEnvironment>();
    env->spec = spec;
    if (spec.source == EnvironmentSource::Studio) {
        env->source = QStringLiteral("studio");
        env->image = environment::renderStudio(spec.studio);
    } else {
        r.error =
            QStringLiteral("could not read %1: image environments are not supported yet").arg(spec.file);
        return r;
    }
    environment::applySpots(&env->image, spec.spots);
    env->prefiltered = prefilterEnvironment(env->image);
    r.environment = std::move(env);
    return r;
}

} // namespace lr
