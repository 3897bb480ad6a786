// File › Export turntable (issue 17, app/turntableexport.h) on a real main window under Xvfb: N frames
// through the screenshot's offscreen path, each a complete PNG of the asked size, no two alike, frame 0 the
// plain screenshot; the progress dialog advances and Cancel stops between frames with the frames written
// so far listed (and no temporary file); the dialog refuses a name without # for several frames.
#include "app/editoractions.h"
#include "app/errordialog.h"
#include "app/mainwindow.h"
#include "app/scene.h"
#include "app/screenshotdialog.h"
#include "app/startwindow.h"
#include "app/turntabledialog.h"
#include "app/turntableexport.h"
#include "app/viewport.h"
#include "editor/document.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageReader>
#include <QProgressDialog>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <functional>

using namespace lr;

class TestTurntableExport : public QObject {
    Q_OBJECT

    std::unique_ptr<MainWindow> m_window;
    QTemporaryDir m_dir;
    QList<ErrorReport> m_errors;

    Viewport* viewport() { return m_window->viewport(); }
    TurntableExportResult exportWhile(const TurntableOptions& o, const std::function<void()>& tick) {
        QTimer timer;
        timer.setInterval(0);
        connect(&timer, &QTimer::timeout, this, tick);
        timer.start();
        const TurntableExportResult r =
            exportTurntableWithProgress(m_window.get(), viewport(), m_window->document()->renderRig(),
                                        viewport()->renderCamera(), m_window->scene()->frame().center, o);
        timer.stop();
        return r;
    }
    TurntableOptions options(const QString& name, int frames) {
        TurntableOptions o;
        o.shot.path = m_dir.filePath(name);
        o.shot.size = QSize(96, 64);
        o.shot.supersample = 1;
        o.frames = frames;
        return o;
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
        QVERIFY(m_window->actions()->exportTurntable); // in the File menu
    }
    void cleanupTestCase() {
        m_window->document()->undoStack()->setClean();
        m_window.reset();
        setErrorPresenter({});
        QVERIFY(m_errors.isEmpty());
    }

    void framesAroundTheModel_data() {
        QTest::addColumn<int>("rotate");
        QTest::newRow("camera") << int(TurntableRotation::Camera);
        QTest::newRow("lights") << int(TurntableRotation::Lights);
    }
    void framesAroundTheModel() {
        QFETCH(int, rotate);
        TurntableOptions o = options(QStringLiteral("turn%1_##.png").arg(rotate), 6);
        o.rotate = TurntableRotation(rotate);
        int progressMaximum = 0;
        const TurntableExportResult r = exportWhile(o, [&] {
            if (auto* d = m_window->findChild<QProgressDialog*>(QStringLiteral("turntableProgress")))
                progressMaximum = d->maximum();
        });
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.written.size(), 6);
        QVERIFY(progressMaximum > 0);
        QList<QImage> images;
        for (int k = 0; k < 6; ++k) {
            const QString file =
                m_dir.filePath(QStringLiteral("turn%1_%2.png").arg(rotate).arg(k, 2, 10, QLatin1Char('0')));
            QCOMPARE(r.written.value(k), file);
            QImageReader reader(file);
            QCOMPARE(reader.format(), QByteArray("png"));
            images << reader.read().convertToFormat(QImage::Format_RGBA8888);
            QCOMPARE(images.last().size(), QSize(96, 64));
        }
        for (int a = 0; a < 6; ++a)
            for (int b = a + 1; b < 6; ++b)
                QVERIFY2(images[a] != images[b],
                         qPrintable(QStringLiteral("frames %1 and %2").arg(a).arg(b)));
        QString error;
        const QImage plain = viewport()->renderScreenshot(o.shot, &error);
        QVERIFY2(!plain.isNull(), qPrintable(error));
        QVERIFY(plain.convertToFormat(QImage::Format_RGBA8888) == images[0]);
    }

    void cancelStopsBetweenFramesAndSaysWhatWasWritten() {
        const TurntableOptions o = options(QStringLiteral("cancel_####.png"), 40);
        const TurntableExportResult r = exportWhile(o, [&] {
            auto* d = m_window->findChild<QProgressDialog*>(QStringLiteral("turntableProgress"));
            if (!d || d->value() < 2000 || d->wasCanceled()) return; // after two frames
            QPushButton* cancel = d->findChild<QPushButton*>();      // what the user clicks
            QVERIFY(cancel);
            cancel->click();
        });
        QVERIFY(r.cancelled);
        QVERIFY(r.error.isEmpty());
        QVERIFY2(r.written.size() >= 2 && r.written.size() < 40,
                 qPrintable(QString::number(r.written.size())));
        const QStringList files = QDir(m_dir.path()).entryList({QStringLiteral("cancel_*")}, QDir::Files);
        QCOMPARE(files.size(), r.written.size()); // exactly those listed, no temporary file
        for (const QString& file : r.written)
            QCOMPARE(QImageReader(file).size(), QSize(96, 64));
    }

    void dialogNeedsAFrameNumberForSeveralFrames() {
        TurntableDialog dialog(QSize(640, 360), m_dir.filePath(QStringLiteral("plain.png")));
        TurntableOptions o = options(QStringLiteral("plain.png"), 12);
        dialog.setOptions(o);
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Rejected));
        QVERIFY2(dialog.message().contains(QStringLiteral("#")), qPrintable(dialog.message()));
        o.frames = 1; // one frame needs no number
        dialog.setOptions(o);
        dialog.accept();
        QCOMPARE(dialog.result(), int(QDialog::Accepted));
        QCOMPARE(dialog.options().frames, 1);
    }

    // Issue 41 item 16: a folder that does not exist yet is accepted by the dialog and created by the export.
    void exportCreatesItsFolder() {
        const QString folder = m_dir.filePath(QStringLiteral("new/turns"));
        TurntableOptions o = options(QStringLiteral("new/turns/frame_##.png"), 2);
        TurntableDialog dialog(QSize(640, 360), o.shot.path);
        dialog.setOptions(o);
        dialog.accept();
        QVERIFY2(dialog.result() == QDialog::Accepted, qPrintable(dialog.message()));
        QVERIFY(!QFileInfo::exists(folder)); // the dialog creates nothing
        const TurntableExportResult r = exportWhile(o, [] {});
        QVERIFY2(r.ok(), qPrintable(r.error));
        QCOMPARE(r.written.size(), 2);
        for (const QString& file : r.written)
            QCOMPARE(QImageReader(file).size(), QSize(96, 64));
        // Under a file, no folder can be made: the dialog says so.
        QFile blocker(m_dir.filePath(QStringLiteral("a-file")));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        o.shot.path = m_dir.filePath(QStringLiteral("a-file/sub/frame_##.png"));
        dialog.setOptions(o);
        dialog.accept();
        QVERIFY2(dialog.message().contains(QStringLiteral("a-file")), qPrintable(dialog.message()));
    }
};

QTEST_MAIN(TestTurntableExport)
#include "tst_turntableexport.moc"
