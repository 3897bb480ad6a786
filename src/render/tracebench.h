// `bench`'s path tier (issue 36): per scene, a converged path-traced image (trace/pathtracer.h, many
// samples, its own seed) is the yardstick of
// - the path tracer itself: seconds per sample, samples per second, and its image after 1, 2, 4, 8 …
//   samples (up to PathBenchOptions::samples) against the converged one (PSNR, mean error), so the table
//   shows how fast it converges and when it is within 30 dB;
// - every raster tier: the tier's single-sample 8-bit image (BenchResult::image) against the converged
//   traced image, over the pixels the direct-light reference compares (BenchResult::covered), beside the
//   tier's error against that reference: what the real-time tier misses of the true image (environment
//   occlusion, bounce light), not only of the direct light.
// Runs after runQualityBench (whose results must have kept their images: BenchOptions::keepImages). The
// errors compare 8-bit sRGB after the run's exposure and tone map (core/imagecompare.h).
#pragma once

#include "qualitybench.h"

#include <QJsonArray>
#include <QString>
#include <vector>

namespace lr {

struct PathBenchOptions {
    int samples = 64;           // the ladder's largest step: 1, 2, 4, 8, … up to this
    int convergedSamples = 256; // the converged image's samples per pixel
    int bounces = 8;
    int threads = 0; // 0: every core
};

// Traces each scene's converged image, runs the ladder, and fills each raster result's traced figures
// (BenchResult::hasTracedErrors, tracedErrors; report->results in scene order as runQualityBench leaves
// them). Appends to report->path. False only when `progress` cancelled.
bool runPathBench(const std::vector<BenchScene>& scenes, const PathBenchOptions& options, BenchReport* report,
                  const BenchProgress& progress = {});

// The path tier's table (one line per scene and step) for benchTable; empty without path results.
QString pathBenchTable(const BenchReport& report);
// [{"scene", "width", "height", "threads", "bounces", "seconds_per_sample", "samples_per_second",
//   "seconds_to_30db", "converged_samples", "converged_seconds", "steps": [{"samples", "seconds", "noise",
//   "psnr_db", "mean_error_levels", "max_error_levels"}]}]; psnr_db null when identical.
QJsonArray pathBenchJson(const BenchReport& report);

} // namespace lr
