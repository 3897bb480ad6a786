#include "turntableexport.h"

#include "editor/document.h"
#include "errordialog.h"
#include "mainwindow.h"
#include "scene.h"
#include "screenshotexport.h"
#include "turntabledialog.h"
#include "viewport.h"

#include <QCoreApplication>
#include <QDir>
#include <QEventLoop>
#include <QFileInfo>
#include <QFutureWatcher>
#include <QProgressDialog>
#include <QStatusBar>
#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>
#include <atomic>

namespace lr {

TurntableExportResult exportTurntableWithProgress(QWidget* parent, Viewport* viewport, const Rig& rig,
                                                  const ViewCamera& camera, const glm::dvec3& center,
                                                  const TurntableOptions& options) {
    TurntableExportResult result;
    const QString folder = QFileInfo(options.shot.path).absolutePath();
    if (!QDir().mkpath(folder)) { // the dialog allows a folder that does not exist yet
        result.error = QObject::tr("%1: could not create the folder").arg(QDir::toNativeSeparators(folder));
        return result;
    }
    const int frames = std::max(1, options.frames);
    constexpr int kSteps = 1000; // progress steps per frame
    QProgressDialog dialog(parent);
    dialog.setObjectName(QStringLiteral("turntableProgress"));
    dialog.setWindowTitle(QObject::tr("Export turntable"));
    dialog.setWindowModality(Qt::WindowModal);
    dialog.setMinimumDuration(300);
    dialog.setAutoReset(false);
    dialog.setAutoClose(false);
    dialog.setRange(0, frames * kSteps);
    std::atomic<bool> cancel{false};
    QObject::connect(&dialog, &QProgressDialog::canceled, &dialog, [&cancel] { cancel = true; });
    // Until the (window-modal) dialog shows, the window must not take input: no edits, no second export.
    const auto inputWhileVisible = [&dialog] {
        return dialog.isVisible() ? QEventLoop::AllEvents : QEventLoop::ExcludeUserInputEvents;
    };
    QTimer poll; // wakes the wait while writing to see cancel() called without the signal
    QObject::connect(&poll, &QTimer::timeout, &dialog, [&dialog, &cancel] {
        if (dialog.wasCanceled()) cancel = true;
    });
    poll.start(50);

    for (int k = 0; k < frames && !cancel; ++k) {
        const QString path = frames > 1 || hasFrameField(options.shot.path) ? framePath(options.shot.path, k)
                                                                            : options.shot.path;
        dialog.setLabelText(QObject::tr("Rendering frame %1 of %2 (%3)…")
                                .arg(k + 1)
                                .arg(frames)
                                .arg(QFileInfo(path).fileName()));
        const double degrees = turntableDegrees(k, frames);
        const bool orbit = options.rotate == TurntableRotation::Camera;
        QString error;
        const QImage image = viewport->renderScreenshot(
            options.shot, orbit ? rig : rotateRigLights(rig, center, degrees),
            orbit ? orbitCamera(camera, center, degrees) : camera, &error, [&](int done, int total) {
                dialog.setValue(k * kSteps + (total > 0 ? done * (kSteps - 1) / total : 0));
                QCoreApplication::processEvents(inputWhileVisible()); // repaint, and hear Cancel
                if (dialog.wasCanceled()) cancel = true;
                return !cancel.load();
            });
        if (cancel) break;
        if (image.isNull()) {
            result.error = error;
            return result;
        }
        bool stopped = false; // written by the worker, read after it finished
        QFutureWatcher<QString> watcher;
        watcher.setFuture(QtConcurrent::run([image, path, format = options.shot.format, &cancel, &stopped] {
            return saveImageAtomically(image, path, format, &cancel, &stopped);
        }));
        while (!watcher.isFinished()) // its finished event wakes the wait
            QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents | inputWhileVisible());
        watcher.waitForFinished();
        if (stopped) break;
        if (!watcher.result().isEmpty()) {
            result.error = watcher.result();
            return result;
        }
        result.written << path;
        dialog.setValue((k + 1) * kSteps);
    }
    result.cancelled = cancel && result.written.size() < frames;
    return result;
}

void exportTurntableInteractive(MainWindow* window) {
    const QString rigPath = window->document()->filePath();
    const QString base = rigPath.isEmpty()
                             ? QDir::home().filePath(QStringLiteral("lightrig_####.png"))
                             : QFileInfo(rigPath).dir().filePath(QFileInfo(rigPath).completeBaseName() +
                                                                 QStringLiteral("_####.png"));
    Viewport* viewport = window->viewport();
    TurntableDialog dialog(viewport->size() * viewport->devicePixelRatio(), base, window);
    if (dialog.exec() != QDialog::Accepted) return;
    const TurntableOptions o = dialog.options();
    const TurntableExportResult result =
        exportTurntableWithProgress(window, viewport, window->document()->renderRig(),
                                    viewport->renderCamera(), window->scene()->frame().center, o);
    const auto shown = [](const QString& path) { return QDir::toNativeSeparators(path); };
    if (result.cancelled) {
        window->statusBar()->showMessage(
            result.written.isEmpty()
                ? QObject::tr("Turntable export cancelled; no frame written")
                : QObject::tr("Turntable export cancelled; wrote %1 of %2 frames (%3 … %4)")
                      .arg(result.written.size())
                      .arg(o.frames)
                      .arg(shown(result.written.first()), shown(result.written.last())),
            15000);
        return;
    }
    if (!result.ok()) {
        showError(window, {QObject::tr("Export turntable"),
                           QObject::tr("Could not export the turntable (%1 of %2 frames written).")
                               .arg(result.written.size())
                               .arg(o.frames),
                           {result.error}});
        return;
    }
    window->statusBar()->showMessage(QObject::tr("Wrote %1 frames (%2 … %3)")
                                         .arg(result.written.size())
                                         .arg(shown(result.written.first()), shown(result.written.last())),
                                     8000);
}

} // namespace lr
