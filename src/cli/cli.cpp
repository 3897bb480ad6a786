#include "cli.h"

#include "sceneoptions.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QTextStream>
#include <memory>

namespace lr::cli {

int runPrefilter(const QStringList& args); // prefilter.cpp (issue 15)
int runCompare(const QStringList& args);   // compare.cpp (issue 17)
int runExport(const QStringList& args);    // export.cpp (issue 17)
int runMix(const QStringList& args);       // mix.cpp (issue 37)

namespace {
bool g_displayAvailable = true;
struct Subcommand {
    const char* name;
    int (*fn)(const QStringList&);
    bool needsGui; // renders with OpenGL: needs a QGuiApplication (and a display, e.g. xvfb-run)
};
const Subcommand kSubcommands[] = {
    {"validate", runValidate, false},
    {"format", runFormat, false},
    {"render", runRender, true},
    {"bench", runBench, true},
    {"import-worker", runImportWorker, false}, // hidden: model/isolatedimport.h runs it
    {"prefilter", runPrefilter, false},
    {"compare", runCompare, true},
    {"export", runExport, false},
    {"mix", runMix, false},
};
} // namespace

int CommandUsage::operator()(const QString& message) const {
    err << name << ": " << message << "\nUsage: " << line << "\nTry '" << name << " --help'.\n";
    return Usage;
}

std::optional<int> CommandUsage::parse(QCommandLineParser& parser, const QStringList& args,
                                       const QCommandLineOption& help) const {
    if (!parser.parse(args)) return (*this)(parser.errorText());
    if (!parser.isSet(help)) return std::nullopt;
    QString text = parser.helpText();
    text.replace(0, text.indexOf(QLatin1Char('\n')), QStringLiteral("Usage: ") + QLatin1String(line));
    out << text;
    return Ok;
}

bool displayAvailable() {
    return g_displayAvailable;
}

QString subcommandOf(int argc, char** argv) {
    if (argc < 2) return {};
    const QString first = QString::fromLocal8Bit(argv[1]);
    for (const Subcommand& s : kSubcommands)
        if (first == QLatin1String(s.name)) return first;
    return {};
}

int run(const QString& subcommand, int argc, char** argv) {
    for (const Subcommand& s : kSubcommands) {
        if (subcommand != QLatin1String(s.name)) continue;
        std::unique_ptr<QCoreApplication> app;
        if (s.needsGui) {
            // Without a display the xcb platform aborts inside QGuiApplication's constructor: start on the
            // offscreen platform instead, so the subcommand can still parse its arguments and say why it
            // cannot render (displayAvailable()).
            g_displayAvailable = haveDisplay();
            if (!g_displayAvailable) qputenv("QT_QPA_PLATFORM", "offscreen");
            // bench: first frames pay a real shader compile, not a hit in Mesa's on-disk cache (read when
            // the display connection is opened, so set here). MESA_SHADER_CACHE_DISABLE=false keeps it.
            if (subcommand == QLatin1String("bench") &&
                !qEnvironmentVariableIsSet("MESA_SHADER_CACHE_DISABLE"))
                qputenv("MESA_SHADER_CACHE_DISABLE", "true");
            app = std::make_unique<QGuiApplication>(argc, argv);
        } else {
            app = std::make_unique<QCoreApplication>(argc, argv);
        }
        QCoreApplication::setApplicationName(QStringLiteral("lightrig"));
        QStringList args = QCoreApplication::arguments();
        args.removeFirst(); // program
        return s.fn(args);  // args[0] is the subcommand name
    }
    QTextStream(stderr) << "lightrig: unknown command " << subcommand << '\n';
    return Usage;
}

} // namespace lr::cli
