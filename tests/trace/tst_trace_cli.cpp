// `lightrig render --quality path` (issue 36): renders on the CPU without a display, writes the image
// with the scene options' size, gives the same image for the same --seed and another for another seed,
// stops at a time limit or a noise threshold, and refuses bad --samples, --time-limit, --noise-threshold,
// --bounces, --threads, --firefly-clamp and --seed values, the path options without --quality path, and a
// classic-shading rig, each with a clear message.
#include "support/cli.h"

#include <QImage>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using namespace lrtest;

namespace {

QString model() {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/model/pbr.gltf");
}

} // namespace

class TraceCli : public QObject {
    Q_OBJECT
  private slots:
    void rendersWithoutADisplay() {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("traced.png"));
        const QProcessEnvironment env = environmentWithoutDisplay();
        const CliRun run = runLightrig(
            {QStringLiteral("render"), model(), QStringLiteral("--quality"), QStringLiteral("path"),
             QStringLiteral("--samples"), QStringLiteral("4"), QStringLiteral("--bounces"),
             QStringLiteral("3"), QStringLiteral("--size"), QStringLiteral("48x32"),
             QStringLiteral("--ground"), QStringLiteral("visible"), QStringLiteral("--environment"),
             QStringLiteral("studio"), QStringLiteral("-o"), out},
            &env);
        QVERIFY2(run.code == 0, qPrintable(run.show()));
        QVERIFY2(run.out.contains(QLatin1String("path traced, 4 samples per pixel, 3 bounces")),
                 qPrintable(run.show()));
        const QImage image(out);
        QCOMPARE(image.size(), QSize(48, 32));
        // Not one flat colour: the model and the ground were traced.
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                colours.insert(image.pixel(x, y));
        QVERIFY(colours.size() > 20);
    }

    // --seed picks the random sequence: the same seed gives the same image, another an independent one
    // (what an error estimate against a reference image needs: scripts/perf/versus_cycles.sh).
    void seed() {
        QTemporaryDir dir;
        const auto render = [&](const QString& seed, const QString& name) {
            const QString out = dir.filePath(name);
            QStringList args{QStringLiteral("render"),
                             model(),
                             QStringLiteral("--quality"),
                             QStringLiteral("path"),
                             QStringLiteral("--samples"),
                             QStringLiteral("1"),
                             QStringLiteral("--size"),
                             QStringLiteral("24x16"),
                             QStringLiteral("--environment"),
                             QStringLiteral("studio"),
                             QStringLiteral("-o"),
                             out};
            if (!seed.isEmpty()) args << QStringLiteral("--seed") << seed;
            const CliRun run = runLightrig(args);
            if (run.code != 0) qWarning("%s", qPrintable(run.show()));
            return QImage(out).convertToFormat(QImage::Format_RGBA8888);
        };
        const QImage a = render({}, QStringLiteral("default.png"));
        const QImage b = render(QStringLiteral("0"), QStringLiteral("zero.png"));
        const QImage c = render(QStringLiteral("7"), QStringLiteral("seven.png"));
        QVERIFY(!a.isNull() && !c.isNull());
        QCOMPARE(a, b); // the default seed is 0
        QVERIFY(a != c);
    }

    // With no --samples the sample target is out of reach: the time limit or the noise threshold stops
    // the render, and the summary says which, with the samples done and the noise reached.
    void stopsAtTimeOrNoise_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("reason");
        QTest::newRow("time") << QStringList{QStringLiteral("--time-limit"), QStringLiteral("0.5")}
                              << QStringLiteral("time");
        QTest::newRow("noise") << QStringList{QStringLiteral("--noise-threshold"), QStringLiteral("0.3")}
                               << QStringLiteral("noise");
    }
    void stopsAtTimeOrNoise() {
        QFETCH(QStringList, args);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("traced.png"));
        const CliRun run = runLightrig(
            QStringList{QStringLiteral("render"), model(), QStringLiteral("--quality"),
                        QStringLiteral("path"), QStringLiteral("--size"), QStringLiteral("24x16"),
                        QStringLiteral("--ground"), QStringLiteral("visible"), QStringLiteral("-o"), out} +
            args);
        QVERIFY2(run.code == 0, qPrintable(run.show()));
        const QRegularExpression summary(QStringLiteral(
            R"(path traced, (\d+) samples per pixel.* ([0-9.]+) s \(\d+ samples/s\), noise ([^,]+), stopped by (\w+);)"));
        const QRegularExpressionMatch m = summary.match(run.out);
        QVERIFY2(m.hasMatch(), qPrintable(run.show()));
        QCOMPARE(m.captured(4), reason);
        QVERIFY(m.captured(1).toInt() < 1000000);
        if (reason == QLatin1String("noise")) {
            QVERIFY2(m.captured(3).toDouble() <= 0.3, qPrintable(run.show()));
            QVERIFY(m.captured(1).toInt() >= 2);
        }
        QCOMPARE(QImage(out).size(), QSize(24, 16));
    }

    void transparentCatcher() {
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("catcher.png"));
        const CliRun run = runLightrig(
            {QStringLiteral("render"), model(), QStringLiteral("--quality"), QStringLiteral("path"),
             QStringLiteral("--samples"), QStringLiteral("2"), QStringLiteral("--size"),
             QStringLiteral("32x24"), QStringLiteral("--ground"), QStringLiteral("catcher"),
             QStringLiteral("--transparent"), QStringLiteral("-o"), out});
        QVERIFY2(run.code == 0, qPrintable(run.show()));
        const QImage image = QImage(out).convertToFormat(QImage::Format_RGBA8888);
        QVERIFY(image.hasAlphaChannel());
        int clear = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                clear += qAlpha(image.pixel(x, y)) == 0 ? 1 : 0;
        QVERIFY(clear > 0); // the unshadowed catcher and the background are transparent
    }

    void badValues_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("code");
        QTest::addColumn<QString>("message");
        const QStringList path{QStringLiteral("--quality"), QStringLiteral("path")};
        QTest::newRow("samples 0") << (path + QStringList{QStringLiteral("--samples"), QStringLiteral("0")})
                                   << 2
                                   << QStringLiteral(
                                          "--samples must be a whole number in 1..1000000, got '0'");
        QTest::newRow("samples word")
            << (path + QStringList{QStringLiteral("--samples"), QStringLiteral("many")}) << 2
            << QStringLiteral("--samples must be a whole number in 1..1000000, got 'many'");
        QTest::newRow("bounces negative")
            << (path + QStringList{QStringLiteral("--bounces"), QStringLiteral("-1")}) << 2
            << QStringLiteral("--bounces must be a whole number in 0..1024, got '-1'");
        QTest::newRow("threads 0") << (path + QStringList{QStringLiteral("--threads"), QStringLiteral("0")})
                                   << 2 << QStringLiteral("--threads must be a whole number in 1..1024");
        QTest::newRow("clamp 0") << (path +
                                     QStringList{QStringLiteral("--firefly-clamp"), QStringLiteral("0")})
                                 << 2
                                 << QStringLiteral("--firefly-clamp must be a linear radiance > 0, got '0'");
        QTest::newRow("seed -1") << (path + QStringList{QStringLiteral("--seed"), QStringLiteral("-1")}) << 2
                                 << QStringLiteral(
                                        "--seed must be a whole number in 0..2147483647, got '-1'");
        QTest::newRow("time limit 0")
            << (path + QStringList{QStringLiteral("--time-limit"), QStringLiteral("0")}) << 2
            << QStringLiteral("--time-limit must be a number of seconds > 0, got '0'");
        QTest::newRow("time limit word")
            << (path + QStringList{QStringLiteral("--time-limit"), QStringLiteral("soon")}) << 2
            << QStringLiteral("--time-limit must be a number of seconds > 0, got 'soon'");
        QTest::newRow("noise negative")
            << (path + QStringList{QStringLiteral("--noise-threshold"), QStringLiteral("-0.1")}) << 2
            << QStringLiteral("--noise-threshold must be a relative noise > 0, got '-0.1'");
        QTest::newRow("noise nan")
            << (path + QStringList{QStringLiteral("--noise-threshold"), QStringLiteral("nan")}) << 2
            << QStringLiteral("--noise-threshold must be a relative noise > 0, got 'nan'");
        QTest::newRow("time limit without path")
            << QStringList{QStringLiteral("--time-limit"), QStringLiteral("4")} << 2
            << QStringLiteral("--time-limit needs --quality path");
        QTest::newRow("samples without path") << QStringList{QStringLiteral("--samples"), QStringLiteral("4")}
                                              << 2 << QStringLiteral("--samples needs --quality path");
        QTest::newRow("supersample with path")
            << (path + QStringList{QStringLiteral("--supersample"), QStringLiteral("2")}) << 2
            << QStringLiteral("--supersample does not apply to --quality path");
        QTest::newRow("unknown quality")
            << QStringList{QStringLiteral("--quality"), QStringLiteral("traced")} << 2
            << QStringLiteral("\"exact\", \"balanced\", \"fast\" or \"path\"");
        QTest::newRow("classic rig") << (path +
                                         QStringList{QStringLiteral("--shading"), QStringLiteral("classic")})
                                     << 1 << QStringLiteral("uses classic shading");
    }
    void badValues() {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        QFETCH(QString, message);
        QTemporaryDir dir;
        const QString out = dir.filePath(QStringLiteral("never.png"));
        const CliRun run =
            runLightrig(QStringList{QStringLiteral("render"), model(), QStringLiteral("--size"),
                                    QStringLiteral("16x16"), QStringLiteral("-o"), out} +
                        args);
        QVERIFY2(run.code == code, qPrintable(run.show()));
        QVERIFY2(run.err.contains(message), qPrintable(run.show()));
        QVERIFY(!QFile::exists(out));
    }
};

QTEST_MAIN(TraceCli)
#include "tst_trace_cli.moc"
