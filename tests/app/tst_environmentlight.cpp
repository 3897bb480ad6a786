// Issue 15 part 7 through the main window: with the procedural studio loaded, a Ctrl+Alt+click on the
// viewport's background where a softbox is adds a directional light "Env light 1" shining from it and
// dims the spot, in one undo step; Edit › Light from environment does it for a plain click (here without
// dimming); a click on the model or on a uniform part of the sky adds nothing and says why. Also: the
// viewport's renderer ends with the Scene's loaded environment, and an unreadable image shows the error box
// naming the file while the rig stays as it is.
#include "app/controlshelp.h"
#include "app/environmentlighttool.h"
#include "app/environmentloading.h"
#include "app/errordialog.h"
#include "render/environmentloader.h"
#include "startwindow.h"

#include <QAction>
#include <QSignalSpy>
#include <QStatusBar>
#include <glm/geometric.hpp>

using namespace lr;

namespace {
double degreesBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 /
           environment::kPi;
}

// The camera far out along d, looking further along it (the model behind it): the view's centre is d.
void lookAlong(MainWindow& window, const glm::dvec3& d) {
    const SceneFrame f = window.scene()->frame();
    ViewCamera c = window.viewport()->camera();
    c.eye = f.center + d * (20.0 * f.radius);
    c.target = c.eye + d * f.radius;
    c.up = std::abs(d.y) > 0.99 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    window.viewport()->setCamera(c);
}
} // namespace

class TestEnvironmentLight : public QObject {
    Q_OBJECT
    QList<ErrorReport> m_errors;

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("lightrig-test-environmentlight"));
        setErrorPresenter([this](const ErrorReport& r) { m_errors.append(r); });
    }
    void cleanupTestCase() { setErrorPresenter({}); }

    void lightFromASoftbox() {
        MainWindow window;
        const QString started = test::startMainWindow(window);
        QVERIFY2(started.isEmpty(), qPrintable(started));
        Document* doc = window.document();
        Viewport* viewport = window.viewport();
        EnvironmentLightTool* tool = window.environmentLightTool();
        QVERIFY(tool && !tool->pickAction()->associatedObjects().isEmpty()); // in a menu
        QVERIFY(controlsHtml(&window).contains(QLatin1String("Ctrl+Alt+click the background")));
        QVERIFY(tool->dimAction()->isChecked()); // dimming is the default

        Environment e;
        e.source = EnvironmentSource::Studio;
        Softbox box;
        box.azimuth = 45.0;
        box.elevation = 40.0;
        box.width = box.height = 20.0;
        box.color = glm::dvec3(1.0, 0.9, 0.8);
        box.intensity = 20.0;
        e.studio.softboxes = {box};
        QVERIFY(doc->setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        // Loaded in the background, then drawn by the viewport's renderer.
        QTRY_VERIFY_WITH_TIMEOUT(window.scene()->environment() != nullptr, 30000);
        QTRY_VERIFY_WITH_TIMEOUT(viewport->renderedEnvironment() == window.scene()->environment(), 10000);

        const glm::dvec3 d = environment::softboxDirection(box.azimuth, box.elevation);
        lookAlong(window, d);
        const int lights = doc->lightCount();
        const int steps = doc->undoStack()->count();
        QSignalSpy status(tool, &EnvironmentLightTool::statusMessage);
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::ControlModifier | Qt::AltModifier,
                          viewport->rect().center());
        QCOMPARE(doc->lightCount(), lights + 1);
        const Light& light = doc->light(lights);
        QCOMPARE(light.name, QStringLiteral("Env light 1"));
        QCOMPARE(int(light.type), int(LightType::Directional));
        QVERIFY2(degreesBetween(-light.direction, d) < 1.0,
                 qPrintable(QString::number(degreesBetween(-light.direction, d))));
        QVERIFY(std::abs(light.color.y - 0.9) < 1e-6 && std::abs(light.color.z - 0.8) < 1e-6);
        QVERIFY(light.intensity > 0.0);
        QCOMPARE(doc->rig().environment.spots.size(), size_t(1));
        QVERIFY(degreesBetween(doc->rig().environment.spots[0].direction, d) < 1.0);
        QCOMPARE(doc->undoStack()->count(), steps + 1); // one step for both
        QCOMPARE(doc->undoStack()->text(steps), QStringLiteral("Light from environment"));
        QVERIFY(doc->selectedRows() == QList<int>{lights});
        QVERIFY(!status.isEmpty() && status.last().at(0).toString().contains(QLatin1String("Env light 1")));
        // The dimmed spot is loaded: the same place has nothing bright any more.
        QTRY_VERIFY_WITH_TIMEOUT(window.scene()->environment()->spec.spots.size() == 1, 30000);
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::ControlModifier | Qt::AltModifier,
                          viewport->rect().center());
        QCOMPARE(doc->lightCount(), lights + 1);
        QVERIFY2(status.last().at(0).toString().contains(QLatin1String("nothing bright here")),
                 qPrintable(status.last().at(0).toString()));

        doc->undoStack()->undo(); // the light and the spot, together
        QCOMPARE(doc->lightCount(), lights);
        QVERIFY(doc->rig().environment.spots.empty());
        QTRY_VERIFY_WITH_TIMEOUT(window.scene()->environment()->spec.spots.empty() &&
                                     !window.environmentLoading()->isLoading(),
                                 30000);

        // Armed from the menu, a plain click, without dimming.
        tool->dimAction()->setChecked(false);
        tool->pickAction()->setChecked(true);
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, viewport->rect().center());
        QCOMPARE(doc->lightCount(), lights + 1);
        QCOMPARE(doc->light(lights).name, QStringLiteral("Env light 1"));
        QVERIFY(doc->rig().environment.spots.empty());
        QVERIFY(!tool->pickAction()->isChecked()); // one light per arming
        // Unarmed, a plain click just clears the selection.
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::NoModifier, viewport->rect().center());
        QCOMPARE(doc->lightCount(), lights + 1);
        QVERIFY(doc->selectedRows().isEmpty());

        // Straight down into the studio's uniform floor: nothing bright.
        lookAlong(window, glm::dvec3(0.0, -1.0, 0.001));
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::ControlModifier | Qt::AltModifier,
                          viewport->rect().center());
        QCOMPARE(doc->lightCount(), lights + 1);
        QVERIFY(status.last().at(0).toString().contains(QLatin1String("nothing bright here")));
        // On the model: not the background.
        viewport->frameAll();
        QTest::mouseClick(viewport, Qt::LeftButton, Qt::ControlModifier | Qt::AltModifier,
                          viewport->rect().center());
        QCOMPARE(doc->lightCount(), lights + 1);
        QVERIFY2(status.last().at(0).toString().contains(QLatin1String("model")),
                 qPrintable(status.last().at(0).toString()));
    }

    void anUnreadableImageIsReportedAndTheRigKept() {
        MainWindow window;
        const QString started = test::startMainWindow(window);
        QVERIFY2(started.isEmpty(), qPrintable(started));
        Document* doc = window.document();
        m_errors.clear();
        Environment e;
        e.source = EnvironmentSource::Image;
        e.file = QStringLiteral("/nonexistent/folder/broken-sky.hdr");
        QVERIFY(doc->setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        const Rig rig = doc->rig();
        QTRY_VERIFY_WITH_TIMEOUT(m_errors.size() == 1, 30000);
        QVERIFY2(m_errors[0].details.join(QLatin1Char('\n')).contains(QLatin1String("broken-sky.hdr")),
                 qPrintable(m_errors[0].details.join(QLatin1Char('\n'))));
        QVERIFY(window.statusBar()->currentMessage().contains(QLatin1String("broken-sky.hdr")));
        QVERIFY(doc->rig() == rig);
        QVERIFY(!window.scene()->environment());
        QVERIFY(!window.viewport()->renderedEnvironment());
    }
};

QTEST_MAIN(TestEnvironmentLight)
#include "tst_environmentlight.moc"
