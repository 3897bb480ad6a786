#include "editoractions.h"

#include "abcompare.h"
#include "controlshelp.h"
#include "documentfiles.h"
#include "editor/document.h"
#include "environmentlighttool.h"
#include "errordialog.h"
#include "gltfexportdialog.h"
#include "lightsdock.h"
#include "linktools.h"
#include "mainwindow.h"
#include "mixerdock.h"
#include "presetsdock.h"
#include "recentfiles.h"
#include "scene.h"
#include "scene/camera.h"
#include "screenshotdialog.h"
#include "screenshotjob.h"
#include "turntableexport.h"
#include "viewbookmarks.h"
#include "viewport.h"
#include "viewsettings.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QUndoStack>

namespace lr {

EditorActions::EditorActions(MainWindow* window) : QObject(window), m_window(window) {
    createFileMenu();
    createEditMenu();
    createViewMenu();
    createOtherMenus();
    Document* doc = m_window->document();
    connect(doc, &Document::selectionChanged, this, &EditorActions::updateEnabled);
    connect(doc, &Document::rigChanged, this, &EditorActions::updateEnabled);
    connect(m_window->scene(), &Scene::modelChanged, this, [this] {
        rebuildModelCameras();
        updateEnabled();
    });
    rebuildModelCameras();
    updateEnabled();
}

void EditorActions::createFileMenu() {
    DocumentFiles* files = m_window->files();
    QMenu* menu = m_window->menuBar()->addMenu(tr("&File"));
    auto add = [&](const QString& text, QKeySequence key, auto slot) {
        QAction* a = menu->addAction(text);
        if (!key.isEmpty()) a->setShortcut(key);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    newRig = add(tr("&New rig"), QKeySequence::New, [files] { files->newRig(); });
    openRig = add(tr("&Open rig…"), QKeySequence::Open, [files] { files->openRig(); });
    openModel = add(tr("Open &model…"), QKeySequence(tr("Ctrl+Shift+O")), [files] { files->openModel(); });
    // Issue 41: the bundled models (their rig follows, as for any model opened on an untouched rig).
    QMenu* samples = menu->addMenu(tr("Open &sample"));
    samples->setObjectName(QStringLiteral("samplesMenu"));
    connect(samples->addAction(tr("Avocado: product shot (physically based)")), &QAction::triggered, files,
            [files] { files->openModel(MainWindow::bundledModelPath()); });
    connect(samples->addAction(tr("Suzanne: classic shading")), &QAction::triggered, files,
            [files] { files->openModel(MainWindow::suzannePath()); });
    recentMenu = menu->addMenu(tr("Open &recent"));
    m_window->recentFiles()->attachMenu(recentMenu);
    connect(m_window->recentFiles(), &RecentFiles::openRequested, files, &DocumentFiles::openFile);
    menu->addSeparator();
    save = add(tr("&Save"), QKeySequence::Save, [files] { files->save(); });
    // Spelled out: QKeySequence::SaveAs is empty on platforms without a theme that defines it (X11 without
    // KDE or GNOME, Xvfb), which left Save As without a shortcut.
    saveAs =
        add(tr("Save &as…"), QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S), [files] { files->saveAs(); });
    menu->addSeparator();
    importLights =
        add(tr("&Import lights from model"), QKeySequence(), [files] { files->importLightsFromModel(); });
    exportScreenshot =
        add(tr("&Export screenshot…"), QKeySequence(tr("Ctrl+E")), [this] { exportScreenshotInteractive(); });
    exportTurntable =
        add(tr("Export &turntable…"), QKeySequence(), [this] { exportTurntableInteractive(m_window); });
    add(tr("Export &glTF…"), QKeySequence(), [this] { exportGltfInteractive(m_window); }); // issue 17
    menu->addSeparator();
    quit = add(tr("&Quit"), QKeySequence::Quit, [this] { m_window->close(); });
    quit->setMenuRole(QAction::QuitRole);
}

void EditorActions::createEditMenu() {
    QMenu* menu = m_window->menuBar()->addMenu(tr("&Edit"));
    QUndoStack* stack = m_window->document()->undoStack();
    undo = stack->createUndoAction(this, tr("&Undo"));
    undo->setShortcut(QKeySequence::Undo);
    redo = stack->createRedoAction(this, tr("&Redo"));
    redo->setShortcut(QKeySequence::Redo);
    menu->addAction(undo);
    menu->addAction(redo);
    menu->addSeparator();
    QMenu* lights = menu->addMenu(tr("&Lights"));
    for (QAction* a : m_window->lightsDock()->lightActions())
        lights->addAction(a);
    menu->addSeparator();
    m_window->environmentLightTool()->addActions(
        menu); // issue 15: a light from the environment's bright spot
}

void EditorActions::createViewMenu() {
    QMenu* menu = m_window->menuBar()->addMenu(tr("&View"));
    Viewport* viewport = m_window->viewport();
    frame = menu->addAction(tr("&Frame selection"));
    frame->setShortcut(QKeySequence(Qt::Key_F));
    frame->setToolTip(
        tr("Frame the model and the selected lights, or the model when no light is selected (F)"));
    connect(frame, &QAction::triggered, viewport, &Viewport::frameSelectionOrAll);
    frameAll = menu->addAction(tr("Frame &all"));
    frameAll->setShortcut(QKeySequence(Qt::Key_Home));
    connect(frameAll, &QAction::triggered, viewport, &Viewport::frameAll);
    frameAllLights = menu->addAction(tr("Frame all &lights"));
    frameAllLights->setShortcut(QKeySequence(Qt::SHIFT | Qt::Key_F));
    frameAllLights->setToolTip(tr("Frame the model and every light around it (Shift+F)"));
    connect(frameAllLights, &QAction::triggered, viewport, &Viewport::frameAllLights);
    standardViewsMenu = menu->addMenu(tr("&Standard views"));
    int key = Qt::Key_1;
    for (const QString& name : standardViewNames()) {
        QAction* a = standardViewsMenu->addAction(name);
        a->setShortcut(QKeySequence(key++));
        connect(a, &QAction::triggered, viewport, [viewport, name] { viewport->setStandardView(name); });
    }
    modelCamerasMenu = menu->addMenu(tr("&Model cameras"));
    viewBookmarks =
        new ViewBookmarks(m_window->document(), viewport, menu->addMenu(tr("Sa&ved views")), m_window);
    connect(viewBookmarks, &ViewBookmarks::statusMessage, m_window->statusBar(),
            [this](const QString& t) { m_window->statusBar()->showMessage(t, 8000); });
    lookThroughLight = menu->addAction(tr("&Look through light"));
    lookThroughLight->setShortcut(QKeySequence(Qt::Key_L));
    lookThroughLight->setToolTip(tr("View the scene from the selected spot light, along its axis"));
    connect(lookThroughLight, &QAction::triggered, viewport,
            [this, viewport] { viewport->lookThroughLight(m_window->document()->currentRow()); });
    menu->addSeparator();
    m_window->compare()->addActions(menu); // issue 17: A/B comparison
    menu->addSeparator();
    QAction* mixer = m_window->mixerDock()->toggleViewAction(); // issue 37 (also in Window)
    mixer->setText(tr("Light &mixer"));
    mixer->setToolTip(tr("Re-balance a render per light group and write the mix into the rig"));
    menu->addAction(mixer);
    menu->addAction(m_window->linkTools()->matrixAction()); // issue 38: the linking matrix
    menu->addSeparator();
    ViewSettings* settings = m_window->viewSettings();
    showGizmos = menu->addAction(tr("Light &gizmos"));
    showGizmos->setCheckable(true);
    showGizmos->setShortcut(QKeySequence(Qt::Key_G));
    connect(showGizmos, &QAction::toggled, settings, &ViewSettings::setGizmos);
    showGrid = menu->addAction(tr("Ground g&rid"));
    showGrid->setCheckable(true);
    connect(showGrid, &QAction::toggled, settings, &ViewSettings::setGrid);
    auto sync = [this, settings] {
        showGizmos->setChecked(settings->options().gizmos);
        showGrid->setChecked(settings->options().grid);
    };
    connect(settings, &ViewSettings::changed, this, sync);
    sync();
}

void EditorActions::createOtherMenus() {
    QMenu* presets = m_window->menuBar()->addMenu(tr("&Presets"));
    m_window->presetsDock()->attachMenu(presets);
    QMenu* windows = m_window->menuBar()->addMenu(tr("&Window"));
    for (QDockWidget* dock : m_window->findChildren<QDockWidget*>())
        windows->addAction(dock->toggleViewAction());
    QMenu* help = m_window->menuBar()->addMenu(tr("&Help"));
    controls = help->addAction(tr("&Controls"));
    controls->setShortcut(QKeySequence::HelpContents);
    connect(controls, &QAction::triggered, m_window, [this] { showControls(m_window); });
    QAction* about = help->addAction(tr("&About LightRig"));
    connect(about, &QAction::triggered, m_window, [this] {
        QMessageBox::about(
            m_window, tr("About LightRig"),
            tr("<b>LightRig %1</b><p>Design light rigs on 3D models: point, spot, directional and rim "
               "lights with the falloff and cone models of classic real-time rendering.</p>"
               "<p>Help › Controls lists the mouse and keyboard bindings.</p>")
                .arg(QApplication::applicationVersion()));
    });
}

void EditorActions::rebuildModelCameras() {
    modelCamerasMenu->clear();
    const auto& cameras = m_window->scene()->model()->cameras;
    for (int i = 0; i < int(cameras.size()); ++i) {
        const QString name =
            cameras[size_t(i)].name.isEmpty() ? tr("Camera %1").arg(i + 1) : cameras[size_t(i)].name;
        QAction* a = modelCamerasMenu->addAction(name);
        connect(a, &QAction::triggered, m_window->viewport(),
                [this, i] { m_window->viewport()->setModelCamera(i); });
    }
    modelCamerasMenu->setEnabled(!cameras.empty());
}

void EditorActions::updateEnabled() {
    const Document* doc = m_window->document();
    const int row = doc->currentRow();
    lookThroughLight->setEnabled(row >= 0 && doc->light(row).type == LightType::Spot);
    importLights->setEnabled(!m_window->scene()->model()->lights.lights.empty());
}

void EditorActions::exportScreenshotInteractive() {
    if (m_window->findChild<ScreenshotJob*>()) {
        m_window->statusBar()->showMessage(tr("A screenshot is being exported; wait for it or cancel it"),
                                           8000);
        return;
    }
    const QString base = m_window->document()->filePath().isEmpty()
                             ? QDir::home().filePath(QStringLiteral("lightrig.png"))
                             : QFileInfo(m_window->document()->filePath())
                                   .dir()
                                   .filePath(QFileInfo(m_window->document()->filePath()).completeBaseName() +
                                             QStringLiteral(".png"));
    ScreenshotDialog dialog(m_window->viewport()->size() * m_window->viewport()->devicePixelRatio(), base,
                            m_window);
    if (dialog.exec() != QDialog::Accepted) return;
    // In the background (issue 41): the window keeps taking edits, which do not change the image.
    auto* job = new ScreenshotJob(m_window->viewport(), dialog.options(), m_window);
    exportScreenshot->setEnabled(false);
    connect(job, &ScreenshotJob::finished, this, [this, job] {
        job->deleteLater();
        exportScreenshot->setEnabled(true);
        const ScreenshotOptions& o = job->options();
        const ScreenshotExportResult result = job->result();
        if (result.cancelled) {
            m_window->statusBar()->showMessage(
                tr("Screenshot export cancelled; %1 not written").arg(QDir::toNativeSeparators(o.path)),
                8000);
        } else if (!result.ok()) {
            showError(m_window,
                      {tr("Export screenshot"), tr("Could not export the screenshot."), {result.error}});
        } else {
            m_window->statusBar()->showMessage(tr("Wrote %1 (%2×%3)")
                                                   .arg(QDir::toNativeSeparators(o.path))
                                                   .arg(o.size.width())
                                                   .arg(o.size.height()),
                                               8000);
        }
    });
    showInStatusBar(m_window, job);
    job->start();
}

} // namespace lr
