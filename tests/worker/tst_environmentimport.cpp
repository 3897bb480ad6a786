// Environment images through the import worker (model/environmentdecode.h importEnvironmentIsolated):
// the round trip gives what decoding in process gives; the worker's errors name the file; the parent
// refuses a reply with a NaN or the wrong byte count, and reports a crash; and the loader
// (scene/environmentloader.h) resolves builtin, relative and absolute files and names the file it could
// not read. Runs against LIGHTRIG_EXECUTABLE.
#include "model/environmentdecode.h"
#include "model/importprotocol.h"
#include "scene/environmentloader.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;

namespace {

const QString kData = QStringLiteral(LIGHTRIG_TEST_DATA "/environment/");

struct CrashMode {
    explicit CrashMode(const QByteArray& mode) { qputenv(importprotocol::kTestCrashVariable, mode); }
    ~CrashMode() { qunsetenv(importprotocol::kTestCrashVariable); }
};

} // namespace

class TestEnvironmentImport : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE)); }
    void roundTrip_data() {
        QTest::addColumn<QString>("file");
        for (const char* f : {"tiny.exr", "tiny_zip.exr", "nonfinite.exr", "tiny.hdr", "rle.hdr"})
            QTest::newRow(f) << QString::fromLatin1(f);
    }
    void roundTrip() {
        QFETCH(QString, file);
        const EnvironmentDecodeResult direct = decodeEnvironmentFile(kData + file);
        const EnvironmentDecodeResult viaWorker = importEnvironmentIsolated(kData + file);
        QVERIFY2(viaWorker.ok(), qPrintable(viaWorker.error));
        QCOMPARE(viaWorker.image.width, direct.image.width);
        QCOMPARE(viaWorker.image.height, direct.image.height);
        QCOMPARE(viaWorker.image.texels, direct.image.texels);
        QCOMPARE(viaWorker.warnings, direct.warnings);
    }
    void sharedExrThroughTheWorker() {
        QString file = QStringLiteral(LIGHTRIG_SHARED_MODELS "/../environments/studio.exr");
        if (!QFile::exists(file)) file = QStringLiteral("/work/shared/environments/studio.exr");
        if (!QFile::exists(file))
            QSKIP("no shared environments (LIGHTRIG_SHARED_MODELS/../environments, /work/shared)");
        const EnvironmentDecodeResult viaWorker = importEnvironmentIsolated(file);
        QVERIFY2(viaWorker.ok(), qPrintable(viaWorker.error));
        QCOMPARE(viaWorker.image.width, 1024);
        QCOMPARE(viaWorker.image.texels, decodeEnvironmentFile(file).image.texels); // DWAB, bit for bit
    }
    void workerErrorsNameTheFile() {
        QTemporaryDir dir;
        const QString junk = dir.filePath("junk.exr");
        QFile f(junk);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(QByteArray(1000, 'x'));
        f.close();
        const EnvironmentDecodeResult r = importEnvironmentIsolated(junk);
        QVERIFY(!r.ok());
        QCOMPARE(r.error, QStringLiteral("could not read %1: %2").arg(junk, r.reason));
        QVERIFY2(r.reason.contains("not an OpenEXR or Radiance"), qPrintable(r.reason));
    }
    void parentChecksTheReply_data() {
        QTest::addColumn<QByteArray>("mode");
        QTest::addColumn<QString>("expected");
        QTest::newRow("NaN texel") << QByteArray("env-nan") << "malformed reply (a texel value nan";
        QTest::newRow("byte count")
            << QByteArray("env-size")
            << "malformed reply (32 bytes for an environment of 2×1 texels (36 expected))";
        QTest::newRow("model reply") << QByteArray("garbage") << "malformed reply";
        QTest::newRow("crash") << QByteArray("segv") << "the importer crashed (signal 11)";
    }
    void parentChecksTheReply() {
        QFETCH(QByteArray, mode);
        QFETCH(QString, expected);
        const CrashMode crash(mode);
        const EnvironmentDecodeResult r = importEnvironmentIsolated(kData + "tiny.exr");
        QVERIFY(!r.ok());
        QVERIFY(r.image.isNull());
        QVERIFY2(r.error.startsWith("could not read " + kData + "tiny.exr: "), qPrintable(r.error));
        QVERIFY2(r.error.contains(expected), qPrintable(r.error));
    }
    void timeout() {
        const CrashMode crash("hang");
        ImportLimits limits;
        limits.timeoutMs = 300;
        const EnvironmentDecodeResult r = importEnvironmentIsolated(kData + "tiny.exr", limits);
        QVERIFY2(r.error.endsWith("the importer did not finish within 0.3 s"), qPrintable(r.error));
    }
    void loaderResolvesFiles() {
        QTemporaryDir rigFolder;
        QVERIFY(QDir(rigFolder.path()).mkpath("hdr"));
        QVERIFY(QFile::copy(kData + "nonfinite.exr", rigFolder.filePath("hdr/sky.exr")));
        Environment spec;
        spec.source = EnvironmentSource::Image;
        spec.file = "hdr/sky.exr";
        const EnvironmentLoadResult relative = loadEnvironment(spec, rigFolder.path());
        QVERIFY2(relative.environment, qPrintable(relative.error));
        QCOMPARE(relative.environment->source, rigFolder.filePath("hdr/sky.exr"));
        QCOMPARE(relative.environment->image.width, 4);
        QCOMPARE(relative.environment->prefiltered.specular.size(), size_t(kSpecularLevels));
        QCOMPARE(relative.environment->warnings,
                 (QStringList{"sky.exr: 2 texels were NaN or infinite and were set to 0",
                              "sky.exr: 1 texels were negative (down to -1) and were set to 0"}));
        spec.file = rigFolder.filePath("hdr/sky.exr"); // absolute: as is
        const EnvironmentLoadResult absolute = loadEnvironment(spec, "/nowhere");
        QVERIFY2(absolute.environment, qPrintable(absolute.error));
        QVERIFY(absolute.environment->decodeSeconds > 0.0);
        spec.file = "builtin:studio";
        const EnvironmentLoadResult builtin = loadEnvironment(spec, "/nowhere");
        QVERIFY2(builtin.environment, qPrintable(builtin.error));
        QCOMPARE(builtin.environment->source, QStringLiteral("builtin:studio"));
        QCOMPARE(builtin.environment->image.width, 1024);
        QVERIFY(builtin.environment->prefiltered.seconds > 0.0);
    }
    void loaderErrorsNameTheFile() {
        QTemporaryDir rigFolder;
        Environment spec;
        spec.source = EnvironmentSource::Image;
        spec.file = "hdr/missing.exr";
        const EnvironmentLoadResult missing = loadEnvironment(spec, rigFolder.path());
        QVERIFY(!missing.environment);
        QVERIFY2(missing.error.startsWith(QStringLiteral("could not read hdr/missing.exr (%1): ")
                                              .arg(rigFolder.filePath("hdr/missing.exr"))),
                 qPrintable(missing.error));
        spec.file = "builtin:nope";
        const EnvironmentLoadResult unknown = loadEnvironment(spec, rigFolder.path());
        QVERIFY2(unknown.error.startsWith("could not read builtin:nope: no bundled environment"),
                 qPrintable(unknown.error));
        spec.source = EnvironmentSource::None;
        QVERIFY(!loadEnvironment(spec, {}).environment);
        QVERIFY(loadEnvironment(spec, {}).error.isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestEnvironmentImport)
#include "tst_environmentimport.moc"
