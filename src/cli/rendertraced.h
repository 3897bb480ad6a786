// `lightrig render MODEL --quality path [--samples N] [--time-limit S] [--noise-threshold T] [--bounces B]
// [--threads T] [--firefly-clamp X] [--seed S]`:
// the path-traced image (src/trace) of one model, rig and view, on the CPU: no OpenGL context and no
// display needed. The scene options (rig, --shading, --ground, --environment..., camera, size, exposure,
// tone map, --transparent) mean what they mean for the raster qualities.
#pragma once

#include "renderrun.h"

namespace lr::cli {

struct TracedRenderOptions {
    int samples = 64;            // per pixel
    double timeLimit = 0.0;      // seconds; > 0: stop then (trace/progressive.h)
    double noiseThreshold = 0.0; // > 0: stop once the relative noise (PathTracer::noiseEstimate) is ≤ this
    int bounces = 8;             // surface interactions per path
    int threads = 0;             // 0: every core
    double fireflyClamp = 0.0;   // 0: off
    int seed = 0;                // the sampler's seed (trace::TraceSettings::seed)
};

// Renders the one item (exit 0 written, 1 the model, rig, scene or output failed).
int runRenderTraced(const RenderRequest& request, const RenderItem& item, const TracedRenderOptions& traced);

} // namespace lr::cli
