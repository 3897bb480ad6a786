// The cost of per-group output (issue 37; `lightrig bench --groups`, docs/performance.md "Light-group
// layers"): per scene and tier, the beauty alone (OffscreenRenderer::renderRadiance) against the whole
// split (rasterlayers.h: the beauty, one pass per group, the emission's pass, the G-buffer), median wall
// and process CPU ms of a few frames after a warm-up one, and the layers' bytes; and for the double
// reference (referencelayers.h) one evaluation without and one with the split.
#pragma once

#include "qualitybench.h"

#include <QString>
#include <vector>

namespace lr {

struct GroupBenchOptions {
    QSize size{1280, 720};
    int warmupFrames = 1;
    int frames = 3;
    std::vector<Quality> tiers{Quality::Exact, Quality::Balanced, Quality::Fast};
    int msaaSamples = -1;  // -1: each tier's own (tierMsaaSamples)
    bool reference = true; // one more row per scene: the double reference
    std::uint8_t approximations = render::approx::kDefault;
};

struct GroupBenchResult {
    QString scene;
    QString tier; // "exact", "balanced", "fast", "reference"
    int lights = 0, groups = 0;
    int passes = 0;                              // radiance passes per split (the reference: 1)
    double beautyMs = 0.0, layersMs = 0.0;       // wall, median
    double beautyCpuMs = 0.0, layersCpuMs = 0.0; // process CPU (all threads), median
    qint64 beautyBytes = 0, layersBytes = 0;     // what each returns (the reference's: its double images too)
    // Raster: one float read-back of the frame (median); beautyMs + groups × readbackMs bounds from below
    // what one accumulation per group (all groups in one lighting pass) would cost.
    double readbackMs = 0.0;
    double accumulationBoundMs() const { return readbackMs > 0.0 ? beautyMs + groups * readbackMs : 0.0; }
};

// Needs a QGuiApplication whose platform offers OpenGL. False and *error when a scene fails.
bool runGroupBench(const std::vector<BenchScene>& scenes, const GroupBenchOptions& options,
                   std::vector<GroupBenchResult>* results, QString* glDescription, QString* error);

// /proc/loadavg's three figures ("1.02 0.87 0.55"), "unknown" where there is none.
QString loadAverageNow();

// The results as a table, one row per scene and tier.
QString groupBenchTable(const std::vector<GroupBenchResult>& results);

} // namespace lr
