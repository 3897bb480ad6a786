// `lightrig validate FILE...` and `lightrig format [--check] FILE...`: the rig file reader and canonical
// writer (core/rigjson.h) on the command line. Exit codes: 0 all good, 1 a file is invalid (or, for
// format, not canonical / not writable), 2 usage error.
#include "cli.h"
#include "environmentoption.h"

#include "core/ies.h"
#include "core/rigjson.h"

#include <QCommandLineParser>
#include <QFile>
#include <QTextStream>

namespace lr::cli {

namespace {

// Parses `args` (args[0] is the subcommand). Returns -1 to go on, else the exit code to return.
int parse(QCommandLineParser& parser, const QStringList& args, const QString& usage, const QString& about) {
    parser.setApplicationDescription(about);
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Show this help."));
    parser.addOption(help);
    parser.addPositionalArgument(QStringLiteral("FILE"), QStringLiteral("Rig files (.json)."),
                                 QStringLiteral("FILE..."));
    QTextStream err(stderr);
    const QString name = QStringLiteral("lightrig ") + args.value(0);
    if (!parser.parse(args)) {
        err << name << ": " << parser.errorText() << "\nTry '" << name << " --help'.\n";
        return Usage;
    }
    if (parser.isSet(help)) {
        QString text = parser.helpText();
        text.replace(0, text.indexOf(QLatin1Char('\n')), QStringLiteral("Usage: ") + usage);
        QTextStream(stdout) << text;
        return Ok;
    }
    if (parser.positionalArguments().isEmpty()) {
        err << name << ": no files given\nUsage: " << usage << "\nTry '" << name << " --help'.\n";
        return Usage;
    }
    return -1;
}

void print(QTextStream& out, const QStringList& lines) {
    for (const QString& l : lines)
        out << l << '\n';
}

// "FILE: path: reason" -> "FILE: warning: path: reason", so warnings after "FILE: ok" read as such.
void printWarnings(QTextStream& out, const QString& file, const QStringList& warnings) {
    for (const QString& w : warnings)
        out << (w.startsWith(file + QStringLiteral(": "))
                    ? file + QStringLiteral(": warning: ") + w.mid(file.size() + 2)
                    : w)
            << '\n';
}

} // namespace

// Issue 39: every IES profile the rig names reads ("FILE: lights[i].ies.file: IESFILE:LINE: reason").
bool checkIesFiles(const Rig& rig, const QString& file, RigReadResult* r) {
    for (size_t i = 0; i < rig.lights.size(); ++i) {
        const std::optional<IesSpec>& ies = rig.lights[i].ies;
        QString error;
        if (ies && !readIesFile(ies->resolved.isEmpty() ? ies->file : ies->resolved, &error))
            r->errors << QStringLiteral("%1: lights[%2].ies.file: %3").arg(file).arg(i).arg(error);
    }
    return r->errors.isEmpty();
}

int runValidate(const QStringList& args) {
    QCommandLineParser parser;
    if (const int rc =
            parse(parser, args, QStringLiteral("lightrig validate [options] FILE..."),
                  QStringLiteral("Checks LightRig rig files (docs/rig-format.md) and lists every error "
                                 "as\nFILE: json.path: reason. Prints FILE: ok for a valid file, then "
                                 "its warnings\n(FILE: warning: json.path: reason, e.g. unknown keys).\n"
                                 "Exit status: 0 all files are valid, 1 a file is not, 2 usage error."));
        rc >= 0)
        return rc;
    QTextStream out(stdout);
    int rc = Ok;
    for (const QString& file : parser.positionalArguments()) {
        RigReadResult r = readRigFile(file);
        // Issue 15: its environment decodes; issue 39: its IES profiles read (both report).
        const bool filesOk = r.ok() && checkEnvironment(*r.rig, file, &r) && checkIesFiles(*r.rig, file, &r);
        if (r.ok() && !filesOk) {
            print(out, r.errors);
            rc = Failed;
        } else if (r.ok()) {
            out << file << ": ok\n";
        } else {
            print(out, r.errors);
            rc = Failed;
        }
        printWarnings(out, file, r.warnings);
    }
    return rc;
}

int runFormat(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption check(
        QStringLiteral("check"),
        QStringLiteral("Change nothing; exit with 1 if a file is not in canonical form."));
    parser.addOption(check);
    if (const int rc =
            parse(parser, args, QStringLiteral("lightrig format [--check] FILE..."),
                  QStringLiteral("Rewrites valid rig files in the canonical form (stable key order, only "
                                 "the fields\neach light uses, shortest exact numbers), atomically. "
                                 "Invalid files and files with\nunknown keys are left alone.\nExit "
                                 "status: 0 done, 1 a file is invalid, not canonical (--check) or not "
                                 "writable,\n2 usage error."));
        rc >= 0)
        return rc;
    QTextStream out(stdout);
    int rc = Ok;
    for (const QString& file : parser.positionalArguments()) {
        const RigReadResult r = readRigFile(file);
        print(out, r.errors);
        printWarnings(out, file, r.warnings);
        if (!r.ok()) {
            rc = Failed;
            continue;
        }
        QFile in(file);
        const QByteArray current =
            in.open(QIODevice::ReadOnly) ? in.read(kMaxRigFileBytes + 1) : QByteArray();
        const QByteArray canonical = writeRigJson(*r.rig);
        if (current == canonical) {
            out << file << ": ok (canonical)\n";
        } else if (parser.isSet(check)) {
            out << file << ": not in canonical form (run: lightrig format " << file << ")\n";
            rc = Failed;
        } else if (!r.warnings.isEmpty()) {
            out << file
                << ": not formatted: formatting would drop the unknown keys above; remove them first\n";
            rc = Failed;
        } else if (QString error; !saveRigFile(*r.rig, file, &error)) {
            out << error << '\n';
            rc = Failed;
        } else {
            out << file << ": formatted\n";
        }
    }
    return rc;
}

} // namespace lr::cli
