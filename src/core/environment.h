// Environment lighting (issue 15; docs/rig-format.md "environment", docs/lighting-models.md
// "Environment"): the rig's description of it, the decoded image, the prefiltered form the renderer
// shades with, and the one definition of how a direction maps to the image.
//
// Conventions (the same as three.js's and Blender's for a Y-up glTF scene):
//   - An environment is an equirectangular image of linear radiance, row 0 the top (+Y, up).
//   - Column u in [0, 1) (left to right) is the azimuth atan2(d.z, d.x) / 2π + 1/2: the image's centre
//     column looks along +X, u = 3/4 along +Z, u = 1/4 along −Z. Row v in [0, 1] (top to bottom) is
//     1/2 − asin(d.y) / π.
//   - Directions are in the rig's world (Y up). `rotation` turns the environment about +Y by that many
//     degrees, counter-clockwise seen from above (+Y): the image is looked up at R_y(−rotation) · d.
//   - Radiance is the image's value × 2^intensity (EV). Under physically based shading it is radiance as
//     in glTF/three.js (a uniform environment of 1 lights a white Lambertian surface to 1). Classic
//     shading uses the same convention (docs/lighting-models.md): a white Lambert surface in a uniform
//     environment of 1 shows 1, so a texel of radiance L and solid angle Ω acts as a classic
//     directional light of intensity L·Ω/π and as a physically based one of L·Ω lux.
#pragma once

#include "types.h"

#include <QString>
#include <array>
#include <cmath>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace lr {

// One softbox of the procedural studio: a flat emitting rectangle facing the model, seen from the model's
// centre as `width` × `height` degrees (its gnomonic extent) around the direction (azimuth, elevation).
struct Softbox {
    double azimuth = 0.0;               // degrees about +Y: 0 is +Z, 90 is +X
    double elevation = 30.0;            // degrees above the horizon (-90 ... 90)
    double width = 40.0, height = 30.0; // degrees of arc, each in (0, 170]
    glm::dvec3 color{1.0};              // linear
    double intensity = 4.0;             // radiance = color × intensity (>= 0)
    bool operator==(const Softbox&) const = default;
};

// The built-in procedural environment: a sky gradient from `zenith` (straight up) to `horizon`, a uniform
// `floor` below the horizon (with a narrow blend across it), and softboxes drawn over both.
struct Studio {
    glm::dvec3 zenith{0.35}, horizon{0.6}, floor{0.12}; // linear radiance
    std::vector<Softbox> softboxes;
    bool operator==(const Studio&) const = default;
};

// A spot of the environment dimmed after a light was taken from it ("Lights from the environment"): every
// direction within `angle` degrees of `direction` (world, unit; before rotation — in the image's own
// frame) whose radiance has a luminance (environment::luminance) of at least `threshold` has its radiance
// multiplied by `factor` (0 ... 1). The threshold keeps the dimming to the light's own footprint (a
// softbox, not the sky around it); 0 dims the whole cone.
struct EnvironmentSpot {
    glm::dvec3 direction{0.0, 1.0, 0.0};
    double angle = 5.0;
    double factor = 0.0;
    double threshold = 0.0;
    bool operator==(const EnvironmentSpot&) const = default;
};

// The rig's environment. What it adds at a surface is DEFINED as the limit of one directional light per
// texel, shining from the texel's direction (rotated), of radiance L (× 2^intensity) and solid angle Ω:
//   - physically based: a glTF directional light of L·Ω lux (colour L/|L|), the glTF BRDF with Lambert's
//     cosine, i.e. ∫ L(ω) f(ω, v) (n·ω)⁺ dω;
//   - classic: a directional light of intensity L·Ω/π with `diffuse` as its diffuse model, the rig's
//     specular and viewer models, specular colour = its colour, no ambient; i.e.
//     Lambert       albedo/π · ∫ L(ω) (n·ω)⁺ dω
//     half-Lambert  albedo/π · ∫ L(ω) ((n·ω)/2 + 1/2)² dω   (the whole sphere: 4/3·albedo in a uniform 1)
//     Phong         ks/π · ∫_{n·ω>0} L(ω) (r·ω)⁺^shininess dω, r = reflect(−v, n)
//     Blinn-Phong   ks/π · ∫_{n·ω>0} L(ω) (n·h)⁺^shininess dω, h = normalize(ω + v);
//   - in both, times the material's occlusion (glTF: occlusion applies to indirect light). No shadowing
//     by the model (the environment is not occluded by geometry; docs/lighting-models.md).
// The reference integrates exactly this (in double); the GPU tiers approximate it (prefiltering).
struct Environment {
    EnvironmentSource source = EnvironmentSource::None;
    // Image: the file as the rig writes it: a path relative to the rig's folder (or absolute), or
    // kBuiltinEnvironmentPrefix + a bundled environment's name ("builtin:studio").
    QString file;
    double intensity = 0.0; // EV: radiance × 2^intensity; -20 ... 20
    double rotation = 0.0;  // degrees about +Y; any value, written in [0, 360)
    EnvironmentBackground background = EnvironmentBackground::Visible;
    double blur = 0.3; // Blurred: the background's blur as a GGX roughness, 0 ... 1
    DiffuseModel diffuse = DiffuseModel::Lambert; // classic shading: the diffuse model it is shaded with
    Studio studio;                                // Studio: the procedural environment
    std::vector<EnvironmentSpot> spots;
    bool isNone() const { return source == EnvironmentSource::None; }
    // What the prefiltered form depends on: changing only intensity, rotation, background or blur never
    // re-filters.
    bool sameRadiance(const Environment& o) const {
        return source == o.source && file == o.file && studio == o.studio && spots == o.spots;
    }
    bool operator==(const Environment&) const = default;
};

inline constexpr char kBuiltinEnvironmentPrefix[] = "builtin:";

// A decoded environment: linear RGB radiance, row-major, top row first, every value finite and >= 0.
struct EnvironmentImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> texels;
    bool isNull() const { return width <= 0 || height <= 0; }
    const glm::vec3& at(int x, int y) const { return texels[size_t(y) * size_t(width) + size_t(x)]; }
    glm::vec3& at(int x, int y) { return texels[size_t(y) * size_t(width) + size_t(x)]; }
};

// The environment prepared for shading (prefiltered once per image; rotation and intensity are applied at
// lookup). Every image here is in the environment's own frame (before rotation) and at intensity 0 EV.
struct PrefilteredEnvironment {
    // Irradiance as 9 spherical-harmonic coefficients: E(n) = Σ sh[i] · shBasis9(n)[i], the cosine lobe's
    // convolution already folded in (Ramamoorthi & Hanrahan 2001).
    std::array<glm::vec3, 9> sh{};
    // Irradiance E(n) per direction n, equirectangular (small: kIrradianceWidth × kIrradianceWidth / 2).
    EnvironmentImage irradiance;
    // The split-sum specular chain: level k (k = 0 ... kSpecularLevels − 1) is the radiance convolved with
    // the GGX lobe of roughness k / (kSpecularLevels − 1) (N = V = R), kSpecularBaseWidth >> k texels wide
    // and half as high; level 0 is the image itself resampled to kSpecularBaseWidth.
    std::vector<EnvironmentImage> specular;
    double seconds = 0.0; // wall time the prefiltering took
};
inline constexpr int kIrradianceWidth = 64;
inline constexpr int kSpecularLevels = 6;
inline constexpr int kSpecularBaseWidth = 1024;

namespace environment {

inline constexpr double kPi = 3.14159265358979323846;

// The image coordinate (u right, v down, each in [0, 1]) of a world direction (unit), the environment
// turned by `rotationDegrees` about +Y.
glm::dvec2 equirectUv(const glm::dvec3& direction, double rotationDegrees = 0.0);
// The unit world direction of image coordinate (u, v), the environment turned by `rotationDegrees`.
glm::dvec3 equirectDirection(double u, double v, double rotationDegrees = 0.0);
// The direction of texel (x, y)'s centre in a width × height image (rotation 0), and its solid angle
// (sr): (2π / width) · (π / height) · cos(latitude of the centre) (exact for the row:
// 2π/width · (sin φ1 − sin φ0)).
glm::dvec3 texelDirection(int x, int y, int width, int height);
double texelSolidAngle(int y, int width, int height);
// R_y(degrees) · d (counter-clockwise seen from +Y).
glm::dvec3 rotateAboutUp(const glm::dvec3& d, double degrees);

// The 9 real spherical-harmonic basis functions at a unit direction, bands 0..2 in the order
// Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22 (Ramamoorthi & Hanrahan's constants: 0.282095,
// 0.488603·(y, z, x), 1.092548·(xy, yz), 0.315392·(3z² − 1), 1.092548·xz, 0.546274·(x² − y²)).
std::array<double, 9> shBasis9(const glm::dvec3& d);

// The unit direction of a softbox's centre (azimuth, elevation in degrees).
glm::dvec3 softboxDirection(double azimuthDegrees, double elevationDegrees);
// The procedural studio as an equirectangular image `width` × width/2 (rotation 0, 0 EV).
EnvironmentImage renderStudio(const Studio& studio, int width = 1024);
// Rec. 709 luminance of linear RGB: 0.2126 R + 0.7152 G + 0.0722 B.
inline double luminance(const glm::vec3& c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}
// Which texels a spot dims: those whose centre is within spot.angle of spot.direction and whose radiance
// has a luminance of at least spot.threshold (nothing for a zero or non-finite direction).
class SpotCover {
  public:
    explicit SpotCover(const EnvironmentSpot& spot);
    bool covers(const glm::dvec3& texelDirection, const glm::vec3& radiance) const {
        const glm::dvec3& d = texelDirection;
        return m_valid && m_axis.x * d.x + m_axis.y * d.y + m_axis.z * d.z >= m_cosAngle &&
               luminance(radiance) >= m_threshold;
    }

  private:
    bool m_valid = false;
    glm::dvec3 m_axis{0.0};
    double m_cosAngle = 1.0, m_threshold = 0.0;
};
// Multiplies the radiance of every texel a spot covers (SpotCover) by spot.factor, for each spot in turn.
// Returns how many texels it tested: a few more than the spots' caps hold, in O(texels + spots × covered
// texels) time.
std::size_t applySpots(EnvironmentImage* image, const std::vector<EnvironmentSpot>& spots);

} // namespace environment
} // namespace lr
