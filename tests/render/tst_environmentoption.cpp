// The command line's environment options in process (src/cli/environmentoption.h, sceneoptions.h; issue
// 15): parsing and its errors, applying them to a rig's environment, where relative files are found, the
// environment loaded with the scene and handed to the renderer, and validate's check.
#include "cli/environmentoption.h"
#include "cli/sceneoptions.h"
#include "core/rigjson.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;
using namespace lr::cli;

namespace {

QString suzanne() {
    return QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/suzanne/Suzanne.gltf");
}

// The scene options of `lightrig render ARGS...`, or the usage error.
std::optional<SceneOptions> parse(const QStringList& args, QString* error) {
    QCommandLineParser parser;
    const SceneOptionSet set;
    set.addTo(parser);
    if (!parser.parse(QStringList{QStringLiteral("render")} + args)) {
        *error = parser.errorText();
        return std::nullopt;
    }
    return set.read(parser, error);
}

} // namespace

class TestEnvironmentOption : public QObject {
    Q_OBJECT
  private slots:
    void parsesAndApplies();
    void badValues_data();
    void badValues();
    void sources();
    void folders();
    void sceneCarriesTheEnvironmentToTheRenderer();
    void loadErrorsNameTheFile();
    void loadedEnvironmentServesAgain();
    void validateChecksTheEnvironment();
};

void TestEnvironmentOption::parsesAndApplies() {
    QString error;
    const auto o = parse({QStringLiteral("--environment"), QStringLiteral("hdr/sky.exr"),
                          QStringLiteral("--environment-intensity"), QStringLiteral("-2.5"),
                          QStringLiteral("--environment-rotation"), QStringLiteral("-90"),
                          QStringLiteral("--environment-background"), QStringLiteral("blurred")},
                         &error);
    QVERIFY2(o, qPrintable(error));
    QCOMPARE(o->environment.source, QStringLiteral("hdr/sky.exr"));
    Environment e;
    e.source = EnvironmentSource::Studio;
    e.studio.softboxes = {Softbox{}};
    e.spots = {EnvironmentSpot{}};
    e.blur = 0.7;
    applyEnvironmentOverrides(e, o->environment);
    QVERIFY(e.source == EnvironmentSource::Image);
    QCOMPARE(e.file, QDir::current().absoluteFilePath(QStringLiteral("hdr/sky.exr"))); // the current folder's
    QCOMPARE(e.intensity, -2.5);
    QCOMPARE(e.rotation, 270.0);
    QVERIFY(e.background == EnvironmentBackground::Blurred);
    QCOMPARE(e.blur, 0.7); // the rest is the rig's
    QCOMPARE(e.studio.softboxes.size(), size_t(1));
    QCOMPARE(e.spots.size(), size_t(1));

    // Without the options nothing changes.
    const auto none = parse({}, &error);
    QVERIFY(none);
    Environment kept = e;
    applyEnvironmentOverrides(kept, none->environment);
    QVERIFY(kept == e);
}

void TestEnvironmentOption::badValues_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    const auto row = [](const char* name, const char* option, const char* value, const char* message) {
        QTest::newRow(name) << QStringList{QString::fromLatin1(option), QString::fromLatin1(value)}
                            << QString::fromUtf8(message);
    };
    row("intensity 21", "--environment-intensity", "21",
        "--environment-intensity must be a number of EV in -20..20, got '21'");
    row("intensity word", "--environment-intensity", "bright",
        "--environment-intensity must be a number of EV in -20..20, got 'bright'");
    row("intensity inf", "--environment-intensity", "inf",
        "--environment-intensity must be a number of EV in -20..20, got 'inf'");
    row("rotation nan", "--environment-rotation", "nan",
        "--environment-rotation must be a finite number of degrees, got 'nan'");
    row("rotation 1e999", "--environment-rotation", "1e999",
        "--environment-rotation must be a finite number of degrees, got '1e999'");
    row("background", "--environment-background", "blur",
        "--environment-background must be \"visible\", \"blurred\" or \"color\", got 'blur'");
    row("empty environment", "--environment", "", "--environment needs a file, builtin:NAME, studio or none");
    row("builtin without a name", "--environment",
        "builtin:", "--environment builtin: needs the name of a bundled environment after it");
}

void TestEnvironmentOption::badValues() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    QString error;
    QVERIFY(!parse(args, &error));
    QVERIFY2(error.startsWith(message), qPrintable(error));
}

// studio: the rig's studio settings; none: off (the file kept for later); builtin:NAME as given.
void TestEnvironmentOption::sources() {
    Environment rig;
    rig.source = EnvironmentSource::Image;
    rig.file = QStringLiteral("sky.hdr");
    rig.studio.zenith = glm::dvec3(2.0);
    Environment e = rig;
    EnvironmentOverrides o;
    o.source = QStringLiteral("studio");
    applyEnvironmentOverrides(e, o);
    QVERIFY(e.source == EnvironmentSource::Studio && e.studio == rig.studio);
    QCOMPARE(environmentName(e), QStringLiteral("studio environment"));
    o.source = QStringLiteral("none");
    applyEnvironmentOverrides(e, o);
    QVERIFY(e.isNone());
    QCOMPARE(e.file, QStringLiteral("sky.hdr"));
    QCOMPARE(environmentName(e), QString());
    o.source = QStringLiteral("builtin:studio");
    applyEnvironmentOverrides(e, o);
    QVERIFY(e.source == EnvironmentSource::Image);
    QCOMPARE(e.file, QStringLiteral("builtin:studio"));
    QCOMPARE(environmentName(e), QStringLiteral("environment builtin:studio"));
    o.source = QStringLiteral("/abs/sky.exr");
    applyEnvironmentOverrides(e, o);
    QCOMPARE(e.file, QStringLiteral("/abs/sky.exr"));
}

// A rig's relative file is found beside the rig; a rig that is no file (the default rule's, a built-in
// preset) resolves against the current folder.
void TestEnvironmentOption::folders() {
    QCOMPARE(environmentFolder(QStringLiteral("/rigs/studio/key.json")), QStringLiteral("/rigs/studio"));
    QCOMPARE(environmentFolder(QStringLiteral("key.json")), QDir::currentPath());
    QCOMPARE(environmentFolder(QString()), QDir::currentPath());
    QCOMPARE(environmentFolder(QStringLiteral(":/resources/presets/pbr-hdri-studio.json")),
             QDir::currentPath());
}

// --environment studio: the scene's rig has it, the loaded (prefiltered) environment comes with the scene
// and reaches the renderer through showScene, as `lightrig render` does; without it, nothing does.
void TestEnvironmentOption::sceneCarriesTheEnvironmentToTheRenderer() {
    QString error;
    auto options = parse({QStringLiteral("--environment"), QStringLiteral("studio"),
                          QStringLiteral("--environment-intensity"), QStringLiteral("1")},
                         &error);
    QVERIFY2(options, qPrintable(error));
    LoadedScene scene;
    QVERIFY2(loadScene(suzanne(), *options, &scene, &error), qPrintable(error));
    QVERIFY(scene.environment);
    QVERIFY(scene.rig.environment.source == EnvironmentSource::Studio);
    QCOMPARE(scene.rig.environment.intensity, 1.0);
    QVERIFY(scene.environment->spec.sameRadiance(scene.rig.environment));
    QVERIFY(!scene.environment->image.isNull());
    QVERIFY2(scene.rigSource.endsWith(QStringLiteral(", studio environment")), qPrintable(scene.rigSource));
    Renderer renderer;
    showScene(renderer, scene);
    QVERIFY(renderer.environment() != nullptr);
    QVERIFY(renderer.environment() == scene.environment);

    options = parse({}, &error);
    LoadedScene plain;
    QVERIFY2(loadScene(suzanne(), *options, &plain, &error), qPrintable(error));
    QVERIFY(!plain.environment);
    QVERIFY(!plain.rigSource.contains(QStringLiteral("environment")));
    showScene(renderer, plain);
    QVERIFY(renderer.environment() == nullptr);
}

// A file that cannot be loaded fails the scene with a message naming it: given on the command line
// (relative to the current folder) or written in the rig (relative to the rig's folder).
void TestEnvironmentOption::loadErrorsNameTheFile() {
    QString error;
    auto options = parse({QStringLiteral("--environment"), QStringLiteral("no-such-sky.exr")}, &error);
    QVERIFY(options);
    LoadedScene scene;
    QVERIFY(!loadScene(suzanne(), *options, &scene, &error));
    QVERIFY2(error.contains(QStringLiteral("no-such-sky.exr")), qPrintable(error));

    QTemporaryDir dir;
    Rig rig;
    rig.environment.source = EnvironmentSource::Image;
    rig.environment.file = QStringLiteral("hdr/missing.exr");
    const QString rigPath = dir.filePath(QStringLiteral("env.json"));
    QVERIFY2(saveRigFile(rig, rigPath, &error), qPrintable(error));
    options = parse({QStringLiteral("--rig"), rigPath}, &error);
    QVERIFY(options);
    QVERIFY(!loadScene(suzanne(), *options, &scene, &error));
    QVERIFY2(error.contains(QStringLiteral("missing.exr")), qPrintable(error));
    // --environment none switches it off: the scene loads.
    options = parse(
        {QStringLiteral("--rig"), rigPath, QStringLiteral("--environment"), QStringLiteral("none")}, &error);
    QVERIFY2(loadScene(suzanne(), *options, &scene, &error), qPrintable(error));
    QVERIFY(!scene.environment);
}

// An environment loaded already is kept for the same radiance from the same file (intensity and rotation
// are uniforms), and loaded anew for other radiance, another file, or the same relative name elsewhere.
void TestEnvironmentOption::loadedEnvironmentServesAgain() {
    const QString data = QFINDTESTDATA("../data/environment/tiny.hdr");
    QVERIFY(!data.isEmpty());
    QTemporaryDir a, b;
    QVERIFY(QFile::copy(data, a.filePath(QStringLiteral("sky.hdr"))) &&
            QFile::copy(data, b.filePath(QStringLiteral("sky.hdr"))));
    Environment e;
    e.source = EnvironmentSource::Image;
    e.file = QStringLiteral("sky.hdr");
    QString error;
    std::shared_ptr<const LoadedEnvironment> loaded;
    QVERIFY2(loadCliEnvironment(e, a.path(), &loaded, &error), qPrintable(error));
    const auto first = loaded;
    QVERIFY(first);
    e.intensity = 2.0, e.rotation = 90.0;
    QVERIFY2(loadCliEnvironment(e, a.path(), &loaded, &error), qPrintable(error));
    QVERIFY(loaded == first); // served again: no second decode or prefilter
    QVERIFY2(loadCliEnvironment(e, b.path(), &loaded, &error), qPrintable(error));
    QVERIFY(loaded && loaded != first); // the same name in another folder is another file
    const auto second = loaded;
    e.spots.push_back(EnvironmentSpot{});
    QVERIFY2(loadCliEnvironment(e, b.path(), &loaded, &error), qPrintable(error));
    QVERIFY(loaded && loaded != second); // dimmed spots change the radiance
    e.source = EnvironmentSource::None;
    QVERIFY(loadCliEnvironment(e, b.path(), &loaded, &error) && !loaded);
}

// `lightrig validate`'s check: a studio loads; an image that does not is an error at environment.file.
void TestEnvironmentOption::validateChecksTheEnvironment() {
    Rig rig;
    RigReadResult result;
    QVERIFY(checkEnvironment(rig, QStringLiteral("none.json"), &result));
    rig.environment.source = EnvironmentSource::Studio;
    QVERIFY(checkEnvironment(rig, QStringLiteral("studio.json"), &result));
    QVERIFY(result.errors.isEmpty());
    rig.environment.source = EnvironmentSource::Image;
    rig.environment.file = QStringLiteral("missing.exr");
    QVERIFY(!checkEnvironment(rig, QStringLiteral("/rigs/image.json"), &result));
    QCOMPARE(result.errors.size(), 1);
    QVERIFY2(result.errors[0].startsWith(QStringLiteral("/rigs/image.json: environment.file: ")) &&
                 result.errors[0].contains(QStringLiteral("missing.exr")),
             qPrintable(result.errors[0]));
}

QTEST_GUILESS_MAIN(TestEnvironmentOption)
#include "tst_environmentoption.moc"
