#include "envlight.h"

#include <QCoreApplication>
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

namespace lr {

namespace {
using environment::kPi;

QString tr(const char* text) {
    return QCoreApplication::translate("lr::EnvironmentLight", text);
}

double radians(double degrees) {
    return degrees * (kPi / 180.0);
}

double angleBetween(const glm::dvec3& a, const glm::dvec3& b) { // unit vectors; finite for any input
    return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
}

// The rows a cap of `radius` radians around the unit direction d (image frame) can touch.
std::pair<int, int> capRows(const glm::dvec3& d, double radius, int height) {
    const double lat = std::asin(std::clamp(d.y, -1.0, 1.0));
    const double top = std::min(kPi / 2.0, lat + radius), bottom = std::max(-kPi / 2.0, lat - radius);
    const int y0 = std::clamp(int(std::floor((0.5 - top / kPi) * height)) - 1, 0, height - 1);
    const int y1 = std::clamp(int(std::ceil((0.5 - bottom / kPi) * height)) + 1, 0, height - 1);
    return {y0, y1};
}

EnvironmentLight nothing(const QString& reason) {
    EnvironmentLight out;
    out.reason = reason;
    return out;
}
} // namespace

EnvironmentLight lightFromEnvironment(const EnvironmentImage& image, double rotationDegrees,
                                      double intensityEv, ShadingModel shading, const glm::dvec3& clicked,
                                      const EnvironmentLightOptions& options) {
    using namespace environment;
    if (image.isNull() || image.texels.size() != size_t(image.width) * size_t(image.height))
        return nothing(tr("nothing bright here: no environment is loaded"));
    const double length = glm::length(clicked);
    if (!std::isfinite(length) || length <= 0.0 || !std::isfinite(rotationDegrees) ||
        !std::isfinite(intensityEv))
        return nothing(tr("nothing bright here: not a direction"));
    // The image's own frame: it is looked up at R_y(−rotation) · d.
    const glm::dvec3 d = rotateAboutUp(clicked / length, -rotationDegrees);
    const int w = image.width, h = image.height;

    // The brightest texel around the click, and the neighbourhood's mean luminance (by solid angle).
    const double search = radians(std::clamp(options.searchDegrees, 0.1, 90.0));
    const double cosSearch = std::cos(search);
    int px = -1, py = -1;
    double peak = -1.0, peakDot = -2.0;
    const auto [sy0, sy1] = capRows(d, search, h);
    for (int y = sy0; y <= sy1; ++y) {
        for (int x = 0; x < w; ++x) {
            const double dot = glm::dot(texelDirection(x, y, w, h), d);
            if (dot < cosSearch) continue;
            const double l = luminance(image.at(x, y));
            if (l > peak || (l == peak && dot > peakDot)) { // ties (a uniform softbox): nearest the click
                peak = l;
                peakDot = dot;
                px = x;
                py = y;
            }
        }
    }
    if (px < 0) { // a search cap narrower than a texel: the texel under the click
        const glm::dvec2 uv = equirectUv(d);
        px = std::clamp(int(uv.x * w), 0, w - 1);
        py = std::clamp(int(uv.y * h), 0, h - 1);
        peak = luminance(image.at(px, py));
    }
    // The whole environment's mean luminance (by solid angle, 4π): a light stands out from it. (The
    // neighbourhood's own mean would count a large softbox against itself.)
    double mean = 0.0;
    for (int y = 0; y < h; ++y) {
        double row = 0.0;
        for (int x = 0; x < w; ++x)
            row += luminance(image.at(x, y));
        mean += row * texelSolidAngle(y, w, h);
    }
    mean /= 4.0 * kPi;
    if (!(peak > 0.0))
        return nothing(tr("nothing bright here: the environment is black around that direction"));
    if (peak < options.minContrast * mean)
        return nothing(tr("nothing bright here: the brightest point within %1° is only %2× the environment's "
                          "average (a light needs %3×)")
                           .arg(options.searchDegrees)
                           .arg(peak / mean, 0, 'f', 2)
                           .arg(options.minContrast));

    // The region: connected texels that stand out from the environment as the peak does (minContrast ×
    // the mean) and are at least spotFraction of the peak, within the cap around the peak. A light's
    // dimmer housing or falloff belongs to it (issue 41: on studio.exr a threshold of half the peak left
    // the panel's bright frame as a ring around the dimmed hole).
    const glm::dvec3 peakDir = texelDirection(px, py, w, h);
    const double cosCap = std::cos(radians(std::clamp(options.maxSpotDegrees, 0.1, 90.0)));
    const double threshold = std::min(
        peak, std::max(options.minContrast * mean, std::clamp(options.spotFraction, 0.0, 1.0) * peak));
    std::vector<unsigned char> seen(size_t(w) * size_t(h), 0);
    std::vector<std::pair<int, int>> stack{{px, py}}, region;
    seen[size_t(py) * size_t(w) + size_t(px)] = 1;
    while (!stack.empty()) {
        const auto [x, y] = stack.back();
        stack.pop_back();
        region.emplace_back(x, y);
        const std::pair<int, int> next[4] = {{(x + 1) % w, y}, {(x + w - 1) % w, y}, {x, y - 1}, {x, y + 1}};
        for (const auto& [nx, ny] : next) {
            if (ny < 0 || ny >= h) continue;
            unsigned char& s = seen[size_t(ny) * size_t(w) + size_t(nx)];
            if (s) continue;
            s = 1;
            if (luminance(image.at(nx, ny)) < threshold) continue;
            if (glm::dot(texelDirection(nx, ny, w, h), peakDir) < cosCap) continue;
            stack.emplace_back(nx, ny);
        }
    }

    // The dimmed spot: the cone around the region's luminance-weighted centroid that just holds the
    // region's texel centres, keyed to the region's threshold so that it dims the footprint and not the
    // sky around it (issue 41).
    glm::dvec3 centroid(0.0);
    for (const auto& [x, y] : region)
        centroid += luminance(image.at(x, y)) * texelSolidAngle(y, w, h) * texelDirection(x, y, w, h);
    const double centroidLength = glm::length(centroid);
    const glm::dvec3 towards = centroidLength > 0.0 ? centroid / centroidLength : peakDir;
    double radius = 0.0;
    for (const auto& [x, y] : region)
        radius = std::max(radius, angleBetween(towards, texelDirection(x, y, w, h)));
    EnvironmentSpot spot;
    spot.direction = towards;
    spot.angle = std::min(90.0, radius * (180.0 / kPi) + 1e-6); // a hair more: the centres are inside
    spot.factor = 0.0;
    spot.threshold = threshold;

    // The light is exactly what the spot removes: Σ L·Ω (per channel) over the texels it covers (the
    // region, and any texel as bright within its cone), and their luminance-weighted centroid.
    const SpotCover cover(spot);
    glm::dvec3 sum(0.0), lit(0.0);
    double omegaSum = 0.0;
    int texels = 0;
    const auto [ry0, ry1] = capRows(towards, radians(spot.angle) + kPi / h, h);
    for (int y = ry0; y <= ry1; ++y) {
        const double omega = texelSolidAngle(y, w, h);
        for (int x = 0; x < w; ++x) {
            const glm::dvec3 dir = texelDirection(x, y, w, h);
            if (!cover.covers(dir, image.at(x, y))) continue;
            const glm::dvec3 L(image.at(x, y));
            sum += L * omega;
            lit += luminance(image.at(x, y)) * omega * dir;
            omegaSum += omega;
            ++texels;
        }
    }
    const double litLength = glm::length(lit);
    const glm::dvec3 from = litLength > 0.0 ? lit / litLength : towards;

    const double scale = std::exp2(intensityEv);
    const double largest = std::max({sum.x, sum.y, sum.z});
    EnvironmentLight out;
    out.found = true;
    out.direction = -rotateAboutUp(from, rotationDegrees);
    out.color = sum / largest;
    out.intensity = largest * scale / (shading == ShadingModel::Classic ? kPi : 1.0);
    out.solidAngle = omegaSum;
    out.texels = texels;
    out.spot = spot;
    return out;
}

} // namespace lr
