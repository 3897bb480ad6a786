// "Export screenshot" in the background (issue 41 item 12: the export was window-modal, its progress far
// from linear). A ScreenshotJob fixes at its start what it renders (the rig as drawn, the camera, the view
// settings, the model and the environment: edits made meanwhile do not change the image), then renders one
// tile per pass of the event loop on the GUI thread (the offscreen GL context lives there), so the window
// keeps taking input between tiles; the file is encoded and written atomically on a worker thread
// (render/imagefile.h). A path-traced screenshot (ScreenshotOptions::pathTraced) renders on a worker
// instead (tracedshot.h), its progress the samples done. Progress is honest: the share of rendered pixels, up
// to kRenderedPercent, then 100 when the file is written. Cancel (or a failure) leaves an existing file byte
// for byte as it was.
#pragma once

#include "screenshotdialog.h"
#include "screenshotexport.h"

#include <QFutureWatcher>
#include <QImage>
#include <QObject>
#include <QPointer>
#include <QTimer>
#include <atomic>
#include <memory>

class QMainWindow;

namespace lr {

struct SnapshotJob;
class TracedShot;
class Viewport;

class ScreenshotJob : public QObject {
    Q_OBJECT
  public:
    static constexpr int kRenderedPercent = 95; // all tiles rendered; the rest is encoding and writing

    ScreenshotJob(Viewport* viewport, const ScreenshotOptions& options, QObject* parent = nullptr);
    ~ScreenshotJob() override;

    // Fixes the scene and starts (the first tile renders from the event loop). finished() follows even on
    // an immediate failure.
    void start();
    void cancel(); // stops before the next tile, or before the file is committed
    const ScreenshotOptions& options() const { return m_options; }
    int percent() const { return m_percent; } // 0 ... 100, never decreasing
    bool isRunning() const { return m_running; }
    bool isWriting() const { return m_writing; }
    ScreenshotExportResult result() const { return m_result; }

  signals:
    void progressChanged(int percent);
    void finished(); // result() says how

  private:
    void step();
    void startTraced();
    void write(QImage image);
    void finish();
    void setPercent(int percent);

    QPointer<Viewport> m_viewport;
    ScreenshotOptions m_options;
    std::unique_ptr<SnapshotJob> m_job;
    QTimer m_slice;
    QFutureWatcher<QString> m_write;
    std::shared_ptr<TracedShot> m_traced; // a path-traced screenshot's renderer
    QFutureWatcher<QImage> m_trace;
    QString m_traceError;
    QTimer m_traceProgress;
    std::atomic<bool> m_cancel{false};
    bool m_stopped = false; // the writer saw the cancel before the commit
    bool m_running = false, m_writing = false;
    int m_percent = 0;
    ScreenshotExportResult m_result;
};

// The status bar's part of a job: "Screenshot NAME" with a progress bar (object name
// "screenshotProgress") and Cancel ("screenshotCancel"), gone when the job finishes.
void showInStatusBar(QMainWindow* window, ScreenshotJob* job);

} // namespace lr
