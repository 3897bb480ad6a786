// The editor's main window driven headless (Xvfb) with QTest mouse and keyboard events: add a spot light,
// change its cone, undo, save, reopen, compare; the title and modified flag; Save/Discard/Cancel; a failed
// rig open leaves everything as it was; selecting, dragging and aiming lights in the viewport.
#include "app/commandline.h"
#include "app/documentfiles.h"
#include "app/editoractions.h"
#include "app/editorapp.h"
#include "app/editorstatusbar.h"
#include "app/errordialog.h"
#include "app/gizmointeraction.h"
#include "app/lightsdock.h"
#include "app/mainwindow.h"
#include "app/mixerdock.h"
#include "app/numberedit.h"
#include "app/presetsdock.h"
#include "app/presetstore.h"
#include "app/propertiesdock.h"
#include "app/scene.h"
#include "app/screenshotdialog.h"
#include "app/viewport.h"
#include "core/defaultrig.h"
#include "core/rigjson.h"
#include "editor/document.h"
#include "model/isolatedimport.h"
#include "startwindow.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QMenu>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QUrl>
#include <glm/geometric.hpp>

using namespace lr;

class TestMainWindow : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
    QList<ErrorReport> m_errors;

    Document* doc() { return m_window->document(); }
    Viewport* viewport() { return m_window->viewport(); }

    void pressKey(int key, Qt::KeyboardModifiers mods = Qt::NoModifier) {
        QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : m_window.get(),
                        Qt::Key(key), mods);
    }

    static QByteArray json(const Rig& rig) { return writeRigJson(rig); }

    // A mouse move with the left button held (QTest::mouseMove does not carry the button state reliably).
    static void dragTo(QWidget* w, const QPointF& pos, Qt::KeyboardModifiers mods = Qt::NoModifier) {
        QMouseEvent e(QEvent::MouseMove, pos, w->mapToGlobal(pos), Qt::NoButton, Qt::LeftButton, mods);
        QApplication::sendEvent(w, &e);
    }

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("lightrig-test")); // models import in lightrig
        QVERIFY(m_dir.isValid());
        setErrorPresenter([this](const ErrorReport& r) { m_errors.append(r); });
        // No test may end up in a modal file dialog (it would wait forever under Xvfb).
        auto noDialog = [] {
            qWarning("unexpected file dialog");
            return QString();
        };

        m_window = std::make_unique<MainWindow>();
        m_window->files()->askOpenPath = [noDialog](const QString&, const QString&) { return noDialog(); };
        m_window->files()->askSavePath = [noDialog](const QString&, const QString&, const QString&) {
            return noDialog();
        };
        const QString started = test::startMainWindow(*m_window);
        QVERIFY2(started.isEmpty(), qPrintable(started));
        QVERIFY2(viewport()->lastError().isEmpty(), qPrintable(viewport()->lastError()));
        QVERIFY(m_errors.isEmpty());
    }

    void cleanupTestCase() {
        // Nothing unsaved is left to ask about, so closing does not block.
        doc()->undoStack()->setClean();
        m_window.reset();
        setErrorPresenter({});
    }

    void startsWithTheDefaultRig_untitledAndClean() {
        QVERIFY(doc()->lightCount() > 0);
        QCOMPARE(json(doc()->rig()), json(defaultRig()));
        QVERIFY(m_window->windowTitle().contains(QLatin1String("Untitled")));
        QVERIFY(!m_window->isWindowModified());
        QVERIFY(!m_window->editorStatusBar()->frameTimeText().isEmpty()); // frame time is shown
    }

    void addSpot_changeCone_undo_save_reopen() {
        doc()->newRig(Rig{});
        QVERIFY(!m_window->isWindowModified());

        // Add a spot light with the Lights dock's toolbar button.
        LightsDock* lights = m_window->lightsDock();
        QWidget* addSpot = lights->toolBar()->widgetForAction(lights->addLightAction(LightType::Spot));
        QVERIFY(addSpot);
        QTest::mouseClick(addSpot, Qt::LeftButton);
        QCOMPARE(doc()->lightCount(), 1);
        QVERIFY(doc()->light(0).type == LightType::Spot);
        QCOMPARE(doc()->selectedRows(), QList<int>{0});
        QVERIFY(m_window->isWindowModified());

        // Change its cone in the Properties dock: the model by keyboard, then the outer angle typed in.
        PropertiesDock* props = m_window->propertiesDock();
        auto* coneModel = qobject_cast<QComboBox*>(props->field(LightProperty::ConeModel));
        QVERIFY(coneModel && coneModel->isVisibleTo(m_window.get()));
        coneModel->setFocus();
        QTest::keyClick(coneModel, Qt::Key_End); // "hard", the last model
        QVERIFY(doc()->light(0).cone.model == ConeModel::Hard);
        QVERIFY(!props->field(LightProperty::ConeInner)->isVisibleTo(m_window.get()));
        const QByteArray afterModel = json(doc()->rig());

        auto* outer = qobject_cast<NumberEdit*>(props->field(LightProperty::ConeOuter));
        QVERIFY(outer);
        outer->setFocus();
        outer->selectAll();
        QTest::keyClicks(outer, "50");
        QTest::keyClick(outer, Qt::Key_Return);
        QCOMPARE(doc()->light(0).cone.outer, 50.0);

        // Undo (Ctrl+Z from the window) takes back exactly the angle.
        m_window->activateWindow();
        viewport()->setFocus();
        QTest::keyClick(viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(json(doc()->rig()), afterModel);
        const Rig saved = doc()->rig();

        // Save (Ctrl+S): untitled, so it asks for a file name.
        const QString path = m_dir.filePath(QStringLiteral("spot.json"));
        m_window->files()->askSavePath = [path](const QString&, const QString&, const QString&) {
            return path;
        };
        QTest::keyClick(viewport(), Qt::Key_S, Qt::ControlModifier);
        QVERIFY(QFile::exists(path));
        QCOMPARE(doc()->filePath(), path);
        QVERIFY(m_window->windowTitle().contains(QLatin1String("spot.json")));
        QVERIFY(!m_window->isWindowModified());
        // Issue 41: the file also holds the camera as it was saved (the rig's "view").
        Rig withView = saved;
        withView.view = doc()->rig().view;
        QVERIFY(withView.view.has_value());

        // Reopen: the same rig, and the file holds exactly its canonical form.
        doc()->newRig(Rig{});
        QVERIFY(m_window->files()->openRig(path));
        QCOMPARE(doc()->lightCount(), 1);
        QVERIFY(doc()->rig() == withView);
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), json(withView));
        QVERIFY(!m_window->isWindowModified());
    }

    // Issue 37: the Mixer is a dock of the window (a tab behind Properties), in the View and Window menus,
    // and its Capture fills it with the view split into the rig's light groups (raster: they sum to the
    // beauty).
    void mixerDock_isRegisteredAndCaptures() {
        MixerDock* mixer = m_window->mixerDock();
        QVERIFY(mixer);
        QCOMPARE(mixer->objectName(), QStringLiteral("MixerDock"));
        QVERIFY(m_window->tabifiedDockWidgets(m_window->propertiesDock()).contains(mixer));
        QStringList menus;
        for (QObject* o : mixer->toggleViewAction()->associatedObjects())
            if (auto* menu = qobject_cast<QMenu*>(o)) menus << menu->title().remove(QLatin1Char('&'));
        QVERIFY2(menus.contains(QStringLiteral("View")) && menus.contains(QStringLiteral("Window")),
                 qPrintable(menus.join(QLatin1Char(','))));
        mixer->findChild<QPushButton*>(QStringLiteral("mixerCapture"))->click();
        QVERIFY2(mixer->hasLayers(), qPrintable(m_window->statusBar()->currentMessage()));
        QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("Captured raster")),
                 qPrintable(m_window->statusBar()->currentMessage()));
        const RenderLayers& layers = mixer->layers();
        for (const LightGroup& g : lightGroups(doc()->rig()))
            if (g.kind == LightGroupKind::Lights)
                QVERIFY2(groupNames(layers.groups).contains(g.name), qPrintable(g.name));
        QVERIFY2(groupSumError(layers) < 1e-4, qPrintable(QString::number(groupSumError(layers))));
        QVERIFY(!mixer->isStale());
    }

    void modifiedFlag_followsTheUndoStack() {
        QVERIFY(doc()->lightCount() > 0);
        QVERIFY(doc()->setLightValue({0}, LightProperty::Intensity, 3.25));
        QVERIFY(m_window->isWindowModified());
        doc()->undoStack()->undo();
        QVERIFY(!m_window->isWindowModified());
    }

    void unsavedChanges_askSaveDiscardCancel() {
        QVERIFY(doc()->setLightValue({0}, LightProperty::Intensity, 4.5));
        const QByteArray before = json(doc()->rig());
        int asked = 0;
        auto answer = DocumentFiles::UnsavedAnswer::Cancel;
        m_window->files()->askUnsaved = [&](const QString&) {
            ++asked;
            return answer;
        };
        QVERIFY(!m_window->files()->newRig()); // Cancel: nothing happens
        QCOMPARE(asked, 1);
        QCOMPARE(json(doc()->rig()), before);
        QVERIFY(!m_window->close()); // closing asks too, and Cancel keeps the window
        QCOMPARE(asked, 2);
        QVERIFY(m_window->isVisible());

        answer = DocumentFiles::UnsavedAnswer::Save; // Save writes the file, then the new rig comes
        const QString path = doc()->filePath();
        QVERIFY(m_window->files()->newRig());
        QCOMPARE(readRigFile(path).rig->lights[0].intensity, 4.5);

        QVERIFY(doc()->addLight(LightType::Point));
        answer = DocumentFiles::UnsavedAnswer::Discard;
        QVERIFY(m_window->files()->openRig(path));
        QCOMPARE(asked, 4);
        QCOMPARE(doc()->light(0).intensity, 4.5);
    }

    void failedOpen_leavesTheRigUntouched() {
        const QByteArray before = json(doc()->rig());
        const QString filePath = doc()->filePath();
        const int steps = doc()->undoStack()->count();
        const QString bad = m_dir.filePath(QStringLiteral("bad.json"));
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(
            R"({"format": "lightrig", "version": 1, "lights": [{"name": "A", "type": "point", "intensity": -5}]})");
        f.close();
        m_errors.clear();
        QVERIFY(!m_window->files()->openRig(bad));
        QCOMPARE(json(doc()->rig()), before);
        QCOMPARE(doc()->filePath(), filePath);
        QCOMPARE(doc()->undoStack()->count(), steps);
        QCOMPARE(m_errors.size(), 1);
        const QString all =
            m_errors[0].summary + QLatin1Char('\n') + m_errors[0].details.join(QLatin1Char('\n'));
        QVERIFY2(all.contains(QLatin1String("bad.json")) &&
                     all.contains(QLatin1String("lights[0].intensity")),
                 qPrintable(all));

        // A model that cannot be read leaves the model as it was, too.
        const auto model = m_window->scene()->model();
        QSignalSpy failed(m_window->files(), &DocumentFiles::modelLoadFailed);
        QVERIFY(m_window->files()->openModel(m_dir.filePath(QStringLiteral("missing.obj"))));
        QVERIFY(failed.wait(30000));
        QCOMPARE(m_window->scene()->model(), model);
    }

    void viewport_selectDragAndAim() {
        // The spot in front of the model, between it and the camera, a little off-centre.
        QVERIFY(test::spotInFrontOfTheModel(*m_window));
        const SceneFrame frame = m_window->scene()->frame();
        doc()->setSelection({});
        QApplication::processEvents();

        // Click selects.
        const auto at = viewport()->lightScreenPosition(0);
        QVERIFY(at && viewport()->rect().contains(at->toPoint()));
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, at->toPoint());
        QCOMPARE(doc()->selectedRows(), QList<int>{0});

        // Drag moves it in the view plane: one undo step, the depth kept.
        const int steps = doc()->undoStack()->count();
        const glm::dvec3 before = doc()->light(0).position;
        const QPoint p0 = at->toPoint();
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, p0);
        QVERIFY(!viewport()->isNavigating()); // a press alone is not a drag
        for (int i = 1; i <= 8; ++i)
            dragTo(viewport(), p0 + QPoint(5 * i, 0));
        QVERIFY(viewport()->isNavigating()); // interactive frames while dragging (proxies, no MSAA)
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, p0 + QPoint(40, 0));
        QVERIFY(!viewport()->isNavigating()); // the full-quality frame follows the release
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        const glm::dvec3 after = doc()->light(0).position;
        QVERIFY(glm::length(after - before) > 1e-6);
        const ScreenProjector proj = viewport()->projector();
        const double worldBefore = proj.depth(before), worldAfter = proj.depth(after); // world space rig
        QVERIFY(std::abs(worldBefore - worldAfter) < 1e-6 * std::max(1.0, worldBefore));
        const auto moved = viewport()->lightScreenPosition(0);
        QVERIFY(moved && std::abs(moved->x() - (p0.x() + 40)) < 1.5);
        doc()->undoStack()->undo();
        QVERIFY(doc()->light(0).position == before);

        // Escape during a drag takes it back; the steps before it stay.
        const int index = doc()->undoStack()->index();
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, p0);
        for (int i = 1; i <= 4; ++i)
            dragTo(viewport(), p0 + QPoint(0, 6 * i));
        QVERIFY(doc()->light(0).position != before);
        QTest::keyClick(viewport(), Qt::Key_Escape);
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, p0 + QPoint(0, 24));
        QVERIFY(doc()->light(0).position == before);
        QCOMPARE(doc()->undoStack()->index(), index);

        // Ctrl+drag moves along the view axis: the light keeps its place on screen.
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::ControlModifier, p0);
        for (int i = 1; i <= 4; ++i)
            dragTo(viewport(), p0 - QPoint(0, 5 * i), Qt::ControlModifier);
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::ControlModifier, p0 - QPoint(0, 20));
        QVERIFY(proj.depth(doc()->light(0).position) > proj.depth(before) + 1e-6); // pushed away
        const auto still = viewport()->lightScreenPosition(0);
        QVERIFY(still && QLineF(*still, QPointF(p0)).length() < 1.5);
        doc()->undoStack()->undo();

        // Shift+click on the model aims the selected spot at the clicked point.
        const auto centre = proj.project(frame.center);
        QVERIFY(centre);
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ShiftModifier, centre->toPoint());
        const glm::dvec3 toCentre = glm::normalize(frame.center - doc()->light(0).position);
        QVERIFY2(glm::dot(doc()->light(0).direction, toCentre) > 0.9,
                 qPrintable(QString::number(glm::dot(doc()->light(0).direction, toCentre))));

        // A click on empty space clears the selection.
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, QPoint(3, 3));
        QVERIFY(doc()->selectedRows().isEmpty());
    }

    // A wheel step dollies with interactive frames, and the full-quality frame follows once the wheel rests.
    void viewport_wheelDolliesThenSettles() {
        const ViewCamera before = viewport()->camera();
        const QPointF at(viewport()->width() / 2.0, viewport()->height() / 2.0);
        QWheelEvent wheel(at, viewport()->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(viewport(), &wheel);
        QVERIFY(viewport()->isNavigating());
        QVERIFY(glm::length(viewport()->camera().eye - viewport()->camera().target) <
                glm::length(before.eye - before.target));
        QTRY_VERIFY_WITH_TIMEOUT(!viewport()->isNavigating(), 3000);
        viewport()->setCamera(before);
    }

    void viewport_coneEdgeDragChangesTheOuterAngle() {
        QVERIFY(doc()->lightCount() == 1);
        doc()->setSelectedRows({0}, 0);
        QVERIFY(doc()->setLightValue({0}, LightProperty::ConeOuter, 30.0));
        const Light& l = doc()->light(0);
        const SceneFrame frame = m_window->scene()->frame();
        const ScreenProjector proj = viewport()->projector();
        const auto rim = coneRim(lightAnchor(doc()->rig(), frame, l), l.direction, l.cone.outer,
                                 spotGizmoLength(doc()->rig(), frame, l), 16);
        // A rim point well away from the light's own icon.
        std::optional<QPointF> grab;
        const auto icon = viewport()->lightScreenPosition(0);
        for (const auto& q : rim) {
            const auto s = proj.project(q);
            if (s && viewport()->rect().contains(s->toPoint()) &&
                (!grab || QLineF(*s, *icon).length() > QLineF(*grab, *icon).length()))
                grab = s;
        }
        QVERIFY(grab);
        QVERIFY(QLineF(*grab, *icon).length() > 2 * GizmoInteraction::kPickPixels);
        QCOMPARE(viewport()->interaction()->pickConeEdge(proj, *grab), 0);
        const int steps = doc()->undoStack()->count();
        const QPointF outward = *icon + (*grab - *icon) * 1.3;
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, grab->toPoint());
        dragTo(viewport(), (*grab + outward) / 2);
        dragTo(viewport(), outward.toPoint());
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, outward.toPoint());
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        QVERIFY2(doc()->light(0).cone.outer > 30.0, qPrintable(QString::number(doc()->light(0).cone.outer)));
        doc()->undoStack()->undo();
        QCOMPARE(doc()->light(0).cone.outer, 30.0);
    }

    void lookThroughLight_andFrameSelected() {
        doc()->setSelectedRows({0}, 0);
        m_window->actions()->lookThroughLight->trigger();
        const glm::dvec3 eye = lightAnchor(doc()->rig(), m_window->scene()->frame(), doc()->light(0));
        QVERIFY(glm::length(viewport()->camera().eye - eye) < 1e-9);
        QVERIFY(glm::dot(viewport()->camera().forward(), doc()->light(0).direction) > 0.999);

        m_window->actions()->frame->trigger(); // F with a selection: frames the light and the model
        const auto p = viewport()->lightScreenPosition(0);
        QVERIFY(p && QRectF(viewport()->rect()).contains(*p));
        const auto centre = viewport()->projector().project(m_window->scene()->frame().center);
        QVERIFY(centre && QRectF(viewport()->rect()).contains(*centre));
    }

    void exportScreenshot_atAnySize() {
        ScreenshotOptions o;
        o.path = m_dir.filePath(QStringLiteral("shot.png"));
        o.size = QSize(320, 200);
        o.supersample = 2;
        o.transparent = true;
        viewport()->frameAll();
        const QString error = viewport()->exportScreenshot(o);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const QImage image(o.path);
        QCOMPARE(image.size(), o.size);
        QVERIFY(image.hasAlphaChannel());
        QCOMPARE(qAlpha(image.pixel(0, 0)), 0);       // background corner: transparent
        QCOMPARE(qAlpha(image.pixel(160, 100)), 255); // the model in the middle

        o.path = m_dir.filePath(QStringLiteral("shot.jpg"));
        o.format = "JPEG";
        o.transparent = false;
        QVERIFY(viewport()->exportScreenshot(o).isEmpty());
        QCOMPARE(QImage(o.path).size(), o.size);
        o.path = m_dir.filePath(QStringLiteral("no/such/folder/shot.png"));
        QVERIFY(!viewport()->exportScreenshot(o).isEmpty());
    }

    void presets_saveWithThumbnail_andApplyAsOneStep() {
        PresetStore* store = m_window->presetStore();
        QDir(store->userDir()).removeRecursively(); // test-mode app data: start empty
        doc()->newRig(defaultRig());
        QVERIFY(doc()->setLightValue({0}, LightProperty::Intensity, 7.0));
        const Rig mine = doc()->rig();
        QVERIFY(m_window->presetsDock()->saveAsPreset(QStringLiteral("Test preset")));
        const QString presetFile = QDir(store->userDir()).filePath(QStringLiteral("Test preset.json"));
        const QString png = QDir(store->userDir()).filePath(QStringLiteral("Test preset.png"));
        QVERIFY(QFile::exists(presetFile));
        const QImage thumbnail(png);
        QVERIFY2(!thumbnail.isNull(), "a thumbnail rendered by LightRig");
        QVERIFY(thumbnail.pixelColor(thumbnail.width() / 2, thumbnail.height() / 2) !=
                thumbnail.pixelColor(0, 0)); // the model is in it

        // Applying a built-in and then the saved preset: one undo step each.
        PresetEntry builtin, saved;
        for (const PresetEntry& e : store->presets()) {
            if (e.builtin && e.name == QLatin1String("three-point")) builtin = e;
            if (!e.builtin && e.name == QLatin1String("Test preset")) saved = e;
        }
        QVERIFY(!builtin.path.isEmpty() && !saved.path.isEmpty());
        const int index = doc()->undoStack()->index();
        QVERIFY(m_window->presetsDock()->applyPreset(builtin));
        QCOMPARE(doc()->undoStack()->index(), index + 1);
        QVERIFY(doc()->rig() == *readBuiltinPreset(QStringLiteral("three-point")).rig);
        QVERIFY(m_window->presetsDock()->applyPreset(saved));
        Rig expected = mine;
        expected.name = QStringLiteral("Test preset");
        QCOMPARE(json(doc()->rig()), json(expected));
        doc()->undoStack()->undo();
        doc()->undoStack()->undo();
        QCOMPARE(json(doc()->rig()), json(mine));
        QDir(store->userDir()).removeRecursively();
    }

    void dropARigFile_opensIt() {
        doc()->undoStack()->setClean();
        const QString path = m_dir.filePath(QStringLiteral("dropped.json"));
        Rig rig;
        rig.lights.push_back(makeLight(LightType::Directional, QStringLiteral("Dropped sun")));
        QString error;
        QVERIFY2(saveRigFile(rig, path, &error), qPrintable(error));
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(path)});
        const QPoint at = m_window->rect().center();
        QDragEnterEvent enter(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(m_window.get(), &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(at, Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(m_window.get(), &drop);
        QCOMPARE(doc()->filePath(), path);
        QCOMPARE(doc()->light(0).name, QStringLiteral("Dropped sun"));
    }

    void importLightsAndCamerasFromAModel() {
        const QString path = QStringLiteral(LIGHTRIG_SHARED_MODELS "/bench/helmet_8spot.glb");
        if (!QFile::exists(path)) QSKIP("the shared models (../shared/models/bench) are not present");
        QSignalSpy loaded(m_window->files(), &DocumentFiles::modelLoaded);
        QVERIFY(m_window->files()->openModel(path));
        QVERIFY(loaded.wait(60000));
        const Model& model = *m_window->scene()->model();
        QVERIFY(!model.lights.lights.empty());
        QVERIFY(!model.cameras.empty());
        QVERIFY(m_window->actions()->importLights->isEnabled());
        QCOMPARE(m_window->actions()->modelCamerasMenu->actions().size(), qsizetype(model.cameras.size()));

        doc()->newRig(defaultRig()); // a model-space rig: the world-space lights are converted
        const int before = doc()->lightCount();
        const int steps = doc()->undoStack()->count();
        m_window->actions()->importLights->trigger();
        QCOMPARE(doc()->lightCount(), before + int(model.lights.lights.size()));
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        const SceneFrame frame = m_window->scene()->frame();
        const glm::dvec3 world = rigToWorld(doc()->rig(), frame, doc()->light(before).position);
        QVERIFY(glm::length(world - model.lights.lights[0].position) < 1e-9 * std::max(1.0, frame.radius));
        doc()->undoStack()->undo();
        QCOMPARE(doc()->lightCount(), before);

        m_window->actions()->modelCamerasMenu->actions().first()->trigger();
        QVERIFY(glm::length(viewport()->camera().eye - model.cameras[0].position) < 1e-9);

        QSignalSpy back(m_window->files(), &DocumentFiles::modelLoaded);
        QVERIFY(m_window->files()->openModel(MainWindow::suzannePath()));
        QVERIFY(back.wait(60000));
    }

    void nextStart_restoresRigModelAndLayout() {
        // A window of a session that restores: close it on a saved rig...
        const QString rigPath = m_dir.filePath(QStringLiteral("session.json"));
        QString error;
        QVERIFY2(saveRigFile(defaultRig(), rigPath, &error), qPrintable(error));
        {
            MainWindow first;
            QSignalSpy loaded(first.files(), &DocumentFiles::modelLoadFinished);
            EditorOptions options;
            options.rigPath = rigPath;
            first.openInitial(options);
            QVERIFY(loaded.wait(60000));
            first.show();
            QVERIFY(QTest::qWaitForWindowExposed(&first));
            first.resize(1111, 777);
            first.propertiesDock()->hide();
            QVERIFY(first.close());
        }
        // ...the next one (no arguments) reopens that rig with the same window layout.
        MainWindow second;
        QSignalSpy loaded(second.files(), &DocumentFiles::modelLoadFinished);
        second.openInitial(EditorOptions{});
        QVERIFY(loaded.wait(60000));
        QCOMPARE(second.document()->filePath(), rigPath);
        QCOMPARE(second.scene()->path(), MainWindow::bundledModelPath());
        QCOMPARE(second.size(), QSize(1111, 777));
        QVERIFY(second.propertiesDock()->isHidden());
    }

    // Issue 13: opened without a rig, the editor lets the model choose (core/defaultrig.h, as `render`
    // does): the bundled Suzanne keeps the classic default; a model with lights gets them, shaded physically
    // based exactly when its imported materials are; once the user edits the rig, it is theirs and the next
    // model keeps it.
    void modelOpenedWithoutARig_choosesItsDefaultRig() {
        MainWindow w;
        w.files()->askTexturesOutsideFolder = [](const QString&, const QStringList&) { return false; };
        QSignalSpy first(w.files(), &DocumentFiles::modelLoadFinished);
        EditorOptions options;
        options.restoreSession = false;
        options.modelPath = MainWindow::suzannePath();
        w.openInitial(options);
        QVERIFY(first.count() > 0 || first.wait(60000));
        QCOMPARE(w.scene()->path(), MainWindow::suzannePath());
        QVERIFY(w.document()->rig() == defaultRig());
        QVERIFY(w.files()->rigFollowsModel());

        const QString path = QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf");
        QSignalSpy loaded(w.files(), &DocumentFiles::modelLoaded);
        QVERIFY(w.files()->openModel(path));
        QVERIFY(loaded.wait(60000));
        const lr::ModelLoadResult imported = importModelIsolated(path);
        QVERIFY2(imported.ok(), qPrintable(imported.error));
        const Model& model = *imported.model;
        QVERIFY(!model.lights.lights.empty());
        const Rig& rig = w.document()->rig();
        QVERIFY(rig.lights == model.lights.lights);
        QCOMPARE(int(rig.shading.model), int(defaultShadingFor(model.hasPbrMaterials(), path)));
        QCOMPARE(w.document()->undoStack()->count(), 0);
        QVERIFY(!w.document()->isModified());

        QVERIFY(w.document()->setRigValue(RigProperty::Name, QStringLiteral("mine")));
        const Rig mine = w.document()->rig();
        QVERIFY(!w.files()->rigFollowsModel());
        QSignalSpy again(w.files(), &DocumentFiles::modelLoaded);
        QVERIFY(w.files()->openModel(QStringLiteral(LIGHTRIG_TEST_DATA "/model/quad.obj")));
        QVERIFY(again.wait(60000));
        QVERIFY(w.document()->rig() == mine);
    }
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
