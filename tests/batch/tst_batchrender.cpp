// Issue 17, parts 2 and 3: `lightrig render` turntables and batch catalogs as a user runs them (QProcess on
// the built executable). A 3-model × 2-rig catalog under GNU parallel -j2 (Debian `parallel`, installed by
// scripts/setup.sh) writes every {model}_{rig}_{view}.png as a PNG of the asked size with one summary line
// each; a catalog with a model that does not import exits 1 and still renders the rest; a 12-frame
// turntable writes 12 distinct images whose frame 0 is the plain render of its view; usage errors exit 2.
#include "render/glfixture.h"
#include "support/cli.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QImageReader>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

namespace {

using Run = lrtest::CliRun;

QString source(const char* path) {
    return QStringLiteral(LIGHTRIG_SOURCE_DIR "/") + QLatin1String(path);
}
const QStringList kModels{source("resources/models/suzanne/Suzanne.gltf"),
                          source("tests/data/model/tetra.stl"), source("tests/data/model/shiny.obj")};
const QStringList kModelNames{QStringLiteral("Suzanne"), QStringLiteral("tetra"), QStringLiteral("shiny")};
const QStringList kRigs{source("resources/presets/three-point.json"),
                        source("resources/presets/rim-backlight.json")};
const QStringList kRigNames{QStringLiteral("three-point"), QStringLiteral("rim-backlight")};

// "" when `path` is a PNG file of `size`, else what is wrong.
QString checkPng(const QString& path, QSize size) {
    QImageReader reader(path);
    if (reader.format() != "png") return path + QStringLiteral(": not a PNG");
    const QImage image = reader.read();
    if (image.isNull()) return path + QStringLiteral(": does not decode: ") + reader.errorString();
    if (image.size() != size)
        return QStringLiteral("%1: %2x%3").arg(path).arg(image.width()).arg(image.height());
    return {};
}

QList<QJsonObject> jsonLines(const QByteArray& text) {
    QList<QJsonObject> lines;
    for (const QByteArray& line : text.split('\n'))
        if (!line.trimmed().isEmpty()) lines << QJsonDocument::fromJson(line).object();
    return lines;
}

QImage rgba(const QString& path) {
    return QImage(path).convertToFormat(QImage::Format_RGBA8888);
}

} // namespace

class TestBatchRender : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

    QString path(const QString& name) const { return m_dir.filePath(name); }
    Run lightrig(const QStringList& args) {
        return lrtest::runLightrig(QStringList{QStringLiteral("render")} + args, nullptr, 300000);
    }

  private slots:
    void initTestCase() { QVERIFY(m_dir.isValid()); }

    void usageErrorsExit2_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QString m = kModels[0], o = path(QStringLiteral("never.png"));
        QTest::newRow("two models, one file")
            << QStringList{m, kModels[1], QStringLiteral("-o"), o}
            << QStringLiteral("several models need -o FOLDER or a pattern with {model}");
        QTest::newRow("two rigs, one file")
            << QStringList{m,        QStringLiteral("--rig"), kRigs[0], QStringLiteral("--rig"),
                           kRigs[1], QStringLiteral("-o"),    o}
            << QStringLiteral("would both write");
        QTest::newRow("turntable without #")
            << QStringList{m, QStringLiteral("--turntable"), QStringLiteral("12"), QStringLiteral("-o"), o}
            << QStringLiteral("--turntable 12 needs a run of # in the output's file name");
        QTest::newRow("turntable 0") << QStringList{m, QStringLiteral("--turntable"), QStringLiteral("0"),
                                                    QStringLiteral("-o"), o}
                                     << QStringLiteral("--turntable must be a number of frames");
        QTest::newRow("rotate without turntable")
            << QStringList{m, QStringLiteral("--rotate"), QStringLiteral("lights"), QStringLiteral("-o"), o}
            << QStringLiteral("--rotate needs --turntable N");
        QTest::newRow("bad rotate") << QStringList{m,
                                                   QStringLiteral("--turntable"),
                                                   QStringLiteral("4"),
                                                   QStringLiteral("--rotate"),
                                                   QStringLiteral("model"),
                                                   QStringLiteral("-o"),
                                                   path(QStringLiteral("t_#.png"))}
                                    << QStringLiteral("--rotate must be \"camera\" or \"lights\"");
        QTest::newRow("bad view in a list")
            << QStringList{m, QStringLiteral("--view"), QStringLiteral("front,sideways"),
                           QStringLiteral("-o"), path(QStringLiteral("{view}.png"))}
            << QStringLiteral("got 'sideways'");
        QTest::newRow("same name in two folders")
            << QStringList{m,
                           source("tests/data/model/hostile/../../../../resources/models/suzanne/"
                                  "Suzanne.gltf"),
                           QStringLiteral("-o"), m_dir.path() + QLatin1Char('/')}
            << QStringLiteral("would both write");
    }

    void usageErrorsExit2() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const Run r = lightrig(args);
        QVERIFY2(r.code == 2, qPrintable(r.show()));
        QVERIFY2(r.err.contains(message), qPrintable(r.show()));
        QVERIFY(QDir(m_dir.path()).entryList(QDir::Files).isEmpty()); // nothing rendered
    }

    // The catalog of the issue's done-when under GNU parallel: one job per model and rig, two at a time, the
    // jobs' summary lines collected on parallel's stdout.
    void catalogUnderGnuParallel() {
        LR_REQUIRE_DISPLAY();
        const QString parallel = QStandardPaths::findExecutable(QStringLiteral("parallel"));
        QVERIFY2(!parallel.isEmpty(), "GNU parallel is missing: scripts/setup.sh installs Debian's parallel");
        const QString out = path(QStringLiteral("catalog/"));
        QVERIFY(QDir().mkpath(out));
        QProcess p;
        p.setProgram(parallel);
        p.setArguments(QStringList{QStringLiteral("-j2"), lrtest::lightrigExecutable(),
                                   QStringLiteral("render"), QStringLiteral("{1}"), QStringLiteral("--rig"),
                                   QStringLiteral("{2}"), QStringLiteral("-o"), out, QStringLiteral("--size"),
                                   QStringLiteral("96x64"), QStringLiteral("--summary"), QStringLiteral("-"),
                                   QStringLiteral(":::")} +
                       kModels + QStringList{QStringLiteral(":::")} + kRigs);
        p.start();
        QVERIFY(p.waitForFinished(300000));
        const QByteArray stdoutText = p.readAllStandardOutput();
        const QString detail = QString::fromUtf8(stdoutText + "\n" + p.readAllStandardError());
        QVERIFY2(p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0, qPrintable(detail));
        const QList<QJsonObject> lines = jsonLines(stdoutText);
        QCOMPARE(lines.size(), 6);
        QSet<QString> files;
        for (const QJsonObject& line : lines) {
            QVERIFY2(line.value(QStringLiteral("status")).toString() == QLatin1String("ok"),
                     qPrintable(detail));
            QVERIFY(line.value(QStringLiteral("error")).isNull());
            QVERIFY(line.value(QStringLiteral("seconds")).toDouble(-1) >= 0.0);
            QCOMPARE(line.value(QStringLiteral("view")).toString(), QStringLiteral("default"));
            files << QDir::cleanPath(line.value(QStringLiteral("file")).toString());
        }
        for (const QString& model : kModelNames)
            for (const QString& rig : kRigNames) {
                const QString file =
                    QDir::cleanPath(out + QStringLiteral("%1_%2_default.png").arg(model, rig));
                QVERIFY2(files.contains(file),
                         qPrintable(file + QStringLiteral(" not in the summary\n") + detail));
                const QString problem = checkPng(file, QSize(96, 64));
                QVERIFY2(problem.isEmpty(), qPrintable(problem));
            }
        QCOMPARE(QDir(out).entryList(QDir::Files).size(), 6);
    }

    // One process, several models, rigs and views: a model that does not import fails its items (exit 1,
    // said once, summary lines "failed" with the reason) and the others are written, named by the pattern.
    void catalogInOneProcessRendersTheRestOfAFailure() {
        LR_REQUIRE_DISPLAY();
        const QString summary = path(QStringLiteral("one/summary.jsonl"));
        QVERIFY(QDir().mkpath(path(QStringLiteral("one"))));
        const QString missing = path(QStringLiteral("missing.glb"));
        const Run r = lightrig({kModels[0], missing, kModels[1], QStringLiteral("--rig"), kRigs[0],
                                QStringLiteral("--view"), QStringLiteral("front,top"), QStringLiteral("-o"),
                                path(QStringLiteral("one/{model}-{view}.png")), QStringLiteral("--size"),
                                QStringLiteral("48x32"), QStringLiteral("--summary"), summary});
        QVERIFY2(r.code == 1, qPrintable(r.show()));
        QCOMPARE(r.errorLines().filter(QStringLiteral("missing.glb")).size(), 1);
        QFile f(summary);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QJsonObject> lines = jsonLines(f.readAll());
        QCOMPARE(lines.size(), 6);
        int failed = 0;
        for (const QJsonObject& line : lines) {
            const QString file = line.value(QStringLiteral("file")).toString();
            if (line.value(QStringLiteral("status")).toString() == QLatin1String("failed")) {
                ++failed;
                QVERIFY(
                    line.value(QStringLiteral("error")).toString().contains(QStringLiteral("missing.glb")));
                QVERIFY(!QFile::exists(file));
                continue;
            }
            QCOMPARE(line.value(QStringLiteral("rig")).toString(), kRigs[0]);
            const QString problem = checkPng(file, QSize(48, 32));
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
        }
        QCOMPARE(failed, 2);
        for (const char* name : {"Suzanne-front", "Suzanne-top", "tetra-front", "tetra-top"})
            QVERIFY(QFile::exists(path(QStringLiteral("one/%1.png").arg(QLatin1String(name)))));
        QVERIFY(rgba(path(QStringLiteral("one/Suzanne-front.png"))) !=
                rgba(path(QStringLiteral("one/Suzanne-top.png"))));
        QVERIFY(rgba(path(QStringLiteral("one/Suzanne-front.png"))) != // each model is its own
                rgba(path(QStringLiteral("one/tetra-front.png"))));
    }

    // 12 frames around the model: 12 files, no two images alike, frame 0 the plain render of the view.
    // With --rotate lights the camera stays and the rig turns: frame 0 the same, the others different.
    void turntable_data() {
        QTest::addColumn<QString>("rotate");
        QTest::addColumn<int>("frames");
        QTest::newRow("camera, 12 frames") << QStringLiteral("camera") << 12;
        QTest::newRow("lights, 4 frames") << QStringLiteral("lights") << 4;
    }

    void turntable() {
        LR_REQUIRE_DISPLAY();
        QFETCH(QString, rotate);
        QFETCH(int, frames);
        const QString folder = path(QStringLiteral("turntable-") + rotate);
        QVERIFY(QDir().mkpath(folder));
        const QStringList common{kModels[0],
                                 QStringLiteral("--rig"),
                                 kRigs[0],
                                 QStringLiteral("--view"),
                                 QStringLiteral("three-quarter"),
                                 QStringLiteral("--size"),
                                 QStringLiteral("96x64")};
        const Run r = lightrig(common + QStringList{QStringLiteral("--turntable"), QString::number(frames),
                                                    QStringLiteral("--rotate"), rotate, QStringLiteral("-o"),
                                                    folder + QStringLiteral("/tt_###.png")});
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        QCOMPARE(r.lines().size(), frames); // one "wrote" line per frame
        QCOMPARE(QDir(folder).entryList(QDir::Files).size(), frames);
        QList<QImage> images;
        for (int k = 0; k < frames; ++k) {
            const QString file = folder + QStringLiteral("/tt_%1.png").arg(k, 3, 10, QLatin1Char('0'));
            const QString problem = checkPng(file, QSize(96, 64));
            QVERIFY2(problem.isEmpty(), qPrintable(problem));
            images << rgba(file);
        }
        for (int a = 0; a < frames; ++a)
            for (int b = a + 1; b < frames; ++b)
                QVERIFY2(images[a] != images[b],
                         qPrintable(QStringLiteral("frames %1 and %2 are alike").arg(a).arg(b)));
        const Run plain =
            lightrig(common + QStringList{QStringLiteral("-o"), folder + QStringLiteral("/plain.png")});
        QVERIFY2(plain.code == 0, qPrintable(plain.show()));
        QVERIFY(images[0] == rgba(folder + QStringLiteral("/plain.png")));
    }
};

LR_GL_TEST_MAIN(TestBatchRender)
#include "tst_batchrender.moc"
