// Issue 41, item 10: `lightrig render --size 32768x32768 --supersample 4` started allocating with no word
// of the memory (or time) it would take. It now says, before a byte of the image is allocated, what it
// needs (cli/renderestimate.h), and refuses, naming the options, beyond what the process may use: the
// machine's memory, or its address-space limit (the test sets one with ulimit -v, so that the refusal
// does not depend on the machine the test runs on).
#include "support/cli.h"

#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

namespace {

// `lightrig ARGS...` under `ulimit -v KIB`; killed (code -1) after timeoutMs.
lrtest::CliRun lightrigLimited(qint64 kib, const QStringList& args, int timeoutMs = 60000) {
    return lrtest::runProgram(QStringLiteral("/bin/sh"),
                              QStringList{QStringLiteral("-c"),
                                          QStringLiteral("ulimit -v %1 && exec \"$0\" \"$@\"").arg(kib),
                                          lrtest::lightrigExecutable()} +
                                  args,
                              nullptr, timeoutMs);
}

const QString kModel = QStringLiteral(LIGHTRIG_TEST_DATA "/model/tetra.stl");

} // namespace

class TestRenderEstimate : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

  private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    // 131072 × 131072 rendered pixels: the 4 GiB image, twice while encoded, and a tile's targets do not
    // fit 8 GiB of address space. Refused at once (exit 2), naming the options, with nothing written.
    void tooLargeForTheProcessIsRefusedBeforeRendering() {
        const QString out = m_dir.filePath(QStringLiteral("huge.png"));
        const lrtest::CliRun r = lightrigLimited(
            8ll << 20, {QStringLiteral("render"), kModel, QStringLiteral("-o"), out, QStringLiteral("--size"),
                        QStringLiteral("32768x32768"), QStringLiteral("--supersample"), QStringLiteral("4")});
        QVERIFY2(r.code == 2, qPrintable(r.show()));
        QVERIFY2(r.err.contains(QStringLiteral("lightrig render: --size 32768x32768 --supersample 4 renders "
                                               "131072x131072 pixels in 1024 tile(s) of at most 4096x4096")),
                 qPrintable(r.show()));
        QVERIFY2(r.err.contains(QStringLiteral("--size 32768x32768 --supersample 4 needs about")) &&
                     r.err.contains(QStringLiteral("its address-space limit, ulimit -v")) &&
                     r.err.contains(QStringLiteral("--no-memory-check")),
                 qPrintable(r.show()));
        QVERIFY(!QFile::exists(out));
    }

    // Within the limit the estimate is said before anything else happens (here: before the display is
    // found missing); a render of a usual size says nothing of it.
    void estimateIsSaidFirstAndOnlyForLargeRenders() {
        const QProcessEnvironment noDisplay = lrtest::environmentWithoutDisplay();
        const QString out = m_dir.filePath(QStringLiteral("large.png"));
        const lrtest::CliRun large =
            lrtest::runLightrig({QStringLiteral("render"), kModel, QStringLiteral("-o"), out,
                                 QStringLiteral("--size"), QStringLiteral("16384x16384")},
                                &noDisplay, 60000);
        QVERIFY2(large.code == 1, qPrintable(large.show()));
        const QStringList lines = large.errorLines();
        QVERIFY2(lines.size() == 2 &&
                     lines[0].startsWith(QStringLiteral("lightrig render: --size 16384x16384 "
                                                        "renders 16384x16384 pixels in 16 "
                                                        "tile(s)")) &&
                     lines[0].contains(QStringLiteral("needs about")) &&
                     lines[1].contains(QStringLiteral("needs an X display")),
                 qPrintable(large.show()));
        const lrtest::CliRun usual = lrtest::runLightrig(
            {QStringLiteral("render"), kModel, QStringLiteral("-o"), out, QStringLiteral("--size"),
             QStringLiteral("1280x720"), QStringLiteral("--supersample"), QStringLiteral("2")},
            &noDisplay, 60000);
        QVERIFY2(usual.code == 1 && !usual.err.contains(QStringLiteral("needs about")),
                 qPrintable(usual.show()));
        QVERIFY(!QFile::exists(out));
    }
};

QTEST_GUILESS_MAIN(TestRenderEstimate)

#include "tst_renderestimate.moc"
