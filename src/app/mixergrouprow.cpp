#include "mixergrouprow.h"

#include "colorbutton.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSlider>
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

namespace lr {

namespace {
// The slider counts tenths of an EV.
int sliderTicks(double ev) {
    const double reach = kMixerSliderEV * kMixerTicksPerEV;
    return int(std::lround(std::clamp(ev * kMixerTicksPerEV, -reach, reach)));
}
} // namespace

MixerGroupRow::MixerGroupRow(const QString& group, const QString& toolTip, QWidget* parent)
    : QWidget(parent), m_group(group) {
    setObjectName(QStringLiteral("mixerGroup_") + group);
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_on = new QCheckBox(this);
    m_on->setToolTip(tr("Whether the group's light is in the mix"));
    m_slider = new QSlider(Qt::Horizontal, this);
    m_slider->setRange(sliderTicks(-kMixerSliderEV), sliderTicks(kMixerSliderEV));
    m_slider->setSingleStep(1);
    m_slider->setPageStep(10); // one EV
    m_slider->setMinimumWidth(80);
    m_ev = new QDoubleSpinBox(this);
    m_ev->setRange(-kMaxMixEV, kMaxMixEV);
    m_ev->setSingleStep(1.0 / kMixerTicksPerEV);
    m_ev->setDecimals(2);
    m_ev->setSuffix(tr(" EV"));
    m_ev->setKeyboardTracking(false);
    for (QWidget* w : {static_cast<QWidget*>(m_slider), static_cast<QWidget*>(m_ev)})
        w->setToolTip(tr("Exposure change of the group: × 2^EV (double-click: 0)"));
    m_tint = new ColorButton(this);
    m_tint->setToolButtonStyle(Qt::ToolButtonIconOnly); // the swatch; its values in the tooltip
    m_tint->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    m_name = new QLabel(group, this);
    m_name->setToolTip(toolTip);
    m_name->setMinimumWidth(60);
    layout->addWidget(m_on);
    layout->addWidget(m_slider, 1);
    layout->addWidget(m_ev);
    layout->addWidget(m_tint);
    layout->addWidget(m_name, 1);
    m_slider->installEventFilter(this);
    m_ev->installEventFilter(this);
    if (QLineEdit* line = m_ev->findChild<QLineEdit*>()) line->installEventFilter(this);

    connect(m_on, &QCheckBox::toggled, this, [this](bool on) {
        GroupMix m = m_mix;
        m.enabled = on;
        edit(m);
    });
    connect(m_slider, &QSlider::valueChanged, this, [this](int ticks) {
        GroupMix m = m_mix;
        m.ev = double(ticks) / kMixerTicksPerEV;
        edit(m);
    });
    connect(m_ev, &QDoubleSpinBox::valueChanged, this, [this](double ev) {
        GroupMix m = m_mix;
        m.ev = ev;
        edit(m);
    });
    connect(m_tint, &ColorButton::colorPicked, this, [this](const glm::dvec3& tint) {
        GroupMix m = m_mix;
        m.tint = glm::clamp(tint, glm::dvec3(0.0), glm::dvec3(kMaxMixTint));
        edit(m);
    });
    display(m_mix);
}

void MixerGroupRow::setMix(const GroupMix& mix) {
    m_mix = mix;
    display(mix);
}

void MixerGroupRow::edit(const GroupMix& mix) {
    if (mix == m_mix) return;
    m_mix = mix;
    display(mix);
    emit mixEdited(m_group, m_mix);
}

void MixerGroupRow::display(const GroupMix& mix) {
    const QSignalBlocker a(m_on), b(m_slider), c(m_ev);
    m_on->setChecked(mix.enabled);
    m_slider->setValue(sliderTicks(mix.ev));
    m_ev->setValue(mix.ev);
    m_tint->setColor(mix.tint);
    m_tint->setToolTip(tr("Tint of the group, × per channel: %1").arg(m_tint->text()));
    for (QWidget* w : {static_cast<QWidget*>(m_slider), static_cast<QWidget*>(m_ev),
                       static_cast<QWidget*>(m_tint), static_cast<QWidget*>(m_name)})
        w->setEnabled(mix.enabled);
}

bool MixerGroupRow::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::MouseButtonDblClick) {
        GroupMix m = m_mix;
        m.ev = 0.0;
        edit(m);
        return true;
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace lr
