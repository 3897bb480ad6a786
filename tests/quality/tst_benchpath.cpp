// `lightrig bench --quality ...,path` (issue 36) run as the user runs it: the path tier's ladder (PSNR
// against the converged traced image grows with the samples) and each raster tier's error against the
// traced image beside its error against the direct-light reference, in the table and the JSON; the path
// options' usage errors. Values are checked for sanity and direction only (no timed tests).
#include "support/cli.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

using lrtest::CliRun;
using lrtest::haveDisplay;

namespace {

CliRun bench(const QStringList& args, const QProcessEnvironment* env = nullptr) {
    return lrtest::runLightrig(QStringList{QStringLiteral("bench")} + args, env, 300000);
}

} // namespace

class TestBenchPath : public QObject {
    Q_OBJECT

  private slots:
    void usageErrors_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::addRow("path samples without path")
            << QStringList{QStringLiteral("--path-samples"), QStringLiteral("16")}
            << QStringLiteral("--path-samples needs the path tier (--quality ...,path)");
        QTest::addRow("converged 0") << QStringList{QStringLiteral("--quality"), QStringLiteral("fast,path"),
                                                    QStringLiteral("--converged-samples"),
                                                    QStringLiteral("0")}
                                     << QStringLiteral("--converged-samples must be a whole number in "
                                                       "1..1000000, got '0'");
        QTest::addRow("threads word")
            << QStringList{QStringLiteral("--quality"), QStringLiteral("path"), QStringLiteral("--threads"),
                           QStringLiteral("all")}
            << QStringLiteral("--threads must be a whole number in 1..1024, got 'all'");
        QTest::addRow("bad tier with path")
            << QStringList{QStringLiteral("--quality"), QStringLiteral("path,traced")}
            << QStringLiteral("or \"path\"");
    }
    void usageErrors() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const CliRun r = bench(args);
        QVERIFY2(r.code == 2, qPrintable(r.show()));
        QVERIFY2(r.err.contains(message), qPrintable(r.show()));
    }

    void pathTierAndTracedColumns() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        QTemporaryDir dir;
        const QString json = dir.filePath(QStringLiteral("bench.json"));
        const CliRun r = bench(
            {QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"), QStringLiteral("--quality"),
             QStringLiteral("fast,exact,path"), QStringLiteral("--size"), QStringLiteral("48x32"),
             QStringLiteral("--frames"), QStringLiteral("2"), QStringLiteral("--warmup"), QStringLiteral("0"),
             QStringLiteral("--no-uber"), QStringLiteral("--ground"), QStringLiteral("visible"),
             QStringLiteral("--path-samples"), QStringLiteral("64"), QStringLiteral("--converged-samples"),
             QStringLiteral("512"), QStringLiteral("--json"), json});
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        QVERIFY2(r.out.contains(QLatin1String("path PSNR")) && r.out.contains(QLatin1String("Path tier")),
                 qPrintable(r.show()));
        QFile f(json);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject doc = QJsonDocument::fromJson(f.readAll()).object();
        const QJsonArray results = doc.value(QStringLiteral("results")).toArray();
        QCOMPARE(results.size(), 2);
        for (const QJsonValue& v : results) {
            const QJsonObject o = v.toObject();
            for (const char* key : {"path_psnr_db", "path_mean_error_levels", "path_max_error_levels"})
                QVERIFY2(o.value(QLatin1String(key)).isDouble() &&
                             std::isfinite(o.value(QLatin1String(key)).toDouble()),
                         key);
            QVERIFY(o.value(QStringLiteral("path_compared_pixels")).toDouble() > 0.0);
            QVERIFY(o.contains(QStringLiteral("psnr_db"))); // beside the direct-light reference's
        }
        const QJsonArray path = doc.value(QStringLiteral("path")).toArray();
        QCOMPARE(path.size(), 1);
        const QJsonObject p = path.first().toObject();
        QCOMPARE(p.value(QStringLiteral("converged_samples")).toInt(), 512);
        QVERIFY(p.value(QStringLiteral("samples_per_second")).toDouble() > 0.0);
        QVERIFY(p.value(QStringLiteral("seconds_per_sample")).toDouble() > 0.0);
        const QJsonArray steps = p.value(QStringLiteral("steps")).toArray();
        QCOMPARE(steps.size(), 7); // 1, 2, 4, … 64
        double psnr = 0.0, seconds = 0.0;
        for (int i = 0; i < steps.size(); ++i) {
            const QJsonObject s = steps[i].toObject();
            QCOMPARE(s.value(QStringLiteral("samples")).toInt(), 1 << i);
            const double db = s.value(QStringLiteral("psnr_db")).toDouble();
            QVERIFY2(std::isfinite(db) && db > psnr,
                     qPrintable(QStringLiteral("step %1: %2 dB after %3 dB").arg(i).arg(db).arg(psnr)));
            QVERIFY(s.value(QStringLiteral("seconds")).toDouble() >= seconds);
            psnr = db;
            seconds = s.value(QStringLiteral("seconds")).toDouble();
        }
        // Noise is unknown after one sample and falls after.
        QVERIFY(steps[0].toObject().value(QStringLiteral("noise")).isNull());
        QVERIFY(steps[3].toObject().value(QStringLiteral("noise")).toDouble() <
                steps[1].toObject().value(QStringLiteral("noise")).toDouble());
    }

    // `--quality path` alone runs no raster tier (nor the über-shader run): only the path tier, on the
    // CPU, with no display.
    void pathAlone() {
        const QProcessEnvironment env = lrtest::environmentWithoutDisplay();
        QTemporaryDir dir;
        const QString json = dir.filePath(QStringLiteral("bench.json"));
        const CliRun r = bench({QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"),
                                QStringLiteral("--quality"), QStringLiteral("path"), QStringLiteral("--size"),
                                QStringLiteral("24x16"), QStringLiteral("--path-samples"),
                                QStringLiteral("4"), QStringLiteral("--converged-samples"),
                                QStringLiteral("16"), QStringLiteral("--json"), json},
                               &env);
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        QFile f(json);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject doc = QJsonDocument::fromJson(f.readAll()).object();
        QCOMPARE(doc.value(QStringLiteral("results")).toArray().size(), 0);
        QCOMPARE(doc.value(QStringLiteral("path")).toArray().size(), 1);
    }
};

QTEST_MAIN(TestBenchPath)
#include "tst_benchpath.moc"
