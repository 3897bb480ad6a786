#include "screenshotexport.h"

#include "render/imagefile.h"
#include "screenshotdialog.h"
#include "viewport.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QImage>
#include <QProgressDialog>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

namespace lr {

QString saveImageAtomically(const QImage& image, const QString& path, const QByteArray& format,
                            const std::atomic<bool>* cancel, bool* cancelled) {
    const QString reason = writeImageAtomically(image, path, format, cancel, cancelled);
    if (reason.isEmpty() || (cancelled && *cancelled)) return reason;
    return QStringLiteral("%1: could not write the image: %2").arg(path, reason);
}

ScreenshotExportResult exportScreenshotWithProgress(QWidget* parent, Viewport* viewport,
                                                    const ScreenshotOptions& options) {
    ScreenshotExportResult result;
    const QString file = QFileInfo(options.path).fileName();
    QProgressDialog dialog(parent);
    dialog.setObjectName(QStringLiteral("screenshotProgress"));
    dialog.setWindowTitle(QObject::tr("Export screenshot"));
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setMinimumDuration(300);
    dialog.setAutoReset(false);
    dialog.setAutoClose(false);
    dialog.setLabelText(
        QObject::tr("Rendering %1 (%2×%3)…").arg(file).arg(options.size.width()).arg(options.size.height()));
    std::atomic<bool> cancel{false};
    QObject::connect(&dialog, &QProgressDialog::canceled, &dialog, [&cancel] { cancel = true; });
    // Until the (window-modal) dialog shows, the window must not take input: no edits, no second export.
    const auto inputWhileVisible = [&dialog] {
        return dialog.isVisible() ? QEventLoop::AllEvents : QEventLoop::ExcludeUserInputEvents;
    };

    QString error;
    const QImage image = viewport->renderScreenshot(options, &error, [&](int done, int total) {
        if (dialog.maximum() != total) dialog.setMaximum(total);
        dialog.setValue(done);
        result.tiles = done;
        QCoreApplication::processEvents(inputWhileVisible()); // repaint, and hear Cancel
        if (dialog.wasCanceled()) cancel = true;              // cancel() called without the signal
        return !cancel.load();
    });
    if (cancel) {
        result.cancelled = true;
        return result;
    }
    if (image.isNull()) {
        result.error = error;
        return result;
    }

    // Encoding a large PNG takes seconds: on a worker thread, the dialog (busy) still answering Cancel.
    dialog.setLabelText(QObject::tr("Writing %1…").arg(file));
    dialog.setRange(0, 0);
    bool stopped = false; // written by the worker, read after it finished
    QFutureWatcher<QString> watcher;
    QTimer poll; // wakes the loop below to see cancel() called without the signal
    QObject::connect(&poll, &QTimer::timeout, &dialog, [&dialog, &cancel] {
        if (dialog.wasCanceled()) cancel = true;
    });
    poll.start(50);
    watcher.setFuture(
        QtConcurrent::run([image, path = options.path, format = options.format, &cancel, &stopped] {
            return saveImageAtomically(image, path, format, &cancel, &stopped);
        }));
    while (!watcher.isFinished()) // its finished event wakes the wait
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents | inputWhileVisible());
    watcher.waitForFinished();
    result.cancelled = stopped; // a Cancel after the commit comes too late: the file is written
    if (!stopped) result.error = watcher.result();
    return result;
}

} // namespace lr
