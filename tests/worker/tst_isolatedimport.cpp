// Importing in a child process (model/isolatedimport.h) with LIGHTRIG_EXECUTABLE as the worker: a good
// model arrives equal to a direct import, every way the worker can die (crash, abort, hang, memory limit,
// garbage, truncated reply, bare exit) becomes its own clear message, cancellation works, and every file
// of ../shared/models loads or fails with a message. The failures are provoked through the worker's
// test-only LIGHTRIG_WORKER_TEST_CRASH variable.
#include "model/importprotocol.h"
#include "model/isolatedimport.h"
#include "model/modelchecks.h"
#include "model/modelloader.h"
#include "modelcompare.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QTest>
#include <QThreadPool>
#include <QtConcurrent>
#include <algorithm>
#include <atomic>
#include <thread>

#if defined(__SANITIZE_ADDRESS__)
#define TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TEST_ASAN 1
#endif
#endif

using namespace lr;

namespace {

const QString kData = QStringLiteral(LIGHTRIG_TEST_DATA "/model");
// The error for quad.obj, which names the path as given: "could not import <kData>/quad.obj: <reason>".
QString quadError(const char* reason) {
    return QStringLiteral("could not import %1/quad.obj: %2").arg(kData, QString::fromUtf8(reason));
}
const QString kShared = QStringLiteral(LIGHTRIG_SHARED_MODELS);

void setCrashMode(const char* mode) {
    if (mode)
        qputenv(importprotocol::kTestCrashVariable, mode);
    else
        qunsetenv(importprotocol::kTestCrashVariable);
}

// Compares an isolated import with a direct one of the same file.
QString compareWithDirect(const QString& path, const ModelLoadResult& isolated) {
    const ModelLoadResult direct = loadModel(path);
    if (direct.ok() != isolated.ok())
        return QStringLiteral("direct: %1, isolated: %2").arg(direct.error, isolated.error);
    if (!direct.ok())
        return direct.error == isolated.error ? QString()
                                              : direct.error + QStringLiteral(" vs ") + isolated.error;
    return test::modelDifference(*direct.model, *isolated.model, false);
}

} // namespace

class TestIsolatedImport : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE)); }
    // No warning of any kind (e.g. "QProcess: Destroyed while process is still running").
    void init() { QTest::failOnWarning(QRegularExpression(QStringLiteral(".*"))); }
    void cleanup() {
        setCrashMode(nullptr);
        setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE));
    }
    void goodModelsEqualDirectImport_data();
    void goodModelsEqualDirectImport();
    void loaderErrorsPassThrough();
    void worksOnOtherThreads();
    void texturesKeepTheirPagesOnly();
    void progressIsMonotonicAndEnds();
    void workerDeaths_data();
    void workerDeaths();
    void memoryLimit();
    void timeLimit();
    void cancelFromProgress();
    void cancelFromFlag();
    void missingWorkerExecutable();
    void workerFromEnvironment();
    void workerRefusesBareUse();
    void everySharedFileLoadsOrFails();
};

void TestIsolatedImport::goodModelsEqualDirectImport_data() {
    QTest::addColumn<QString>("path");
    QTest::addColumn<bool>("sharedMemory");
    QStringList paths;
    // pbr.gltf and shiny.obj: every physically based Material field and the import warnings of issue 13.
    for (const char* f : {"quad.obj", "colors.ply", "scene.gltf", "tetra.stl", "pbr.gltf", "shiny.obj"})
        paths << kData + QLatin1Char('/') + QLatin1String(f);
    paths << QStringLiteral(":/resources/models/suzanne/Suzanne.gltf"); // the bundled model, a resource
    for (const QString& path : paths)
        for (const bool shared : {true, false})
            QTest::addRow("%s via %s", qPrintable(QFileInfo(path).fileName()), shared ? "memfd" : "pipe")
                << path << shared;
}

void TestIsolatedImport::goodModelsEqualDirectImport() {
    QFETCH(QString, path);
    QFETCH(bool, sharedMemory);
    ImportLimits limits;
    limits.sharedMemory = sharedMemory;
    const ModelLoadResult isolated = importModelIsolated(path, {}, limits);
    QVERIFY2(isolated.ok(), qPrintable(isolated.error));
    QVERIFY(isolated.model->loadMs > 0.0);
    const QString problem = test::modelProblems(*isolated.model);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));
    const QString difference = compareWithDirect(path, isolated);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
    if (path.endsWith(QLatin1String("pbr.gltf"))) { // the comparison above covered non-default values
        QVERIFY(isolated.model->hasPbrMaterials());
        QVERIFY(std::any_of(isolated.model->materials.begin(), isolated.model->materials.end(),
                            [](const Material& m) {
                                return m.occlusionTexture >= 0 && m.metallicRoughnessTexture >= 0 &&
                                       !m.occlusionTransform.isIdentity();
                            }));
    }
}

void TestIsolatedImport::loaderErrorsPassThrough() {
    const QString missing = kData + QStringLiteral("/no such model.obj");
    const ModelLoadResult isolated = importModelIsolated(missing);
    QVERIFY(!isolated.ok());
    QVERIFY(!isolated.cancelled);
    QCOMPARE(isolated.error, loadModel(missing).error);
    QVERIFY2(isolated.error.startsWith(QStringLiteral("could not import %1: ").arg(missing)),
             qPrintable(isolated.error));
}

// The editor imports on a QtConcurrent pool thread; two at once must not disturb each other.
void TestIsolatedImport::worksOnOtherThreads() {
    const QString a = kData + QStringLiteral("/scene.gltf"), b = kData + QStringLiteral("/colors.ply");
    QFuture<ModelLoadResult> fa = QtConcurrent::run([a] { return importModelIsolated(a); });
    QFuture<ModelLoadResult> fb = QtConcurrent::run([b] { return importModelIsolated(b); });
    ModelLoadResult rb;
    std::thread plain([&] { rb = importModelIsolated(b); }); // not a QThread: no event dispatcher
    plain.join();
    for (const auto& [path, r] : {std::pair{a, fa.result()}, std::pair{b, fb.result()}, std::pair{b, rb}}) {
        QVERIFY2(r.ok(), qPrintable(r.error));
        const QString difference = compareWithDirect(path, r);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }
    QThreadPool::globalInstance()->waitForDone(); // the pool's tasks let go of their results (and mappings)
}

namespace {
// Mappings of the shared reply's memfd in this process (/proc/self/maps names it "memfd:lightrig-import").
int sharedMappings() {
    QFile maps(QStringLiteral("/proc/self/maps"));
    if (!maps.open(QIODevice::ReadOnly)) return -1;
    return int(maps.readAll().count("lightrig-import"));
}
} // namespace

// Through the memfd, texture images keep their pages of the mapping (no copy) and nothing else stays
// mapped; the last image gone, nothing is mapped.
void TestIsolatedImport::texturesKeepTheirPagesOnly() {
    QCOMPARE(sharedMappings(), 0); // -1 when /proc/self/maps cannot be read: Linux always has it
    ModelLoadResult r = importModelIsolated(QStringLiteral(":/resources/models/suzanne/Suzanne.gltf"));
    QVERIFY2(r.ok(), qPrintable(r.error));
    const std::size_t textures = std::count_if(r.model->textures.begin(), r.model->textures.end(),
                                               [](const Texture& t) { return !t.image.isNull(); });
    QVERIFY(textures >= 1);
    QCOMPARE(sharedMappings(), int(textures)); // one region per texture, the rest unmapped
    const QImage kept = r.model->textures[0].image;
    r = {};
    QCOMPARE(sharedMappings(), kept.isNull() ? 0 : 1);
}

void TestIsolatedImport::progressIsMonotonicAndEnds() {
    ModelLoadOptions options;
    QList<double> seen;
    options.progress = [&](double f) {
        seen << f;
        return true;
    };
    const ModelLoadResult r = importModelIsolated(kData + QStringLiteral("/scene.gltf"), options);
    QVERIFY2(r.ok(), qPrintable(r.error));
    QVERIFY(seen.size() >= 2);
    QCOMPARE(seen.front(), 0.0);
    QCOMPARE(seen.back(), 1.0);
    for (qsizetype i = 1; i < seen.size(); ++i)
        QVERIFY2(seen[i] >= seen[i - 1] && seen[i] <= 1.0, qPrintable(QString::number(seen[i])));
}

void TestIsolatedImport::workerDeaths_data() {
    QTest::addColumn<QByteArray>("mode");
    QTest::addColumn<QString>("expected");
    QTest::newRow("segv") << QByteArray("segv") << QStringLiteral("the importer crashed (signal 11)");
    QTest::newRow("abort") << QByteArray("abort") << QStringLiteral("the importer aborted (signal 6)");
    QTest::newRow("garbage") << QByteArray("garbage")
                             << QStringLiteral("the importer sent a malformed reply (");
    QTest::newRow("truncate") << QByteArray("truncate")
                              << QStringLiteral("the importer sent a malformed reply (truncated)");
    QTest::newRow("shared-garbage") << QByteArray("shared-garbage")
                                    << QStringLiteral("the importer sent a malformed reply (");
    QTest::newRow("shared-short") << QByteArray("shared-short")
                                  << QStringLiteral(
                                         "the importer sent a malformed reply (the shared reply is "
                                         "shorter than announced)");
    QTest::newRow("exit") << QByteArray("exit")
                          << QStringLiteral("the importer exited with code 3 without a result");
}

void TestIsolatedImport::workerDeaths() {
    QFETCH(QByteArray, mode);
    QFETCH(QString, expected);
    setCrashMode(mode.constData());
    const ModelLoadResult r = importModelIsolated(kData + QStringLiteral("/quad.obj"));
    QVERIFY(!r.ok());
    QVERIFY(!r.cancelled);
    QVERIFY2(r.error.startsWith(quadError("") + expected), qPrintable(r.error));
}

void TestIsolatedImport::memoryLimit() {
#ifdef TEST_ASAN
    QSKIP("AddressSanitizer builds run the worker without an address-space limit");
#endif
    setCrashMode("oom");
    ImportLimits limits;
    limits.memoryBytes = 1ll << 30;
    const ModelLoadResult r = importModelIsolated(kData + QStringLiteral("/quad.obj"), {}, limits);
    QCOMPARE(r.error, quadError("the importer ran out of its 1 GiB memory limit"));
    QCOMPARE(formatMemoryLimit(8ll << 30), QStringLiteral("8 GiB"));
    QCOMPARE(formatMemoryLimit(512ll << 20), QStringLiteral("512 MiB"));
}

void TestIsolatedImport::timeLimit() {
    setCrashMode("hang");
    ImportLimits limits;
    limits.timeoutMs = 1500;
    const ModelLoadResult r = importModelIsolated(kData + QStringLiteral("/quad.obj"), {}, limits);
    QCOMPARE(r.error, quadError("the importer did not finish within 1.5 s"));
    QVERIFY(!r.cancelled);
}

void TestIsolatedImport::cancelFromProgress() {
    setCrashMode("hang"); // no progress ever arrives: the callback must still be polled
    ModelLoadOptions options;
    int calls = 0;
    options.progress = [&](double) { return ++calls < 5; };
    const ModelLoadResult r = importModelIsolated(kData + QStringLiteral("/quad.obj"), options);
    QVERIFY(!r.ok());
    QVERIFY(r.cancelled);
    QCOMPARE(calls, 5);
    QCOMPARE(r.error, quadError("cancelled"));
}

void TestIsolatedImport::cancelFromFlag() {
    setCrashMode("hang");
    std::atomic<bool> cancel{false};
    ImportLimits limits;
    limits.cancel = &cancel;
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        cancel = true;
    });
    const ModelLoadResult r = importModelIsolated(kData + QStringLiteral("/quad.obj"), {}, limits);
    canceller.join();
    QVERIFY(r.cancelled);
    QCOMPARE(r.error, quadError("cancelled"));
}

void TestIsolatedImport::missingWorkerExecutable() {
    setImportWorkerExecutable(QStringLiteral("/nonexistent/lightrig"));
    const ModelLoadResult r = importModelIsolated(kData + QStringLiteral("/quad.obj"));
    QVERIFY(!r.ok());
    QVERIFY2(r.error.startsWith(quadError("could not start the import worker "
                                          "/nonexistent/lightrig")),
             qPrintable(r.error));
}

void TestIsolatedImport::workerFromEnvironment() {
    const QByteArray saved = qgetenv("LIGHTRIG_IMPORT_WORKER");
    setImportWorkerExecutable(QString());
    qputenv("LIGHTRIG_IMPORT_WORKER", LIGHTRIG_EXECUTABLE);
    QCOMPARE(importWorkerExecutable(), QStringLiteral(LIGHTRIG_EXECUTABLE));
    const ModelLoadResult r = importModelIsolated(kData + QStringLiteral("/tetra.stl"));
    qunsetenv("LIGHTRIG_IMPORT_WORKER");
    // Without either, the worker is the running executable if it is lightrig, else there is none.
    QCOMPARE(importWorkerExecutable(), QString());
    const ModelLoadResult none = importModelIsolated(kData + QStringLiteral("/tetra.stl"));
    QVERIFY2(none.error.startsWith(
                 QStringLiteral("could not import %1/tetra.stl: no import worker: this is not lightrig")
                     .arg(kData)),
             qPrintable(none.error));
    const QString name = QCoreApplication::applicationName();
    QCoreApplication::setApplicationName(QStringLiteral("lightrig"));
    QCOMPARE(importWorkerExecutable(), QCoreApplication::applicationFilePath());
    QCoreApplication::setApplicationName(name);
    if (!saved.isEmpty()) qputenv("LIGHTRIG_IMPORT_WORKER", saved);
    QVERIFY2(r.ok(), qPrintable(r.error));
}

void TestIsolatedImport::workerRefusesBareUse() {
    QProcess p;
    p.start(QStringLiteral(LIGHTRIG_EXECUTABLE), {QString::fromLatin1(importprotocol::kSubcommand)});
    QVERIFY(p.waitForStarted());
    p.closeWriteChannel();
    QVERIFY(p.waitForFinished(30'000));
    QCOMPARE(p.exitStatus(), QProcess::NormalExit);
    QCOMPARE(p.exitCode(), 2);
    QVERIFY(p.readAllStandardError().contains("expects a JSON request"));
    QVERIFY(p.readAllStandardOutput().isEmpty());
}

void TestIsolatedImport::everySharedFileLoadsOrFails() {
    if (!QFileInfo(kShared).isDir())
        QSKIP("no third-party models at LIGHTRIG_SHARED_MODELS (../shared/models)");
    const QStringList suffixes = importableSuffixes();
    QStringList files;
    for (QDirIterator it(kShared, QDir::Files, QDirIterator::Subdirectories); it.hasNext();) {
        const QString f = it.next();
        // Every model file, and every file in invalid/ whatever its name.
        if (suffixes.contains(QFileInfo(f).suffix().toLower()) || f.contains(QLatin1String("/invalid/")))
            files << f;
    }
    files.sort();
    QVERIFY(files.size() > 20);
    QStringList failures;
    int loaded = 0, refused = 0;
    for (const QString& file : files) {
        const QString relative = QDir(kShared).relativeFilePath(file);
        const ModelLoadResult r = importModelIsolated(file);
        if (r.ok()) {
            ++loaded;
            if (const QString p = test::modelProblems(*r.model); !p.isEmpty())
                failures << relative + QStringLiteral(": ") + p;
            else if (const QString d = compareWithDirect(file, r); !d.isEmpty())
                failures << relative + QStringLiteral(": differs from the direct import: ") + d;
        } else {
            ++refused;
            qInfo("%s", qPrintable(r.error));
            if (!r.error.startsWith(QStringLiteral("could not import %1: ").arg(file)))
                failures << relative + QStringLiteral(": message does not name the file: ") + r.error;
        }
    }
    qInfo("%d files: %d loaded (equal to a direct import), %d refused with a message", int(files.size()),
          loaded, refused);
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join(QLatin1Char('\n'))));
}

QTEST_GUILESS_MAIN(TestIsolatedImport)
#include "tst_isolatedimport.moc"
