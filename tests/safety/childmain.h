// A test executable that can also be its own child process: `TEST --child-NAME ARGS...` runs
// childMain(arguments) instead of the tests. Used to kill a real process mid-save or mid-session (SIGKILL)
// and look at what it left behind.
#pragma once

#include <QCoreApplication>
#include <QProcess>
#include <QTest>
#include <cstring>

// childMain(QStringList args) gets {"--child-NAME", ARGS...}; it returns the exit code or runs app.exec().
#define LIGHTRIG_TEST_MAIN_WITH_CHILD(AppClass, TestClass, childMain)                                        \
    int main(int argc, char** argv) {                                                                        \
        AppClass app(argc, argv);                                                                            \
        if (argc > 1 && std::strncmp(argv[1], "--child-", 8) == 0) return childMain(app.arguments().mid(1)); \
        TestClass test;                                                                                      \
        QTEST_SET_MAIN_SOURCE_PATH                                                                           \
        return QTest::qExec(&test, argc, argv);                                                              \
    }

namespace safetytest {

// Starts this executable as a child: `--child-NAME args...`, stdout and stderr merged.
inline void startChild(QProcess& p, const QString& name, const QStringList& args) {
    p.setProcessChannelMode(QProcess::MergedChannels);
    p.start(QCoreApplication::applicationFilePath(), QStringList{QStringLiteral("--child-") + name} + args);
}

// Reads the child's output until a line equal to `line` arrives (true) or it exits / times out (false).
inline bool waitForLine(QProcess& p, const QByteArray& line, QByteArray* all, int timeoutMs = 30000) {
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < timeoutMs) {
        if (all->contains('\n' + line + '\n') || all->startsWith(line + '\n')) return true;
        if (p.state() == QProcess::NotRunning) return false;
        p.waitForReadyRead(100);
        *all += p.readAll();
    }
    return false;
}

} // namespace safetytest
