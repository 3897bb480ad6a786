// lightrig: a subcommand (validate, format, render, bench) when argv[1] names one, else the editor.
#include "app/editorapp.h"
#include "cli/cli.h"
#include "core/hugepages.h"

#include <csignal>

int main(int argc, char** argv) {
    lr::reexecWithHugePages(argv); // returns in the process that has the tunable (core/hugepages.h)
    // A write to a pipe whose reader is gone (an import worker that exited early, a closed stdout) fails
    // with EPIPE instead of killing LightRig (issue 41: `render` died of SIGPIPE once in 5,200 renders).
    // QProcess ignores SIGPIPE around its own writes only by swapping the process's handler in and out,
    // which races when two threads run workers at once (a model and its environment decode together).
    std::signal(SIGPIPE, SIG_IGN);
    const QString sub = lr::cli::subcommandOf(argc, argv);
    if (!sub.isEmpty()) return lr::cli::run(sub, argc, argv);
    return lr::runEditor(argc, argv);
}
