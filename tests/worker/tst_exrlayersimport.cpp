// Multi-layer OpenEXR through the import worker (issue 37; model/exrdecode.h importExrLayersIsolated): the
// round trip gives what decoding in process gives; errors name the file (the decoder's reason, a FIFO or
// a missing file refused before any worker starts); the parent refuses a reply of another kind and reports
// a crash. Runs against LIGHTRIG_EXECUTABLE.
#include "model/exrfixtures.h"
#include "model/importprotocol.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>
#include <sys/stat.h>

using namespace lr;
using namespace exrtest;

namespace {

struct CrashMode {
    explicit CrashMode(const QByteArray& mode) { qputenv(importprotocol::kTestCrashVariable, mode); }
    ~CrashMode() { qunsetenv(importprotocol::kTestCrashVariable); }
};

QString writeTemp(const QTemporaryDir& dir, const QString& name, const QByteArray& bytes) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        qFatal("cannot write %s", qPrintable(path));
    return path;
}

} // namespace

class TestExrLayersImport : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

  private slots:
    void initTestCase() { setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE)); }
    void roundTrip_data() {
        QTest::addColumn<bool>("half");
        QTest::newRow("float") << false;
        QTest::newRow("half") << true;
    }
    void roundTrip() {
        QFETCH(bool, half);
        const QString path =
            writeTemp(m_dir, "aovs.exr",
                      encodeOrFail(31, 17, aovLayers(31, 17), half ? ExrPixel::Half : ExrPixel::Float));
        QString error;
        const std::optional<ExrFile> direct = decodeExrLayersFile(path, &error);
        QVERIFY2(direct, qPrintable(error));
        const std::optional<ExrFile> viaWorker = importExrLayersIsolated(path, &error);
        QVERIFY2(viaWorker, qPrintable(error));
        QCOMPARE(viaWorker->width, direct->width);
        QCOMPARE(viaWorker->height, direct->height);
        QCOMPARE(viaWorker->attributes, direct->attributes);
        QCOMPARE(viaWorker->layers.size(), direct->layers.size());
        for (size_t l = 0; l < direct->layers.size(); ++l) {
            QCOMPARE(viaWorker->layers[l].name, direct->layers[l].name);
            QCOMPARE(viaWorker->layers[l].channels, direct->layers[l].channels);
            QCOMPARE(viaWorker->layers[l].pixels, direct->layers[l].pixels);
        }
    }
    void errorsNameTheFile() {
        QString error;
        const QString junk = writeTemp(m_dir, "junk.exr", QByteArray(1000, 'x'));
        QVERIFY(!importExrLayersIsolated(junk, &error));
        QCOMPARE(error,
                 QStringLiteral("could not read %1: not an OpenEXR file (unknown first bytes)").arg(junk));
        const QByteArray aovs = encodeOrFail(31, 17, aovLayers(31, 17), ExrPixel::Half);
        const QString cut = writeTemp(m_dir, "cut.exr", aovs.left(aovs.size() * 2 / 3));
        QVERIFY(!importExrLayersIsolated(cut, &error));
        QVERIFY2(error.startsWith(QStringLiteral("could not read %1: truncated or corrupt OpenEXR").arg(cut)),
                 qPrintable(error));
        const QString absent = m_dir.filePath("absent.exr");
        QVERIFY(!importExrLayersIsolated(absent, &error));
        QCOMPARE(error, QStringLiteral("could not read %1: no such file").arg(absent));
        const QString fifo = m_dir.filePath("fifo.exr");
        QCOMPARE(::mkfifo(QFile::encodeName(fifo).constData(), 0600), 0);
        QVERIFY(!importExrLayersIsolated(fifo, &error));
        QVERIFY2(error.contains("not a regular file"), qPrintable(error));
    }
    void parentChecksTheReply_data() {
        QTest::addColumn<QByteArray>("mode");
        QTest::addColumn<QString>("expected");
        QTest::newRow("a model reply")
            << QByteArray("garbage") << "malformed reply (a reply of type 'M' to a layers";
        QTest::newRow("an environment reply")
            << QByteArray("env-nan") << "a reply of type 'V' to a layers request";
        QTest::newRow("crash") << QByteArray("segv") << "the importer crashed (signal 11)";
    }
    void parentChecksTheReply() {
        QFETCH(QByteArray, mode);
        QFETCH(QString, expected);
        const QString path = writeTemp(m_dir, "ok.exr", encodeOrFail(4, 3, aovLayers(4, 3), ExrPixel::Half));
        const CrashMode crash(mode);
        QString error;
        QVERIFY(!importExrLayersIsolated(path, &error));
        QVERIFY2(error.startsWith(QStringLiteral("could not read %1: ").arg(path)), qPrintable(error));
        QVERIFY2(error.contains(expected), qPrintable(error + " lacks " + expected));
    }
};

QTEST_GUILESS_MAIN(TestExrLayersImport)
#include "tst_exrlayersimport.moc"
