// One path: unidirectional path tracing with next-event estimation at every surface (each rig light, one
// point of the environment by luminance, one emissive triangle by power) and BSDF sampling, the two
// combined by multiple importance sampling with the power heuristic (Veach 1997) wherever both can reach
// an emitter (area lights, the environment, emissive triangles; point, spot and directional lights are
// sampled by light alone). Russian roulette from the `rouletteDepth`-th bounce (survival probability =
// the throughput's largest channel, at most 0.95), and a hard limit of `bounces` surface interactions
// (1: direct light only). Nothing is clamped unless fireflyClamp is set (a named, biased option, off by
// default). A sample whose radiance is not finite is dropped and counted, never averaged in.
#pragma once

#include "sampler.h"
#include "tracescene.h"

#include <glm/vec3.hpp>

namespace lr::trace {

struct TraceSettings {
    int bounces = 8;       // surface interactions per path, >= 0 (0: emitters and the background only)
    int rouletteDepth = 3; // Russian roulette from this bounce on
    // The largest channel of one sample's radiance is clamped here when > 0: removes fireflies, biased
    // (darker highlights). 0: off (the default).
    double fireflyClamp = 0.0;
    bool transparent = false;                   // escaped camera rays (and the catcher's shadow) go to alpha
    glm::dvec3 background{0.019, 0.019, 0.023}; // linear; the raster's default rgb(38, 38, 42)
    bool jitter = true;                         // a uniform point of the pixel per sample, else its centre
    std::uint32_t seed = 0;
};

struct PathSample {
    glm::dvec3 radiance{0.0};
    double alpha = 1.0;
    bool finite = true;
};

PathSample tracePath(const TraceScene& scene, const glm::dvec3& origin, const glm::dvec3& dir,
                     Sampler& sampler, const TraceSettings& settings);

} // namespace lr::trace
