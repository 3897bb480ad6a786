// Issue 12 ("What a new user tripped over in the editor"), items 3, 4, 6 and 7, driven through the main
// window headless (Xvfb): new lights land around a model of any size and in view, the rig switches between
// model and world space in the Render settings dock as one undo step, framing keeps the model and the
// lights in view, import warnings can be read from the status bar, and a model's up axis is chosen in the
// Render settings dock and remembered for its file.
#include "app/commandline.h"
#include "app/documentfiles.h"
#include "app/editoractions.h"
#include "app/editorapp.h"
#include "app/editorstatusbar.h"
#include "app/errordialog.h"
#include "app/gizmointeraction.h"
#include "app/lightsdock.h"
#include "app/mainwindow.h"
#include "app/modeldock.h"
#include "app/modeltreemodel.h"
#include "app/presetsdock.h"
#include "app/rendersettingsdock.h"
#include "app/scene.h"
#include "app/viewport.h"
#include "core/rigjson.h"
#include "editor/document.h"
#include "editor/placement.h"
#include "model/isolatedimport.h"
#include "startwindow.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QFile>
#include <QMenu>
#include <QPlainTextEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QToolBar>
#include <QToolButton>
#include <QTreeView>
#include <glm/geometric.hpp>

using namespace lr;

namespace {
// The spider's size (fbx/spider.fbx: bounding diagonal about 25,770 units), off the origin.
std::shared_ptr<const Model> bigModel() {
    return std::make_shared<const Model>(makeSphere(12885.0, 32, 16, glm::dvec3(1000.0, -400.0, 250.0)));
}

// Mean brightness (0..255) of the central third of an image.
double centreBrightness(const QImage& image) {
    const QImage img = image.convertToFormat(QImage::Format_RGB32);
    double sum = 0.0;
    int n = 0;
    for (int y = img.height() / 3; y < 2 * img.height() / 3; ++y)
        for (int x = img.width() / 3; x < 2 * img.width() / 3; ++x, ++n)
            sum += qGray(img.pixel(x, y));
    return n ? sum / n : 0.0;
}
} // namespace

class TestNewUser : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
    QList<ErrorReport> m_errors;

    Document* doc() { return m_window->document(); }
    Viewport* viewport() { return m_window->viewport(); }
    Scene* scene() { return m_window->scene(); }

    bool onScreen(const glm::dvec3& world) {
        const auto p = viewport()->projector().project(world);
        return p && QRectF(viewport()->rect()).contains(*p);
    }
    bool lightOnScreen(int row) {
        return onScreen(lightAnchor(doc()->rig(), scene()->frame(), doc()->light(row)));
    }
    // The model's bounding box corners all in view.
    bool modelOnScreen() {
        const Bounds& b = scene()->model()->bounds;
        for (int i = 0; i < 8; ++i)
            if (!onScreen({i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z}))
                return false;
        return true;
    }
    void clickAdd(LightType type) {
        LightsDock* lights = m_window->lightsDock();
        QWidget* button = lights->toolBar()->widgetForAction(lights->addLightAction(type));
        QVERIFY(button);
        QTest::mouseClick(button, Qt::LeftButton);
    }

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("lightrig-test-newuser"));
        QVERIFY(m_dir.isValid());
        setErrorPresenter([this](const ErrorReport& r) { m_errors.append(r); });
        m_window = std::make_unique<MainWindow>();
        const QString started = test::startMainWindow(*m_window);
        QVERIFY2(started.isEmpty(), qPrintable(started));
    }

    void cleanupTestCase() {
        doc()->undoStack()->setClean();
        m_window.reset();
        setErrorPresenter({});
    }

    // Item 4: the default framing shows the model and the rig's lights (the presets' key and fill).
    void loadingAModel_framesItWithTheLights() {
        Rig rig;
        rig.space = RigSpace::Model;
        Light key = makeLight(LightType::Point, QStringLiteral("Key"));
        key.position = glm::dvec3(2.0, 2.5, 3.5);
        key.falloff.range = 12.0;
        Light fill = makeLight(LightType::Point, QStringLiteral("Fill"));
        fill.position = glm::dvec3(-3.5, 1.0, 3.0);
        fill.falloff.range = 12.0;
        rig.lights = {key, fill};
        doc()->newRig(rig);
        scene()->setModel(bigModel(), QString());
        QVERIFY(lightOnScreen(0));
        QVERIFY(lightOnScreen(1));
        QVERIFY(modelOnScreen());
    }

    // Item 4: F frames the selected light *and* the model; "Frame all lights" brings every light back.
    void frameSelection_keepsTheModel_frameAllLightsShowsEveryLight() {
        QCOMPARE(doc()->lightCount(), 2);
        m_window->actions()->frameAll->trigger(); // the model alone: Key and Fill may be off-screen
        doc()->setSelectedRows({0}, 0);
        viewport()->setFocus();
        QTest::keyClick(viewport(), Qt::Key_F);
        QVERIFY(lightOnScreen(0));
        QVERIFY(modelOnScreen());
        // Off to the side: the light away from the model, the camera on the model.
        viewport()->setStandardView(QStringLiteral("front"));
        viewport()->frameAll();
        QVERIFY(m_window->actions()->frameAllLights);
        QCOMPARE(m_window->actions()->frameAllLights->shortcut(), QKeySequence(Qt::SHIFT | Qt::Key_F));
        QTest::keyClick(viewport(), Qt::Key_F, Qt::ShiftModifier);
        QVERIFY(lightOnScreen(0));
        QVERIFY(lightOnScreen(1));
        QVERIFY(modelOnScreen());
    }

    // Item 3: on a model 25,770 units across, new lights land outside it, light it, and stay in view.
    void newLights_landAroundABigModel_andLightIt() {
        doc()->newRig(Rig{}); // world space, no lights: the model is black
        scene()->setModel(bigModel(), QString());
        const SceneFrame f = scene()->frame();
        const double dark = centreBrightness(viewport()->grabFramebuffer());
        QVERIFY2(dark < 5.0, qPrintable(QString::number(dark)));
        clickAdd(LightType::Spot);
        clickAdd(LightType::Point);
        QCOMPARE(doc()->lightCount(), 2);
        for (int row = 0; row < 2; ++row) {
            const Light& l = doc()->light(row);
            const double d = glm::length(rigToWorld(doc()->rig(), f, l.position) - f.center);
            QVERIFY2(d > 1.5 * f.radius,
                     qPrintable(QStringLiteral("%1 at %2 radii").arg(l.name).arg(d / f.radius)));
            QVERIFY(l.falloff.range / distanceScale(doc()->rig(), f) > d + f.radius); // reaches the far side
            QVERIFY(lightOnScreen(row));
        }
        QVERIFY(modelOnScreen());
        const double lit = centreBrightness(viewport()->grabFramebuffer());
        QVERIFY2(lit > dark + 20.0, qPrintable(QStringLiteral("%1 -> %2").arg(dark).arg(lit)));
    }

    // Item 3: the Space box converts the rig (nothing moves) as one undo step.
    void spaceSwitch_convertsTheRigAsOneUndoStep() {
        QCOMPARE(int(doc()->rig().space), int(RigSpace::World));
        const SceneFrame f = scene()->frame();
        const glm::dvec3 before = rigToWorld(doc()->rig(), f, doc()->light(0).position);
        const int steps = doc()->undoStack()->count();
        auto* space = m_window->renderSettingsDock()->findChild<QComboBox*>(QStringLiteral("rigSpace"));
        QVERIFY(space);
        QVERIFY(space->isEnabled());
        space->setFocus();
        QTest::keyClick(space, Qt::Key_Down); // world -> model
        QCOMPARE(int(doc()->rig().space), int(RigSpace::Model));
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        QVERIFY(glm::length(doc()->light(0).position) < 10.0); // radii now, not model units
        QVERIFY(glm::length(rigToWorld(doc()->rig(), f, doc()->light(0).position) - before) <
                1e-6 * f.radius);
        doc()->undoStack()->undo();
        QCOMPARE(int(doc()->rig().space), int(RigSpace::World));
        QCOMPARE(space->currentIndex(), int(RigSpace::World));
        QCOMPARE(rigToWorld(doc()->rig(), f, doc()->light(0).position), before);
    }

    // Item 6: the warnings stay reachable from the status bar and open in full — since issue 13 in the Model
    // dock, on its Warnings branch, each warning a row of its own.
    void importWarnings_areReadableFromTheStatusBar() {
        auto model = std::make_shared<Model>(makeSphere(1.0, 8, 6));
        model->warnings = {QStringLiteral("spider.fbx: texture 'Spinnen_Bein_tex_COLOR_.jpg' not found"),
                           QStringLiteral("spider.fbx: texture 'SH3.png' not found"),
                           QStringLiteral("spider.fbx: 12 degenerate triangles dropped")};
        scene()->setModel(model, QStringLiteral("/models/spider.fbx"));
        QToolButton* button = m_window->editorStatusBar()->warningsButton();
        QVERIFY(button->isVisible());
        QVERIFY2(button->text().contains(QLatin1String("3")), qPrintable(button->text()));
        ModelDock* dock = m_window->modelDock();
        // In the default layout a tab beside Presets and History, and listed in the Window menu.
        QVERIFY(m_window->tabifiedDockWidgets(m_window->historyDock()).contains(dock));
        bool inMenu = false;
        for (QObject* o : dock->toggleViewAction()->associatedObjects())
            inMenu = inMenu || qobject_cast<QMenu*>(o) != nullptr;
        QVERIFY(inMenu);
        m_window->presetsDock()->raise(); // the Model dock is a tab behind Presets
        QTest::mouseClick(button, Qt::LeftButton);
        QVERIFY(dock->isVisible());
        QVERIFY(!dock->visibleRegion().isEmpty()); // raised in front of its tab siblings
        const ModelTreeModel* tree = dock->treeModel();
        const QModelIndex warnings = tree->branchIndex(ModelTreeModel::Warnings);
        QCOMPARE(dock->view()->currentIndex(), warnings);
        QVERIFY(dock->view()->isExpanded(warnings));
        QCOMPARE(tree->rowCount(warnings), int(model->warnings.size()));
        for (int i = 0; i < model->warnings.size(); ++i)
            QCOMPARE(tree->index(i, 0, warnings).data().toString(), model->warnings[i]);
        // A model without warnings takes the button away and empties the branch.
        scene()->setModel(std::make_shared<const Model>(makeSphere(1.0, 8, 6)),
                          QStringLiteral("/models/ball.obj"));
        QVERIFY(!button->isVisible());
        QCOMPARE(tree->rowCount(tree->branchIndex(ModelTreeModel::Warnings)), 0);
    }

    // Item 7: the up axis rotates the model, not the rig, and is remembered for the file.
    void upAxis_rotatesTheModel_rememberedPerFile() {
        const QString path = m_dir.filePath(QStringLiteral("lying.stl"));
        {
            QFile f(path);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("solid x\nendsolid x\n");
        }
        // A model standing along +Z (as a Z-up tool writes it).
        auto lying = std::make_shared<const Model>(makeSphere(1.0, 16, 8, glm::dvec3(0.0, 0.0, 5.0)));
        doc()->newRig(defaultRig());
        const QByteArray rigBefore = writeRigJson(doc()->rig());
        scene()->setModel(lying, path);
        QCOMPARE(int(scene()->upAxis()), int(ModelUpAxis::YUp));
        auto* up = m_window->renderSettingsDock()->findChild<QComboBox*>(QStringLiteral("modelUp"));
        QVERIFY(up);
        QVERIFY(up->isEnabled());
        QCOMPARE(up->currentIndex(), int(ModelUpAxis::YUp));
        up->setFocus();
        QTest::keyClick(up, Qt::Key_Down); // +Y -> +Z
        QCOMPARE(int(scene()->upAxis()), int(ModelUpAxis::ZUp));
        QVERIFY(glm::length(scene()->model()->bounds.center() - glm::dvec3(0.0, 5.0, 0.0)) < 1e-9);
        QCOMPARE(writeRigJson(doc()->rig()), rigBefore); // the rig is not touched
        QVERIFY(modelOnScreen());                        // reframed on the stood-up model

        // Another model, then the same file again: the axis comes back with it.
        scene()->setModel(bigModel(), QString());
        QCOMPARE(int(scene()->upAxis()), int(ModelUpAxis::YUp));
        QCOMPARE(up->currentIndex(), int(ModelUpAxis::YUp));
        scene()->setModel(lying, path);
        QCOMPARE(int(scene()->upAxis()), int(ModelUpAxis::ZUp));
        QCOMPARE(up->currentIndex(), int(ModelUpAxis::ZUp));
        QVERIFY(glm::length(scene()->model()->bounds.center() - glm::dvec3(0.0, 5.0, 0.0)) < 1e-9);
        // Back to +Y: exactly the model as imported, and nothing remembered any more.
        QTest::keyClick(up, Qt::Key_Up);
        QCOMPARE(int(scene()->upAxis()), int(ModelUpAxis::YUp));
        QCOMPARE(scene()->model()->bounds.min, lying->bounds.min);
        QCOMPARE(int(Scene::rememberedUpAxis(path)), int(ModelUpAxis::YUp));
    }
};

QTEST_MAIN(TestNewUser)
#include "tst_newuser.moc"
