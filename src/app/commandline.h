// The editor's command line: `lightrig [MODEL] [--rig RIG]`, plus the hidden `--screenshot OUT.png`
// (or LIGHTRIG_SCREENSHOT=OUT.png) used to take the README screenshot under Xvfb.
#pragma once

#include <QString>
#include <QStringList>
#include <optional>

namespace lr {

struct EditorOptions {
    QString modelPath; // empty: the last session's model, else the bundled one
    QString rigPath;   // empty: the last session's rig file, else the default preset
    QString
        screenshotPath; // non-empty: open, select a spot light, grab the window after the first frame, quit
    bool restoreSession = true; // false with --no-restore (and in screenshot mode): defaults only
};

struct CommandLineResult {
    std::optional<EditorOptions> options; // nullopt: exit with exitCode after printing message
    QString message;                      // help, version or a usage error
    int exitCode = 0;
};

// args includes the program name (QCoreApplication::arguments()). Needs a QCoreApplication for help texts.
CommandLineResult parseEditorCommandLine(const QStringList& args);

} // namespace lr
