// One light group's row in the Mixer dock (issue 37): on/off, its exposure change in EV (a slider over
// −10 … 10 in 0.1 EV steps beside a spin box that also takes a mix file's ±20; a double-click on either
// resets it to 0), its tint (ColorButton, linear RGB) and its name. Edits are announced with the group's
// whole GroupMix; setMix shows one without announcing it.
#pragma once

#include "core/lightmix.h"

#include <QWidget>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QSlider;

namespace lr {

class ColorButton;

inline constexpr double kMixerSliderEV = 10.0; // the slider's reach; the spin box takes kMaxMixEV
inline constexpr int kMixerTicksPerEV = 10;    // the slider's and the spin box's step: 0.1 EV

class MixerGroupRow : public QWidget {
    Q_OBJECT
  public:
    MixerGroupRow(const QString& group, const QString& toolTip, QWidget* parent = nullptr);

    const QString& group() const { return m_group; }
    const GroupMix& mix() const { return m_mix; }
    void setMix(const GroupMix& mix); // shows it; no signal

    QCheckBox* onBox() const { return m_on; }
    QSlider* slider() const { return m_slider; }
    QDoubleSpinBox* evBox() const { return m_ev; }
    ColorButton* tintButton() const { return m_tint; }

  signals:
    void mixEdited(const QString& group, const lr::GroupMix& mix);

  protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

  private:
    void edit(const GroupMix& mix);
    void display(const GroupMix& mix);

    QString m_group;
    GroupMix m_mix;
    QCheckBox* m_on = nullptr;
    QSlider* m_slider = nullptr;
    QDoubleSpinBox* m_ev = nullptr;
    ColorButton* m_tint = nullptr;
    QLabel* m_name = nullptr;
};

} // namespace lr
