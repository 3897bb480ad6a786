// The environment on the command line (issue 15; docs/rig-format.md "environment"), shared by `lightrig
// render` and `bench` through sceneoptions.h, and `validate`'s check that a rig's environment loads:
//   --environment FILE|builtin:NAME|studio|none   replaces the rig's environment source (FILE relative to
//                                                 the current folder; studio: the rig's studio settings)
//   --environment-intensity EV (-20 ... 20)   --environment-rotation DEGREES   --environment-background
//   visible|blurred|color                         override the rig's values
#pragma once

#include "core/rig.h"
#include "core/rigjson.h"
#include "scene/environmentloader.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QList>
#include <QString>
#include <memory>
#include <optional>

namespace lr::cli {

struct EnvironmentOverrides {
    std::optional<QString> source; // --environment as given: a file, "builtin:NAME", "studio" or "none"
    std::optional<double> intensity, rotation;
    std::optional<EnvironmentBackground> background;
};

struct EnvironmentOptionSet {
    QCommandLineOption environment, intensity, rotation, background;
    EnvironmentOptionSet();
    QList<QCommandLineOption> options() const;
    // The parsed values, or a usage error naming the option and the reason (exit 2).
    std::optional<EnvironmentOverrides> read(const QCommandLineParser& parser, QString* usageError) const;
};

// The overrides applied to a rig's environment. A FILE is made absolute against the current folder, so
// that it is not resolved against the rig's folder; "studio" keeps the rig's studio settings (lr::Studio's
// defaults when it has none); every other setting of the rig (spots included) is kept.
void applyEnvironmentOverrides(Environment& environment, const EnvironmentOverrides& overrides);

// The file --environment names, or empty for builtin:NAME, studio, none or no --environment (the files a
// command reads, outputfiles.h checkDistinctFiles).
QString environmentFileOf(const EnvironmentOverrides& overrides);

// Where a rig's relative environment file is found: the rig file's folder, or the current folder for a
// rig that is not a file (the default rule's, a built-in preset).
QString environmentFolder(const QString& rigPath);

// Decodes and prefilters the environment (scene/environmentloader.h). *loaded stays null for source none.
// False with the loader's reason, which names the file, on failure. An environment *loaded already holds is
// kept when it serves (environmentServes): render's catalogs load a rig's environment once, not per model.
bool loadCliEnvironment(const Environment& environment, const QString& rigFolder,
                        std::shared_ptr<const LoadedEnvironment>* loaded, QString* error);

// `lightrig validate`: whether the rig's environment loads (its image decodes), resolved against the rig
// file's folder. On failure the loader's reason is added to result->errors ("FILE: environment.file: could
// not read ..."), and its warnings to result->warnings in any case; false on failure.
bool checkEnvironment(const Rig& rig, const QString& rigFile, RigReadResult* result);

// How the summary lines name it: "studio environment", "environment builtin:studio", "environment
// /abs/sky.exr"; empty for none.
QString environmentName(const Environment& environment);
// "decoded in 0.12 s, prefiltered in 0.34 s" for a loaded environment.
QString environmentTimes(const LoadedEnvironment& loaded);

} // namespace lr::cli
