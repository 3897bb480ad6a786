// Temporary: subcommands whose implementation has not landed yet. Each helper deletes its line here.
#include "cli.h"
#include <QTextStream>
namespace lr::cli {
static int pending(const char* what) { QTextStream(stderr) << "lightrig: " << what << " is not implemented yet\n"; return Failed; }
int runBench(const QStringList&) { return pending("bench"); }
}
