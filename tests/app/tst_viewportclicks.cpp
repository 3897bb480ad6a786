// Issue 41 item 13, through the main window under Xvfb: adding a light leaves the camera where it is (the
// camera is no part of the undo step); a plain click on the model moves no light (Ctrl+click places the
// highlight); the click that moves the keyboard focus from a dock's field to the viewport keeps the
// selection; the wheel over the viewport takes the focus too, so number keys then choose standard views
// instead of typing into the field last edited. Issue 38: Alt+click on the model links the part there.
// Issue 40: while the view orbits, frames are drawn at the moving scale; the still frame at full size.
#include "app/gizmointeraction.h"
#include "app/lightsdock.h"
#include "app/linkingsection.h"
#include "app/linkmatrixdialog.h"
#include "app/linktools.h"
#include "app/numberedit.h"
#include "app/picking.h"
#include "app/propertiesdock.h"
#include "app/viewsettings.h"
#include "editor/linkmatrixmodel.h"
#include "render/scaledoutput.h"
#include "startwindow.h"

#include <QAction>
#include <QApplication>
#include <QLineEdit>
#include <QLineF>
#include <QTest>
#include <QUndoStack>
#include <QWheelEvent>
#include <glm/geometric.hpp>

using namespace lr;

class TestViewportClicks : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;

    Document* doc() { return m_window->document(); }
    Viewport* viewport() { return m_window->viewport(); }

    // A point on the model near the centre and one on the background, neither on a light's gizmo.
    void modelAndBackground(QPoint* onModel, QPoint* background) {
        const ScreenProjector proj = viewport()->projector();
        const Model& model = *m_window->scene()->model();
        std::optional<QPoint> m, b;
        for (int y = 4; y < viewport()->height() && !(m && b); y += 7)
            for (int x = 4; x < viewport()->width() && !(m && b); x += 7) {
                const QPoint q(x, y);
                if (viewport()->interaction()->pickLight(proj, q) >= 0) continue;
                const bool hit = intersectModel(model, proj.ray(q)).has_value();
                if (hit && !m && QLineF(q, viewport()->rect().center()).length() < 80) m = q;
                if (!hit && !b) b = q;
            }
        QVERIFY(m && b);
        *onModel = *m;
        *background = *b;
    }

    static bool sameCamera(const ViewCamera& a, const ViewCamera& b) {
        return glm::length(a.eye - b.eye) < 1e-12 && glm::length(a.target - b.target) < 1e-12 &&
               glm::length(a.up - b.up) < 1e-12 && a.yfovDeg == b.yfovDeg;
    }

    // Presses on `background`, moves 4 times (waiting for a frame after each), releases and waits for the
    // still frame at `full` size; *moving gets the sizes of the frames drawn while navigating.
    void orbitOnce(QPoint background, QSize full, std::vector<QSize>* moving) {
        moving->clear();
        QSignalSpy frames(viewport(), &Viewport::frameRendered);
        const auto connection = connect(viewport(), &Viewport::frameRendered, this, [&] {
            if (viewport()->isNavigating()) moving->push_back(viewport()->lastDrawnSize());
        });
        QTest::mousePress(viewport(), Qt::LeftButton, Qt::NoModifier, background);
        for (int i = 1; i <= 4; ++i) {
            const QPointF at = QPointF(background) + QPointF(12.0 * i, 0.0);
            QMouseEvent move(QEvent::MouseMove, at, viewport()->mapToGlobal(at), Qt::NoButton, Qt::LeftButton,
                             Qt::NoModifier);
            QApplication::sendEvent(viewport(), &move);
            const int before = int(frames.count());
            QTRY_VERIFY(frames.count() > before);
        }
        QTest::mouseRelease(viewport(), Qt::LeftButton, Qt::NoModifier, background + QPoint(48, 0));
        QTRY_VERIFY(!viewport()->isNavigating() && viewport()->lastDrawnSize() == full);
        disconnect(connection);
    }

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("lightrig-viewportclicks-test"));
        m_window = std::make_unique<MainWindow>();
        const QString started = test::startMainWindow(*m_window);
        QVERIFY2(started.isEmpty(), qPrintable(started));
    }

    // Issue 40: with "While moving" at a frame rate, an orbit draws its frames at the scale the controller
    // holds (told here of a slow frame: its smallest), and the frame after the release at full size; at
    // "full size" every moving frame is full size.
    void orbit_drawsSmallerWhileMoving() {
        doc()->newRig(Rig{});
        viewport()->frameAll();
        QPoint onModel, background;
        modelAndBackground(&onModel, &background);
        const qreal dpr = viewport()->devicePixelRatioF();
        const QSize full(int(std::lround(viewport()->width() * dpr)),
                         int(std::lround(viewport()->height() * dpr)));
        m_window->viewSettings()->setMovingFrameRate(30);
        viewport()->movingResolution().frameDrawn(1e5, 1.0); // a frame far over the budget
        const double scale = viewport()->movingResolution().scale();
        QCOMPARE(scale, DynamicResolution::kMinScale);
        std::vector<QSize> moving;
        orbitOnce(background, full, &moving);
        if (QTest::currentTestFailed()) return;
        QVERIFY(!moving.empty());
        QCOMPARE(moving.front(), render::scaledDrawSize(full, scale));
        m_window->viewSettings()->setMovingFrameRate(0);
        orbitOnce(background, full, &moving);
        if (QTest::currentTestFailed()) return;
        QVERIFY(!moving.empty());
        for (const QSize& s : moving)
            QCOMPARE(s, full);
        m_window->viewSettings()->setMovingFrameRate(30);
    }

    void cleanupTestCase() {
        doc()->undoStack()->setClean();
        m_window.reset();
    }

    // A light added while the camera is close in lands outside the view: the camera does not follow it
    // (it did, outside undo); the status bar says so instead.
    void addLight_leavesTheCamera() {
        doc()->newRig(Rig{});
        viewport()->frameAll();
        ViewCamera close = viewport()->camera();
        close.eye = close.target + (close.eye - close.target) * 0.15; // inside the placement radius
        viewport()->setCamera(close);
        const ViewCamera before = viewport()->camera();
        auto* add = m_window->findChild<QAction*>(QStringLiteral("addLight_spot"));
        QVERIFY(add);
        add->trigger();
        QCOMPARE(doc()->lightCount(), 1);
        const auto at = viewport()->lightScreenPosition(0);
        QVERIFY2(!at || !QRectF(viewport()->rect()).contains(*at), "the new light must be off-screen here");
        QVERIFY(sameCamera(viewport()->camera(), before));
        doc()->undoStack()->undo();
        QCOMPARE(doc()->lightCount(), 0);
        QVERIFY(sameCamera(viewport()->camera(), before));
    }

    // A plain click on the model moves no light and adds no step; Ctrl+click places the highlight.
    void plainClickOnTheModel_movesNoLight() {
        QVERIFY(test::spotInFrontOfTheModel(*m_window));
        doc()->setSelectedRows({0});
        QPoint onModel, background;
        modelAndBackground(&onModel, &background);
        const Light before = doc()->light(0);
        const int steps = doc()->undoStack()->count();
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, onModel);
        QCOMPARE(doc()->undoStack()->count(), steps);
        QVERIFY(doc()->light(0).position == before.position);
        QVERIFY(doc()->light(0).direction == before.direction);
        QCOMPARE(doc()->selectedRows(), QList<int>{0});
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::ControlModifier, onModel);
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        QVERIFY(doc()->light(0).position != before.position);
        QCOMPARE(doc()->selectedRows(), QList<int>{0});
    }

    // Issue 38: Alt+click on the model switches whether the selected light lights the part there (one step,
    // moving nothing; again: back to lighting it); the Linking section, open, has the viewport highlight
    // the parts the light lights; View › Light linking opens the matrix on the rig's lights.
    void altClickOnTheModel_linksThePart() {
        QVERIFY(test::spotInFrontOfTheModel(*m_window));
        doc()->setSelectedRows({0}, 0);
        QPoint onModel, background;
        modelAndBackground(&onModel, &background);
        LinkingSection* section = m_window->propertiesDock()->linking();
        section->setOpen(true);
        QVERIFY(!section->rows().empty());
        const std::size_t parts = m_window->scene()->model()->meshes.size();
        QCOMPARE(viewport()->highlightedParts().size(), parts); // a new light lights everything
        const Light before = doc()->light(0);
        const int steps = doc()->undoStack()->index();
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::AltModifier, onModel);
        QCOMPARE(doc()->undoStack()->index(), steps + 1);
        QVERIFY(!doc()->light(0).link.lit.exclude.isEmpty());
        QVERIFY(doc()->light(0).position == before.position);
        QVERIFY(viewport()->highlightedParts().size() < parts);
        QCOMPARE(doc()->selectedRows(), QList<int>{0});
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::AltModifier, onModel);
        QCOMPARE(doc()->undoStack()->index(), steps + 2);
        QVERIFY(doc()->light(0).link.isDefault());
        QCOMPARE(viewport()->highlightedParts().size(), parts);
        // Closed: no highlight.
        section->setOpen(false);
        QVERIFY(viewport()->highlightedParts().empty());
        // On the background: nothing.
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::AltModifier, background);
        QCOMPARE(doc()->undoStack()->index(), steps + 2);

        m_window->linkTools()->matrixAction()->trigger();
        LinkMatrixDialog* matrix = m_window->linkTools()->matrixDialog();
        QVERIFY(matrix->isVisible());
        QCOMPARE(matrix->matrix()->rowCount(), doc()->lightCount());
        QCOMPARE(matrix->matrix()->columnCount(), int(section->rows().size()));
        matrix->close();
    }

    // A name typed into the Properties dock's field (the focus stays there), then the viewport used.
    QLineEdit* editName(const QString& text) {
        QWidget* field = m_window->propertiesDock()->field(LightProperty::Name);
        if (!field) return nullptr;
        auto* name = qobject_cast<QLineEdit*>(field) ? qobject_cast<QLineEdit*>(field)
                                                     : field->findChild<QLineEdit*>();
        if (!name) return nullptr;
        name->setFocus(Qt::MouseFocusReason);
        if (!QTest::qWaitFor([name] { return name->hasFocus(); })) return nullptr;
        name->selectAll();
        QTest::keyClicks(name, text);
        QTest::keyClick(name, Qt::Key_Return);
        return name;
    }

    // Turning the wheel over the viewport after editing a field moves the keyboard focus there: "1" then
    // chooses the first standard view instead of typing into the field.
    void wheelOverTheViewport_numberKeysGoToTheView() {
        QVERIFY(test::spotInFrontOfTheModel(*m_window));
        doc()->setSelectedRows({0});
        QLineEdit* name = editName(QStringLiteral("Key"));
        QVERIFY(name);
        QCOMPARE(doc()->light(0).name, QStringLiteral("Key"));
        const QPointF at(viewport()->width() / 2, viewport()->height() / 2);
        QWheelEvent wheel(at, viewport()->mapToGlobal(at), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(viewport(), &wheel);
        QTRY_VERIFY(viewport()->hasFocus());
        const ViewCamera before = viewport()->camera();
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_1);
        QCOMPARE(name->text(), QStringLiteral("Key"));
        QCOMPARE(doc()->light(0).name, QStringLiteral("Key"));
        QVERIFY(!sameCamera(viewport()->camera(), before)); // the first standard view
    }

    // Clicking the viewport's background to focus it (from a field) keeps the selection; a second click
    // there clears it.
    void focusClick_keepsTheSelection() {
        QVERIFY(test::spotInFrontOfTheModel(*m_window));
        doc()->setSelectedRows({0});
        QPoint onModel, background;
        modelAndBackground(&onModel, &background);
        QVERIFY(editName(QStringLiteral("Fill")));
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, background);
        QTRY_VERIFY(viewport()->hasFocus());
        QCOMPARE(doc()->selectedRows(), QList<int>{0}); // the focus click
        test::shot(*m_window, QStringLiteral("editor2-focus-click-keeps-selection"));
        QTest::mouseClick(viewport(), Qt::LeftButton, Qt::NoModifier, background);
        QVERIFY(doc()->selectedRows().isEmpty());
    }
};

QTEST_MAIN(TestViewportClicks)
#include "tst_viewportclicks.moc"
