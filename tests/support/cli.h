// Running the built `lightrig` executable as a user would (QProcess), for the tests of the subcommands.
#pragma once

#include <QProcessEnvironment>
#include <QString>
#include <QStringList>

namespace lrtest {

struct CliRun {
    int code = -1; // the exit code; -1 when it crashed or did not finish in time
    QString out, err;
    QStringList lines() const { return out.split(QLatin1Char('\n'), Qt::SkipEmptyParts); }
    // Ours, without platform chatter such as XDG_RUNTIME_DIR notes: the stderr lines starting "lightrig".
    QStringList errorLines() const;
    QString show() const; // "exit N\nstdout:\n...\nstderr:\n..." for failure messages
};

QString lightrigExecutable(); // the build's lightrig (LIGHTRIG_EXECUTABLE)

// `lightrig ARGS...` with `env` (the test's own environment when null), waiting up to timeoutMs; a run that
// does not finish is killed and reads as code -1.
CliRun runLightrig(const QStringList& args, const QProcessEnvironment* env = nullptr, int timeoutMs = 120000);
// The same for any program (a shell that sets limits before it runs lightrig, say).
CliRun runProgram(const QString& program, const QStringList& args, const QProcessEnvironment* env = nullptr,
                  int timeoutMs = 120000);

// The test's environment without a display (DISPLAY, WAYLAND_DISPLAY, QT_QPA_PLATFORM removed).
QProcessEnvironment environmentWithoutDisplay();
bool haveDisplay(); // DISPLAY or WAYLAND_DISPLAY is set

} // namespace lrtest
