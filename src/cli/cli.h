// Command-line subcommands. Each lives in its own file and returns the process exit code:
// 0 success, 1 failure of the work (bad file, ...), 2 usage error.
#pragma once

#include <QStringList>
#include <optional>

class QCommandLineOption;
class QCommandLineParser;
class QTextStream;

namespace lr::cli {

enum ExitCode { Ok = 0, Failed = 1, Usage = 2 };

// The subcommand named by argv[1], or an empty string when the editor should start.
QString subcommandOf(int argc, char** argv);

// Runs a subcommand with a QGuiApplication or QCoreApplication of its own; `args` excludes argv[0].
int run(const QString& subcommand, int argc, char** argv);

// False when a GUI subcommand started without DISPLAY/WAYLAND_DISPLAY/QT_QPA_PLATFORM (it then runs on
// the offscreen platform, which has no OpenGL here): it should fail with "needs an X display".
bool displayAvailable();

// A subcommand's name and usage line, for its usage errors and its --help (render, bench, compare, export).
struct CommandUsage {
    QString name;     // "lightrig render"
    const char* line; // the usage line
    QTextStream& out; // the command's own streams, so that what it prints stays in order
    QTextStream& err;
    // "NAME: message", the usage line and "Try 'NAME --help'." on err; returns Usage.
    int operator()(const QString& message) const;
    // Parses args: a parse error is a usage error, --help prints the help with the usage line first and
    // returns Ok; nullopt when the command goes on.
    std::optional<int> parse(QCommandLineParser& parser, const QStringList& args,
                             const QCommandLineOption& help) const;
};

int runValidate(const QStringList& args);     // validate.cpp
int runFormat(const QStringList& args);       // validate.cpp
int runRender(const QStringList& args);       // render.cpp
int runBench(const QStringList& args);        // bench.cpp
int runImportWorker(const QStringList& args); // importworker.cpp (hidden, see model/isolatedimport.h)

} // namespace lr::cli
