#include "logslider.h"

#include "numberedit.h"

#include <QHBoxLayout>
#include <QSlider>
#include <cmath>

namespace lr {

LogSliderEdit::LogSliderEdit(QWidget* parent)
    : QWidget(parent), m_slider(new QSlider(Qt::Horizontal, this)), m_spin(new NumberEdit(this)) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_spin);
    m_slider->setRange(0, kSteps);
    m_slider->setPageStep(kSteps / 20);
    m_spin->setLimits(0.0, m_max);
    connect(m_slider, &QSlider::valueChanged, this, [this](int pos) {
        if (m_syncing) return;
        const double v = valueAt(pos);
        m_syncing = true;
        m_spin->setValueQuietly(v);
        m_syncing = false;
        emit valueEdited(v);
    });
    connect(m_slider, &QSlider::sliderReleased, this, &LogSliderEdit::editFinished);
    connect(m_spin, &NumberEdit::valueEdited, this, [this](double v) {
        m_syncing = true;
        m_slider->setValue(positionFor(v));
        m_syncing = false;
        emit valueEdited(v);
    });
    connect(m_spin, &QAbstractSpinBox::editingFinished, this, &LogSliderEdit::editFinished);
}

void LogSliderEdit::setLimits(double lowest, double max) {
    m_lowest = lowest;
    m_max = max;
    m_spin->setLimits(0.0, max);
}

void LogSliderEdit::setValue(double v) {
    m_syncing = true;
    m_spin->setValueQuietly(v);
    // While the user drags the handle it stays under the mouse (the stored value is rounded: no jitter).
    if (!m_slider->isSliderDown()) m_slider->setValue(positionFor(v));
    m_syncing = false;
}

double LogSliderEdit::value() const {
    return m_spin->value();
}

int LogSliderEdit::positionFor(double v) const {
    if (!(v > 0.0)) return 0;
    if (v <= m_lowest) return 1;
    if (v >= m_max) return kSteps;
    const double t = std::log(v / m_lowest) / std::log(m_max / m_lowest);
    return 1 + int(std::lround(t * (kSteps - 1)));
}

double LogSliderEdit::valueAt(int position) const {
    if (position <= 0) return 0.0;
    if (position >= kSteps) return m_max;
    const double t = double(position - 1) / double(kSteps - 1);
    const double v = m_lowest * std::pow(m_max / m_lowest, t);
    // Round to 3 significant digits so slider values read cleanly (1.23, 45.6, 7890).
    const double mag = std::pow(10.0, std::floor(std::log10(v)) - 2.0);
    return std::round(v / mag) * mag;
}

} // namespace lr
