// Not a test: the editor's own frames while the user orbits (issue 40), measured through the real window.
// Opens MODEL with RIG in the main window with a WxH viewport, waits for the model, the environment and a
// still frame, then holds the left button and moves the mouse 4 pixels every 16 ms (a hand orbiting at
// ~150 degrees a second) for SECONDS, and prints one JSON line. The moves are posted from a thread of
// their own, as the window system's arrive, so one posted while a frame is drawn waits for it:
//   frames, fps            viewport frames drawn while moving, and per second
//   frame_ms_median/max    intervals between them
//   input_ms_median/max    from a mouse move being posted to the viewport receiving it (what "the window
//                          stays responsive" means: Qt delivers input between frames, so a move waits for
//                          the frame being drawn when it came)
//   drawn                  the sizes the moving frames were drawn at, with counts (dynamicresolution.h)
//   still_ms               after the release, until the full-size still frame was drawn
//   moving_frame_rate      the "While moving" setting used (0: full size)
//
//   xvfb-run -a -s "-screen 0 1920x1080x24" build/dev/tests/app/editor_orbit MODEL RIG
//       [--seconds S] [--size WxH] [--moving-fps N]
// scripts/perf/editor_orbit.sh runs it on the scene.
#include "app/viewsettings.h"
#include "startwindow.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMouseEvent>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <thread>
#include <vector>

using namespace lr;

namespace {

double median(std::vector<double> v) {
    if (v.empty()) return -1.0;
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double maximum(const std::vector<double>& v) {
    return v.empty() ? -1.0 : *std::max_element(v.begin(), v.end());
}

using Clock = std::chrono::steady_clock;

// Milliseconds since `start`, as a mouse event's timestamp carries them.
quint64 msSince(Clock::time_point start) {
    return quint64(std::chrono::duration_cast<std::chrono::milliseconds>(Clock::now() - start).count());
}

// How long each posted mouse move took to reach the viewport: the poster stamps it with its post time.
class InputClock : public QObject {
  public:
    Clock::time_point start = Clock::now();
    std::vector<double> latencies;
    bool eventFilter(QObject* watched, QEvent* event) override {
        if (event->type() == QEvent::MouseMove)
            latencies.push_back(double(msSince(start)) -
                                double(static_cast<QMouseEvent*>(event)->timestamp()));
        return QObject::eventFilter(watched, event);
    }
};

int fail(const QString& message) {
    std::fprintf(stderr, "editor_orbit: %s\n", qPrintable(message));
    return 1;
}

} // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    test::prepareEditorTest(QStringLiteral("lightrig-editor-orbit"));
    QCommandLineParser parser;
    const QCommandLineOption seconds(QStringLiteral("seconds"), QStringLiteral("Seconds of orbiting."),
                                     QStringLiteral("S"), QStringLiteral("5"));
    const QCommandLineOption size(QStringLiteral("size"), QStringLiteral("Viewport size."),
                                  QStringLiteral("WxH"), QStringLiteral("1280x720"));
    const QCommandLineOption fps(QStringLiteral("moving-fps"),
                                 QStringLiteral("The While moving frame rate (0: full size)."),
                                 QStringLiteral("N"), QStringLiteral("30"));
    parser.addOptions({seconds, size, fps});
    parser.addPositionalArgument(QStringLiteral("MODEL"), QStringLiteral("The model."));
    parser.addPositionalArgument(QStringLiteral("RIG"), QStringLiteral("The rig."));
    parser.process(app);
    if (parser.positionalArguments().size() != 2)
        return fail(QStringLiteral("usage: editor_orbit MODEL RIG"));
    const QStringList wh = parser.value(size).split(QLatin1Char('x'));
    const QSize viewportSize(wh.value(0).toInt(), wh.value(1).toInt());
    if (viewportSize.isEmpty()) return fail(QStringLiteral("bad --size"));

    MainWindow window;
    window.viewSettings()->setPersistent(false);
    window.viewSettings()->setMovingFrameRate(parser.value(fps).toInt());
    QSignalSpy loaded(window.files(), &DocumentFiles::modelLoadFinished);
    EditorOptions options;
    options.restoreSession = false;
    options.modelPath = parser.positionalArguments()[0];
    options.rigPath = parser.positionalArguments()[1];
    window.openInitial(options);
    Viewport* viewport = window.viewport();
    viewport->setFixedSize(viewportSize);
    window.show();
    if (!QTest::qWaitForWindowExposed(&window)) return fail(QStringLiteral("the window was never exposed"));
    QApplication::setActiveWindow(&window);
    if (loaded.count() == 0 && !loaded.wait(120000)) return fail(QStringLiteral("the model did not load"));
    if (window.scene()->isEmpty()) return fail(QStringLiteral("the model loaded empty"));
    const bool environment = window.document()->rig().environment.source != EnvironmentSource::None;
    if (!QTest::qWaitFor(
            [&] { return viewport->hasRenderedFrame() && (!environment || viewport->renderedEnvironment()); },
            120000))
        return fail(QStringLiteral("no frame with the environment in 120 s"));
    QTest::qWait(1500); // the still frame after the environment, and the interaction proxies if any

    std::vector<double> frames;
    std::map<QString, int> drawn;
    QElapsedTimer clock;
    QObject::connect(viewport, &Viewport::frameRendered, viewport, [&] {
        if (!viewport->isNavigating()) return;
        frames.push_back(double(clock.nsecsElapsed()) * 1e-6);
        const QSize s = viewport->lastDrawnSize();
        ++drawn[QStringLiteral("%1x%2").arg(s.width()).arg(s.height())];
    });
    InputClock input;
    viewport->installEventFilter(&input);
    const QPointF centre(viewportSize.width() / 2.0, viewportSize.height() / 2.0);
    const QPointF global = viewport->mapToGlobal(centre.toPoint());
    QTest::mousePress(viewport, Qt::LeftButton, {}, centre.toPoint());
    clock.start();
    input.start = Clock::now();
    const double runMs = parser.value(seconds).toDouble() * 1000.0;
    std::atomic<bool> moving{true};
    std::thread hand([&] { // posting is thread-safe; the viewport receives the moves on the GUI thread
        for (int step = 1; moving; ++step) {
            const QPointF at = centre + QPointF(4.0 * (step % 200) - 400.0, 0.0);
            auto* move = new QMouseEvent(QEvent::MouseMove, at, global + (at - centre), Qt::NoButton,
                                         Qt::LeftButton, Qt::NoModifier);
            move->setTimestamp(msSince(input.start));
            QCoreApplication::postEvent(viewport, move);
            std::this_thread::sleep_for(std::chrono::milliseconds(16));
        }
    });
    while (clock.elapsed() < runMs)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    moving = false;
    hand.join();
    QCoreApplication::processEvents(); // the moves still queued
    const double movingMs = double(clock.nsecsElapsed()) * 1e-6;
    QTest::mouseRelease(viewport, Qt::LeftButton, {}, centre.toPoint());
    QElapsedTimer still;
    still.start();
    QSignalSpy settled(viewport, &Viewport::frameRendered);
    const bool stillDrawn = settled.wait(30000);
    const double stillMs = double(still.nsecsElapsed()) * 1e-6;

    std::vector<double> intervals;
    for (size_t i = 1; i < frames.size(); ++i)
        intervals.push_back(frames[i] - frames[i - 1]);
    QJsonObject sizes;
    for (const auto& [s, n] : drawn)
        sizes.insert(s, n);
    const QJsonObject out{
        {QStringLiteral("viewport"), parser.value(size)},
        {QStringLiteral("moving_frame_rate"), window.viewSettings()->options().movingFrameRate},
        {QStringLiteral("quality"), toString(window.viewSettings()->options().quality)},
        {QStringLiteral("seconds"), movingMs / 1000.0},
        {QStringLiteral("frames"), int(frames.size())},
        {QStringLiteral("fps"),
         frames.size() > 1 ? 1000.0 * double(frames.size() - 1) / (frames.back() - frames.front()) : 0.0},
        {QStringLiteral("frame_ms_median"), median(intervals)},
        {QStringLiteral("frame_ms_max"), maximum(intervals)},
        {QStringLiteral("input_ms_median"), median(input.latencies)},
        {QStringLiteral("input_ms_max"), maximum(input.latencies)},
        {QStringLiteral("inputs"), int(input.latencies.size())},
        {QStringLiteral("drawn"), sizes},
        {QStringLiteral("frame_times"),
         [&] {
             QJsonArray a;
             for (double t : frames)
                 a.append(std::round(t));
             return a;
         }()},
        {QStringLiteral("still_ms"), stillDrawn ? stillMs : -1.0},
        {QStringLiteral("still_size"), QStringLiteral("%1x%2")
                                           .arg(viewport->lastDrawnSize().width())
                                           .arg(viewport->lastDrawnSize().height())}};
    std::printf("%s\n", QJsonDocument(out).toJson(QJsonDocument::Compact).constData());
    return 0;
}
