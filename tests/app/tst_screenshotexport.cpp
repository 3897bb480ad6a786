// "Export screenshot" in the background (app/screenshotjob.h, issue 41 item 12) on a real main window under
// Xvfb: a large export advances tile by tile, its progress rising to 100 in proportion to the pixels
// rendered, while the event loop runs (timers fire, the viewport repaints, an edit is applied) and the
// image stays what it was when the export began; Cancel during the render or during the writing leaves an
// existing file byte for byte as it was (and no temporary file); a thumbnail rendered through the same
// offscreen renderer between tiles does not change the exported pixels; the dialog keeps its last file.
#include "app/commandline.h"
#include "app/documentfiles.h"
#include "app/editorapp.h"
#include "app/errordialog.h"
#include "app/mainwindow.h"
#include "app/screenshotdialog.h"
#include "app/screenshotexport.h"
#include "app/screenshotjob.h"
#include "app/viewport.h"
#include "editor/document.h"
#include "model/isolatedimport.h"
#include "startwindow.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImageReader>
#include <QProgressBar>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <functional>

using namespace lr;

class TestScreenshotExport : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
    QList<ErrorReport> m_errors;

    Viewport* viewport() { return m_window->viewport(); }
    // Starts a background export with its status-bar progress and runs the event loop until it finished,
    // `tick` on every pass (between tiles, while writing); the job's percentages in *percents.
    ScreenshotExportResult exportWhile(const ScreenshotOptions& o,
                                       const std::function<void(ScreenshotJob&)>& tick,
                                       QList<int>* percents = nullptr) {
        ScreenshotJob job(viewport(), o);
        connect(&job, &ScreenshotJob::progressChanged, this, [percents](int p) {
            if (percents) percents->append(p);
        });
        QSignalSpy done(&job, &ScreenshotJob::finished);
        QTimer timer;
        timer.setInterval(0);
        connect(&timer, &QTimer::timeout, this, [&] { tick(job); });
        showInStatusBar(m_window.get(), &job);
        job.start();
        timer.start();
        if (!done.wait(240000)) qWarning("the export did not finish in 240 s");
        timer.stop();
        return job.result();
    }
    static QByteArray bytes(const QString& path) {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("lightrig-test"));
        QVERIFY(m_dir.isValid());
        setErrorPresenter([this](const ErrorReport& r) { m_errors.append(r); });
        m_window = std::make_unique<MainWindow>();
        const QString started = test::startMainWindow(*m_window);
        QVERIFY2(started.isEmpty(), qPrintable(started));
        viewport()->frameAll();
    }
    void cleanupTestCase() {
        m_window->document()->undoStack()->setClean();
        m_window.reset();
        setErrorPresenter({});
        QVERIFY(m_errors.isEmpty());
    }
    void largeExportAdvancesPerTile_andTheWindowTakesEdits();
    void cancelWhileRendering_leavesTheFileAsItWas();
    void cancelWhileWriting_leavesTheFileAsItWas();
    void thumbnailBetweenTiles_doesNotChangeTheImage();
    void dialogRemembersTheLastPath();
};

void TestScreenshotExport::largeExportAdvancesPerTile_andTheWindowTakesEdits() {
    ScreenshotOptions o;
    o.path = m_dir.filePath(QStringLiteral("large.png"));
    o.size = QSize(1000, 600); // 2000×1200 rendered in 7 × 4 tiles, the last column and row smaller
    o.supersample = 2;
    o.tileSize = 320;
    QString error;
    const QImage expected = // the scene as the export begins, in the same tiles
        viewport()->renderScreenshot(o, &error, [](int, int) { return true; });
    QVERIFY2(!expected.isNull(), qPrintable(error));
    QList<int> percents, barValues;
    int timerTicks = 0, tilesWhenEdited = -1;
    bool shotTaken = false;
    QTimer other; // an unrelated timer keeps firing while the export runs
    other.setInterval(0);
    connect(&other, &QTimer::timeout, this, [&] { ++timerTicks; });
    other.start();
    QSignalSpy frames(viewport(), &Viewport::frameRendered);
    Document* doc = m_window->document();
    const Rig before = doc->rig();
    const ScreenshotExportResult r = exportWhile(
        o,
        [&](ScreenshotJob& job) {
            if (auto* bar = m_window->findChild<QProgressBar*>(QStringLiteral("screenshotProgress")))
                if (barValues.isEmpty() || barValues.last() != bar->value()) barValues << bar->value();
            if (tilesWhenEdited < 0 && job.percent() > 0 && job.isRunning() && !job.isWriting()) {
                // An edit in the middle of the export: applied now, not drawn into the image.
                QList<int> all;
                for (int row = 0; row < doc->lightCount(); ++row)
                    all << row;
                QVERIFY(doc->setLightsEnabled(all, false));
                tilesWhenEdited = job.percent();
            }
            if (job.percent() >= 40 && !shotTaken) {
                shotTaken = true;
                test::shot(*m_window, QStringLiteral("editor2-export-in-background"));
            }
            viewport()->update();
        },
        &percents);
    other.stop();
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(r.tiles, 28);
    QVERIFY2(tilesWhenEdited > 0 && tilesWhenEdited < ScreenshotJob::kRenderedPercent,
             qPrintable(QString::number(tilesWhenEdited)));
    QVERIFY(doc->rig() != before); // the edit was applied while the export ran
    QVERIFY2(timerTicks >= 28, qPrintable(QString::number(timerTicks)));
    QVERIFY2(frames.size() >= 2, "the viewport repainted while the screenshot rendered");
    QVERIFY(std::is_sorted(percents.begin(), percents.end()));
    QVERIFY2(percents.size() >= 25, qPrintable(QString::number(percents.size()))); // tile by tile
    QCOMPARE(percents.first(), 0);
    QCOMPARE(percents.last(), 100);
    // Honest: after the first tile (320×320 of 2000×1200 rendered pixels) its share of the pixels.
    QVERIFY(percents.contains(int(ScreenshotJob::kRenderedPercent * (320.0 * 320) / (2000.0 * 1200))));
    QVERIFY(std::is_sorted(barValues.begin(), barValues.end()));
    QVERIFY(barValues.size() >= 10);
    QVERIFY(!m_window->findChild<QProgressBar*>(QStringLiteral("screenshotProgress")) || QTest::qWaitFor([&] {
        return !m_window->findChild<QProgressBar*>(QStringLiteral("screenshotProgress"));
    }));
    QImageReader reader(o.path);
    QCOMPARE(reader.size(), o.size);
    QVERIFY(reader.read().convertToFormat(QImage::Format_RGBA8888) ==
            expected.convertToFormat(QImage::Format_RGBA8888));
    doc->undoStack()->undo();
}

void TestScreenshotExport::cancelWhileRendering_leavesTheFileAsItWas() {
    ScreenshotOptions o;
    o.path = m_dir.filePath(QStringLiteral("large.png")); // written by the previous test
    o.size = QSize(2048, 2048);
    o.supersample = 1;
    o.tileSize = 256; // 64 tiles
    const QByteArray before = bytes(o.path);
    QVERIFY(!before.isEmpty());
    const ScreenshotExportResult r = exportWhile(o, [&](ScreenshotJob& job) {
        if (job.isRunning() && !job.isWriting() && job.percent() >= 4) {
            auto* cancel = m_window->findChild<QToolButton*>(QStringLiteral("screenshotCancel"));
            QVERIFY(cancel); // what the user clicks
            cancel->click();
        }
    });
    QVERIFY(r.cancelled);
    QVERIFY(r.error.isEmpty());
    QVERIFY2(r.tiles >= 3 && r.tiles < 64, qPrintable(QString::number(r.tiles)));
    QVERIFY(bytes(o.path) == before);
    QCOMPARE(QDir(m_dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("large.png")});
}

void TestScreenshotExport::cancelWhileWriting_leavesTheFileAsItWas() {
    ScreenshotOptions o;
    o.path = m_dir.filePath(QStringLiteral("large.png"));
    o.size = QSize(2048, 2048);
    o.supersample = 1;
    o.tileSize = 1024;
    const QByteArray before = bytes(o.path);
    bool sawWriting = false;
    const ScreenshotExportResult r = exportWhile(o, [&](ScreenshotJob& job) {
        if (job.isWriting() && !sawWriting) { // encoding the file
            sawWriting = true;
            job.cancel();
        }
    });
    QVERIFY(sawWriting);
    QVERIFY(r.cancelled);
    QCOMPARE(r.tiles, 4);
    QVERIFY(bytes(o.path) == before);
    QCOMPARE(QDir(m_dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("large.png")});

    // Nothing to write with a cancel already set; a write that goes ahead replaces the file whole.
    std::atomic<bool> cancel{true};
    bool stopped = false;
    QImage small(8, 8, QImage::Format_RGBA8888);
    small.fill(Qt::red);
    QCOMPARE(saveImageAtomically(small, o.path, "PNG", &cancel, &stopped), QStringLiteral("cancelled"));
    QVERIFY(stopped);
    QVERIFY(bytes(o.path) == before);
    cancel = false;
    QCOMPARE(saveImageAtomically(small, o.path, "PNG", &cancel, &stopped), QString());
    QVERIFY(!stopped);
    QCOMPARE(QImage(o.path).size(), small.size());
}

void TestScreenshotExport::thumbnailBetweenTiles_doesNotChangeTheImage() {
    ScreenshotOptions o;
    o.size = QSize(384, 256);
    o.supersample = 2;
    o.tileSize = 128; // 6 x 4 tiles
    QString error;
    int calls = 0;
    const QImage plain = viewport()->renderScreenshot(o, &error, [&](int, int) { return ++calls, true; });
    QVERIFY2(!plain.isNull(), qPrintable(error));
    QCOMPARE(calls, 25); // (0, 24) and one per tile
    Rig other;           // no lights: a black thumbnail through the same offscreen renderer
    QImage thumbnail;
    const QImage interrupted = viewport()->renderScreenshot(o, &error, [&](int done, int) {
        if (done == 5) thumbnail = viewport()->renderThumbnail(other, QSize(64, 64));
        return true;
    });
    QVERIFY2(!interrupted.isNull(), qPrintable(error));
    QVERIFY(!thumbnail.isNull());
    QVERIFY(interrupted == plain);
    // Cancelling is not a failure of the renderer: a null image saying so.
    const QImage cancelled = viewport()->renderScreenshot(o, &error, [](int done, int) { return done < 2; });
    QVERIFY(cancelled.isNull());
    QCOMPARE(error, QStringLiteral("cancelled"));
}

// Issue 41 item 16: the dialog offers the file last exported to, not the suggestion, while its folder exists.
void TestScreenshotExport::dialogRemembersTheLastPath() {
    const QString chosen = m_dir.filePath(QStringLiteral("chosen.png"));
    {
        ScreenshotDialog dialog(QSize(640, 360), m_dir.filePath(QStringLiteral("suggested.png")));
        ScreenshotOptions o = dialog.options();
        o.path = chosen;
        dialog.setOptions(o);
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
    }
    ScreenshotDialog again(QSize(640, 360), m_dir.filePath(QStringLiteral("other.png")));
    QCOMPARE(again.options().path, chosen);
}

QTEST_MAIN(TestScreenshotExport)
#include "tst_screenshotexport.moc"
