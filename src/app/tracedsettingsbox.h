// Render settings' "Path traced" box (issue 36): the targets at which the viewport's path-traced view
// (tracedview.h) stops accumulating: samples per pixel, seconds, estimated noise; 0 switches one off. View
// settings (ViewSettings, kept in QSettings), not rig values: no undo.
#pragma once

#include <QGroupBox>

class QDoubleSpinBox;
class QSpinBox;

namespace lr {

class ViewSettings;

class TracedSettingsBox : public QGroupBox {
    Q_OBJECT
  public:
    explicit TracedSettingsBox(ViewSettings* settings, QWidget* parent = nullptr);

    QSpinBox* samples() const { return m_samples; }
    QDoubleSpinBox* seconds() const { return m_seconds; }
    QDoubleSpinBox* noise() const { return m_noise; }

  private:
    void load();
    void store();

    ViewSettings* m_settings;
    QSpinBox* m_samples;
    QDoubleSpinBox* m_seconds;
    QDoubleSpinBox* m_noise;
};

} // namespace lr
