// The path tracer's options (issue 36), one definition for every command that traces: `lightrig render
// --quality path` and `lightrig compare --quality path` (`bench`'s path tier has its own ladder options,
// benchtraced.h). Each option needs --quality path; a bad value is a usage error naming the option, the
// accepted range and the value given.
#pragma once

#include "rendertraced.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <optional>

namespace lr::cli {

struct TracedOptionSet {
    QCommandLineOption samples, timeLimit, noiseThreshold, bounces, threads, fireflyClamp, seed;
    TracedOptionSet();
    void addTo(QCommandLineParser& parser) const;
    // The values (defaults where not set; with --time-limit or --noise-threshold and no --samples, the
    // sample target is 1,000,000), or nullopt and the usage error. `path`: whether --quality path was given.
    std::optional<TracedRenderOptions> read(const QCommandLineParser& parser, bool path,
                                            QString* error) const;
};

// A whole number in [lo, hi] from an option's value, or nullopt and the usage message naming the option.
std::optional<int> wholeNumber(const QCommandLineParser& parser, const QCommandLineOption& option, int lo,
                               int hi, QString* message);

} // namespace lr::cli
