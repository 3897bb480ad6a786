// Issue 41 item 16 through the main window under Xvfb: the camera is saved with the rig and restored when
// the rig is opened (also at start-up, before the model has loaded); View › Saved views keeps named views
// in the rig (saving or removing one is an undo step; recalling one moves the camera, no step).
#include "app/editoractions.h"
#include "app/viewbookmarks.h"
#include "core/rigjson.h"
#include "editor/rigviews.h"
#include "startwindow.h"

#include <QAction>
#include <QMenu>
#include <QTemporaryDir>
#include <QUndoStack>
#include <glm/geometric.hpp>

using namespace lr;

class TestViewBookmarks : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;

    Document* doc() { return m_window->document(); }
    Viewport* viewport() { return m_window->viewport(); }

    static bool near(const glm::dvec3& a, const glm::dvec3& b) { return glm::length(a - b) < 1e-9; }
    static bool sameView(const ViewCamera& a, const ViewCamera& b) {
        return near(a.eye, b.eye) && near(a.target, b.target) && std::abs(a.yfovDeg - b.yfovDeg) < 1e-9 &&
               near(a.trueUp(), b.trueUp());
    }
    // A camera no framing would choose: off to the side, looking down, a narrow lens.
    ViewCamera someView() const {
        ViewCamera c = m_window->viewport()->camera();
        c.orbit(63.0, -21.0);
        c.dolly(1.7);
        c.yfovDeg = 31.0;
        return c;
    }

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("lightrig-viewbookmarks-test"));
        QVERIFY(m_dir.isValid());
        m_window = std::make_unique<MainWindow>();
        const QString started = test::startMainWindow(*m_window);
        QVERIFY2(started.isEmpty(), qPrintable(started));
    }

    void cleanupTestCase() {
        doc()->undoStack()->setClean();
        m_window.reset();
    }

    // Saving writes the camera as the rig's "view" (no edit: the rig stays clean); opening the rig
    // brings the camera back.
    void cameraIsSavedWithTheRig_andRestoredOnOpen() {
        const ViewCamera saved = someView();
        viewport()->setCamera(saved);
        const QString path = m_dir.filePath(QStringLiteral("viewed.json"));
        QVERIFY(m_window->files()->saveAs(path));
        const RigReadResult r = readRigFile(path);
        QVERIFY(r.ok());
        QVERIFY(r.rig->view.has_value());
        QVERIFY(sameView(viewCameraOf(*r.rig->view), saved));

        viewport()->frameAll();
        viewport()->setCamera(ViewCamera{});
        QVERIFY(!doc()->isModified()); // moving the camera is no edit
        QVERIFY(m_window->files()->openRig(path));
        QVERIFY(sameView(viewport()->camera(), saved));
    }

    // A rig opened at start-up keeps its view when the model arrives after it.
    void startUpRigKeepsItsView_whenTheModelLoadsAfter() {
        const ViewCamera saved = someView();
        viewport()->setCamera(saved);
        const QString path = m_dir.filePath(QStringLiteral("start.json"));
        QVERIFY(m_window->files()->saveAs(path));
        MainWindow second;
        QSignalSpy loaded(second.files(), &DocumentFiles::modelLoadFinished);
        EditorOptions options;
        options.restoreSession = false;
        options.rigPath = path;
        second.openInitial(options);
        second.show();
        QVERIFY(loaded.wait(60000));
        QVERIFY(!second.scene()->isEmpty());
        QVERIFY(sameView(second.viewport()->camera(), saved));
        second.document()->undoStack()->setClean();
    }

    // View › Saved views: save (an undo step), recall (no step), saved with the rig, remove (a step).
    void savedViews_undoAndRecall() {
        ViewBookmarks* bookmarks = m_window->actions()->viewBookmarks;
        QVERIFY(bookmarks);
        const ViewCamera front = someView();
        viewport()->setCamera(front);
        bookmarks->askName = [](const QString&) { return QStringLiteral("Hero"); };
        const int steps = doc()->undoStack()->count();
        auto* save = m_window->findChild<QAction*>(QStringLiteral("saveView"));
        QVERIFY(save);
        save->trigger();
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        QCOMPARE(doc()->rig().views.size(), size_t(1));
        QCOMPARE(doc()->rig().views[0].name, QStringLiteral("Hero"));
        QVERIFY(doc()->isModified());

        viewport()->frameAll();
        QVERIFY(!sameView(viewport()->camera(), front));
        auto* recall = m_window->findChild<QAction*>(QStringLiteral("view:Hero"));
        QVERIFY(recall);
        recall->trigger();
        QVERIFY(sameView(viewport()->camera(), front));
        QCOMPARE(doc()->undoStack()->count(), steps + 1); // recalling is no step
        if (auto* menu = qobject_cast<QMenu*>(recall->parent())) {
            menu->popup(m_window->mapToGlobal(QPoint(200, 40)));
            QTest::qWait(200);
            if (!qEnvironmentVariableIsEmpty("LIGHTRIG_SHOTS"))
                menu->grab().save(qEnvironmentVariable("LIGHTRIG_SHOTS") +
                                  QStringLiteral("/editor2-saved-views-menu.png"));
            menu->hide();
        }
        test::shot(*m_window, QStringLiteral("editor2-saved-view-recalled"));

        const QString path = m_dir.filePath(QStringLiteral("bookmarks.json"));
        QVERIFY(m_window->files()->saveAs(path));
        const RigReadResult r = readRigFile(path);
        QVERIFY(r.ok());
        QCOMPARE(r.rig->views.size(), size_t(1));
        QVERIFY(sameView(viewCameraOf(r.rig->views[0]), front));

        doc()->undoStack()->undo();
        QVERIFY(doc()->rig().views.empty());
        QVERIFY(!m_window->findChild<QAction*>(QStringLiteral("view:Hero")));
        doc()->undoStack()->redo();
        QVERIFY(m_window->findChild<QAction*>(QStringLiteral("view:Hero")));
        QVERIFY(removeRigView(doc(), QStringLiteral("Hero")));
        QVERIFY(doc()->rig().views.empty());
        doc()->undoStack()->undo();
        QCOMPARE(doc()->rig().views.size(), size_t(1));
    }
};

QTEST_MAIN(TestViewBookmarks)
#include "tst_viewbookmarks.moc"
