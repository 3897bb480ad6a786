// What a `lightrig bench` will cost, said before it starts (issue 41, item 10: `bench --lights 65535` ran
// 7 minutes without finishing its first run and without a word on how long it would take).
//
// The cost of a bench is light·pixel evaluations: every frame shades each of W×H pixels with each light (the
// procedural lights have no range), on llvmpipe on the CPU; the double-precision reference does the same once
// per scene in double, an area light costing hundreds of points (its Monte Carlo integration). Nothing in it
// is worse than linear in lights or pixels, but 65,535 lights at 1280x720 are 6e10 evaluations a frame.
//
// - benchReferenceWork: the reference's work in point-light·pixels (area lights weighted); a scene over
//   BenchOptions::maxReferenceWork gets no reference and no error figures (qualitybench.h), with a note.
// - estimateBench: one frame of the heaviest scene of each set of light types rendered at a small size of
//   the same aspect, timed, and scaled to every frame of every run by pixels and lights.
#pragma once

#include "qualitybench.h"

#include <QSize>
#include <QString>
#include <optional>
#include <vector>

namespace lr {

// An area light's reference integration costs about this many point lights' (measured: ~32 µs against
// ~60 ns per light and covered pixel on llvmpipe's host, the Monte Carlo taking ~33 points per light).
inline constexpr double kAreaReferenceWeight = 512.0;

// Light·pixels of one frame of `scene` at `size` (enabled lights).
double benchFrameWork(const BenchScene& scene, QSize size);
// The reference's work for `scene` at `size`: W×H × Σ lights, an area light weighted kAreaReferenceWeight.
double benchReferenceWork(const BenchScene& scene, QSize size);
// Whether the bench is beyond the standard suite's scale (more than 256 lights in a scene, or more than
// 1280×720×256 light·pixels a frame): then bench.cpp probes and prints an estimate before it starts.
bool benchIsHeavy(const std::vector<BenchScene>& scenes, const BenchOptions& options);

struct BenchEstimate {
    QString scene;            // the scene with the slowest frame
    QSize probeSize;          // its probe frame
    double frameSeconds = 0;  // one exact-tier frame of that scene at the bench's size
    double framesSeconds = 0; // every frame of every run of every scene
    int frames = 0;           // how many frames that is
    double referenceWork = 0; // Σ benchReferenceWork of the scenes that get a reference
    int referencesSkipped = 0;
};

// Renders 2 frames of the heaviest scene of each set of light types at a small size (at most 64×64 pixels,
// the bench's aspect) in a fresh OffscreenRenderer and scales the second's time. Needs what runQualityBench
// needs (a GUI thread with OpenGL); nullopt with *error when the probe cannot render.
std::optional<BenchEstimate> estimateBench(const std::vector<BenchScene>& scenes, const BenchOptions& options,
                                           QString* error);
// One paragraph for stderr: the time, what it is made of, and the options that bound it.
QString describeBenchEstimate(const BenchEstimate& estimate, const BenchOptions& options);

} // namespace lr
