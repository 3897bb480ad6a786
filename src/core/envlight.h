// A light taken from the environment (issue 15, part 7; Marmoset's sky editor): the user clicks a bright spot
// of the environment and gets a directional light of its direction, colour and strength, and optionally a
// dimmed spot (EnvironmentSpot) so the environment does not light the model twice.
//
// The spot: the brightest texel within `searchDegrees` of the clicked direction, grown (4-connected, across
// the image's left/right seam) over the texels that stand out as it does (at least `minContrast` × the
// environment's mean luminance) and have at least `spotFraction` of its luminance, no farther than
// `maxSpotDegrees` from it. The dimmed spot is the cone around the region's centroid that holds the region,
// keyed to that same luminance (EnvironmentSpot::threshold), so it dims the footprint and nothing of the
// darker surroundings; the light is exactly what that spot removes (issue 41). By the definition above
// struct Environment (core/environment.h), each texel of radiance L and solid angle Ω acts as a directional
// light of L·Ω lux (physically based) or L·Ω/π (classic), so the spot's light is their sum over the texels
// the spot covers: colour = Σ L·Ω over its largest channel, intensity = that channel (÷ π under classic
// shading), both × 2^EV; direction = minus the luminance-weighted centroid of their directions. Nothing is
// found where the brightest texel is not clearly brighter than the environment as a whole (`minContrast` ×
// its mean luminance over the sphere): a uniform sky, a floor, a plain gradient.
#pragma once

#include "environment.h"

#include <QString>
#include <glm/vec3.hpp>

namespace lr {

struct EnvironmentLightOptions {
    double searchDegrees = 15.0;  // where the brightest texel is looked for, around the click
    double maxSpotDegrees = 30.0; // the region's cap, around its brightest texel
    double spotFraction = 0.01;   // the region: texels of at least this × the peak's luminance
    double minContrast = 2.0;     // peak / the environment's mean luminance
};

struct EnvironmentLight {
    bool found = false;
    QString reason;                       // when not found: "nothing bright here: ..."
    glm::dvec3 direction{0.0, -1.0, 0.0}; // world, unit: where the light travels (minus towards the spot)
    glm::dvec3 color{1.0};                // linear, largest channel 1
    double intensity = 0.0;               // lux (physically based) or classic intensity
    double solidAngle = 0.0;              // sr of the region
    int texels = 0;                       // the spot covers
    EnvironmentSpot spot; // the footprint in the image's own frame (before rotation), factor 0
};

// `image`: LoadedEnvironment::image (radiance after the rig's spots, before rotation and intensity).
// `clicked`: a world direction (need not be unit; non-zero and finite, else nothing is found).
EnvironmentLight lightFromEnvironment(const EnvironmentImage& image, double rotationDegrees,
                                      double intensityEv, ShadingModel shading, const glm::dvec3& clicked,
                                      const EnvironmentLightOptions& options = {});

} // namespace lr
