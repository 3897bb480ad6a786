// View settings: how the viewport shows the scene, not part of the rig (so not undoable): exposure,
// tone mapping, quality, background, ground grid, gizmos. Persisted in QSettings under "view/".
// Shading model and viewer are rig values and live in the Document instead.
#pragma once

#include "core/quality.h"
#include "core/types.h"

#include <QColor>
#include <QObject>

namespace lr {

struct ViewOptions {
    double exposure = 0.0; // EV
    ToneMap toneMap = ToneMap::Aces;
    Quality quality = Quality::Exact;
    QColor background{46, 48, 54}; // sRGB
    bool grid = true;
    bool gizmos = true;
    bool operator==(const ViewOptions&) const = default;
};

class ViewSettings : public QObject {
    Q_OBJECT
  public:
    explicit ViewSettings(QObject* parent = nullptr);

    const ViewOptions& options() const { return m_options; }
    void setOptions(const ViewOptions& options); // emits changed() when different, saves

    void setExposure(double ev);
    void setToneMap(ToneMap op);
    void setQuality(Quality q);
    void setBackground(const QColor& c);
    void setGrid(bool on);
    void setGizmos(bool on);

    // Not persistent: changes are not written to QSettings (scripted runs such as the README screenshot).
    void setPersistent(bool persistent) { m_persistent = persistent; }

    void load(); // from QSettings (invalid stored values fall back to defaults)
    void save() const;

  signals:
    void changed();

  private:
    ViewOptions m_options;
    bool m_persistent = true;
};

} // namespace lr
