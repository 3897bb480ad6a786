// What an environment adds at a surface, integrated in double precision for the reference (issue 15;
// docs/quality.md "Environment"). The definition integrated is the one above `struct Environment`
// (environment.h): the limit of one directional light per texel, classic (intensity L·Ω/π with the
// environment's diffuse model, the rig's specular and viewer models) or physically based (L·Ω lux, the
// glTF BRDF with Lambert's cosine), × the material's occlusion, no shadowing by the model.
//
// "The limit": each texel's radiance is constant over its cell of the sphere (the lat-long rectangle it
// covers), so refining a texel into sub-lights of the same radiance changes nothing; the environment is
// that piecewise-constant function L(ω) and the contribution is ∫ L(ω) W(ω) dω, W the per-direction
// weight shadeLight()/shadeLightPbr() give a unit directional light.
//
// Two evaluations:
//   - environmentRadianceBySum(): literally one directional light per texel (or per sub-cell, each texel
//     split `subdivide`² times) through shade.h: the definition itself, for tests and small images;
//   - EnvironmentField::integrate(): the numerical integrator for real images (1024×512). The diffuse
//     kernels are integrated deterministically: half-Lambert exactly (it is a quadratic in ω, so three
//     moments of the image give it), Lambert's clamped cosine by an adaptive quadrature over a pyramid
//     of the image's cells with a hard error bound (a cell wholly above the surface's horizon contributes
//     exactly n·∫L ω dω; only cells the horizon crosses are refined, down to sub-texel cells). The rest —
//     specular lobes, and under PBR the Fresnel share of the diffuse lobe — by Monte Carlo with multiple
//     importance sampling (balance heuristic) between the BRDF lobe and the image's luminance × solid
//     angle, randomised quasi-Monte Carlo (independently shifted replicates of a low-discrepancy
//     sequence, seeded by the pixel; the standard error is the replicates' spread), batches until the
//     estimated standard error is below the target in 8-bit levels after exposure, tone map and sRGB.
#pragma once

#include "environment.h"
#include "shade.h"

#include <array>
#include <cstdint>
#include <functional>
#include <glm/mat3x3.hpp>
#include <memory>
#include <vector>

namespace lr::envintegrate {

// When the integrator stops at one pixel, and what its error is measured in.
struct Convergence {
    double exposureEV = 0.0;
    ToneMap toneMap = ToneMap::Clamp;
    double targetLevels = 0.5; // estimated error, 8-bit levels of the largest channel
    // Sample pairs (one from the lobe, one from the image) come from `replicates` independently shifted
    // low-discrepancy sequences, `batch` points each per batch: 64 pairs a batch, 64 to 16,384 in all (and
    // where a narrow lobe takes the window after the first quarter, the rest of the sphere again).
    int replicates = 16;
    int batch = 4;
    int minBatches = 1, maxBatches = 256;
    double quadratureLevels = 0.1; // share of the target the diffuse quadrature's hard bound may use
};

// The largest channel's change, in 8-bit levels, of the displayed value (exposure, tone map, sRGB) when
// the radiance x moves by ±e: how an estimate's error shows (area lights' integrator too, areaintegrate.h).
double displayErrorLevels(const glm::dvec3& x, const glm::dvec3& e, const Convergence& c);

struct Estimate {
    glm::dvec3 radiance{0.0};      // what the environment adds (linear, before exposure)
    glm::dvec3 standardError{0.0}; // of the Monte Carlo part (0 when it has none)
    glm::dvec3 bound{0.0};         // hard bound on the diffuse quadrature's error, plus the lobe window's
                                   // midpoint-rule error estimate where it was used
    bool windowed = false;         // the lobe's core was summed texel by texel (EnvironmentField::Window)
    int samples = 0;               // MIS sample pairs taken
    // max over channels of |display(rest + radiance ± (standardError + bound)) − display(rest + radiance)|
    // in 8-bit levels (not rounded): the pixel's estimated error.
    double errorLevels = 0.0;
};

// The environment as the reference integrates it. Built once per image (the pyramid of cell moments and
// the luminance distribution: about 0.1 s for 1024×512), then shared read-only by every pixel's thread.
class EnvironmentField {
  public:
    EnvironmentField(std::shared_ptr<const EnvironmentImage> image, double intensityEV,
                     double rotationDegrees, DiffuseModel classicDiffuse = DiffuseModel::Lambert);

    const EnvironmentImage& image() const { return *m_image; }
    double scale() const { return m_scale; } // 2^intensity
    double rotation() const { return m_rotation; }
    DiffuseModel diffuse() const { return m_diffuse; }
    bool isBlack() const { return !(m_totalLuminance > 0.0); }

    // The radiance (× 2^EV) arriving from a world direction: the texel its cell lies in.
    glm::dvec3 radianceAt(const glm::dvec3& worldDirection) const;
    // ∫ L(ω) (n·ω)⁺ dω (per channel) for a unit normal in the image's frame, by the adaptive quadrature;
    // *bound gets its hard error bound (per channel). `tolerance`: the bound's luminance aimed at.
    glm::dvec3 irradiance(const glm::dvec3& worldNormal, double tolerance, glm::dvec3* bound = nullptr) const;

    // The environment's radiance at a surface (view space, as the G-buffer has it); viewToWorld rotates
    // view-space directions into the rig's world. `seed` makes it reproducible (the pixel's index); `rest`
    // is the pixel's radiance from everything else (lights, emissive), for the display error.
    Estimate integrate(const lighting::Surface<double>& s, const lighting::ShadeSettings<double>& st,
                       const glm::dmat3& viewToWorld, std::uint64_t seed, const Convergence& convergence,
                       const glm::dvec3& rest = glm::dvec3(0.0)) const;

  private:
    // A cell of the pyramid: ∫L and ∫L ω per channel, and a cone (axis, cos β, sin β) holding the cell.
    struct Node {
        glm::dvec3 flux{0.0};
        std::array<glm::dvec3, 3> first{};
        glm::dvec3 axis{0.0, 1.0, 0.0};
        double cosBeta = -1.0, sinBeta = 0.0;
        double luminance = 0.0;
    };
    struct Item;                          // a cell on the quadrature's stack
    glm::dvec3 texel(int x, int y) const; // scaled radiance
    int texelIndexOf(const glm::dvec3& imageDirection) const;
    glm::dvec3 imageDirection(const glm::dvec3& world) const; // world -> the image's frame (R_y(−rotation))

    std::shared_ptr<const EnvironmentImage> m_image;
    double m_scale = 1.0, m_rotation = 0.0;
    DiffuseModel m_diffuse = DiffuseModel::Lambert;
    int m_width = 0, m_height = 0;
    // Per row/column cell geometry.
    std::vector<double> m_rowSolidAngle, m_rowCc, m_rowSc, m_rowCosBeta, m_rowSinBeta, m_rowCosLat,
        m_rowSinLat;
    std::vector<double> m_colDSin, m_colDCos, m_colCos, m_colSin;
    // Whole-sphere moments (per channel): Φ = ∫L, M = ∫L ω, Q = ∫L ω ωᵀ (xx, yy, zz, xy, yz, xz).
    glm::dvec3 m_flux{0.0};
    std::array<glm::dvec3, 3> m_first{};
    std::array<std::array<double, 6>, 3> m_second{};
    double m_totalLuminance = 0.0; // ∫ luminance(L) dω
    // The pyramid: level k (1 ...) has cells of 2^k × 2^k texels; level 0 (texels) is not stored.
    std::vector<std::vector<Node>> m_levels;
    std::vector<int> m_levelWidth, m_levelHeight;
    // Luminance × solid angle distribution: per row the cumulative share of the row's texels, and the
    // cumulative share of the rows (inverted row then column: a mapping from the unit square that keeps
    // the low-discrepancy points' stratification, which an alias table would scramble); and the density
    // (per steradian) of each texel's directions.
    std::vector<double> m_rowCdf, m_colCdf, m_pdf;

    // The core of a narrow specular lobe, summed texel by texel (envintegrate_window.cpp): where Monte Carlo
    // alone does not converge — a near-mirror lobe over a softbox's edge, where only the lobe's samples
    // see the edge and they converge slowly — integrate() sums the texels whose centres lie within the
    // window's cone (each split into subdivide² cells of equal solid angle, at their centres) and leaves
    // Monte Carlo only the rest of the sphere.
    struct Window {
        glm::dvec3 axis{0.0, 1.0, 0.0};
        double halfAngle = 0.0;
        double cosHalfAngle = 1.0;
    };
    using Integrand = std::function<glm::dvec3(const glm::dvec3& direction, const glm::dvec3& radiance)>;
    bool inWindow(const Window& w, int texelIndex) const;
    glm::dvec3 windowSum(const Window& w, const Integrand& f, int subdivide) const;

    void sampleImage(double u0, double u1, double u2, double u3, glm::dvec3* direction,
                     int* texelIndex) const;
    double imagePdf(int texelIndex) const; // per steradian
};

// The definition: one directional light per texel (each texel split into subdivide × subdivide cells of
// its radiance, each a light of the cell's solid angle, at the cell's centre), summed through
// lighting::shadeLight / shadeLightPbr in view space, × occlusion. O(texels × subdivide²) per call.
glm::dvec3 environmentRadianceBySum(const EnvironmentField& field, const lighting::Surface<double>& s,
                                    const lighting::ShadeSettings<double>& st, const glm::dmat3& viewToWorld,
                                    int subdivide = 1);

// The directional light a sub-texel cell is, in view space (the building block of the sum).
lighting::ShadeLight<double> texelLight(const glm::dvec3& viewDirectionToTexel, const glm::dvec3& radiance,
                                        double solidAngle, ShadingModel model, DiffuseModel classicDiffuse);

// Luminance (Rec. 709) of a linear colour.
inline double luminance(const glm::dvec3& c) {
    return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
}

} // namespace lr::envintegrate
