// Presenting a BenchReport (qualitybench.h): the human table (`lightrig bench` stdout, the Quality panel),
// the JSON document (--json) and the chart of time against error per tier (--chart, the Quality panel).
#pragma once

#include "qualitybench.h"

#include <QImage>
#include <QJsonObject>
#include <QString>
#include <QStringList>

namespace lr {

// Column headers and one row of cells per result, as the table shows them (the Quality panel's model).
// `shadows` adds the shadow measure's two columns (benchHasShadows: only rigs with casters have them),
// `traced` the error against the converged path-traced image (path PSNR, path err; benchHasTraced: with
// the path tier, tracebench.h).
QStringList benchTableHeaders(bool shadows = false, bool traced = false);
QStringList benchTableRow(const BenchResult& r, bool shadows = false, bool traced = false);
bool benchHasShadows(const BenchReport& report);
bool benchHasTraced(const BenchReport& report);
// Whether some scene's reference integrated an environment (BenchResult::hasEnvironment).
bool benchHasEnvironment(const BenchReport& report);
bool benchHasAreaLights(const BenchReport& report); // some result's reference integrated area lights

// The aligned text table, one line per result, followed by the über-shader comparison when present and,
// when a reference integrated an environment, one line per such scene with its convergence.
QString benchTable(const BenchReport& report);

// {"tool", "gl", "options", "results": [...], "uber_shader": [...]}. Per result the keys scene, lights,
// quality, width, height, ms_median, ms_min, ms_max, first_frame_ms, max_error_levels, mean_error_levels,
// psnr_db, nonfinite_pixels and more (docs/quality.md lists them). psnr_db is null for an image identical
// to the reference (infinite PSNR); error keys are null when errors were not measured. Results with the
// shadow measure also carry shadow_differing_share, shadow_mean_error_levels, shadow_compared_pixels and
// shadow_band_pixels; results whose reference integrated an environment environment_source,
// environment_reference_ms, environment_over_half_level_share, environment_max_error_levels,
// environment_mean_error_levels and environment_mean_samples (and the document environment_reference).
// With the path tier, results carry path_psnr_db, path_mean_error_levels, path_max_error_levels and
// path_compared_pixels, and the document "path" (tracebench.h pathBenchJson; [] without it).
QJsonObject benchJson(const BenchReport& report);

// The über-shader comparison per scene: specialised exact run against the über-shader run.
struct UberComparison {
    QString scene;
    double specialisedMs = 0.0, uberMs = 0.0;       // wall ms/frame (median)
    double specialisedCpuMs = 0.0, uberCpuMs = 0.0; // CPU ms/frame (median)
    double specialisedFirstDrawMs = 0.0, uberFirstDrawMs = 0.0;
    // Share of the über-shader's time that specialising saves (wall, CPU).
    double saving() const { return uberMs > 0.0 ? 1.0 - specialisedMs / uberMs : 0.0; }
    double cpuSaving() const { return uberCpuMs > 0.0 ? 1.0 - specialisedCpuMs / uberCpuMs : 0.0; }
};
std::vector<UberComparison> uberComparisons(const BenchReport& report);

// Scatter chart: x = median ms/frame (log scale when the times span more than 8×), y = mean error in
// 8-bit levels; one point per scene × tier, coloured by tier, the tiers of a scene joined by a line.
QImage benchChart(const BenchReport& report, QSize size = QSize(1000, 640));

} // namespace lr
