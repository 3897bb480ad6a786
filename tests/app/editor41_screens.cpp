// Not a test: the editor screenshots for issue 41's environment and property items (3, 4, 14, 15), taken
// under Xvfb so the same steps can be grabbed before and after a change. Writes OUTDIR/PREFIX-*.png:
//   item3-truncated-exr   the error box after choosing a truncated EXR over the studio (the rig and view
//   kept) item4-studio-exr      studio.exr after Light from environment with "Dim the spot", looking at the
//   spot item4-procedural      the procedural studio likewise: the softbox dimmed, the sky around it kept
//   item14-softbox-edge   a softbox's edge magnified (8° field of view)
//   item14-gizmo          a white light's gizmo on a bright environment
//   item15-properties     the Properties dock (intensity unit, linear colour, temperature) and the History
//   item15-model-dock     the Model dock on MODEL (DamagedHelmet: no placeholder material)
//
//   xvfb-run -a -s "-screen 0 1920x1080x24" build/dev/tests/app/editor41_screens OUTDIR PREFIX MODEL
#include "app/environmentbox.h"
#include "app/environmentlighttool.h"
#include "app/environmentloading.h"
#include "app/modeldock.h"
#include "app/propertiesdock.h"
#include "app/rendersettingsdock.h"
#include "editor/environmentlight.h"
#include "scene/environmentloader.h"
#include "startwindow.h"

#include <QDir>
#include <QFile>
#include <QScreen>
#include <QTemporaryDir>
#include <QTimer>
#include <cstdio>
#include <functional>

using namespace lr;

namespace {
QString g_out, g_prefix;

QString pathFor(const QString& name) {
    return QDir(g_out).filePath(g_prefix + QLatin1Char('-') + name + QStringLiteral(".png"));
}

void report(bool ok, const QString& path) {
    std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
}

void save(QWidget* w, const QString& name) {
    QTest::qWait(800);
    report(w->grab().toImage().save(pathFor(name)), pathFor(name));
}

// The whole screen (a modal dialog over the window included).
void saveScreen(const QString& name) {
    QScreen* screen = QGuiApplication::primaryScreen();
    report(screen && screen->grabWindow(0).save(pathFor(name)), pathFor(name));
}

bool waitFor(const std::function<bool()>& done, int ms = 60000) {
    return QTest::qWaitFor(done, ms);
}

void setEnvironment(MainWindow& window, const Environment& e) {
    window.document()->setRigValue(RigProperty::Environment, QVariant::fromValue(e));
    waitFor([&] {
        return !window.environmentLoading()->isLoading() && window.scene()->environment() &&
               window.scene()->environment()->spec.sameRadiance(window.document()->rig().environment);
    });
    QTest::qWait(500);
}

void lookFromCentre(MainWindow& window, const glm::dvec3& d, double fov) {
    ViewCamera c = window.viewport()->camera();
    c.eye = window.scene()->frame().center - d * (0.01 * window.scene()->frame().radius);
    c.target = c.eye + d;
    c.up = glm::dvec3(0, 1, 0);
    c.yfovDeg = fov;
    window.viewport()->setCamera(c);
}
} // namespace

int main(int argc, char** argv) {
    Viewport::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    if (argc < 4) {
        std::fprintf(stderr, "usage: editor41_screens OUTDIR PREFIX MODEL\n");
        return 2;
    }
    g_out = QString::fromLocal8Bit(argv[1]);
    g_prefix = QString::fromLocal8Bit(argv[2]);
    const QString model = QString::fromLocal8Bit(argv[3]);
    test::prepareEditorTest(QStringLiteral("lightrig-screens41"));
    MainWindow window;
    window.files()->askUnsaved = [](const QString&) { return DocumentFiles::UnsavedAnswer::Discard; };
    window.resize(1280, 800);
    if (const QString e = test::startMainWindow(window); !e.isEmpty()) {
        std::fprintf(stderr, "%s\n", qPrintable(e));
        return 1;
    }
    Document* doc = window.document();
    auto* box = window.findChild<EnvironmentBox*>();
    if (!box) return 1;
    window.renderSettingsDock()->show();
    window.renderSettingsDock()->raise();

    // Item 3: the procedural studio drawn, then a truncated EXR chosen: the error box over a kept view.
    Environment studio;
    studio.source = EnvironmentSource::Studio;
    studio.studio.softboxes = {Softbox{}};
    setEnvironment(window, studio);
    QTemporaryDir dir;
    QFile good(QStringLiteral(":/resources/environments/studio.exr"));
    if (!good.open(QIODevice::ReadOnly)) return 1;
    const QByteArray bytes = good.readAll();
    QFile broken(dir.filePath(QStringLiteral("truncated.exr")));
    if (!broken.open(QIODevice::WriteOnly)) return 1;
    broken.write(bytes.left(bytes.size() / 2));
    broken.close();
    // The error box is modal (its own event loop): a timer grabs the screen while it is up, then closes it.
    bool grabbed = false;
    int seen = 0;
    QTimer poll;
    QObject::connect(&poll, &QTimer::timeout, [&] {
        QWidget* modal = QApplication::activeModalWidget();
        if (!modal || ++seen < 4) return;
        poll.stop();
        saveScreen(QStringLiteral("item3-truncated-exr"));
        modal->close();
        grabbed = true;
    });
    poll.start(250);
    box->chooseImageFile(broken.fileName());
    waitFor([&] { return grabbed; }, 60000);
    std::printf("item 3: the rig's environment is %s\n", qPrintable(toString(doc->rig().environment.source)));
    QTest::qWait(300);

    // Item 4: studio.exr and the procedural studio, each after Light from environment with the spot dimmed,
    // looking at the spot.
    Environment exr;
    exr.source = EnvironmentSource::Image;
    exr.file = QStringLiteral("builtin:studio");
    exr.background = EnvironmentBackground::Visible;
    setEnvironment(window, exr);
    const EnvironmentImage& img = window.scene()->environment()->image;
    int bx = 0, by = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (environment::luminance(img.at(x, y)) > environment::luminance(img.at(bx, by))) {
                bx = x;
                by = y;
            }
    const glm::dvec3 spot = environment::texelDirection(bx, by, img.width, img.height);
    EnvironmentLightTool* tool = window.environmentLightTool();
    tool->dimAction()->setChecked(true);
    const EnvironmentLightResult r1 = tool->addFromDirection(spot);
    std::printf("studio.exr: %s\n", qPrintable(r1.message));
    waitFor([&] { return !window.environmentLoading()->isLoading(); });
    lookFromCentre(window, spot, 70.0);
    save(&window, QStringLiteral("item4-studio-exr"));

    Environment procedural = studio;
    procedural.studio.softboxes[0].azimuth = 30.0;
    procedural.studio.softboxes[0].elevation = 25.0;
    setEnvironment(window, procedural);
    const glm::dvec3 box0 = environment::softboxDirection(30.0, 25.0);
    const EnvironmentLightResult r2 = tool->addFromDirection(box0);
    std::printf("procedural: %s\n", qPrintable(r2.message));
    waitFor([&] { return !window.environmentLoading()->isLoading(); });
    lookFromCentre(window, box0, 90.0);
    save(&window, QStringLiteral("item4-procedural"));

    // Item 14: a softbox edge magnified, and a white light's gizmo on a bright background.
    setEnvironment(window, studio);
    const Softbox& key = studio.studio.softboxes[0];
    const glm::dvec3 c = environment::softboxDirection(key.azimuth, key.elevation);
    const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), c));
    lookFromCentre(window, glm::normalize(c + right * std::tan(key.width * environment::kPi / 360.0)), 8.0);
    save(&window, QStringLiteral("item14-softbox-edge"));
    Environment bright = studio;
    bright.studio.zenith = bright.studio.horizon = bright.studio.floor = glm::dvec3(2.0);
    setEnvironment(window, bright);
    doc->newRig(Rig{});
    setEnvironment(window, bright);
    doc->addLight(LightType::Spot);
    doc->setLightValue({0}, LightProperty::Color, QVariant::fromValue(glm::dvec3(1.0)));
    doc->setSelectedRows({}, -1);
    window.viewport()->frameAll();
    save(&window, QStringLiteral("item14-gizmo"));

    // Item 15: a directional light's properties under PBR, a light without a temperature after one with,
    // and the History of a few environment edits.
    doc->newRig(Rig{});
    doc->setRigValue(RigProperty::ShadingModel, QStringLiteral("pbr"));
    doc->addLight(LightType::Point);
    doc->setLightValue({0}, LightProperty::Temperature, 3200.0);
    doc->addLight(LightType::Directional);
    doc->setSelectedRows({0}, 0);
    QTest::qWait(200);
    doc->setSelectedRows({1}, 1);
    Environment edited = studio;
    setEnvironment(window, edited);
    edited.intensity = 1.0;
    doc->setRigValue(RigProperty::Environment, QVariant::fromValue(edited));
    edited.rotation = 45.0;
    doc->setRigValue(RigProperty::Environment, QVariant::fromValue(edited));
    edited.studio.zenith = glm::dvec3(0.2, 0.3, 0.6);
    doc->setRigValue(RigProperty::Environment, QVariant::fromValue(edited));
    window.propertiesDock()->show();
    window.propertiesDock()->raise();
    window.historyDock()->show();
    window.historyDock()->raise();
    save(&window, QStringLiteral("item15-properties"));

    QSignalSpy loaded(window.files(), &DocumentFiles::modelLoadFinished);
    window.files()->openModel(model);
    if (!loaded.wait(120000)) return 1;
    window.modelDock()->show();
    window.modelDock()->raise();
    save(&window, QStringLiteral("item15-model-dock"));
    doc->undoStack()->setClean();
    return 0;
}
