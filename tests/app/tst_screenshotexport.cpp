// "Export screenshot" with progress and Cancel (app/screenshotexport.h) on a real main window under Xvfb:
// a large export advances tile by tile while the viewport keeps repainting; Cancel during the render or
// during the writing leaves an existing file byte for byte as it was (and no temporary file); a thumbnail
// rendered through the same offscreen renderer between tiles does not change the exported pixels.
#include "app/commandline.h"
#include "app/documentfiles.h"
#include "app/editorapp.h"
#include "app/errordialog.h"
#include "app/mainwindow.h"
#include "app/screenshotdialog.h"
#include "app/screenshotexport.h"
#include "app/viewport.h"
#include "editor/document.h"
#include "model/isolatedimport.h"
#include "startwindow.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImageReader>
#include <QProgressDialog>
#include <QPushButton>
#include <QSettings>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <functional>

using namespace lr;

class TestScreenshotExport : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
    QList<ErrorReport> m_errors;

    Viewport* viewport() { return m_window->viewport(); }
    QProgressDialog* progressDialog() {
        return m_window->findChild<QProgressDialog*>(QStringLiteral("screenshotProgress"));
    }
    // Runs `tick` on every pass of the event loop while the export runs (between tiles, while writing).
    ScreenshotExportResult exportWhile(const ScreenshotOptions& o, const std::function<void()>& tick) {
        QTimer timer;
        timer.setInterval(0);
        connect(&timer, &QTimer::timeout, this, tick);
        timer.start();
        const ScreenshotExportResult r = exportScreenshotWithProgress(m_window.get(), viewport(), o);
        timer.stop();
        return r;
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
    void largeExportAdvancesPerTile_andTheWindowRepaints();
    void cancelWhileRendering_leavesTheFileAsItWas();
    void cancelWhileWriting_leavesTheFileAsItWas();
    void thumbnailBetweenTiles_doesNotChangeTheImage();
};

void TestScreenshotExport::largeExportAdvancesPerTile_andTheWindowRepaints() {
    ScreenshotOptions o;
    o.path = m_dir.filePath(QStringLiteral("large.png"));
    o.size = QSize(4096, 4096);
    o.supersample = 1;
    o.tileSize = 512; // 8 x 8 tiles
    QList<int> values;
    int maximum = -1;
    QSignalSpy frames(viewport(), &Viewport::frameRendered);
    QElapsedTimer clock;
    clock.start();
    const ScreenshotExportResult r = exportWhile(o, [&] {
        QProgressDialog* d = progressDialog();
        if (!d || d->maximum() == 0) return; // not yet, or writing (busy indicator)
        maximum = d->maximum();
        if (values.isEmpty() || values.last() != d->value()) values << d->value();
        viewport()->update(); // the window keeps painting between tiles
    });
    QVERIFY2(r.ok(), qPrintable(r.error));
    QCOMPARE(r.tiles, 64);
    QCOMPARE(maximum, 64);
    qInfo("4096x4096 in 64 tiles, rendered and written in %lld ms; progress values seen: %lld, viewport "
          "frames during the export: %lld",
          qlonglong(clock.elapsed()), qlonglong(values.size()), qlonglong(frames.size()));
    QVERIFY(std::is_sorted(values.begin(), values.end()));
    QCOMPARE(values.last(), 64);
    QVERIFY2(values.size() >= 16, "the dialog advanced tile by tile");
    QVERIFY2(frames.size() >= 2, "the viewport repainted while the screenshot rendered");
    QCOMPARE(QImageReader(o.path).size(), o.size);
    QVERIFY(!progressDialog()); // gone with the export
}

void TestScreenshotExport::cancelWhileRendering_leavesTheFileAsItWas() {
    ScreenshotOptions o;
    o.path = m_dir.filePath(QStringLiteral("large.png")); // written by the previous test
    o.size = QSize(4096, 4096);
    o.supersample = 1;
    o.tileSize = 512;
    const QByteArray before = bytes(o.path);
    QVERIFY(!before.isEmpty());
    const ScreenshotExportResult r = exportWhile(o, [&] {
        QProgressDialog* d = progressDialog();
        if (!d || d->maximum() == 0 || d->value() < 3 || d->wasCanceled()) return;
        QPushButton* cancel = d->findChild<QPushButton*>(); // what the user clicks
        QVERIFY(cancel);
        cancel->click();
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
    const ScreenshotExportResult r = exportWhile(o, [&] {
        QProgressDialog* d = progressDialog();
        if (d && d->maximum() == 0 && !d->wasCanceled()) { // the busy indicator: encoding the file
            sawWriting = true;
            d->cancel();
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

QTEST_MAIN(TestScreenshotExport)
#include "tst_screenshotexport.moc"
