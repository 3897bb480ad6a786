#include "mainwindow.h"

#include "abcompare.h"
#include "commandline.h"
#include "core/rigjson.h"
#include "documentfiles.h"
#include "editor/document.h"
#include "editoractions.h"
#include "editorstatusbar.h"
#include "environmentbox.h"
#include "environmentlighttool.h"
#include "environmentloading.h"
#include "errordialog.h"
#include "lightsdock.h"
#include "linktools.h"
#include "mixerdock.h"
#include "modeldock.h"
#include "presetsdock.h"
#include "presetstore.h"
#include "propertiesdock.h"
#include "qualitydock.h"
#include "recentfiles.h"
#include "rendersettingsdock.h"
#include "scene.h"
#include "sessionsettings.h"
#include "tracedview.h"
#include "viewbookmarks.h"
#include "viewport.h"
#include "viewsettings.h"

#include <QCloseEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QMimeData>
#include <QUndoView>
#include <cmath>
#include <glm/trigonometric.hpp>

namespace lr {

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_doc(new Document(this)), m_scene(new Scene(this)),
      m_viewSettings(new ViewSettings(this)), m_recent(new RecentFiles(this)),
      m_presets(new PresetStore(QString(), this)), m_files(new DocumentFiles(m_doc, m_scene, m_recent, this)),
      m_viewport(new Viewport(m_doc, m_scene, m_viewSettings, this)), m_status(new EditorStatusBar(this)) {
    setObjectName(QStringLiteral("MainWindow"));
    m_viewSettings->load();
    setCentralWidget(m_viewport);
    setStatusBar(m_status);
    setDockNestingEnabled(true);
    setAcceptDrops(true);
    m_environment = new EnvironmentLoading(m_doc, m_scene, this);
    m_environmentLight = new EnvironmentLightTool(m_doc, m_scene, m_viewport, this);
    m_compare = new AbCompare(m_doc, m_scene, this, this);
    m_viewport->setCompare(m_compare);
    createDocks();
    m_linkTools = new LinkTools(this);
    m_actions = new EditorActions(this);
    connectStatus();
    // Issue 41: the camera is saved with the rig (its "view") and comes back when the rig is opened.
    m_doc->currentView = [this] { return std::optional<RigView>(rigViewOf(m_viewport->camera())); };
    connect(m_files, &DocumentFiles::rigOpened, this, [this] {
        if (const auto& view = m_doc->rig().view)
            m_viewport->showSavedView(viewCameraOf(*view), m_scene->isEmpty() || m_files->isLoadingModel());
    });
    connect(m_doc, &Document::fileChanged, this, &MainWindow::updateTitle);
    connect(m_doc, &Document::modifiedChanged, this, &MainWindow::updateTitle);
    updateTitle();
    resize(1280, 800);
}

MainWindow::~MainWindow() = default;

QString MainWindow::bundledModelPath() {
    return QStringLiteral(":/resources/models/avocado/Avocado.gltf");
}

QString MainWindow::suzannePath() {
    return QStringLiteral(":/resources/models/suzanne/Suzanne.gltf");
}

void MainWindow::createDocks() {
    m_lightsDock = new LightsDock(m_doc, this);
    // New lights go around the model as seen now (editor/placement.h); the camera stays where it is (it is
    // no part of the undo step): a light is pulled in to land in view where it can, else the status bar says
    // it is out of view.
    m_lightsDock->setPlacementView([this] {
        const ViewCamera& c = m_viewport->camera();
        PlacementView v{m_scene->frame(), c.eye - c.target, c.trueUp()};
        v.hasCamera = true;
        v.eye = c.eye;
        v.forward = c.forward();
        v.tanHalfFovY = std::tan(glm::radians(c.yfovDeg) / 2.0);
        v.aspect = m_viewport->height() > 0 ? double(m_viewport->width()) / m_viewport->height() : 1.0;
        return v;
    });
    connect(m_lightsDock, &LightsDock::lightAdded, m_viewport,
            [this](int row) { m_viewport->reportLightsOutOfView({row}); });
    m_propertiesDock = new PropertiesDock(m_doc, this);
    m_renderDock = new RenderSettingsDock(m_doc, m_viewSettings, this);
    m_renderDock->setSceneFrameProvider([this] { return m_scene->frame(); }); // for the space switch
    m_renderDock->setScene(m_scene);                                          // the model's up axis
    m_renderDock->environmentBox()->setLoading(m_environment);
    m_presetsDock = new PresetsDock(m_doc, m_presets, this);
    m_presetsDock->setThumbnailRenderer([this](const Rig& rig, const QSize& size) {
        return m_scene->isEmpty() ? QImage() : m_viewport->renderThumbnail(rig, size);
    });
    m_presetsDock->setBusyCheck([this] { return m_viewport->isNavigating(); });
    connect(m_scene, &Scene::modelChanged, m_presetsDock, &PresetsDock::invalidateThumbnails);
    m_historyDock = new QDockWidget(tr("History"), this);
    m_historyDock->setObjectName(QStringLiteral("HistoryDock"));
    auto* history = new QUndoView(m_doc->undoStack(), m_historyDock);
    history->setEmptyLabel(tr("<opened>"));
    m_historyDock->setWidget(history);
    m_modelDock = new ModelDock(this); // the model's meshes, materials, textures and warnings
    m_modelDock->setScene(m_scene);
    m_modelDock->setDocument(m_doc); // each mesh's lights under light linking (issue 38)

    // The default layout, usable at the default 1280×800 (issue 12: a left column left the light table 250 px
    // wide, its Solo, Colour, Intensity and Falloff columns behind a scrollbar, and Render settings' form
    // squeezed Properties to ~100 px). The light table spans the bottom under the viewport, where all its
    // columns fit, with presets and history beside it; Properties has the whole right column, Render
    // settings and Quality as tabs behind it.
    setCorner(Qt::TopRightCorner, Qt::RightDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    addDockWidget(Qt::BottomDockWidgetArea, m_lightsDock);
    addDockWidget(Qt::BottomDockWidgetArea, m_presetsDock);
    tabifyDockWidget(m_presetsDock, m_historyDock);
    tabifyDockWidget(m_historyDock, m_modelDock); // wide at the bottom: warnings read in full
    addDockWidget(Qt::RightDockWidgetArea, m_propertiesDock);
    tabifyDockWidget(m_propertiesDock, m_renderDock);
    addQualityDock(this); // the Quality panel (qualitydock.h), a tab beside Render settings
    // Issue 37: the Mixer, a tab behind Properties (its image wants the right column's height).
    m_mixerDock = new MixerDock(m_doc, this);
    addDockWidget(Qt::RightDockWidgetArea, m_mixerDock);
    tabifyDockWidget(m_renderDock, m_mixerDock);
    m_presetsDock->raise();
    m_propertiesDock->raise();
    resizeDocks({m_propertiesDock}, {390}, Qt::Horizontal);
    resizeDocks({m_lightsDock, m_presetsDock}, {620, 260}, Qt::Horizontal);
    resizeDocks({m_lightsDock}, {230}, Qt::Vertical);
}

void MainWindow::connectStatus() {
    connect(m_files, &DocumentFiles::statusMessage, this,
            [this](const QString& t) { m_status->showMessage(t, 8000); });
    connect(m_lightsDock, &LightsDock::editRefused, this,
            [this](const QString& t) { m_status->showMessage(t, 8000); });
    connect(m_viewport, &Viewport::statusMessage, this,
            [this](const QString& t) { m_status->showMessage(t, 8000); });
    connect(m_viewport, &Viewport::frameRendered, m_status, &EditorStatusBar::setFrameTime);
    connect(m_environmentLight, &EnvironmentLightTool::statusMessage, this,
            [this](const QString& t) { m_status->showMessage(t, 8000); });
    connect(m_compare, &AbCompare::statusMessage, this,
            [this](const QString& t) { m_status->showMessage(t, 8000); });
    connect(m_mixerDock, &MixerDock::statusMessage, this,
            [this](const QString& t) { m_status->showMessage(t, 8000); });
    connect(m_mixerDock, &MixerDock::captureRequested, this, &MainWindow::captureMixerLayers);
    // The path-traced view keeps light-group layers while the Mixer is open (they cost memory per group),
    // and hands them to the Mixer when asked.
    TracedView* traced = m_viewport->tracedView();
    connect(m_mixerDock, &QDockWidget::visibilityChanged, traced, &TracedView::setLayers);
    connect(traced, &TracedView::layersReady, this, [this](const RenderLayers& layers, int samples) {
        const QString what = tr("traced, %n samples, %1×%2", nullptr, samples)
                                 .arg(layers.beauty.width)
                                 .arg(layers.beauty.height);
        m_mixerDock->setLayers(layers, what);
        m_status->showMessage(tr("Captured %1").arg(what), 5000);
    });
    auto display = [this] {
        m_mixerDock->setDisplay(m_viewSettings->options().exposure, m_viewSettings->options().toneMap);
    };
    connect(m_viewSettings, &ViewSettings::changed, this, display);
    display();
    // An environment that cannot be loaded: said in the status bar and the error box; the rig stays as it is.
    connect(m_environment, &EnvironmentLoading::failed, this, [this](const QString& error) {
        m_status->showMessage(tr("Environment not drawn: %1").arg(error), 8000);
        showError(this, {tr("Environment"), tr("Could not load the environment; it is not drawn."), {error}});
    });
    connect(m_environment, &EnvironmentLoading::refused, this, [this](const QString& error) {
        m_status->showMessage(tr("Environment kept: %1").arg(error), 8000);
        showError(this,
                  {tr("Environment"), tr("Could not load the environment; the rig keeps its own."), {error}});
    });
    connect(m_environment, &EnvironmentLoading::warnings, this,
            [this](const QStringList& w) { m_status->showMessage(w.join(QLatin1String("; ")), 8000); });
    connect(m_files, &DocumentFiles::modelLoadStarted, this,
            [this](const QString& path) { m_status->showLoading(QFileInfo(path).fileName()); });
    connect(m_files, &DocumentFiles::modelLoadProgress, m_status, &EditorStatusBar::setLoadProgress);
    connect(m_files, &DocumentFiles::modelLoadFinished, m_status, &EditorStatusBar::hideLoading);
    connect(m_status, &EditorStatusBar::cancelLoadRequested, m_files, &DocumentFiles::cancelModelLoad);
    connect(m_scene, &Scene::modelChanged, this, [this] {
        m_status->setModelWarnings(QFileInfo(m_scene->path()).fileName(), m_scene->model()->warnings);
    });
    connect(m_status, &EditorStatusBar::warningsRequested, m_modelDock, &ModelDock::showWarnings);
    auto summary = [this] {
        const int n = m_doc->lightCount();
        int on = 0;
        for (int i = 0; i < n; ++i)
            on += m_doc->light(i).enabled ? 1 : 0;
        m_status->setRigSummary(tr("%n light(s), %1 on", nullptr, n).arg(on) +
                                (m_doc->anySoloed() ? tr(" (solo)") : QString()));
    };
    connect(m_doc, &Document::rigChanged, this, summary);
    connect(m_doc, &Document::soloChanged, this, summary);
    summary();
}

void MainWindow::captureMixerLayers() {
    // The view as the viewport shows it, split into light groups: the path-traced view's accumulation when it
    // is on (tracedview.h), else the raster tier at the viewport's aspect, at most 1280 pixels wide.
    const ViewOptions& view = m_viewSettings->options();
    if (view.pathTraced && captureTracedLayers()) return;
    QString error;
    QElapsedTimer clock;
    clock.start();
    std::optional<RenderLayers> layers = m_viewport->renderLayers(QSize(1280, 1280), &error);
    if (!layers) {
        m_status->showMessage(tr("Capture failed: %1").arg(error), 8000);
        return;
    }
    const QString what = tr("raster, %1, %2×%3")
                             .arg(toString(view.quality))
                             .arg(layers->beauty.width)
                             .arg(layers->beauty.height);
    m_mixerDock->setLayers(std::move(*layers), what);
    m_status->showMessage(tr("Captured %1 in %2 ms").arg(what).arg(clock.elapsed()), 5000);
}

bool MainWindow::captureTracedLayers() {
    TracedView* traced = m_viewport->tracedView();
    if (!traced->layers()) traced->setLayers(true); // from the next samples on; the raster meanwhile
    if (!traced->requestLayers()) return false;
    m_status->showMessage(tr("Capturing the path-traced view's light groups after this pass…"), 5000);
    return true;
}

void MainWindow::updateTitle() {
    setWindowTitle(tr("%1[*] — LightRig").arg(m_doc->displayName()));
    setWindowFilePath(m_doc->filePath());
    setWindowModified(m_doc->isModified());
}

void MainWindow::openInitial(const EditorOptions& options) {
    m_restoreSession = options.restoreSession;
    if (options.restoreSession) SessionSettings::restoreWindow(this);
    QString model = options.modelPath;
    if (model.isEmpty() && options.restoreSession) model = SessionSettings::lastModel();
    if (model.isEmpty()) model = bundledModelPath();
    QString rig = options.rigPath;
    if (rig.isEmpty() && options.modelPath.isEmpty() && options.restoreSession)
        rig = SessionSettings::lastRig();
    m_doc->newRig(defaultRig());
    // Without a rig, the model chooses one when it has loaded (core/defaultrig.h: physically based for a
    // model with PBR materials, with its own lights when it has some).
    if (rig.isEmpty() || !m_files->openRig(rig)) m_files->markRigAutomatic();
    if (model != bundledModelPath()) {
        // A model that cannot be loaded leaves an empty scene: fall back to the bundled model then.
        connect(
            m_files, &DocumentFiles::modelLoadFailed, this,
            [this] {
                if (m_scene->isEmpty()) m_files->openModel(bundledModelPath());
            },
            Qt::SingleShotConnection);
    }
    m_files->openModel(model);
}

void MainWindow::saveSession() {
    if (!m_restoreSession) return; // a scripted/defaults-only run leaves the user's session alone
    SessionSettings::saveWindow(this);
    SessionSettings::setLastModel(m_scene->path() == bundledModelPath() ? QString() : m_scene->path());
    SessionSettings::setLastRig(m_doc->filePath());
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    m_files->cancelModelLoad();
    saveSession();
    event->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const QMimeData* mime = event->mimeData();
    if (mime->hasUrls()) {
        for (const QUrl& url : mime->urls()) {
            if (url.isLocalFile()) {
                event->acceptProposedAction();
                return;
            }
        }
    }
}

void MainWindow::dropEvent(QDropEvent* event) {
    // A rig and a model may be dropped together: the rig first (it may ask to save), then the model.
    QStringList rigs, models;
    for (const QUrl& url : event->mimeData()->urls()) {
        if (!url.isLocalFile()) continue;
        (DocumentFiles::isRigFile(url.toLocalFile()) ? rigs : models).append(url.toLocalFile());
    }
    event->acceptProposedAction();
    if (!rigs.isEmpty()) m_files->openFile(rigs.first());
    if (!models.isEmpty()) m_files->openFile(models.first());
}

} // namespace lr
