// The split-sum environment BRDF (Karis 2013, "Real Shading in Unreal Engine 4"): what the glTF BRDF
// (lighting.h's PBR block: GGX D, height-correlated Smith V, Schlick F, Lambert diffuse × (1 − F_dielectric))
// reflects of a UNIFORM environment of radiance 1, per (n·v, roughness). The renderer uploads it once as a
// lookup table (render/environmentgl.h) and multiplies it with the prefiltered environment
// (docs/lighting-models.md "Environment"). In double; no Qt, no GL.
//
// With w = (1 − v·h)^5 (Schlick's weight, F = F0 + (1 − F0)·w):
//   scale   A = ∫ (1 − w) D V (n·l) dω          specular = F0·A + B   (exact in a uniform environment)
//   bias    B = ∫ w D V (n·l) dω
//   diffuse W = (1/π) ∫ (1 − w) (n·l) dω        diffuse  = c_diff · (1 − 0.04) · W   (exact likewise)
// W depends on n·v only (v·h = sqrt((1 + l·v)/2) whatever the roughness).
#pragma once

#include <glm/vec3.hpp>
#include <vector>

namespace lr::envbrdf {

struct Dfg {
    double scale = 0.0;   // A
    double bias = 0.0;    // B
    double diffuse = 0.0; // W
};

// GGX roughness as the shaders clamp it (lighting.h kMinRoughness): α = max(r, 0.0525)², r <= 1.
double alphaOf(double roughness);

// A, B by importance sampling GGX's visible normals (Heitz 2018; `samples` Hammersley points: 1024 leave
// an error below 2e-3 even at grazing angles), W by cosine-weighted sampling of l. nDotV in (0, 1], roughness
// in [0, 1].
Dfg integrate(double nDotV, double roughness, int samples = 1024);

// The same integrals by brute-force midpoint quadrature over the hemisphere of l (`steps` × 4·steps
// cells in θ, φ): slow, independent of the importance sampling; for tests.
Dfg quadrature(double nDotV, double roughness, int steps = 400);

// The lookup table: size × size texels, row-major, texel (i, j) at n·v = (i + 1/2)/size (x) and
// roughness = (j + 1/2)/size (y); each (A, B, W). Sampled with linear filtering at (n·v, roughness).
std::vector<glm::vec3> dfgLut(int size = 32, int samples = 1024);

// The table the renderer uploads: dfgLut(kDfgTableSize) with its default samples, precomputed in
// envbrdf_table.cpp (kDfgTableSize² × (A, B, W) floats, row-major); formulas_envbrdf checks it still is.
constexpr int kDfgTableSize = 32;
const float* dfgTable();

} // namespace lr::envbrdf
