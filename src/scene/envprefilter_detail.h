// Internal to the environment prefilter (envprefilter.h), exposed for its tests: resampling and the
// area-preserving mip pyramid of an equirectangular image, the three convolutions, and brute-force
// versions of them (double, every texel) that the tests measure the fast ones against.
#pragma once

#include "core/environment.h"

#include <array>
#include <functional>
#include <vector>

namespace lr::envfilter {

// fn(0) ... fn(count − 1) on the global thread pool (QtConcurrent), each row once; returns when all ran.
void forEachRow(int count, const std::function<void(int)>& fn);

// `src` resampled to width × width/2: an area average where it shrinks (each texel weighted by its solid
// angle), bilinear where it grows. The same size: a copy.
EnvironmentImage resample(const EnvironmentImage& src, int width);
// Half the size (even width and height): each texel the solid-angle-weighted mean of its 2×2 texels, so
// ∫ L dω is kept exactly.
EnvironmentImage halve(const EnvironmentImage& src);
// base, halve(base), ... down to `minWidth` wide.
std::vector<EnvironmentImage> pyramid(const EnvironmentImage& base, int minWidth);
// Trilinear lookup (u wraps, v clamps) at a fractional level of the pyramid.
glm::vec3 sampleLevel(const std::vector<EnvironmentImage>& mips, float u, float v, float lod);

// Irradiance by exact texel quadrature: SH9 (cosine lobe folded in) over every texel of `src`.
std::array<glm::vec3, 9> irradianceSH(const EnvironmentImage& src);
// E(n) = Σ L Ω (n·ω)⁺ over every texel of `src`, for each texel of a width × width/2 map (rowQuadrature).
EnvironmentImage irradianceMap(const EnvironmentImage& src, int width);

// Σ L · Ω · kernel(n·ω) over the texels of `src` with n·ω > 0, for each texel n of a width × width/2 map
// (both widths powers of 2): the texels of one row differ only by a turn about +Y, so each row's weights
// are computed once and turned along it. `normalise`: divided by the weights' sum, weights below 1e-7 of
// the largest dropped.
EnvironmentImage rowQuadrature(const EnvironmentImage& src, int width,
                               const std::function<double(double)>& kernel, bool normalise);

// The GGX-convolved radiance, width × width/2, of roughness r (α = r², N = V = R, weights D·(n·l),
// Karis 2013), by importance sampling with filtered importance sampling (Colbert & Křivánek 2007) from
// `mips` (pyramid of the level-0 image, widths powers of 2): `samples` GGX samples per texel (Hammersley).
EnvironmentImage ggxLevel(const std::vector<EnvironmentImage>& mips, int width, double roughness,
                          int samples);
// The same by direct quadrature over every texel of `src` (width a power of 2): exact for that source,
// fast for the wide lobes (each row's weights are computed once and turned along the row).
EnvironmentImage ggxLevelQuadrature(const EnvironmentImage& src, int width, double roughness);
// The source width ggxLevelQuadrature is used with at a roughness, or 0 where ggxLevel samples instead.
int ggxQuadratureWidth(double roughness);
// How many samples ggxLevel takes at a roughness (the prefilter's choice).
int ggxSamples(double roughness);

// Brute force, for tests: Σ L Ω D(n·l) (n·l)⁺ / Σ Ω D (n·l)⁺ and Σ L Ω (n·ω)⁺ over every texel of `src`.
glm::dvec3 ggxBruteForce(const EnvironmentImage& src, const glm::dvec3& n, double roughness);
glm::dvec3 irradianceBruteForce(const EnvironmentImage& src, const glm::dvec3& n);

// GGX D for α² = a2 at cos θh² = nh2 (the normalised microfacet distribution).
inline double ggxD(double a2, double nh2) {
    const double d = nh2 * (a2 - 1.0) + 1.0;
    return a2 / (environment::kPi * d * d);
}

} // namespace lr::envfilter
