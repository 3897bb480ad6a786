// View settings: how the viewport shows the scene, not part of the rig (so not undoable): exposure,
// tone mapping, quality, background, ground grid, gizmos, and the path-traced view with its targets
// (tracedview.h). Persisted in QSettings under "view/".
// Shading model and viewer are rig values and live in the Document instead.
#pragma once

#include "core/quality.h"
#include "core/types.h"

#include <QColor>
#include <QObject>

namespace lr {

constexpr int kMaxMovingFrameRate = 120;

struct ViewOptions {
    double exposure = 0.0; // EV
    ToneMap toneMap = ToneMap::Aces;
    Quality quality = Quality::Exact;
    QColor background{46, 48, 54}; // sRGB
    bool grid = true;
    bool gizmos = true;
    // "Path traced" (issue 36): once the view is still the viewport accumulates path-traced samples; while
    // it changes it shows `quality`, the raster tier last chosen. Accumulation stops at the first target
    // reached; 0 switches a target off.
    bool pathTraced = false;
    // While the view moves (orbit, pan, dolly, a light dragged) frames are drawn smaller so that this many
    // fit a second (DynamicResolution); 0: always at full size, however long a frame takes.
    int movingFrameRate = 30;
    int traceSamples = 256;    // samples per pixel
    double traceSeconds = 0.0; // seconds of tracing
    double traceNoise = 0.0;   // estimated relative noise (PathTracer::noiseEstimate) at or below this
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
    void setPathTraced(bool on);
    void setMovingFrameRate(int fps); // clamped to [0, kMaxMovingFrameRate]
    // Negative or non-finite values are taken as 0 (off).
    void setTraceTargets(int samples, double seconds, double noise);

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
