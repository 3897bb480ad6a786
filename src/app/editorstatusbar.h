// The main window's status bar: messages, the viewport's frame time (GPU ms from timer queries, CPU ms as a
// fallback) and the progress of a background model load with a Cancel button.
#pragma once

#include <QStatusBar>

class QLabel;
class QProgressBar;
class QToolButton;

namespace lr {

class EditorStatusBar : public QStatusBar {
    Q_OBJECT
  public:
    explicit EditorStatusBar(QWidget* parent = nullptr);

    void setFrameTime(double gpuMs, double cpuMs); // gpuMs < 0: not measured
    void setRigSummary(const QString& text);
    void showLoading(const QString& fileName);
    void setLoadProgress(double fraction); // 0..1
    void hideLoading();
    QString frameTimeText() const;

  signals:
    void cancelLoadRequested();

  private:
    QLabel* m_rig;
    QLabel* m_frameTime;
    QProgressBar* m_progress;
    QToolButton* m_cancel;
};

} // namespace lr
