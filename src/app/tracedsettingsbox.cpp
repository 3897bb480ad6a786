#include "tracedsettingsbox.h"

#include "viewsettings.h"

#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QSignalBlocker>
#include <QSpinBox>

namespace lr {

TracedSettingsBox::TracedSettingsBox(ViewSettings* settings, QWidget* parent)
    : QGroupBox(tr("Path traced"), parent), m_settings(settings), m_samples(new QSpinBox(this)),
      m_seconds(new QDoubleSpinBox(this)), m_noise(new QDoubleSpinBox(this)) {
    setObjectName(QStringLiteral("tracedSettings"));
    setToolTip(tr("Quality \"path traced\": once the view is still, the viewport accumulates path-traced "
                  "samples until the first of these targets is reached, and starts over on any change."));
    m_samples->setObjectName(QStringLiteral("traceSamples"));
    m_samples->setRange(0, 65536);
    m_samples->setSpecialValueText(tr("no limit"));
    m_samples->setToolTip(tr("Stop at this many samples per pixel (0: no limit)"));
    m_seconds->setObjectName(QStringLiteral("traceSeconds"));
    m_seconds->setRange(0.0, 3600.0);
    m_seconds->setDecimals(1);
    m_seconds->setSuffix(tr(" s"));
    m_seconds->setSpecialValueText(tr("no limit"));
    m_seconds->setToolTip(tr("Stop after this many seconds of tracing (0: no limit)"));
    m_noise->setObjectName(QStringLiteral("traceNoise"));
    m_noise->setRange(0.0, 100.0); // percent; ViewOptions::traceNoise is the fraction
    m_noise->setDecimals(2);
    m_noise->setSingleStep(0.5);
    m_noise->setSuffix(tr(" %"));
    m_noise->setSpecialValueText(tr("off"));
    m_noise->setToolTip(tr("Stop once the estimated noise is at or below this (0: off): the pixels' standard "
                           "error relative to the image's mean luminance; 1 % is a clean image"));
    auto* form = new QFormLayout(this);
    form->addRow(tr("Stop at &samples"), m_samples);
    form->addRow(tr("Stop after &time"), m_seconds);
    form->addRow(tr("Stop at &noise"), m_noise);
    connect(m_samples, &QSpinBox::valueChanged, this, &TracedSettingsBox::store);
    connect(m_seconds, &QDoubleSpinBox::valueChanged, this, &TracedSettingsBox::store);
    connect(m_noise, &QDoubleSpinBox::valueChanged, this, &TracedSettingsBox::store);
    connect(m_settings, &ViewSettings::changed, this, &TracedSettingsBox::load);
    load();
}

void TracedSettingsBox::load() {
    const ViewOptions& o = m_settings->options();
    const QSignalBlocker b1(m_samples), b2(m_seconds), b3(m_noise);
    m_samples->setValue(o.traceSamples);
    m_seconds->setValue(o.traceSeconds);
    m_noise->setValue(100.0 * o.traceNoise);
}

void TracedSettingsBox::store() {
    m_settings->setTraceTargets(m_samples->value(), m_seconds->value(), m_noise->value() / 100.0);
}

} // namespace lr
