// A value over a wide range (light intensity 0 … 1e6) as a logarithmic slider beside a NumberEdit.
// Slider position 0 is exactly 0; positions 1..kSteps cover [lowest, max] logarithmically.
#pragma once

#include <QWidget>

class QSlider;

namespace lr {

class NumberEdit;

class LogSliderEdit : public QWidget {
    Q_OBJECT
  public:
    static constexpr int kSteps = 1000;

    explicit LogSliderEdit(QWidget* parent = nullptr);
    void setLimits(double lowest, double max); // lowest > 0: the smallest non-zero slider value
    void setValue(double v);                   // no signal
    double value() const;
    NumberEdit* spinBox() const { return m_spin; }
    QSlider* slider() const { return m_slider; }

    int positionFor(double v) const;
    double valueAt(int position) const;

  signals:
    void valueEdited(double value); // every change while dragging or typing
    void editFinished();            // slider released / spin box editing finished: end of one gesture

  private:
    QSlider* m_slider;
    NumberEdit* m_spin;
    double m_lowest = 1e-3, m_max = 1e6;
    bool m_syncing = false;
};

} // namespace lr
