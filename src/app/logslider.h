// A value over a wide range (light intensity 0 … 1e6): a slider beside a NumberEdit. The slider's handle
// shows the value on a logarithmic scale (position 0 is exactly 0; positions 1..kSteps cover [lowest, max]),
// but dragging it is relative, in exposure steps (EV, factors of 2) from the value at the press, as in
// Blender: kPixelsPerEv pixels double the value, Shift is ten times finer, Ctrl is four times coarser and
// snaps to whole EV. So a drag stays fine near the current value whatever its magnitude; the number field
// takes exact typed values (never rounded to a slider position).
#pragma once

#include <QSlider>
#include <QWidget>

namespace lr {

class NumberEdit;

// The slider part: reports drags, arrow keys and wheel notches as EV changes instead of jumping to the
// position under the mouse.
class EvDragSlider : public QSlider {
    Q_OBJECT
  public:
    static constexpr double kPixelsPerEv = 40.0; // plain drag: 40 px per doubling
    static constexpr double kFineFactor = 0.1;   // Shift
    static constexpr double kCoarseFactor = 4.0; // Ctrl (and whole-EV snapping)
    static constexpr double kKeyStepEv = 1.0 / 3.0;

    explicit EvDragSlider(QWidget* parent = nullptr);
    bool isDragging() const { return m_dragging; }

  signals:
    void dragStarted();
    void dragged(double ev); // EV from the value at the press (whole numbers with Ctrl)
    void dragFinished();
    void stepped(double ev); // one key press or wheel notch: a gesture of its own

  protected:
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void keyPressEvent(QKeyEvent* event) override;
    void wheelEvent(QWheelEvent* event) override;

  private:
    bool m_dragging = false;
    double m_lastX = 0.0;
    double m_ev = 0.0;
};

class LogSliderEdit : public QWidget {
    Q_OBJECT
  public:
    static constexpr int kSteps = 1000;

    explicit LogSliderEdit(QWidget* parent = nullptr);
    void setLimits(double lowest, double max); // lowest > 0: the smallest non-zero slider value
    void setValue(double v);                   // no signal
    double value() const;
    NumberEdit* spinBox() const { return m_spin; }
    EvDragSlider* slider() const { return m_slider; }

    int positionFor(double v) const;
    double valueAt(int position) const;
    // The value `ev` exposure steps from `start` (a start of 0 counts as 1), within [lowest, max], rounded to
    // 3 significant digits so dragged values read cleanly (steps of at most 1%, 0.015 EV).
    double valueAfterEv(double start, double ev) const;

  signals:
    void valueEdited(double value); // every change while dragging or typing
    void editFinished();            // slider released / spin box editing finished: end of one gesture

  private:
    void applyDragged(double v);

    EvDragSlider* m_slider;
    NumberEdit* m_spin;
    double m_lowest = 1e-3, m_max = 1e6;
    double m_dragStart = 0.0;
    bool m_syncing = false;
};

} // namespace lr
