// `lightrig prefilter FILE... [--repeat N]`: the environment benchmark (issue 15). For each file (or
// builtin:NAME) one JSON line: its size, the decode time (the import worker's round trip, or in process
// for a bundled one), the prefilter time (median of N runs; envprefilter.h) and its CPU time over all
// threads (median; on the shared 2-core VM it still varied 3× with the load), the thread count, warnings.
#include "cli.h"

#include "model/environmentdecode.h"
#include "scene/envprefilter.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTextStream>
#include <QThreadPool>
#include <algorithm>
#include <ctime>

namespace lr::cli {

int runPrefilter(const QStringList& args) {
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Decodes environment images (.exr, .hdr or builtin:NAME) and times their prefiltering."));
    parser.addHelpOption();
    parser.addPositionalArgument(QStringLiteral("files"), QStringLiteral("Environment images."),
                                 QStringLiteral("FILE..."));
    const QCommandLineOption repeat(
        QStringLiteral("repeat"),
        QStringLiteral("Prefilter each image N times; report the median (default 3)."), QStringLiteral("N"),
        QStringLiteral("3"));
    parser.addOption(repeat);
    QTextStream out(stdout), err(stderr);
    if (!parser.parse(args)) {
        err << "lightrig prefilter: " << parser.errorText() << '\n';
        return Usage;
    }
    if (parser.isSet(QStringLiteral("help"))) {
        out << parser.helpText();
        return Ok;
    }
    bool ok = false;
    const int runs = parser.value(repeat).toInt(&ok);
    const QStringList files =
        parser.positionalArguments(); // args[0], the subcommand, is parsed as the program
    if (!ok || runs < 1 || runs > 1000) {
        err << "lightrig prefilter: --repeat: expected a whole number from 1 to 1000, got \""
            << parser.value(repeat) << "\"\n";
        return Usage;
    }
    if (files.isEmpty()) {
        err << "lightrig prefilter: expects at least one FILE (an .exr, .hdr or builtin:NAME)\n";
        return Usage;
    }
    int status = Ok;
    const QString prefix = QLatin1String(kBuiltinEnvironmentPrefix);
    for (const QString& file : files) {
        QElapsedTimer timer;
        timer.start();
        const EnvironmentDecodeResult decoded = file.startsWith(prefix)
                                                    ? decodeBuiltinEnvironment(file.mid(prefix.size()))
                                                    : importEnvironmentIsolated(file);
        const double decodeSeconds = double(timer.nsecsElapsed()) * 1e-9;
        if (!decoded.ok()) {
            err << "lightrig prefilter: " << decoded.error << '\n';
            status = Failed;
            continue;
        }
        std::vector<double> seconds, cpu;
        for (int i = 0; i < runs; ++i) {
            const std::clock_t start = std::clock(); // this process's CPU time, all threads
            seconds.push_back(prefilterEnvironment(decoded.image).seconds);
            cpu.push_back(double(std::clock() - start) / CLOCKS_PER_SEC);
        }
        std::sort(seconds.begin(), seconds.end());
        std::sort(cpu.begin(), cpu.end());
        QJsonObject line{{QStringLiteral("file"), file},
                         {QStringLiteral("width"), decoded.image.width},
                         {QStringLiteral("height"), decoded.image.height},
                         {QStringLiteral("decodeSeconds"), decodeSeconds},
                         {QStringLiteral("prefilterSeconds"), seconds[seconds.size() / 2]},
                         {QStringLiteral("prefilterMinSeconds"), seconds.front()},
                         {QStringLiteral("prefilterCpuSeconds"), cpu[cpu.size() / 2]},
                         {QStringLiteral("runs"), runs},
                         {QStringLiteral("threads"), QThreadPool::globalInstance()->maxThreadCount()},
                         {QStringLiteral("warnings"), QJsonArray::fromStringList(decoded.warnings)}};
        out << QJsonDocument(line).toJson(QJsonDocument::Compact) << '\n';
        out.flush();
    }
    return status;
}

} // namespace lr::cli
