#include "support/cli.h"

#include <QProcess>

namespace lrtest {

QStringList CliRun::errorLines() const {
    QStringList lines;
    for (const QString& l : err.split(QLatin1Char('\n'), Qt::SkipEmptyParts))
        if (l.startsWith(QLatin1String("lightrig"))) lines << l;
    return lines;
}

QString CliRun::show() const {
    return QStringLiteral("exit %1\nstdout:\n%2\nstderr:\n%3").arg(code).arg(out, err);
}

QString lightrigExecutable() {
    return QStringLiteral(LIGHTRIG_EXECUTABLE);
}

CliRun runLightrig(const QStringList& args, const QProcessEnvironment* env, int timeoutMs) {
    return runProgram(lightrigExecutable(), args, env, timeoutMs);
}

CliRun runProgram(const QString& program, const QStringList& args, const QProcessEnvironment* env,
                  int timeoutMs) {
    QProcess p;
    p.setProgram(program);
    p.setArguments(args);
    if (env) p.setProcessEnvironment(*env);
    p.start();
    CliRun r;
    if (!p.waitForFinished(timeoutMs)) {
        p.kill();
        p.waitForFinished();
    } else if (p.exitStatus() == QProcess::NormalExit) {
        r.code = p.exitCode();
    }
    r.out = QString::fromUtf8(p.readAllStandardOutput());
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

QProcessEnvironment environmentWithoutDisplay() {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"})
        env.remove(QLatin1String(name));
    return env;
}

bool haveDisplay() {
    return qEnvironmentVariableIsSet("DISPLAY") || qEnvironmentVariableIsSet("WAYLAND_DISPLAY");
}

} // namespace lrtest
