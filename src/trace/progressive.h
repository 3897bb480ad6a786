// Rendering a PathTracer towards a target: a number of samples per pixel, a time limit, a noise level
// (PathTracer::noiseEstimate), whichever comes first. Samples are added in passes of 1, 1, 2, 4, ... (each
// pass at most as many samples as are done, at most kMaxPass), so the noise is checked often early and
// rarely late; the time limit cancels the running pass from a timer thread (finished tiles keep their
// samples, so a pixel may hold one sample more than samplesDone()). What `render --quality path` and
// `bench`'s path tier and the editor's traced screenshot share.
#pragma once

#include "pathtracer.h"

#include <functional>

namespace lr::trace {

struct RenderTarget {
    int samples = 64;            // per pixel (samplesDone)
    double seconds = 0.0;        // > 0: stop when this much wall time has passed
    double noiseThreshold = 0.0; // > 0: stop once noiseEstimate() ≤ this
    // Called after every pass with samplesDone() (progress). With it, or a time or noise target, the
    // samples come in passes; with none of them, in one.
    std::function<void(int)> afterPass;
};

enum class StopReason { Samples, Time, Noise, Cancelled };
const char* stopReasonName(StopReason reason); // "samples", "time", "noise", "cancelled"

struct RenderOutcome {
    int samples = 0;      // samplesDone() at the end
    double seconds = 0.0; // wall time in render()
    double noise = 0.0;   // noiseEstimate() at the end (+infinity under 2 samples)
    StopReason reason = StopReason::Samples;
};

inline constexpr int kMaxPass = 16;

// Blocking. A cancel() from elsewhere stops it too (StopReason::Cancelled). A stop by time or cancel
// leaves the tracer cancelled (its render() does nothing until restart()).
RenderOutcome renderToTarget(PathTracer& tracer, const RenderTarget& target);

} // namespace lr::trace
