// Command-line subcommands. Each lives in its own file and returns the process exit code:
// 0 success, 1 failure of the work (bad file, ...), 2 usage error.
#pragma once

#include <QStringList>

namespace lr::cli {

enum ExitCode { Ok = 0, Failed = 1, Usage = 2 };

// The subcommand named by argv[1], or an empty string when the editor should start.
QString subcommandOf(int argc, char** argv);

// Runs a subcommand with a QGuiApplication or QCoreApplication of its own; `args` excludes argv[0].
int run(const QString& subcommand, int argc, char** argv);

// False when a GUI subcommand started without DISPLAY/WAYLAND_DISPLAY/QT_QPA_PLATFORM (it then runs on
// the offscreen platform, which has no OpenGL here): it should fail with "needs an X display".
bool displayAvailable();

int runValidate(const QStringList& args);     // validate.cpp
int runFormat(const QStringList& args);       // validate.cpp
int runRender(const QStringList& args);       // render.cpp
int runBench(const QStringList& args);        // bench.cpp
int runImportWorker(const QStringList& args); // importworker.cpp (hidden, see model/isolatedimport.h)

} // namespace lr::cli
