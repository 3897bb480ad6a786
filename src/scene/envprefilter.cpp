// Prefiltering an environment (envprefilter.h): SH9 irradiance by exact quadrature over every texel;
// the irradiance map by direct quadrature over the pyramid's 128 × 64 level (its area-weighted
// downsampling keeps ∫ L dω; tst_envprefilter measures the difference to the full image); the GGX chain by
// filtered importance sampling (envprefilter_ggx.cpp). Each pass runs its rows on the global thread pool.
#include "envprefilter.h"

#include "envprefilter_detail.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace lr {

namespace envfilter {

using environment::kPi;

std::array<glm::vec3, 9> irradianceSH(const EnvironmentImage& src) {
    // Cosine-lobe convolution per band (Ramamoorthi & Hanrahan 2001): π, 2π/3, π/4.
    const double band[9] = {kPi,     2 * kPi / 3, 2 * kPi / 3, 2 * kPi / 3, kPi / 4,
                            kPi / 4, kPi / 4,     kPi / 4,     kPi / 4};
    std::vector<std::array<glm::dvec3, 9>> rows(size_t(src.height));
    std::vector<double> cosPhi(size_t(src.width)), sinPhi(size_t(src.width)); // texelDirection's azimuths
    for (int x = 0; x < src.width; ++x) {
        const glm::dvec3 d = environment::texelDirection(x, src.height / 2, src.width, src.height);
        const double r = std::hypot(d.x, d.z);
        cosPhi[size_t(x)] = d.x / r;
        sinPhi[size_t(x)] = d.z / r;
    }
    forEachRow(src.height, [&](int y) {
        const double omega = environment::texelSolidAngle(y, src.width, src.height);
        const glm::dvec3 d0 = environment::texelDirection(0, y, src.width, src.height);
        const double cosLat = std::hypot(d0.x, d0.z);
        std::array<glm::dvec3, 9> sum{};
        for (int x = 0; x < src.width; ++x) {
            const auto Y =
                environment::shBasis9({cosLat * cosPhi[size_t(x)], d0.y, cosLat * sinPhi[size_t(x)]});
            const glm::dvec3 L = glm::dvec3(src.at(x, y)) * omega;
            for (size_t i = 0; i < 9; ++i)
                sum[i] += L * Y[i];
        }
        rows[size_t(y)] = sum;
    });
    std::array<glm::dvec3, 9> total{};
    for (const auto& r : rows) // in order: the same result on every run
        for (size_t i = 0; i < 9; ++i)
            total[i] += r[i];
    std::array<glm::vec3, 9> sh{};
    for (size_t i = 0; i < 9; ++i)
        sh[i] = glm::vec3(total[i] * band[i]);
    return sh;
}

EnvironmentImage irradianceMap(const EnvironmentImage& src, int width) {
    return rowQuadrature(
        src, width, [](double c) { return c; }, false);
}

glm::dvec3 irradianceBruteForce(const EnvironmentImage& src, const glm::dvec3& n) {
    glm::dvec3 e(0.0);
    for (int y = 0; y < src.height; ++y) {
        const double omega = environment::texelSolidAngle(y, src.width, src.height);
        for (int x = 0; x < src.width; ++x)
            e += glm::dvec3(src.at(x, y)) *
                 (omega *
                  std::max(0.0, glm::dot(n, environment::texelDirection(x, y, src.width, src.height))));
    }
    return e;
}

} // namespace envfilter

PrefilteredEnvironment prefilterEnvironment(const EnvironmentImage& image) {
    QElapsedTimer timer;
    timer.start();
    PrefilteredEnvironment p;
    if (image.isNull()) return p;
    p.sh = envfilter::irradianceSH(image);
    p.specular.push_back(envfilter::resample(image, kSpecularBaseWidth));
    const std::vector<EnvironmentImage> mips = envfilter::pyramid(p.specular[0], 4);
    // The irradiance map's source: the first level at most 128 wide (2.8° texels; the cosine lobe is 180°).
    const auto source =
        std::find_if(mips.begin(), mips.end(), [](const EnvironmentImage& m) { return m.width <= 128; });
    p.irradiance = envfilter::irradianceMap(source == mips.end() ? mips.back() : *source, kIrradianceWidth);
    for (int k = 1; k < kSpecularLevels; ++k) {
        const double roughness = double(k) / (kSpecularLevels - 1);
        const int quadrature = envfilter::ggxQuadratureWidth(roughness);
        const auto coarse = std::find_if(mips.begin(), mips.end(), [quadrature](const EnvironmentImage& m) {
            return m.width <= quadrature;
        });
        p.specular.push_back(quadrature > 0 && coarse != mips.end()
                                 ? envfilter::ggxLevelQuadrature(*coarse, kSpecularBaseWidth >> k, roughness)
                                 : envfilter::ggxLevel(mips, kSpecularBaseWidth >> k, roughness,
                                                       envfilter::ggxSamples(roughness)));
    }
    p.seconds = double(timer.nsecsElapsed()) * 1e-9;
    return p;
}

} // namespace lr
