// `lightrig bench`'s path tier options (issue 36; render/tracebench.h): --quality …,path turns it on,
// --path-samples N (the ladder 1, 2, 4, 8, … N), --converged-samples N (the yardstick), --bounces B and
// --threads T of the path tracer.
#pragma once

#include "render/tracebench.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <optional>

namespace lr::cli {

struct PathBenchOptionSet {
    QCommandLineOption pathSamples, convergedSamples, bounces, threads;
    PathBenchOptionSet();
    void addTo(QCommandLineParser& parser) const;
    // The values (defaults where not set), or a usage error naming the option and the value. `path`:
    // whether --quality named the path tier (the options need it).
    std::optional<PathBenchOptions> read(const QCommandLineParser& parser, bool path, QString* error) const;
};

} // namespace lr::cli
