// What the viewport shows of its path-traced view (tracedview.h): a child widget over the GL view, the size
// of the viewport and transparent to the mouse, that draws the latest traced image over the raster one and
// the readout (samples, seconds, noise; or why the scene cannot be traced) in a box at the bottom left.
// Hidden while the traced view is off.
#pragma once

#include <QWidget>

namespace lr {

class TracedView;

class TracedOverlay : public QWidget {
    Q_OBJECT
  public:
    TracedOverlay(TracedView* view, QWidget* viewport);

  protected:
    void paintEvent(QPaintEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void sync();
    TracedView* m_view;
};

} // namespace lr
