// Issue 15 part 7 through the main window: with the procedural studio loaded, a Ctrl+Alt+click on the
// viewport's background where a softbox is adds a directional light "Env light 1" shining from it and
// dims the spot, in one undo step; Edit › Light from environment does it for a plain click (here without
// dimming); a click on the model or on a uniform part of the sky adds nothing and says why. Also: the
// viewport's renderer ends with the Scene's loaded environment, and an unreadable image shows the error box
// naming the file while the rig stays as it is.
#include "app/controlshelp.h"
#include "app/environmentbox.h"
#include "app/environmentlighttool.h"
#include "app/environmentloading.h"
#include "app/errordialog.h"
#include "core/envlight.h"
#include "scene/environmentloader.h"
#include "startwindow.h"

#include <QAction>
#include <QApplication>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <glm/geometric.hpp>

using namespace lr;

namespace {
double degreesBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 /
           environment::kPi;
}

double luminance(const glm::vec3& c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
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
    QString m_statusAtError;

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("lightrig-test-environmentlight"));
        setErrorPresenter([this](const ErrorReport& r) {
            m_errors.append(r);
            // What the Environment box says while the error box is up (issue 41: not "Loading…").
            m_statusAtError.clear();
            for (QWidget* w : QApplication::topLevelWidgets())
                if (auto* l = w->findChild<QLabel*>(QStringLiteral("environmentStatus")))
                    m_statusAtError = l->text();
        });
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
        // The softbox's colour, but for the sky in its antialiased edge texels (taken with it).
        QVERIFY2(std::abs(light.color.y - 0.9) < 0.01 && std::abs(light.color.z - 0.8) < 0.01,
                 qPrintable(QStringLiteral("%1, %2").arg(light.color.y).arg(light.color.z)));
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
        // Issue 41: the box no longer says "Loading…" under the error box.
        QVERIFY2(!m_statusAtError.contains(QLatin1String("Loading")), qPrintable(m_statusAtError));
        QVERIFY(!window.findChild<QLabel*>(QStringLiteral("environmentStatus"))
                     ->text()
                     .contains(QLatin1String("Loading")));
    }

    void aTruncatedImageChosenLeavesTheRigAndTheView() {
        // Issue 41 item 3: choosing a truncated EXR replaced the working environment (the rig named the
        // broken file, the lighting disappeared). The rig, its history and what is drawn must stay.
        QTemporaryDir dir;
        QFile good(QStringLiteral(":/resources/environments/studio.exr"));
        QVERIFY(good.open(QIODevice::ReadOnly));
        const QByteArray bytes = good.readAll();
        const QString broken = dir.filePath(QStringLiteral("truncated.exr"));
        QFile out(broken);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(bytes.left(bytes.size() / 2));
        out.close();

        MainWindow window;
        const QString started = test::startMainWindow(window);
        QVERIFY2(started.isEmpty(), qPrintable(started));
        Document* doc = window.document();
        Environment e;
        e.source = EnvironmentSource::Studio;
        e.studio.softboxes = {Softbox{}};
        QVERIFY(doc->setRigValue(RigProperty::Environment, QVariant::fromValue(e)));
        QTRY_VERIFY_WITH_TIMEOUT(window.scene()->environment() && window.viewport()->renderedEnvironment(),
                                 30000);
        const auto shown = window.scene()->environment();
        const Rig rig = doc->rig();
        const int steps = doc->undoStack()->count();
        m_errors.clear();

        auto* box = window.findChild<EnvironmentBox*>();
        QVERIFY(box);
        box->chooseImageFile(broken);
        QTRY_VERIFY_WITH_TIMEOUT(m_errors.size() == 1, 30000);
        QVERIFY2(m_errors[0].details.join(QLatin1Char('\n')).contains(QLatin1String("truncated.exr")),
                 qPrintable(m_errors[0].details.join(QLatin1Char('\n'))));
        QTest::qWait(200);
        QVERIFY(doc->rig() == rig); // the rig still names the studio
        QCOMPARE(doc->undoStack()->count(), steps);
        QCOMPARE(window.scene()->environment(), shown); // and it is still what is drawn
        QCOMPARE(window.viewport()->renderedEnvironment(), shown);
        QVERIFY2(!m_statusAtError.contains(QLatin1String("Loading")), qPrintable(m_statusAtError));
        auto* message = window.findChild<QLabel*>(QStringLiteral("environmentMessage"));
        QVERIFY2(message->text().contains(QLatin1String("truncated.exr")), qPrintable(message->text()));

        // A readable image is taken, in one step, and drawn without loading it twice.
        const QString fine = dir.filePath(QStringLiteral("fine.exr"));
        QVERIFY(QFile::copy(QStringLiteral(LIGHTRIG_TEST_DATA "/environment/tiny.exr"), fine));
        QSignalSpy busy(window.findChild<EnvironmentLoading*>(), &EnvironmentLoading::loadingChanged);
        box->chooseImageFile(fine);
        QTRY_VERIFY_WITH_TIMEOUT(doc->rig().environment.source == EnvironmentSource::Image, 30000);
        QCOMPARE(doc->undoStack()->count(), steps + 1);
        QVERIFY(window.scene()->environment() != shown);
        QVERIFY(window.scene()->environment()->spec.sameRadiance(doc->rig().environment));
        QCOMPARE(busy.count(), 2); // one load: started, finished
        QCOMPARE(m_errors.size(), 1);
    }

    void dimmingStudioExrRemovesWhatTheLightTakes() {
        // Issue 41 item 4: on studio.exr "Dim the spot" left a bright ring around a black hole. The dimmed
        // texels' energy (Σ ΔL·Ω) must be the new light's (colour × lux, PBR at 0 EV), and nothing left
        // beside the hole may be as bright as what was dimmed.
        Environment e;
        e.source = EnvironmentSource::Image;
        e.file = QStringLiteral("builtin:studio");
        const EnvironmentLoadResult r = loadEnvironment(e, QDir::currentPath());
        QVERIFY2(r.environment, qPrintable(r.error));
        const EnvironmentImage& img = r.environment->image;
        const int w = img.width, h = img.height;
        int bx = 0, by = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                if (luminance(img.at(x, y)) > luminance(img.at(bx, by))) {
                    bx = x;
                    by = y;
                }
        const EnvironmentLight l =
            lightFromEnvironment(img, 0.0, 0.0, ShadingModel::Pbr, environment::texelDirection(bx, by, w, h));
        QVERIFY2(l.found, qPrintable(l.reason));
        EnvironmentImage after = img;
        environment::applySpots(&after, {l.spot});
        glm::dvec3 removed(0.0);
        double dimmedMin = 1e300, beside = 0.0;
        auto dimmed = [&](int x, int y) { return after.at(x, y) != img.at(x, y); };
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                removed += (glm::dvec3(img.at(x, y)) - glm::dvec3(after.at(x, y))) *
                           environment::texelSolidAngle(y, w, h);
                if (dimmed(x, y)) {
                    dimmedMin = std::min(dimmedMin, luminance(img.at(x, y)));
                    continue;
                }
                const bool border = dimmed((x + 1) % w, y) || dimmed((x + w - 1) % w, y) ||
                                    (y > 0 && dimmed(x, y - 1)) || (y + 1 < h && dimmed(x, y + 1));
                if (border) beside = std::max(beside, luminance(img.at(x, y)));
            }
        const glm::dvec3 taken = l.color * l.intensity;
        qInfo("studio.exr %dx%d: peak %g, %d texels dimmed (%.4f sr, spot %.2f deg), the dimmest %g, the "
              "brightest left beside them %g",
              w, h, luminance(img.at(bx, by)), l.texels, l.solidAngle, l.spot.angle, dimmedMin, beside);
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(removed[c] - taken[c]) <= 1e-6 * taken[c],
                     qPrintable(QStringLiteral("channel %1: dimming removes %2, the light takes %3")
                                    .arg(c)
                                    .arg(removed[c], 0, 'g', 9)
                                    .arg(taken[c], 0, 'g', 9)));
        // No bright ring: nothing beside the hole keeps even 2% of the light's peak.
        QVERIFY2(beside < 0.02 * luminance(img.at(bx, by)),
                 qPrintable(QStringLiteral("a texel of luminance %1 is left beside the dimmed spot (peak %2)")
                                .arg(beside)
                                .arg(luminance(img.at(bx, by)))));
        QVERIFY2(beside < dimmedMin, qPrintable(QStringLiteral("a texel of luminance %1 is left beside the "
                                                               "dimmed ones (the dimmest of which is %2)")
                                                    .arg(beside)
                                                    .arg(dimmedMin)));
    }
};

QTEST_MAIN(TestEnvironmentLight)
#include "tst_environmentlight.moc"
