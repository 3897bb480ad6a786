// Issue 36 item 2: the viewport's "Path traced" view (src/app/tracedview.h) through the main window: it
// accumulates once the view is still (samples grow, the image is the model's and not the raster's), a rig
// change starts it over, the samples target stops it, the exposure and the targets change without starting
// over, a classic rig is refused with the raster image kept, the event loop keeps running while it traces,
// and the window is destroyed cleanly while it traces.
#include "app/rendersettingsdock.h"
#include "app/screenshotjob.h"
#include "app/tracedview.h"
#include "app/viewsettings.h"
#include "startwindow.h"

#include <QComboBox>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>
#include <memory>

using namespace lr;

namespace {
// A physically based rig the tracer takes: an ambient term (added at every surface) and a key light.
Rig tracedRig() {
    Rig rig;
    rig.shading.model = ShadingModel::Pbr;
    rig.ambient = glm::dvec3(2.0);
    Light key;
    key.type = LightType::Directional;
    key.direction = glm::normalize(glm::dvec3(-0.4, -0.7, -0.6));
    key.intensity = 3.0;
    rig.lights.push_back(key);
    return rig;
}

// Share of pixels that differ from `color` by more than `tolerance` in some channel.
double shareUnlike(const QImage& image, QColor color, int tolerance) {
    const QImage a = image.convertToFormat(QImage::Format_RGBA8888);
    qint64 unlike = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QColor c = a.pixelColor(x, y);
            if (std::abs(c.red() - color.red()) > tolerance ||
                std::abs(c.green() - color.green()) > tolerance ||
                std::abs(c.blue() - color.blue()) > tolerance)
                ++unlike;
        }
    return double(unlike) / std::max<qint64>(1, qint64(a.width()) * a.height());
}

double meanLevel(const QImage& x) {
    const QImage a = x.convertToFormat(QImage::Format_RGB888);
    double sum = 0.0;
    for (int row = 0; row < a.height(); ++row) {
        const uchar* p = a.constScanLine(row);
        for (int i = 0; i < a.width() * 3; ++i)
            sum += p[i];
    }
    return sum / std::max(1, a.width() * a.height() * 3);
}

double meanAbsDifference(const QImage& x, const QImage& y) {
    const QImage a = x.convertToFormat(QImage::Format_RGB888);
    const QImage b = y.convertToFormat(QImage::Format_RGB888).scaled(a.size());
    double sum = 0.0;
    for (int row = 0; row < a.height(); ++row) {
        const uchar* p = a.constScanLine(row);
        const uchar* q = b.constScanLine(row);
        for (int i = 0; i < a.width() * 3; ++i)
            sum += std::abs(int(p[i]) - int(q[i]));
    }
    return sum / std::max(1, a.width() * a.height() * 3);
}
} // namespace

class TestTracedView : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> m_window;
    TracedView* traced() const { return m_window->viewport()->tracedView(); }
    ViewSettings* settings() const { return m_window->viewSettings(); }

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("tst_tracedview"));
        m_window = std::make_unique<MainWindow>();
        const QString error = test::startMainWindow(*m_window);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        m_window->document()->newRig(tracedRig());
        m_window->viewport()->resize(320, 240); // the docks keep the window; a small view traces quickly
        QTest::qWait(200);
    }

    void offByDefault() {
        QVERIFY(!settings()->options().pathTraced);
        QVERIFY(traced()->state() == TracedView::State::Off);
        QVERIFY(traced()->image().isNull());
    }

    // The Render settings' Quality box offers it after the raster tiers, and choosing it keeps the raster
    // tier (what the view shows while it changes).
    void qualityBoxOffersIt() {
        auto* dock = m_window->findChild<RenderSettingsDock*>();
        QVERIFY(dock);
        auto* quality = dock->findChild<QComboBox*>(QStringLiteral("quality"));
        QVERIFY(quality);
        QCOMPARE(quality->count(), enumCount<Quality>() + 1);
        settings()->setQuality(Quality::Balanced);
        quality->setCurrentIndex(enumCount<Quality>());
        emit quality->activated(enumCount<Quality>());
        QVERIFY(settings()->options().pathTraced);
        QVERIFY(settings()->options().quality == Quality::Balanced);
        emit quality->activated(int(Quality::Exact));
        QVERIFY(!settings()->options().pathTraced);
        QVERIFY(settings()->options().quality == Quality::Exact);
    }

    void accumulatesToTheTarget() {
        settings()->setTraceTargets(6, 0.0, 0.0);
        QList<int> seen;
        connect(traced(), &TracedView::updated, this, [&] {
            if (seen.isEmpty() || seen.last() != traced()->samples()) seen.append(traced()->samples());
        });
        settings()->setPathTraced(true);
        QVERIFY(traced()->active());
        QVERIFY(QTest::qWaitFor([&] { return traced()->state() == TracedView::State::Done; }, 120000));
        disconnect(traced(), &TracedView::updated, this, nullptr);
        QCOMPARE(traced()->samples(), 6);
        QVERIFY2(seen.size() >= 2, "the image was shown only once");
        for (int i = 1; i < seen.size(); ++i)
            if (seen[i] != 0) QVERIFY(seen[i] > seen[i - 1]);
        const QImage image = traced()->image();
        const qreal dpr = m_window->viewport()->devicePixelRatioF();
        QCOMPARE(image.size(), (QSizeF(m_window->viewport()->size()) * dpr).toSize());
        // The model is in it (the background is one flat colour), and it is not the raster frame.
        const double model = shareUnlike(image, settings()->options().background, 12);
        QVERIFY2(model > 0.005, qPrintable(QString::number(model)));
        // Where no environment is seen the background is the view's colour, as in the raster view.
        QVERIFY(shareUnlike(image.copy(0, 0, 8, 8), settings()->options().background, 1) == 0.0);
        const QImage raster = m_window->viewport()->grabFramebuffer();
        const double difference = meanAbsDifference(image, raster);
        QVERIFY2(difference > 0.5, qPrintable(QString::number(difference)));
        test::shot(*m_window, QStringLiteral("traced-done"));
        // The target holds: no more samples come.
        QTest::qWait(600);
        QCOMPARE(traced()->samples(), 6);
        QVERIFY(traced()->state() == TracedView::State::Done);
        QVERIFY2(traced()->readout().startsWith(QLatin1String("Path traced: 6 samples, ")),
                 qPrintable(traced()->readout()));
    }

    // The exposure and the targets act on the samples traced: a new exposure shows the same samples
    // brighter, a raised target goes on from them, and neither starts over.
    void displayAndTargetsKeepTheSamples() {
        settings()->setTraceTargets(6, 0.0, 0.0);
        QVERIFY(QTest::qWaitFor(
            [&] { return traced()->state() == TracedView::State::Done && traced()->samples() == 6; },
            120000));
        const int restarts = traced()->restarts();
        const QImage before = traced()->image();
        const double exposure = settings()->options().exposure;
        settings()->setExposure(exposure + 2.0);
        QVERIFY(QTest::qWaitFor([&] { return traced()->image() != before; }, 30000));
        QCOMPARE(traced()->samples(), 6);
        QCOMPARE(traced()->restarts(), restarts);
        QVERIFY(traced()->state() == TracedView::State::Done);
        // Brighter where the model is (the background is the view's colour, untouched by exposure).
        const double gain = meanLevel(traced()->image()) - meanLevel(before);
        QVERIFY2(gain > 0.1, qPrintable(QString::number(gain)));
        settings()->setTraceTargets(10, 0.0, 0.0);
        QVERIFY(QTest::qWaitFor(
            [&] { return traced()->state() == TracedView::State::Done && traced()->samples() == 10; },
            120000));
        QCOMPARE(traced()->restarts(), restarts);
        settings()->setExposure(exposure);
        QVERIFY(QTest::qWaitFor([&] { return traced()->state() == TracedView::State::Done; }, 30000));
        QCOMPARE(traced()->restarts(), restarts);
    }

    // Issue 37: with layers on, the traced view hands over its samples split into light groups (the Mixer
    // dock's capture): the groups sum to the beauty, for as many samples as the view shows, without a
    // restart.
    void layersOfTheSamplesSoFar() {
        traced()->setLayers(true);
        settings()->setTraceTargets(4, 0.0, 0.0);
        QVERIFY(QTest::qWaitFor(
            [&] { return traced()->state() == TracedView::State::Done && traced()->samples() == 4; },
            120000));
        const int restarts = traced()->restarts();
        QSignalSpy ready(traced(), &TracedView::layersReady);
        QVERIFY(traced()->requestLayers());
        QVERIFY(ready.wait(30000));
        const RenderLayers layers = ready.first().at(0).value<RenderLayers>();
        QCOMPARE(ready.first().at(1).toInt(), 4);
        QVERIFY(!layers.groups.empty());
        QCOMPARE(layers.groupImages.size(), layers.groups.size());
        QVERIFY2(groupSumError(layers) < 1e-5, qPrintable(QString::number(groupSumError(layers))));
        QCOMPARE(traced()->restarts(), restarts);
        traced()->setLayers(false);
        QVERIFY(QTest::qWaitFor([&] { return traced()->state() == TracedView::State::Done; }, 120000));
        QVERIFY(!traced()->requestLayers()); // off: nothing to give
    }

    // The noise target: accumulation stops once the estimate is at or below it.
    void noiseTargetStops() {
        // The estimate's scale depends on the scene (relative to its mean luminance): the target is a
        // share of the estimate after a few samples, which more samples reach (it falls as 1/sqrt(n)).
        settings()->setTraceTargets(0, 0.0, 0.0);
        QVERIFY(QTest::qWaitFor([&] { return traced()->samples() >= 4 && std::isfinite(traced()->noise()); },
                                120000));
        const double target = 0.7 * traced()->noise();
        settings()->setTraceTargets(0, 0.0, target);
        QVERIFY(QTest::qWaitFor([&] { return traced()->state() == TracedView::State::Done; }, 120000));
        QVERIFY2(traced()->noise() >= 0.0 && traced()->noise() <= target, qPrintable(traced()->readout()));
        QVERIFY(traced()->readout().contains(QLatin1String("noise")));
        QVERIFY(traced()->message().contains(QLatin1String("noise target")));
        const int samples = traced()->samples();
        QTest::qWait(400);
        QCOMPARE(traced()->samples(), samples);
    }

    void rigChangeRestarts() {
        settings()->setTraceTargets(0, 0.0, 0.0); // no target: it goes on
        QVERIFY(QTest::qWaitFor([&] { return traced()->samples() >= 4; }, 120000));
        const int before = traced()->restarts();
        const int samples = traced()->samples();
        QVERIFY(
            m_window->document()->setRigValue(RigProperty::Ambient, QVariant::fromValue(glm::dvec3(1.0))));
        QVERIFY(traced()->restarts() > before);
        QCOMPARE(traced()->samples(), 0);
        QVERIFY(traced()->image().isNull()); // the raster image, until the first pass of the new rig
        QVERIFY(QTest::qWaitFor([&] { return traced()->samples() > 0; }, 60000));
        QVERIFY2(traced()->samples() < samples, qPrintable(QString::number(traced()->samples())));
    }

    // The event loop runs while passes accumulate: a 10 ms timer never waits long (loose: a functional
    // check on a loaded machine, not a benchmark).
    void eventLoopKeepsRunning() {
        QVERIFY(QTest::qWaitFor([&] { return traced()->state() == TracedView::State::Tracing; }, 60000));
        QElapsedTimer clock;
        clock.start();
        qint64 last = 0, worst = 0;
        int ticks = 0;
        QTimer timer;
        timer.setInterval(10);
        connect(&timer, &QTimer::timeout, this, [&] {
            const qint64 now = clock.elapsed();
            worst = std::max(worst, now - last);
            last = now;
            ++ticks;
        });
        const int samples = traced()->samples();
        timer.start();
        QTest::qWait(2000);
        timer.stop();
        QVERIFY(traced()->samples() > samples); // it was tracing all along
        qInfo("event loop while tracing: longest 10 ms timer gap %lld ms over %d ticks", worst, ticks);
        QVERIFY2(worst < 300, qPrintable(QStringLiteral("longest gap %1 ms").arg(worst)));
        QVERIFY(ticks > 20);
    }

    void cameraChangeRestarts() {
        const int before = traced()->restarts();
        ViewCamera camera = m_window->viewport()->camera();
        camera.orbit(20.0, 0.0);
        m_window->viewport()->setCamera(camera);
        QVERIFY(QTest::qWaitFor([&] { return traced()->restarts() > before; }, 10000));
        QVERIFY(QTest::qWaitFor([&] { return traced()->samples() > 0; }, 60000));
    }

    void classicRigIsRefused() {
        QVERIFY(
            m_window->document()->setRigValue(RigProperty::ShadingModel, toString(ShadingModel::Classic)));
        QVERIFY(QTest::qWaitFor([&] { return traced()->state() == TracedView::State::Refused; }, 60000));
        QVERIFY(traced()->image().isNull()); // the raster image stays
        QVERIFY(traced()->readout().contains(QLatin1String("not available")));
        QVERIFY2(!traced()->message().isEmpty(), "the refusal says why");
        QVERIFY(m_window->viewport()->findChild<QWidget*>(QStringLiteral("TracedOverlay"))->isVisible());
        QVERIFY(m_window->document()->setRigValue(RigProperty::ShadingModel, toString(ShadingModel::Pbr)));
        QVERIFY(QTest::qWaitFor([&] { return traced()->samples() > 0; }, 60000));
    }

    void offAgain() {
        settings()->setPathTraced(false);
        QVERIFY(traced()->state() == TracedView::State::Off);
        QVERIFY(!m_window->viewport()->findChild<QWidget*>(QStringLiteral("TracedOverlay"))->isVisible());
        settings()->setPathTraced(true);
        QVERIFY(QTest::qWaitFor([&] { return traced()->samples() > 0; }, 60000));
    }

    // Export screenshot, path traced: on a worker, progress by samples, the file written.
    void tracedScreenshot() {
        QTemporaryDir dir;
        ScreenshotOptions o;
        o.path = dir.filePath(QStringLiteral("traced.png"));
        o.size = QSize(200, 150);
        o.pathTraced = true;
        o.traceSamples = 4;
        ScreenshotJob job(m_window->viewport(), o);
        QList<int> percents;
        connect(&job, &ScreenshotJob::progressChanged, this, [&](int p) { percents.append(p); });
        QSignalSpy done(&job, &ScreenshotJob::finished);
        job.start();
        QVERIFY(done.count() > 0 || done.wait(120000));
        QVERIFY2(job.result().ok(), qPrintable(job.result().error));
        QCOMPARE(percents.last(), 100);
        const QImage image(o.path);
        QCOMPARE(image.size(), o.size);
        QVERIFY(shareUnlike(image, settings()->options().background, 12) > 0.005); // the model is in it
    }

    void tracedScreenshotCancel() {
        QTemporaryDir dir;
        ScreenshotOptions o;
        o.path = dir.filePath(QStringLiteral("traced.png"));
        {
            QFile old(o.path);
            QVERIFY(old.open(QIODevice::WriteOnly));
            old.write("the file before");
        }
        o.size = QSize(400, 300);
        o.pathTraced = true;
        o.traceSamples = 100000; // hours: only Cancel ends it
        ScreenshotJob job(m_window->viewport(), o);
        QSignalSpy done(&job, &ScreenshotJob::finished);
        job.start();
        QTest::qWait(500);
        QVERIFY(job.isRunning());
        job.cancel();
        QVERIFY(done.count() > 0 || done.wait(60000));
        QVERIFY(job.result().cancelled);
        QFile old(o.path);
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), QByteArray("the file before"));
    }

    // Last: the window goes while a pass is running; its job is cancelled and waited for.
    void destroyedWhileTracing() {
        QVERIFY(traced()->active());
        QVERIFY(traced()->state() == TracedView::State::Tracing);
        m_window.reset();
        QTest::qWait(100); // nothing posted by the worker reaches the dead view
    }
};

QTEST_MAIN(TestTracedView)
#include "tst_tracedview.moc"
