// What an area light (rect, disk; issue 16) adds at a surface point, integrated in double precision for the
// reference (docs/quality.md "Area lights"): exactly the definition of lighting_area.h, the integral over
// the emitter's solid angle of directionalResponse() (× 1/π under classic shading), by Monte Carlo.
//
// Three sampling strategies combined by multiple importance sampling (power heuristic, one sample of each
// per point):
//   - the emitter: a rect uniformly by solid angle (Ureña, Fajardo and King 2013, "An Area-Preserving
//     Parametrization for Spherical Rectangles"; by area, its density converted, where it subtends less
//     than kSmallSolidAngle), a disk by area (Shirley and Chiu's concentric map), density converted to
//     solid angle (d² / (A cos θe));
//   - the specular lobe (montecarlo.h: GGX's visible normals under PBR, Phong's or Blinn's lobe): what
//     finds a sharp highlight of a large emitter;
//   - the cosine about the normal: what finds the diffuse light of an emitter filling the hemisphere
//     (a disk 1e4× the model sampled by area puts almost every sample near its far rim).
// Randomised quasi-Monte Carlo as the environment's integrator (envintegrate.h): `replicates` independently
// shifted copies of a 6-dimensional R-sequence seeded by the pixel; the standard error is the replicates'
// spread; batches until the estimated error of the pixel's displayed value (8-bit levels after exposure,
// tone map and sRGB; envintegrate::Convergence) is within the target, up to a cap.
//
// Only the direct terms: the light's ambient and the visibility are shade.h's (the reference evaluates
// shadeSurface with the area lights' visibility 0, which leaves their ambient, and adds visibility ×
// what this returns).
#pragma once

#include "envintegrate.h"
#include "shadetypes.h"

#include <cstdint>
#include <span>
#include <vector>

namespace lr::areaintegrate {

// The stop rule: envintegrate's, with fewer points per batch (a pixel may have many area lights).
envintegrate::Convergence defaultConvergence(double exposureEV, ToneMap toneMap);

struct Estimate {
    glm::dvec3 radiance{0.0};      // Σ visibility_k × direct_k (linear, before exposure)
    glm::dvec3 standardError{0.0}; // of radiance
    int samples = 0;               // points taken (each: one sample of every strategy), all lights
    double errorLevels = 0.0;      // the displayed value's estimated error, 8-bit levels (not rounded)
    bool converged = true;         // errorLevels within the target before the cap
};

// Below this solid angle (sr) a rect is sampled by area: the spherical rectangle's angles cancel there.
inline constexpr double kSmallSolidAngle = 1e-4;

// Whether the light's direct terms can be non-zero at the surface: an area light with an extent, a
// non-zero colour, the surface on its emitting side (either side when two-sided) and some of the emitter
// above the surface's horizon (anywhere with a half-Lambert diffuse). False: the integral is exactly 0.
bool reaches(const lighting::ShadeLight<double>& l, const lighting::Surface<double>& s);

// The emitter's solid angle seen from P (sr), and whether P sees its emitting side: 0 when not.
double solidAngle(const lighting::ShadeLight<double>& l, const glm::dvec3& P);

// The direct terms of every area light in `lights` (other types are skipped), each × its `visibility`
// (empty: 1). `seed` makes it reproducible (the pixel's index); `rest` is the pixel's radiance from
// everything else, for the displayed error. `direct`: when given, each light's unshadowed direct terms
// (indexed like `lights`; 0 for other types).
Estimate integrate(std::span<const lighting::ShadeLight<double>> lights, std::span<const double> visibility,
                   const lighting::Surface<double>& s, const lighting::ShadeSettings<double>& st,
                   std::uint64_t seed, const envintegrate::Convergence& convergence,
                   const glm::dvec3& rest = glm::dvec3(0.0), std::vector<glm::dvec3>* direct = nullptr);

// One light's direct terms (tests).
Estimate integrateOne(const lighting::ShadeLight<double>& l, const lighting::Surface<double>& s,
                      const lighting::ShadeSettings<double>& st, std::uint64_t seed,
                      const envintegrate::Convergence& convergence, const glm::dvec3& rest = glm::dvec3(0.0));

} // namespace lr::areaintegrate
