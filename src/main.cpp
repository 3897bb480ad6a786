// lightrig: a subcommand (validate, format, render, bench) when argv[1] names one, else the editor.
#include "app/editorapp.h"
#include "cli/cli.h"
#include "core/hugepages.h"

int main(int argc, char** argv) {
    lr::reexecWithHugePages(argv); // returns in the process that has the tunable (core/hugepages.h)
    const QString sub = lr::cli::subcommandOf(argc, argv);
    if (!sub.isEmpty()) return lr::cli::run(sub, argc, argv);
    return lr::runEditor(argc, argv);
}
