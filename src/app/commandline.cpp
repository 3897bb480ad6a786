#include "commandline.h"

#include <QCommandLineParser>
#include <QCoreApplication>
#include <QFileInfo>

namespace lr {

CommandLineResult parseEditorCommandLine(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "lightrig", "LightRig: design light rigs on 3D models.\n"
                    "Subcommands: validate, format, render, bench (lightrig SUBCOMMAND --help)."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("MODEL"),
        QCoreApplication::translate("lightrig", "A model file to open (glTF, OBJ, FBX, ...)."),
        QStringLiteral("[MODEL]"));
    const QCommandLineOption rig(QStringList{QStringLiteral("r"), QStringLiteral("rig")},
                                 QCoreApplication::translate("lightrig", "A rig file (.json) to open."),
                                 QStringLiteral("RIG"));
    const QCommandLineOption noRestore(
        QStringLiteral("no-restore"),
        QCoreApplication::translate("lightrig", "Do not reopen the last session's files."));
    QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QCoreApplication::translate("lightrig", "Grab the window to OUT.png and quit."),
        QStringLiteral("OUT.png"));
    screenshot.setFlags(QCommandLineOption::HiddenFromHelp);
    parser.addOptions({rig, noRestore, screenshot});

    CommandLineResult result;
    if (!parser.parse(args)) {
        result.message = parser.errorText() + QStringLiteral("\n\n") + parser.helpText();
        result.exitCode = 2;
        return result;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        result.message = parser.helpText();
        return result;
    }
    if (parser.isSet(QStringLiteral("version"))) {
        result.message = QCoreApplication::applicationName() + QLatin1Char(' ') +
                         QCoreApplication::applicationVersion() + QLatin1Char('\n');
        return result;
    }
    const QStringList positional = parser.positionalArguments();
    // A mistyped subcommand ("lightrig valdiate f.json") would otherwise open the editor on a model of
    // that name, which headless looks like a hang.
    if (!positional.isEmpty() && !QFileInfo::exists(positional.first())) {
        result.message = QCoreApplication::translate(
                             "lightrig", "lightrig: '%1' is neither a subcommand (%2) nor an existing model "
                                         "file\nTry 'lightrig --help' or 'lightrig SUBCOMMAND --help'.\n")
                             .arg(positional.first(), QStringLiteral("validate, format, render, bench"));
        result.exitCode = 2;
        return result;
    }
    if (positional.size() > 1) {
        result.message =
            QCoreApplication::translate("lightrig", "lightrig: expected at most one MODEL, got %1\n\n%2")
                .arg(positional.size())
                .arg(parser.helpText());
        result.exitCode = 2;
        return result;
    }
    EditorOptions o;
    if (!positional.isEmpty()) o.modelPath = positional.first();
    o.rigPath = parser.value(rig);
    o.screenshotPath = parser.value(screenshot);
    if (o.screenshotPath.isEmpty()) o.screenshotPath = qEnvironmentVariable("LIGHTRIG_SCREENSHOT");
    o.restoreSession = !parser.isSet(noRestore) && o.screenshotPath.isEmpty();
    result.options = o;
    return result;
}

} // namespace lr
