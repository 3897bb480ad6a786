// One path: unidirectional path tracing with next-event estimation at every surface (each rig light, one
// point of the environment by luminance, one emissive triangle by power) and BSDF sampling, the two
// combined by multiple importance sampling with the power heuristic (Veach 1997) wherever both can reach
// an emitter (area lights, the environment, emissive triangles; point, spot and directional lights are
// sampled by light alone). Russian roulette from the `rouletteDepth`-th bounce (survival probability =
// the throughput's largest channel, at most 0.95), and a hard limit of `bounces` surface interactions
// (1: direct light only). Nothing is clamped unless fireflyClamp is set (a named, biased option, off by
// default). A sample whose radiance is not finite is dropped and counted, never averaged in.
//
// Light groups (core/lightgroups.h, TraceScene::groups): on request, every term a sample adds is also
// added to the group of the emitter it comes from, so the groups sum to the radiance sample for sample
// (to rounding: the radiance's own sums are left exactly as they are without the split).
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

// What tracePath splits one sample into besides its radiance, when the caller asks for it (a null
// PathSplit: nothing is split, nothing is paid).
struct PathSplit {
    // In: the caller's buffer of scene.groups().size() entries. Out: each group's share of the sample's
    // radiance (the buffer is overwritten): a rig light's next-event term, its area hit by a BSDF ray and
    // its own ambient term → the light's group; the scene ambient → "ambient"; the environment's light
    // and the visible environment behind camera rays → "environment"; emissive surfaces, hit or sampled
    // → "emissive"; the background colour and the shadow catcher's composite → "background". The firefly
    // clamp scales every group by its factor; a dropped (non-finite) sample leaves them all 0.
    glm::dvec3* groups = nullptr;
    // Out: the first surface the camera ray meets (not an area light, which camera rays do not see, and
    // not the shadow catcher, which only composites the background): whether there is one, its base
    // colour, its world shading normal (unit, turned towards the camera) and its distance along the ray.
    bool hit = false;
    glm::dvec3 albedo{0.0}, normal{0.0};
    double distance = 0.0;
};

PathSample tracePath(const TraceScene& scene, const glm::dvec3& origin, const glm::dvec3& dir,
                     Sampler& sampler, const TraceSettings& settings, PathSplit* split = nullptr);

} // namespace lr::trace
