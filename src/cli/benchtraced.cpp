#include "benchtraced.h"

namespace lr::cli {

PathBenchOptionSet::PathBenchOptionSet()
    : pathSamples(QStringLiteral("path-samples"),
                  QStringLiteral("Path tier: the largest of the sample counts 1, 2, 4, 8, … whose image is "
                                 "compared with the converged one, 1..65536 (default 64)."),
                  QStringLiteral("N")),
      convergedSamples(QStringLiteral("converged-samples"),
                       QStringLiteral("Path tier: samples per pixel of the converged path-traced image every "
                                      "tier is compared with, once per scene, 1..1000000 (default 256)."),
                       QStringLiteral("N")),
      bounces(QStringLiteral("bounces"),
              QStringLiteral("Path tier: surface interactions per path, 0..1024 (default 8)."),
              QStringLiteral("B")),
      threads(QStringLiteral("threads"),
              QStringLiteral("Path tier: worker threads, 1..1024 (default: every core)."),
              QStringLiteral("T")) {}

void PathBenchOptionSet::addTo(QCommandLineParser& parser) const {
    parser.addOptions({pathSamples, convergedSamples, bounces, threads});
}

std::optional<PathBenchOptions> PathBenchOptionSet::read(const QCommandLineParser& parser, bool path,
                                                         QString* error) const {
    PathBenchOptions o;
    const auto number = [&](const QCommandLineOption& option, int lo, int hi, int* value) {
        if (!parser.isSet(option)) return true;
        const QString name = option.names().constLast();
        if (!path) {
            *error = QStringLiteral("--%1 needs the path tier (--quality ...,path)").arg(name);
            return false;
        }
        bool ok = false;
        const int v = parser.value(option).toInt(&ok);
        if (!ok || v < lo || v > hi) {
            *error = QStringLiteral("--%1 must be a whole number in %2..%3, got '%4'")
                         .arg(name)
                         .arg(lo)
                         .arg(hi)
                         .arg(parser.value(option));
            return false;
        }
        *value = v;
        return true;
    };
    if (!number(pathSamples, 1, 65536, &o.samples) ||
        !number(convergedSamples, 1, 1000000, &o.convergedSamples) || !number(bounces, 0, 1024, &o.bounces) ||
        !number(threads, 1, 1024, &o.threads))
        return std::nullopt;
    return o;
}

} // namespace lr::cli
