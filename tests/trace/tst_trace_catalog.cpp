// `lightrig render --quality path` beyond one image (issue 36, item 3): turntables (the camera or the lights
// turning) and catalogs of rigs × views, without a display; each item's image is the one a single render of
// it gives, and an item the path tracer refuses (a classic-shading rig) fails alone, said in the summary;
// and `compare --quality path`.
#include "support/cli.h"

#include <QImage>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using namespace lrtest;

namespace {

QString model() {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/model/pbr.gltf");
}

QString rig(const char* name) {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/rig/good/") + QLatin1String(name);
}

QStringList traced(const QStringList& more) {
    return QStringList{QStringLiteral("render"),    model(),
                       QStringLiteral("--quality"), QStringLiteral("path"),
                       QStringLiteral("--samples"), QStringLiteral("2"),
                       QStringLiteral("--size"),    QStringLiteral("40x30")} +
           more;
}

} // namespace

class TraceCatalog : public QObject {
    Q_OBJECT
  private slots:
    // Frame 0 of a turntable is the unturned view: the same image as a single render (the sampler depends
    // on pixel and sample only); the later frames see the model from elsewhere.
    void turntableOfTheCamera() {
        QTemporaryDir dir;
        const QProcessEnvironment env = environmentWithoutDisplay();
        const CliRun single =
            runLightrig(traced({QStringLiteral("-o"), dir.filePath(QStringLiteral("one.png"))}), &env);
        QVERIFY2(single.code == 0, qPrintable(single.show()));
        const CliRun turn =
            runLightrig(traced({QStringLiteral("--turntable"), QStringLiteral("3"), QStringLiteral("-o"),
                                dir.filePath(QStringLiteral("t_#.png"))}),
                        &env);
        QVERIFY2(turn.code == 0, qPrintable(turn.show()));
        QCOMPARE(turn.out.count(QLatin1String("path traced, 2 samples per pixel")), 3);
        const QImage one(dir.filePath(QStringLiteral("one.png")));
        const QImage f0(dir.filePath(QStringLiteral("t_0.png"))), f1(dir.filePath(QStringLiteral("t_1.png"))),
            f2(dir.filePath(QStringLiteral("t_2.png")));
        QVERIFY(!one.isNull() && !f0.isNull() && !f1.isNull() && !f2.isNull());
        QCOMPARE(f0, one);
        QVERIFY(f1 != f0);
        QVERIFY(f2 != f1);
    }

    // --rotate lights turns the rig's lights about the model: the camera stays, the lighting changes.
    void turntableOfTheLights() {
        QTemporaryDir dir;
        const CliRun turn =
            runLightrig(traced({QStringLiteral("--rig"), rig("area.json"), QStringLiteral("--turntable"),
                                QStringLiteral("2"), QStringLiteral("--rotate"), QStringLiteral("lights"),
                                QStringLiteral("-o"), dir.filePath(QStringLiteral("l_#.png"))}));
        QVERIFY2(turn.code == 0, qPrintable(turn.show()));
        const QImage f0(dir.filePath(QStringLiteral("l_0.png"))), f1(dir.filePath(QStringLiteral("l_1.png")));
        QVERIFY(!f0.isNull() && !f1.isNull());
        QVERIFY(f0 != f1);
    }

    // Two rigs × two views into a folder: the classic-shading rig's items fail with the path tracer's
    // reason (exit 1), the physically based rig's are written, and the summary says which.
    void catalogWithARefusedRig() {
        QTemporaryDir dir;
        const CliRun run = runLightrig(
            traced({QStringLiteral("--rig"), rig("minimal.json"), QStringLiteral("--rig"), rig("area.json"),
                    QStringLiteral("--view"), QStringLiteral("front,top"), QStringLiteral("--summary"),
                    QStringLiteral("-"), QStringLiteral("-o"), dir.path() + QLatin1Char('/')}));
        QCOMPARE(run.code, 1);
        QVERIFY2(run.err.contains(QLatin1String("uses classic shading")), qPrintable(run.show()));
        int ok = 0, failed = 0;
        for (const QString& line : run.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
            const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
            const bool isOk = o.value(QStringLiteral("status")).toString() == QLatin1String("ok");
            const QString rigName = o.value(QStringLiteral("rig")).toString();
            QVERIFY2(isOk == rigName.endsWith(QLatin1String("area.json")), qPrintable(line));
            QCOMPARE(QFile::exists(o.value(QStringLiteral("file")).toString()), isOk);
            if (isOk) { // a traced item's samples, noise and what stopped it
                QCOMPARE(o.value(QStringLiteral("samples")).toInt(), 2);
                QVERIFY(o.value(QStringLiteral("noise")).isDouble() &&
                        o.value(QStringLiteral("noise")).toDouble() >= 0.0);
                QCOMPARE(o.value(QStringLiteral("stopped_by")).toString(), QStringLiteral("samples"));
            }
            (isOk ? ok : failed) += 1;
        }
        QCOMPARE(ok, 2);
        QCOMPARE(failed, 2);
        const QImage front(dir.filePath(QStringLiteral("pbr_area_front.png"))),
            top(dir.filePath(QStringLiteral("pbr_area_top.png")));
        QCOMPARE(front.size(), QSize(40, 30));
        QVERIFY(front != top);
    }

    // `compare --quality path` traces both rigs with one seed and no display: one rig against itself is
    // identical (PSNR inf), two rigs differ, and a classic-shading rig B is refused naming B.
    void compareTraced() {
        QTemporaryDir dir;
        const QProcessEnvironment env = environmentWithoutDisplay();
        const auto compare = [&](const char* a, const char* b) {
            return runLightrig({QStringLiteral("compare"), model(), rig(a), rig(b),
                                QStringLiteral("--quality"), QStringLiteral("path"),
                                QStringLiteral("--samples"), QStringLiteral("2"), QStringLiteral("--size"),
                                QStringLiteral("40x30"), QStringLiteral("-o"),
                                dir.filePath(QStringLiteral("diff.png"))},
                               &env);
        };
        const CliRun same = compare("area.json", "area.json");
        QVERIFY2(same.code == 0, qPrintable(same.show()));
        QVERIFY2(same.out.contains(QLatin1String("PSNR inf dB")), qPrintable(same.show()));
        QVERIFY2(same.out.contains(QLatin1String("path traced, 2 samples per pixel")),
                 qPrintable(same.show()));
        const CliRun other = compare("area.json", "environment.json");
        QVERIFY2(other.code == 0, qPrintable(other.show()));
        QVERIFY2(!other.out.contains(QLatin1String("PSNR inf dB")), qPrintable(other.show()));
        QVERIFY(QFile::exists(dir.filePath(QStringLiteral("diff.png"))));
        const CliRun classic = compare("area.json", "minimal.json");
        QCOMPARE(classic.code, 1);
        QVERIFY2(classic.err.contains(QLatin1String("rig B: ")) &&
                     classic.err.contains(QLatin1String("uses classic shading")),
                 qPrintable(classic.show()));
    }
};

QTEST_MAIN(TraceCatalog)
#include "tst_trace_catalog.moc"
