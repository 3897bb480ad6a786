// `lightrig export` (src/cli/export.cpp) as a user runs it: glTF, GLB and (through Assimp) OBJ sources, the
// lights-only export, every export checked by the Khronos glTF-Validator (no error the source does not have
// itself), lossy conversions listed on stderr, and bad input refused with nothing written.
#include "support/cli.h"
#include "support/files.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <unistd.h>

using namespace lrtest;

namespace {

const QString kData = QStringLiteral(LIGHTRIG_TEST_DATA "/model/");

QString validatorDir() {
    const QString env = qEnvironmentVariable("LIGHTRIG_GLTF_VALIDATOR");
    if (!env.isEmpty()) return env;
    const QString cache =
        qEnvironmentVariable("XDG_CACHE_HOME", QDir::homePath() + QStringLiteral("/.cache"));
    return cache + QStringLiteral("/lightrig/gltf-validator");
}

// The validator's report of each file: {"file", "errors", "messages"...}. *missing (and *why) when it cannot
// run at all; *why alone when it ran and did not report on every file (it failed on one of them).
QList<QJsonObject> validate(const QStringList& files, QString* why, bool* missing) {
    QProcess node;
    node.start(QStringLiteral("node"),
               QStringList{QStringLiteral(LIGHTRIG_VALIDATE_GLTF), validatorDir()} + files);
    if (!node.waitForStarted(10000)) {
        *why = QStringLiteral("node is not installed (scripts/setup.sh installs nodejs and gltf-validator)");
        *missing = true;
        return {};
    }
    node.waitForFinished(120000);
    if (node.exitCode() == 2) {
        *why = QString::fromUtf8(node.readAllStandardError()).trimmed();
        *missing = true;
        return {};
    }
    QList<QJsonObject> reports;
    for (const QByteArray& line : node.readAllStandardOutput().split('\n'))
        if (!line.isEmpty()) reports << QJsonDocument::fromJson(line).object();
    if (reports.size() != files.size())
        *why = QStringLiteral("the validator failed: %1").arg(QString::fromUtf8(node.readAllStandardError()));
    return reports;
}

QStringList errorsOf(const QJsonObject& report) {
    QStringList errors;
    const int n = report.value(QStringLiteral("errors")).toInt();
    const QJsonArray messages = report.value(QStringLiteral("messages")).toArray();
    for (qsizetype i = 0; i < n && i < messages.size(); ++i)
        errors << messages[i].toString();
    return errors;
}

} // namespace

class TestExportCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

  private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        // Sources with files beside them are exported into their own folder: copies here.
        for (const QString& f :
             {QStringLiteral("scene.gltf"), QStringLiteral("normal.png"), QStringLiteral("pbr.gltf"),
              QStringLiteral("quad.obj"), QStringLiteral("quad.mtl"), QStringLiteral("checker.png")})
            QVERIFY(copyWritable(kData + f, path(f)));
        const QString suzanne = QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/suzanne/");
        for (const QString& f : QDir(suzanne).entryList(QDir::Files))
            QVERIFY(copyWritable(suzanne + f, path(f)));
        // Issue 41: texture URIs written on Windows (win/): `.\normal.png` and `D:\maps\normal.png` name
        // the normal.png beside the model; unreachable.gltf also names files that are nowhere.
        QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("win")));
        QVERIFY(copyWritable(kData + QStringLiteral("normal.png"), path(QStringLiteral("win/normal.png"))));
        QJsonObject scene = QJsonDocument::fromJson(readFile(kData + QStringLiteral("scene.gltf"))).object();
        QJsonArray textures = scene.value(QStringLiteral("textures")).toArray();
        textures.append(QJsonObject{{QStringLiteral("source"), 1}});
        scene.insert(QStringLiteral("textures"), textures);
        const auto image = [](const char* uri) {
            return QJsonObject{{QStringLiteral("uri"), QLatin1String(uri)}};
        };
        scene.insert(QStringLiteral("images"),
                     QJsonArray{image(".\\normal.png"), image("D:\\maps\\normal.png")});
        QVERIFY(writeFile(path(QStringLiteral("win/fixable.gltf")), QJsonDocument(scene).toJson()));
        scene.insert(QStringLiteral("images"),
                     QJsonArray{image("textures\\gone.png"), image("D:\\maps\\nowhere.png")});
        QVERIFY(writeFile(path(QStringLiteral("win/unreachable.gltf")), QJsonDocument(scene).toJson()));
    }

    void exportsPassTheValidator_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("source");
        QTest::addColumn<QString>("out");
        const QString pbr = QStringLiteral(":/resources/presets/pbr-three-point.json");
        const QString classic = QStringLiteral(":/resources/presets/default.json");
        QTest::newRow("suzanne classic")
            << QStringList{QStringLiteral("--rig"), classic} << path(QStringLiteral("Suzanne.gltf"))
            << path(QStringLiteral("suzanne.gltf"));
        QTest::newRow("suzanne glb") << QStringList{QStringLiteral("--view"), QStringLiteral("front")}
                                     << path(QStringLiteral("Suzanne.gltf"))
                                     << path(QStringLiteral("suzanne.glb"));
        QTest::newRow("scene own lights")
            << QStringList{} << path(QStringLiteral("scene.gltf")) << path(QStringLiteral("scene-out.gltf"));
        QTest::newRow("pbr materials") << QStringList{QStringLiteral("--rig"), pbr}
                                       << path(QStringLiteral("pbr.gltf")) << path(QStringLiteral("pbr.glb"));
        QTest::newRow("obj through assimp")
            << QStringList{QStringLiteral("--rig"), pbr} << path(QStringLiteral("quad.obj"))
            << path(QStringLiteral("quad.glb"));
        QTest::newRow("lights only gltf")
            << QStringList{QStringLiteral("--lights-only"), QStringLiteral("--rig"), classic}
            << path(QStringLiteral("Suzanne.gltf")) << path(QStringLiteral("lights.gltf"));
        QTest::newRow("lights only glb")
            << QStringList{QStringLiteral("--lights-only")} << path(QStringLiteral("scene.gltf"))
            << path(QStringLiteral("lights.glb"));
        QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("elsewhere/deeper")));
        QTest::newRow("gltf written elsewhere") << QStringList{} << path(QStringLiteral("Suzanne.gltf"))
                                                << path(QStringLiteral("elsewhere/deeper/suzanne.gltf"));
        QTest::newRow("obj written elsewhere") << QStringList{} << path(QStringLiteral("quad.obj"))
                                               << path(QStringLiteral("elsewhere/quad.glb"));
        QTest::newRow("windows texture paths, written elsewhere")
            << QStringList{} << path(QStringLiteral("win/fixable.gltf"))
            << path(QStringLiteral("elsewhere/win.gltf"));
        QTest::newRow("windows texture paths, same folder")
            << QStringList{} << path(QStringLiteral("win/fixable.gltf"))
            << path(QStringLiteral("win/out.gltf"));
        QTest::newRow("windows texture paths, glb")
            << QStringList{} << path(QStringLiteral("win/fixable.gltf")) << path(QStringLiteral("win.glb"));
        const QString helmet = QStringLiteral(LIGHTRIG_SHARED_MODELS "/bench/helmet_8spot.glb");
        if (QFile::exists(helmet))
            QTest::newRow("helmet 8 spots")
                << QStringList{QStringLiteral("--rig"), pbr} << helmet << path(QStringLiteral("helmet.glb"));
    }
    void exportsPassTheValidator() {
        QFETCH(QStringList, args);
        QFETCH(QString, source);
        QFETCH(QString, out);
        const CliRun run =
            runLightrig(QStringList{QStringLiteral("export"), source, QStringLiteral("-o"), out} + args);
        QVERIFY2(run.code == 0, qPrintable(run.show()));
        QVERIFY(run.out.startsWith(QStringLiteral("wrote ") + out));
        const QJsonObject exported =
            QJsonDocument::fromJson(out.endsWith(QLatin1String(".gltf")) ? readFile(out) : QByteArray())
                .object();
        if (out.endsWith(QLatin1String(".gltf")) && args.contains(QStringLiteral("--lights-only")))
            QVERIFY(!exported.contains(QStringLiteral("meshes")) &&
                    exported.contains(QStringLiteral("nodes")));
        // No error the source does not have itself (pbr.gltf has out-of-range factors on purpose; an OBJ
        // source is not glTF and is not validated).
        const bool gltfSource = !source.endsWith(QLatin1String(".obj"));
        QString why;
        bool missing = false;
        const QList<QJsonObject> reports =
            validate(gltfSource ? QStringList{source, out} : QStringList{out}, &why, &missing);
        if (missing) QSKIP(qPrintable(QStringLiteral("cannot run the Khronos glTF-Validator: ") + why));
        QVERIFY2(why.isEmpty(), qPrintable(why)); // a file the validator failed on is an error, not a skip
        const QStringList before = gltfSource ? errorsOf(reports.first()) : QStringList();
        for (const QString& e : errorsOf(reports.last()))
            QVERIFY2(before.contains(e), qPrintable(QStringLiteral("%1: %2").arg(out, e)));
        if (!source.endsWith(QLatin1String("pbr.gltf")))
            QCOMPARE(reports.last().value(QStringLiteral("errors")).toInt(), 0);
    }

    // Issue 41: texture files a viewer will not find are said on stderr (they were silent), naming the
    // image and why; the references stay (a file put there later is found).
    void unreachableFilesAreNotes() {
        const CliRun run =
            runLightrig({QStringLiteral("export"), path(QStringLiteral("win/unreachable.gltf")),
                         QStringLiteral("-o"), path(QStringLiteral("unreachable.gltf"))});
        QVERIFY2(run.code == 0, qPrintable(run.show()));
        const QStringList notes = run.errorLines().filter(QStringLiteral("lightrig export: note: images["));
        QVERIFY2(notes.size() == 2, qPrintable(run.show()));
        QVERIFY2(notes[0].contains(QLatin1String("images[0].uri")) &&
                     notes[0].contains(QLatin1String("no such file")),
                 qPrintable(notes[0]));
        QVERIFY2(notes[1].contains(QLatin1String("images[1].uri")) &&
                     notes[1].contains(QLatin1String("Windows drive path")),
                 qPrintable(notes[1]));
        const QJsonArray images = QJsonDocument::fromJson(readFile(path(QStringLiteral("unreachable.gltf"))))
                                      .object()
                                      .value(QStringLiteral("images"))
                                      .toArray();
        QCOMPARE(images[0].toObject().value(QStringLiteral("uri")).toString(),
                 QStringLiteral("win/textures/gone.png"));
    }

    void lossyConversionsOnStderr() {
        const CliRun run =
            runLightrig({QStringLiteral("export"), path(QStringLiteral("Suzanne.gltf")),
                         QStringLiteral("--rig"), QStringLiteral(":/resources/presets/default.json"),
                         QStringLiteral("-o"), path(QStringLiteral("lossy.glb"))});
        QVERIFY2(run.code == 0, qPrintable(run.show()));
        const QStringList lossy = run.errorLines().filter(QStringLiteral("lightrig export: lossy: "));
        for (const char* what : {"classic intensities", "rim light", "ambient", "falloff", "spot cone"})
            QVERIFY2(!lossy.filter(QLatin1String(what)).isEmpty(), what);
        QVERIFY(run.out.contains(QStringLiteral("%1 lossy conversions").arg(lossy.size())));
    }

    // Issue 41: export over its own source (M.glb -o M.glb replaced the model's 8 lights with the rig's 3)
    // or over its rig is refused before anything is written, whatever the spelling.
    void outputThatIsAnInputIsRefused_data() {
        QTest::addColumn<QString>("model");
        QTest::addColumn<QString>("out");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("same path") << path(QStringLiteral("scene.gltf")) << path(QStringLiteral("scene.gltf"))
                                   << QStringLiteral("the model");
        QTest::newRow("spelled ./") << path(QStringLiteral("scene.gltf"))
                                    << m_dir.path() + QStringLiteral("/./scene.gltf")
                                    << QStringLiteral("the model");
        QTest::newRow("a link to it") << path(QStringLiteral("scene.gltf"))
                                      << path(QStringLiteral("link.gltf")) << QStringLiteral("the model");
        QTest::newRow("the rig") << path(QStringLiteral("scene.gltf")) << path(QStringLiteral("rig.gltf"))
                                 << QStringLiteral("the rig");
    }
    void outputThatIsAnInputIsRefused() {
        QFETCH(QString, model);
        QFETCH(QString, out);
        QFETCH(QString, mentions);
        QVERIFY(copyWritable(QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/presets/default.json"),
                             path(QStringLiteral("rig.gltf"))));
        QFile::remove(path(QStringLiteral("link.gltf")));
        QVERIFY(QFile::link(path(QStringLiteral("scene.gltf")), path(QStringLiteral("link.gltf"))));
        const QByteArray source = readFile(model), rig = readFile(path(QStringLiteral("rig.gltf")));
        const CliRun run = runLightrig({QStringLiteral("export"), model, QStringLiteral("--rig"),
                                        path(QStringLiteral("rig.gltf")), QStringLiteral("-o"), out});
        QVERIFY2(run.code == 1, qPrintable(run.show()));
        QVERIFY2(run.errorLines().size() == 1 && run.errorLines().first().contains(mentions),
                 qPrintable(run.show()));
        QCOMPARE(readFile(model), source);
        QCOMPARE(readFile(path(QStringLiteral("rig.gltf"))), rig);
    }

    // Issue 41: `render` died of SIGPIPE once in 5,200 renders (not reproduced: a write to an import worker
    // that had exited). LightRig ignores SIGPIPE from main() on, so a write to a pipe whose reader is gone
    // fails instead of killing it. Here the pipe is its stdout, read end closed before it starts: its help
    // is the first thing it writes (Qt ignores SIGPIPE only from its first write to a child process, and
    // resets it for the child, so lightrig starts with the default action).
    void aPipeWithoutReaderDoesNotKillLightRig() {
        int fds[2];
        QVERIFY(::pipe(fds) == 0);
        ::close(fds[0]);
        const int writeEnd = fds[1];
        QProcess p;
        p.setProgram(lightrigExecutable());
        p.setArguments({QStringLiteral("export"), QStringLiteral("--help")});
        p.setChildProcessModifier([writeEnd] { ::dup2(writeEnd, STDOUT_FILENO); });
        p.start();
        const bool finished = p.waitForFinished(60000);
        ::close(writeEnd);
        QVERIFY(finished);
        QVERIFY2(p.exitStatus() == QProcess::NormalExit,
                 qPrintable(QStringLiteral("killed by signal %1").arg(p.exitCode())));
    }

    void badInputWritesNothing_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<int>("code");
        const QString out = path(QStringLiteral("never.glb"));
        QTest::newRow("hostile glb") << QStringList{kData + QStringLiteral("hostile/glb-huge-chunk.glb"),
                                                    QStringLiteral("-o"), out}
                                     << 1;
        QTest::newRow("missing model")
            << QStringList{path(QStringLiteral("none.gltf")), QStringLiteral("-o"), out} << 1;
        QTest::newRow("bad rig") << QStringList{path(QStringLiteral("Suzanne.gltf")), QStringLiteral("--rig"),
                                                path(QStringLiteral("none.json")), QStringLiteral("-o"), out}
                                 << 1;
        QTest::newRow("camera") << QStringList{path(QStringLiteral("Suzanne.gltf")),
                                               QStringLiteral("--camera-index"), QStringLiteral("5"),
                                               QStringLiteral("-o"), out}
                                << 1;
        QTest::newRow("no folder") << QStringList{path(QStringLiteral("Suzanne.gltf")), QStringLiteral("-o"),
                                                  path(QStringLiteral("none/never.glb"))}
                                   << 1;
        QTest::newRow("bundled files")
            << QStringList{QStringLiteral(":/resources/models/suzanne/Suzanne.gltf"), QStringLiteral("-o"),
                           out}
            << 1;
        QTest::newRow("no output") << QStringList{path(QStringLiteral("Suzanne.gltf"))} << 2;
        QTest::newRow("suffix") << QStringList{path(QStringLiteral("Suzanne.gltf")), QStringLiteral("-o"),
                                               path(QStringLiteral("x.obj"))}
                                << 2;
        QTest::newRow("view") << QStringList{path(QStringLiteral("Suzanne.gltf")), QStringLiteral("--view"),
                                             QStringLiteral("up"), QStringLiteral("-o"), out}
                              << 2;
    }
    void badInputWritesNothing() {
        QFETCH(QStringList, args);
        QFETCH(int, code);
        const CliRun run = runLightrig(QStringList{QStringLiteral("export")} + args);
        QVERIFY2(run.code == code, qPrintable(run.show()));
        QVERIFY2(!run.errorLines().isEmpty(), qPrintable(run.show()));
        QVERIFY(!QFile::exists(path(QStringLiteral("never.glb"))));
        QVERIFY(!QFile::exists(path(QStringLiteral("none"))));
    }
};

QTEST_GUILESS_MAIN(TestExportCli)
#include "tst_exportcli.moc"
