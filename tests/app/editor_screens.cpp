// Not a test: takes the editor screenshots issue 12 asks for (items 3, 4 and 9) under Xvfb at 1280×800, so
// the same steps can be grabbed before and after a change. Uses only long-standing public API.
//
//   xvfb-run -a -s "-screen 0 1920x1080x24" build/dev/tests/app/editor_screens OUTDIR PREFIX MODEL PRESET
//
// writes OUTDIR/PREFIX-item4-default.png (PRESET on MODEL as first framed), -item4-frame-key.png (F on the
// first light), -item3-add-lights.png (an empty rig, then Add point and Add spot), -item9-quality.png (the
// Quality dock after a measurement) and, where the dock offers them, -item9-large.png and -item9-compare.png.
#include "app/commandline.h"
#include "app/documentfiles.h"
#include "app/editoractions.h"
#include "app/editorapp.h"
#include "app/lightsdock.h"
#include "app/mainwindow.h"
#include "app/qualitydock.h"
#include "app/scene.h"
#include "app/viewport.h"
#include "editor/document.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <cstdio>

using namespace lr;

namespace {
QString g_out, g_prefix;

void settle(int ms = 600) {
    QTest::qWait(ms);
}

void save(QWidget* w, const QString& name) {
    settle();
    const QString path = QDir(g_out).filePath(g_prefix + QLatin1Char('-') + name + QStringLiteral(".png"));
    const bool ok = w->grab().toImage().save(path);
    std::printf("%s %s\n", ok ? "wrote" : "FAILED", qPrintable(path));
}
} // namespace

int main(int argc, char** argv) {
    Viewport::setDefaultSurfaceFormat();
    QApplication app(argc, argv);
    if (argc < 5) {
        std::fprintf(stderr, "usage: editor_screens OUTDIR PREFIX MODEL PRESET\n");
        return 2;
    }
    g_out = QString::fromLocal8Bit(argv[1]);
    g_prefix = QString::fromLocal8Bit(argv[2]);
    const QString model = QString::fromLocal8Bit(argv[3]), preset = QString::fromLocal8Bit(argv[4]);
    QStandardPaths::setTestModeEnabled(true); // leave the user's settings alone
    setApplicationIdentity();
    QCoreApplication::setApplicationName(QStringLiteral("lightrig-screens"));

    MainWindow window;
    window.files()->askUnsaved = [](const QString&) { return DocumentFiles::UnsavedAnswer::Discard; };
    EditorOptions options;
    options.restoreSession = false;
    QSignalSpy loaded(window.files(), &DocumentFiles::modelLoadFinished);
    window.openInitial(options);
    window.show();
    if (!loaded.wait(120000)) return 1;
    settle(1500);

    // Item 4: a preset's lights around the model as first framed.
    window.files()->openRig(preset);
    loaded.clear();
    window.files()->openModel(model);
    if (!loaded.wait(120000)) return 1;
    settle(1500);
    save(&window, QStringLiteral("item4-default"));
    window.document()->setSelectedRows({0}, 0);
    window.actions()->frame->trigger();
    save(&window, QStringLiteral("item4-frame-key"));

    // Item 3: new lights on an empty rig.
    window.document()->newRig(Rig{});
    window.actions()->frameAll->trigger();
    window.lightsDock()->addLightAction(LightType::Point)->trigger();
    window.lightsDock()->addLightAction(LightType::Spot)->trigger();
    save(&window, QStringLiteral("item3-add-lights"));

    // Item 9: the Quality dock after a measurement.
    window.document()->newRig(Rig{});
    window.files()->openRig(preset);
    window.actions()->frameAll->trigger();
    auto* quality = window.findChild<QualityDock*>();
    if (!quality) return 1;
    quality->show();
    quality->raise();
    quality->setFrames(3);
    quality->measure();
    if (auto* table = quality->findChild<QTableWidget*>()) table->selectRow(2);
    save(&window, QStringLiteral("item9-quality"));
    for (QPushButton* b : quality->findChildren<QPushButton*>())
        if (b->text() == QLatin1String("Open large")) {
            b->click();
            save(quality, QStringLiteral("item9-large"));
            if (auto* tabs = quality->findChild<QTabWidget*>(QStringLiteral("qualityViews"))) {
                tabs->setCurrentIndex(1);
                save(quality, QStringLiteral("item9-compare"));
            }
        }
    window.document()->undoStack()->setClean();
    return 0;
}
