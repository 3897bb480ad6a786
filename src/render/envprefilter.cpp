#include "envprefilter.h"

#include <QElapsedTimer>
#include <algorithm>
#include <glm/common.hpp>

namespace lr {

namespace {

EnvironmentImage boxDownsample(const EnvironmentImage& src, int width) {
    EnvironmentImage out;
    out.width = width;
    out.height = std::max(width / 2, 1);
    out.texels.assign(size_t(out.width) * size_t(out.height), glm::vec3(0.0f));
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const int sx = std::min(src.width - 1, int((x + 0.5) * src.width / out.width));
            const int sy = std::min(src.height - 1, int((y + 0.5) * src.height / out.height));
            out.at(x, y) = src.at(sx, sy);
        }
    return out;
}

} // namespace

// PLACEHOLDER (issue 15 integration): SH9 by quadrature; the specular chain is point-sampled, not yet
// GGX-convolved. Replaced by the real prefilter before issue 15 lands.
PrefilteredEnvironment prefilterEnvironment(const EnvironmentImage& image) {
    QElapsedTimer timer;
    timer.start();
    PrefilteredEnvironment p;
    if (image.isNull()) return p;
    // Cosine-lobe convolution per band (Ramamoorthi & Hanrahan): π, 2π/3, π/4.
    const double band[9] = {environment::kPi,
                            2.0 * environment::kPi / 3.0,
                            2.0 * environment::kPi / 3.0,
                            2.0 * environment::kPi / 3.0,
                            environment::kPi / 4.0,
                            environment::kPi / 4.0,
                            environment::kPi / 4.0,
                            environment::kPi / 4.0,
                            environment::kPi / 4.0};
    std::array<glm::dvec3, 9> sum{};
    for (int y = 0; y < image.height; ++y) {
        const double dw = environment::texelSolidAngle(y, image.width, image.height);
        for (int x = 0; x < image.width; ++x) {
            const auto Y =
                environment::shBasis9(environment::texelDirection(x, y, image.width, image.height));
            const glm::dvec3 L(image.at(x, y));
            for (int i = 0; i < 9; ++i)
                sum[size_t(i)] += L * (Y[size_t(i)] * dw);
        }
    }
    for (int i = 0; i < 9; ++i)
        p.sh[size_t(i)] = glm::vec3(sum[size_t(i)] * band[i]);
    p.irradiance.width = kIrradianceWidth;
    p.irradiance.height = kIrradianceWidth / 2;
    p.irradiance.texels.resize(size_t(p.irradiance.width) * size_t(p.irradiance.height));
    for (int y = 0; y < p.irradiance.height; ++y)
        for (int x = 0; x < p.irradiance.width; ++x) {
            const auto Y = environment::shBasis9(
                environment::texelDirection(x, y, p.irradiance.width, p.irradiance.height));
            glm::dvec3 e(0.0);
            for (int i = 0; i < 9; ++i)
                e += glm::dvec3(p.sh[size_t(i)]) * Y[size_t(i)];
            p.irradiance.at(x, y) = glm::vec3(glm::max(e, glm::dvec3(0.0)));
        }
    for (int k = 0; k < kSpecularLevels; ++k)
        p.specular.push_back(boxDownsample(image, kSpecularBaseWidth >> k));
    p.seconds = timer.nsecsElapsed() * 1e-9;
    return p;
}

} // namespace lr
