#include "environmentoption.h"

#include "core/rigjson.h"
#include "scene/environmentloader.h"

#include <QDir>
#include <QFileInfo>
#include <cmath>
#include <limits>

namespace lr::cli {

EnvironmentOptionSet::EnvironmentOptionSet()
    : environment(
          QStringLiteral("environment"),
          QStringLiteral("Environment lighting, replacing the rig's: an .hdr or .exr file (relative to "
                         "the current folder), builtin:NAME (a bundled one), studio (the rig's "
                         "procedural studio) or none. Default: the rig's."),
          QStringLiteral("FILE|builtin:NAME|studio|none")),
      intensity(QStringLiteral("environment-intensity"),
                QStringLiteral("The environment's intensity in EV, -%1..%1: radiance x 2^EV (default: the "
                               "rig's).")
                    .arg(kMaxEnvironmentEV),
                QStringLiteral("EV")),
      rotation(QStringLiteral("environment-rotation"),
               QStringLiteral("Turns the environment about the up axis by DEG degrees, counter-clockwise "
                              "seen from above (default: the rig's)."),
               QStringLiteral("DEG")),
      background(QStringLiteral("environment-background"),
                 QStringLiteral("What the environment shows behind the model: %1 (color: the view's "
                                "background colour; default: the rig's).")
                     .arg(allowedNames<EnvironmentBackground>()),
                 QStringLiteral("MODE")) {}

QList<QCommandLineOption> EnvironmentOptionSet::options() const {
    return {environment, intensity, rotation, background};
}

std::optional<EnvironmentOverrides> EnvironmentOptionSet::read(const QCommandLineParser& p,
                                                               QString* usageError) const {
    EnvironmentOverrides o;
    auto bad = [&](const QString& message) {
        *usageError = message;
        return std::nullopt;
    };
    auto number = [&](const QCommandLineOption& option, double limit, const QString& what,
                      std::optional<double>* out) {
        if (!p.isSet(option)) return true;
        bool ok = false;
        const double v = p.value(option).toDouble(&ok);
        if (!ok || !std::isfinite(v) || std::abs(v) > limit) {
            *usageError = QStringLiteral("--%1 must be %2, got '%3'")
                              .arg(option.names().constFirst(), what, p.value(option));
            return false;
        }
        *out = v;
        return true;
    };
    if (p.isSet(environment)) {
        const QString v = p.value(environment);
        if (v.isEmpty())
            return bad(QStringLiteral("--environment needs a file, builtin:NAME, studio or none"));
        if (v == QLatin1String(kBuiltinEnvironmentPrefix))
            return bad(QStringLiteral("--environment %1 needs the name of a bundled environment after it, "
                                      "e.g. %1studio")
                           .arg(v));
        o.source = v;
    }
    if (!number(intensity, kMaxEnvironmentEV,
                QStringLiteral("a number of EV in -%1..%1").arg(kMaxEnvironmentEV), &o.intensity))
        return std::nullopt;
    if (!number(rotation, std::numeric_limits<double>::max(), QStringLiteral("a finite number of degrees"),
                &o.rotation))
        return std::nullopt;
    if (p.isSet(background)) {
        const auto b = fromString<EnvironmentBackground>(p.value(background));
        if (!b)
            return bad(QStringLiteral("--environment-background must be %1, got '%2'")
                           .arg(allowedNames<EnvironmentBackground>(), p.value(background)));
        o.background = *b;
    }
    return o;
}

QString environmentFileOf(const EnvironmentOverrides& o) {
    if (!o.source || *o.source == QLatin1String("none") || *o.source == QLatin1String("studio") ||
        o.source->startsWith(QLatin1String(kBuiltinEnvironmentPrefix)))
        return {};
    return *o.source;
}

void applyEnvironmentOverrides(Environment& e, const EnvironmentOverrides& o) {
    if (o.source) {
        if (*o.source == QLatin1String("none")) {
            e.source = EnvironmentSource::None;
        } else if (*o.source == QLatin1String("studio")) {
            e.source = EnvironmentSource::Studio;
        } else {
            e.source = EnvironmentSource::Image;
            e.file = o.source->startsWith(QLatin1String(kBuiltinEnvironmentPrefix))
                         ? *o.source
                         : QFileInfo(*o.source).absoluteFilePath();
        }
    }
    if (o.intensity) e.intensity = *o.intensity;
    if (o.rotation) e.rotation = normalizedEnvironmentRotation(*o.rotation);
    if (o.background) e.background = *o.background;
}

QString environmentFolder(const QString& rigPath) {
    if (rigPath.isEmpty() || rigPath.startsWith(QLatin1Char(':'))) return QDir::currentPath();
    return QFileInfo(rigPath).absolutePath();
}

bool loadCliEnvironment(const Environment& environment, const QString& rigFolder,
                        std::shared_ptr<const LoadedEnvironment>* loaded, QString* error) {
    if (*loaded && !environment.isNone() && environmentServes(**loaded, environment, rigFolder)) return true;
    loaded->reset();
    if (environment.isNone()) return true;
    EnvironmentLoadResult r = loadEnvironment(environment, rigFolder);
    if (!r.environment) {
        *error = r.error.isEmpty()
                     ? QStringLiteral("could not load the environment %1").arg(environmentName(environment))
                     : r.error;
        return false;
    }
    *loaded = std::move(r.environment);
    return true;
}

bool checkEnvironment(const Rig& rig, const QString& rigFile, RigReadResult* result) {
    if (rig.environment.isNone()) return true;
    const QString path = rig.environment.source == EnvironmentSource::Image
                             ? QStringLiteral("environment.file")
                             : QStringLiteral("environment");
    const EnvironmentLoadResult r = loadEnvironment(rig.environment, environmentFolder(rigFile));
    if (r.environment)
        for (const QString& w : r.environment->warnings)
            result->warnings << QStringLiteral("%1: %2: %3").arg(rigFile, path, w);
    if (r.environment) return true;
    result->errors << QStringLiteral("%1: %2: %3")
                          .arg(rigFile, path,
                               r.error.isEmpty() ? QStringLiteral("could not load the environment")
                                                 : r.error);
    return false;
}

QString environmentName(const Environment& e) {
    switch (e.source) {
    case EnvironmentSource::None:
        return {};
    case EnvironmentSource::Studio:
        return QStringLiteral("studio environment");
    case EnvironmentSource::Image:
        break;
    }
    return QStringLiteral("environment ") + e.file;
}

QString environmentTimes(const LoadedEnvironment& loaded) {
    return QStringLiteral("decoded in %1 s, prefiltered in %2 s")
        .arg(loaded.decodeSeconds, 0, 'f', 3)
        .arg(loaded.prefiltered.seconds, 0, 'f', 3);
}

} // namespace lr::cli
