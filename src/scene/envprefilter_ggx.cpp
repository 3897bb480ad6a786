// The split-sum specular chain (envprefilter_detail.h): the radiance convolved with the GGX lobe, N = V = R,
// weights D·(n·l) (Karis 2013, "Real Shading in Unreal Engine 4"). Two ways, chosen per roughness
// (ggxQuadratureWidth): exact quadrature over a 64 × 32 level of the pyramid for the wide lobes, and for
// the narrow one importance sampling with one fixed Hammersley set and filtered importance sampling
// (Colbert & Křivánek, GPU Gems 3 ch. 20): each sample reads the pyramid at the level whose texels cover
// its share of the lobe's solid angle, Ωs = 1/(N·pdf). Both use that the texels of one row differ only by
// a turn about +Y: the work that depends on latitude is done once a row.
#include "envprefilter_detail.h"

#include "core/lowdiscrepancy.h"

#include <QtGlobal>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>

namespace lr::envfilter {

namespace {

using environment::kPi;

struct LobeSample {
    float x, y, z; // l in the frame of n (z = n·l > 0)
    float lod;     // the pyramid level at the equator (+ the latitude term at lookup)
};

std::vector<LobeSample> lobeSamples(double roughness, int count, int baseWidth, int baseHeight) {
    const double a2 = std::pow(roughness, 4.0);                               // α = r²
    const double omegaP = 2.0 * kPi * kPi / (double(baseWidth) * baseHeight); // a base texel at the equator
    std::vector<LobeSample> out;
    for (int i = 0; i < count; ++i) {
        const double xi1 = (i + 0.5) / count, xi2 = radicalInverse2(std::uint32_t(i));
        const double cos2h = (1.0 - xi1) / (1.0 + (a2 - 1.0) * xi1);
        const double cosh = std::sqrt(cos2h), sinh = std::sqrt(std::max(0.0, 1.0 - cos2h));
        const double nl = 2.0 * cos2h - 1.0;
        if (nl <= 0.0) continue;
        const double phi = 2.0 * kPi * xi2;
        const double pdf = ggxD(a2, cos2h) / 4.0; // of l: D (n·h) / (4 v·h), v·h = n·h
        const double omegaS = 1.0 / (count * pdf);
        // No +1 bias (GPU Gems 3 adds one): measured at roughness 0.2 with 48 samples, rms 2.6 % without it,
        // 4.9 % with it (it blurs).
        const double lod = 0.5 * std::log2(omegaS / omegaP);
        out.push_back({float(2.0 * cosh * sinh * std::cos(phi)), float(2.0 * cosh * sinh * std::sin(phi)),
                       float(nl), float(lod)});
    }
    return out;
}

} // namespace

int ggxQuadratureWidth(double roughness) {
    // Measured (tst_envprefilter, a 512 × 256 sky with Gaussian lights): quadrature over 64 × 32 is within
    // 0.2 % rms of the brute force from roughness 0.4 on (0.05 % over 128 × 64, at twice the time), where
    // 64 filtered samples were off by 2.8 to 8 % rms. At roughness 0.2 the lobe's tails reach across the
    // hemisphere at a fine resolution, so quadrature would cost billions of terms: sampling stays.
    return roughness >= 0.3 ? 64 : 0;
}

int ggxSamples(double roughness) {
    return roughness < 0.3 ? 48 : 64;
}

EnvironmentImage ggxLevel(const std::vector<EnvironmentImage>& mips, int width, double roughness,
                          int samples) {
    const std::vector<LobeSample> lobe = lobeSamples(roughness, samples, mips[0].width, mips[0].height);
    Q_ASSERT(std::all_of(mips.begin(), mips.end(), [](const EnvironmentImage& m) {
        return m.width > 0 && (m.width & (m.width - 1)) == 0;
    }));
    float weightSum = 0.0f;
    for (const LobeSample& s : lobe)
        weightSum += s.z;
    EnvironmentImage out;
    out.width = width;
    out.height = width / 2;
    out.texels.assign(size_t(out.width) * size_t(out.height), glm::vec3(0.0f));
    if (lobe.empty() || !(weightSum > 0.0f)) return out;
    const float inv2Pi = float(0.5 / kPi), invPi = float(1.0 / kPi), maxLod = float(mips.size() - 1);
    // The texels of one row differ only by a turn about +Y, so the lobe's samples are placed once a row
    // (for its first texel, frame of Duff et al. 2017) and then shifted along the row: the latitude, mip
    // level and vertical weights of each tap are the same along it; only the column moves.
    struct Tap {
        const EnvironmentImage* image;
        int y0, y1;
        float ay, x0, step, weight; // column of texel 0 (texel units − 0.5), per output texel, weight
    };
    forEachRow(out.height, [&](int y) {
        const glm::vec3 n(environment::texelDirection(0, y, out.width, out.height));
        const float sign = std::copysign(1.0f, n.z), a = -1.0f / (sign + n.z), b = n.x * n.y * a;
        const glm::vec3 t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
        const glm::vec3 bt(b, sign + n.y * n.y * a, -n.y);
        std::vector<Tap> taps;
        taps.reserve(lobe.size() * 2);
        for (const LobeSample& s : lobe) {
            const glm::vec3 l = t * s.x + bt * s.y + n * s.z;
            const float ly = std::clamp(l.y, -1.0f, 1.0f);
            const float u = std::atan2(l.z, l.x) * inv2Pi + 0.5f, v = 0.5f - std::asin(ly) * invPi;
            const float cosLat = std::sqrt(std::max(1.0f - ly * ly, 1e-6f));
            const float lod = std::clamp(s.lod - 0.5f * std::log2(cosLat), 0.0f, maxLod);
            const int l0 = int(lod);
            const float f = lod - float(l0);
            for (int level = l0; level <= std::min(l0 + 1, int(maxLod)); ++level) {
                const float w = s.z * (level == l0 ? 1.0f - f : f) / weightSum;
                if (w <= 0.0f) continue;
                const EnvironmentImage& img = mips[size_t(level)];
                const float py = v * float(img.height) - 0.5f, fy = std::floor(py);
                taps.push_back({&img, std::clamp(int(fy), 0, img.height - 1),
                                std::clamp(int(fy) + 1, 0, img.height - 1), py - fy,
                                u * float(img.width) - 0.5f, float(img.width) / float(out.width), w});
            }
        }
        // Tap by tap along the row, each texel summing the taps in the same order: a tap's row pointers
        // and vertical weights hold along the row, and the pyramid's widths are powers of 2, so a column
        // wraps by a mask (no branch in the loop).
        glm::vec3* row = &out.texels[size_t(y) * size_t(out.width)]; // zeros so far
        for (const Tap& tap : taps) {
            const int w = tap.image->width, mask = w - 1;
            const glm::vec3* r0 = &tap.image->texels[size_t(tap.y0) * size_t(w)];
            const glm::vec3* r1 = &tap.image->texels[size_t(tap.y1) * size_t(w)];
            const float w0 = (1.0f - tap.ay) * tap.weight, w1 = tap.ay * tap.weight;
            for (int x = 0; x < out.width; ++x) {
                const float px = tap.x0 + float(x) * tap.step, fx = std::floor(px), ax = px - fx;
                const int c0 = int(fx) & mask, c1 = (c0 + 1) & mask;
                row[x] +=
                    (r0[c0] * (1.0f - ax) + r0[c1] * ax) * w0 + (r1[c0] * (1.0f - ax) + r1[c1] * ax) * w1;
            }
        }
    });
    return out;
}

EnvironmentImage rowQuadrature(const EnvironmentImage& src, int width,
                               const std::function<double(double)>& kernel, bool normalise) {
    EnvironmentImage out;
    out.width = width;
    out.height = width / 2;
    out.texels.assign(size_t(out.width) * size_t(out.height), glm::vec3(0.0f));
    // Output texel x = phase + phases·m sees the source turned by m·step columns (both widths powers of 2).
    const int phases = std::max(1, width / src.width), step = std::max(1, src.width / width);
    const int mask = src.width - 1;
    struct Weight {
        int offset; // row × width + column in the source
        float w;
    };
    // Every source texel's direction and solid angle, once (they cost a sine and cosine each).
    std::vector<glm::dvec3> directions(src.texels.size());
    std::vector<double> omegas(size_t(src.height));
    for (int j = 0; j < src.height; ++j) {
        omegas[size_t(j)] = environment::texelSolidAngle(j, src.width, src.height);
        for (int i = 0; i < src.width; ++i)
            directions[size_t(j * src.width + i)] = environment::texelDirection(i, j, src.width, src.height);
    }
    forEachRow(out.height, [&](int y) {
        std::vector<Weight> weights;
        for (int phase = 0; phase < phases; ++phase) {
            const glm::dvec3 n = environment::texelDirection(phase, y, out.width, out.height);
            weights.clear();
            double total = 0.0, peak = 0.0;
            for (int j = 0; j < src.height; ++j) {
                const double omega = omegas[size_t(j)];
                for (int i = 0; i < src.width; ++i) {
                    const double c = glm::dot(n, directions[size_t(j * src.width + i)]);
                    if (c <= 0.0) continue;
                    const double w = omega * kernel(c);
                    weights.push_back({j * src.width + i, float(w)});
                    total += w;
                    peak = std::max(peak, w);
                }
            }
            if (normalise) {
                // Drop what cannot show (below 1e-7 of the peak), then normalise what is left.
                std::erase_if(weights, [peak](const Weight& w) { return double(w.w) < 1e-7 * peak; });
                for (Weight& w : weights)
                    w.w = float(double(w.w) / total);
            }
            for (int x = phase; x < out.width; x += phases) {
                const int shift = (x / phases) * step;
                glm::vec3 sum(0.0f);
                for (const Weight& w : weights) {
                    const int row = w.offset & ~mask, column = ((w.offset & mask) + shift) & mask;
                    sum += src.texels[size_t(row + column)] * w.w;
                }
                out.at(x, y) = sum;
            }
        }
    });
    return out;
}

EnvironmentImage ggxLevelQuadrature(const EnvironmentImage& src, int width, double roughness) {
    const double a2 = std::pow(roughness, 4.0);
    return rowQuadrature(
        src, width, [a2](double c) { return ggxD(a2, (1.0 + c) / 2.0) * c; }, true);
}

glm::dvec3 ggxBruteForce(const EnvironmentImage& src, const glm::dvec3& n, double roughness) {
    const double a2 = std::pow(roughness, 4.0);
    glm::dvec3 sum(0.0);
    double weights = 0.0;
    for (int y = 0; y < src.height; ++y) {
        const double omega = environment::texelSolidAngle(y, src.width, src.height);
        for (int x = 0; x < src.width; ++x) {
            const double c = glm::dot(n, environment::texelDirection(x, y, src.width, src.height));
            if (c <= 0.0) continue;
            const double w = omega * ggxD(a2, (1.0 + c) / 2.0) * c;
            sum += glm::dvec3(src.at(x, y)) * w;
            weights += w;
        }
    }
    return weights > 0.0 ? sum / weights : glm::dvec3(0.0);
}

} // namespace lr::envfilter
