#include "logslider.h"

#include "numberedit.h"

#include <QHBoxLayout>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>

namespace lr {

namespace {
double roundSignificant(double v, int digits) {
    if (!(v > 0.0) || !std::isfinite(v)) return v;
    const double mag = std::pow(10.0, std::floor(std::log10(v)) - double(digits - 1));
    return std::round(v / mag) * mag;
}
} // namespace

EvDragSlider::EvDragSlider(QWidget* parent) : QSlider(Qt::Horizontal, parent) {
    setCursor(Qt::SizeHorCursor);
    setToolTip(tr("Drag to change the intensity relative to its value: %1 px doubles it (1 EV); Shift: "
                  "finer, Ctrl: coarser in whole EV steps. Arrow keys: ±⅓ EV. Type an exact value in the "
                  "field.")
                   .arg(kPixelsPerEv));
}

void EvDragSlider::mousePressEvent(QMouseEvent* event) {
    if (event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    setFocus(Qt::MouseFocusReason);
    m_dragging = true;
    m_lastX = event->position().x();
    m_ev = 0.0;
    emit dragStarted();
    event->accept();
}

void EvDragSlider::mouseMoveEvent(QMouseEvent* event) {
    if (!m_dragging) {
        event->ignore();
        return;
    }
    // Accumulated per motion, so pressing or releasing Shift/Ctrl mid-drag changes the rate without a jump.
    const double x = event->position().x();
    const Qt::KeyboardModifiers mods = event->modifiers();
    const double rate = mods & Qt::ShiftModifier     ? kFineFactor
                        : mods & Qt::ControlModifier ? kCoarseFactor
                                                     : 1.0;
    m_ev += (x - m_lastX) / kPixelsPerEv * rate;
    m_lastX = x;
    emit dragged((mods & Qt::ControlModifier) && !(mods & Qt::ShiftModifier) ? std::round(m_ev) : m_ev);
    event->accept();
}

void EvDragSlider::mouseReleaseEvent(QMouseEvent* event) {
    if (!m_dragging || event->button() != Qt::LeftButton) {
        event->ignore();
        return;
    }
    m_dragging = false;
    emit dragFinished();
    event->accept();
}

void EvDragSlider::keyPressEvent(QKeyEvent* event) {
    const double scale = event->modifiers() & Qt::ShiftModifier     ? kFineFactor
                         : event->modifiers() & Qt::ControlModifier ? 3.0
                                                                    : 1.0;
    switch (event->key()) {
    case Qt::Key_Right:
    case Qt::Key_Up:
        emit stepped(kKeyStepEv * scale);
        break;
    case Qt::Key_Left:
    case Qt::Key_Down:
        emit stepped(-kKeyStepEv * scale);
        break;
    case Qt::Key_PageUp:
        emit stepped(1.0);
        break;
    case Qt::Key_PageDown:
        emit stepped(-1.0);
        break;
    default:
        QSlider::keyPressEvent(event);
        return;
    }
    event->accept();
}

void EvDragSlider::wheelEvent(QWheelEvent* event) {
    const double notches = event->angleDelta().y() / 120.0;
    if (notches == 0.0) {
        event->ignore();
        return;
    }
    emit stepped(notches * kKeyStepEv * (event->modifiers() & Qt::ShiftModifier ? kFineFactor : 1.0));
    event->accept();
}

LogSliderEdit::LogSliderEdit(QWidget* parent)
    : QWidget(parent), m_slider(new EvDragSlider(this)), m_spin(new NumberEdit(this)) {
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_spin);
    m_slider->setRange(0, kSteps);
    m_slider->setPageStep(kSteps / 20);
    m_spin->setLimits(0.0, m_max);
    // Programmatic (and accessibility) changes of the slider's position: the value at that position.
    connect(m_slider, &QSlider::valueChanged, this, [this](int pos) {
        if (m_syncing) return;
        applyDragged(valueAt(pos));
    });
    connect(m_slider, &EvDragSlider::dragStarted, this, [this] { m_dragStart = value(); });
    connect(m_slider, &EvDragSlider::dragged, this,
            [this](double ev) { applyDragged(valueAfterEv(m_dragStart, ev)); });
    connect(m_slider, &EvDragSlider::dragFinished, this, &LogSliderEdit::editFinished);
    connect(m_slider, &QSlider::sliderReleased, this, &LogSliderEdit::editFinished); // accessibility
    connect(m_slider, &EvDragSlider::stepped, this, [this](double ev) {
        applyDragged(valueAfterEv(value(), ev));
        emit editFinished();
    });
    connect(m_spin, &NumberEdit::valueEdited, this, [this](double v) {
        m_syncing = true;
        m_slider->setValue(positionFor(v));
        m_syncing = false;
        emit valueEdited(v);
    });
    connect(m_spin, &QAbstractSpinBox::editingFinished, this, &LogSliderEdit::editFinished);
}

void LogSliderEdit::applyDragged(double v) {
    if (v == value()) return;
    m_syncing = true;
    m_spin->setValueQuietly(v);
    m_slider->setValue(positionFor(v));
    m_syncing = false;
    emit valueEdited(v);
}

void LogSliderEdit::setLimits(double lowest, double max) {
    m_lowest = lowest;
    m_max = max;
    m_spin->setLimits(0.0, max);
}

void LogSliderEdit::setValue(double v) {
    m_syncing = true;
    m_spin->setValueQuietly(v);
    m_slider->setValue(positionFor(v));
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
    // Round to 3 significant digits so slider values read cleanly (1.23, 45.6, 7890).
    return roundSignificant(m_lowest * std::pow(m_max / m_lowest, t), 3);
}

double LogSliderEdit::valueAfterEv(double start, double ev) const {
    const double base = start > 0.0 && std::isfinite(start) ? start : 1.0;
    if (!std::isfinite(ev)) return base;
    const double v = std::clamp(base * std::exp2(ev), m_lowest, m_max);
    return std::clamp(roundSignificant(v, 3), m_lowest, m_max);
}

} // namespace lr
