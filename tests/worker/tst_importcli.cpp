// `lightrig render` and `lightrig bench` import through the worker: an importer crash, abort or memory-limit
// hit (provoked with the worker's test-only LIGHTRIG_WORKER_TEST_CRASH) is exit status 1 with the worker's
// message on stderr and no output file. Needs an X display (ctest under xvfb-run -a); skips without one.
#include "model/importprotocol.h"
#include "support/cli.h"

#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

#if defined(__SANITIZE_ADDRESS__)
#define TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TEST_ASAN 1
#endif
#endif

namespace {

struct Run {
    int status = -1;
    QString err;
};

Run lightrig(const QStringList& args, const QByteArray& crashMode) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove(QStringLiteral("LIGHTRIG_IMPORT_WORKER")); // the worker is lightrig itself
    if (!crashMode.isEmpty())
        env.insert(QString::fromLatin1(lr::importprotocol::kTestCrashVariable),
                   QString::fromLatin1(crashMode));
    const lrtest::CliRun r = lrtest::runLightrig(args, &env, 120'000);
    return {r.code, r.err};
}

Run render(const QString& model, const QString& out, const QByteArray& crashMode) {
    return lightrig({QStringLiteral("render"), model, QStringLiteral("-o"), out, QStringLiteral("--size"),
                     QStringLiteral("64x48")},
                    crashMode);
}

} // namespace

class TestImportCli : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() {
        if (qEnvironmentVariableIsEmpty("DISPLAY") && qEnvironmentVariableIsEmpty("WAYLAND_DISPLAY"))
            QSKIP("lightrig render needs an X display: run under xvfb-run -a");
    }
    void renderThroughTheWorker();
    void renderImporterDeaths_data();
    void renderImporterDeaths();
    void benchImporterDeath();
};

void TestImportCli::renderThroughTheWorker() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString out = dir.filePath(QStringLiteral("quad.png"));
    const Run r = render(QStringLiteral(LIGHTRIG_TEST_DATA "/model/quad.obj"), out, {});
    QVERIFY2(r.status == 0, qPrintable(r.err));
    QVERIFY(QFileInfo(out).size() > 0);
    QVERIFY2(!r.err.contains(QLatin1String("QProcess")), qPrintable(r.err)); // no noise from the worker's end
}

void TestImportCli::renderImporterDeaths_data() {
    QTest::addColumn<QByteArray>("mode");
    QTest::addColumn<QString>("message");
    QTest::newRow("segv") << QByteArray("segv")
                          << QStringLiteral("could not import " LIGHTRIG_TEST_DATA
                                            "/model/quad.obj: the importer crashed (signal 11)");
    QTest::newRow("abort") << QByteArray("abort")
                           << QStringLiteral("could not import " LIGHTRIG_TEST_DATA
                                             "/model/quad.obj: the importer aborted (signal 6)");
#ifndef TEST_ASAN // AddressSanitizer builds run the worker without an address-space limit
    QTest::newRow("oom") << QByteArray("oom")
                         << QStringLiteral("could not import " LIGHTRIG_TEST_DATA
                                           "/model/quad.obj: the importer ran out of its 1.0 GiB memory "
                                           "limit (for 183 bytes of input)");
#endif
    QTest::newRow("garbage") << QByteArray("garbage")
                             << QStringLiteral("could not import " LIGHTRIG_TEST_DATA
                                               "/model/quad.obj: the importer sent a malformed reply");
}

void TestImportCli::renderImporterDeaths() {
    QFETCH(QByteArray, mode);
    QFETCH(QString, message);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString out = dir.filePath(QStringLiteral("quad.png"));
    const Run r = render(QStringLiteral(LIGHTRIG_TEST_DATA "/model/quad.obj"), out, mode);
    QCOMPARE(r.status, 1);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
    QCOMPARE(r.err.count(QLatin1String("lightrig render: ")), 1); // one line of its own (Qt may add warnings)
    QVERIFY(!QFileInfo::exists(out));
    QCOMPARE(QDir(dir.path()).entryList(QDir::NoDotAndDotDot | QDir::AllEntries), QStringList());
}

void TestImportCli::benchImporterDeath() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString json = dir.filePath(QStringLiteral("bench.json"));
    const Run r = lightrig({QStringLiteral("bench"), QStringLiteral(LIGHTRIG_TEST_DATA "/model/quad.obj"),
                            QStringLiteral("--frames"), QStringLiteral("2"), QStringLiteral("--size"),
                            QStringLiteral("64x48"), QStringLiteral("--json"), json},
                           "segv");
    QCOMPARE(r.status, 1);
    QVERIFY2(r.err.contains(QStringLiteral("lightrig bench: could not import " LIGHTRIG_TEST_DATA
                                           "/model/quad.obj: the importer crashed (signal 11)")),
             qPrintable(r.err));
    QVERIFY(!QFileInfo::exists(json));
}

QTEST_GUILESS_MAIN(TestImportCli)
#include "tst_importcli.moc"
