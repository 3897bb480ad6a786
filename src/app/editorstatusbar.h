// The main window's status bar: messages, the viewport's frame time (GPU ms from timer queries, CPU ms as a
// fallback), the progress of a background model load with a Cancel button, and the open model's import
// warnings: a "⚠ N import warnings" button that stays until the next model and asks for the full list
// (warningsRequested: the main window opens the Model dock on its Warnings branch).
#pragma once

#include <QElapsedTimer>
#include <QStatusBar>
#include <QTimer>

class QLabel;
class QProgressBar;
class QToolButton;

namespace lr {

class EditorStatusBar : public QStatusBar {
    Q_OBJECT
  public:
    explicit EditorStatusBar(QWidget* parent = nullptr);

    // gpuMs < 0: not measured. Shown at most every kFrameTimeIntervalMs (the latest value): relabelling the
    // status bar at every frame cost the moving view 20-30 ms a frame (issue 40, the window's composition).
    void setFrameTime(double gpuMs, double cpuMs);
    static constexpr int kFrameTimeIntervalMs = 250;
    void setRigSummary(const QString& text);
    void showLoading(const QString& fileName);
    void setLoadProgress(double fraction); // 0..1
    void hideLoading();
    QString frameTimeText() const;
    // The model's warnings (model/model.h Model::warnings); none hides the button.
    void setModelWarnings(const QString& fileName, const QStringList& warnings);
    QToolButton* warningsButton() const { return m_warnings; }

  signals:
    void cancelLoadRequested();
    void warningsRequested(); // the warnings button was clicked

  private:
    QLabel* m_rig;
    QLabel* m_frameTime;
    QProgressBar* m_progress;
    QToolButton* m_cancel;
    QToolButton* m_warnings;
    QString m_pendingFrameTime; // the latest, not shown yet
    QElapsedTimer m_sinceFrameTime;
    QTimer* m_frameTimeTimer;
    void showFrameTime();
};

} // namespace lr
