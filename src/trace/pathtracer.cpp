#include "pathtracer.h"

#include "core/colour.h"
#include "core/envintegrate.h"
#include "core/lighting.h"

#include <QThread>
#include <QtConcurrent/QtConcurrentMap>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace lr::trace {

PathTracer::PathTracer(std::shared_ptr<const TraceScene> scene, const ViewCamera& camera, QSize size,
                       TraceSettings settings, int threads)
    : m_scene(std::move(scene)), m_camera(camera, size), m_size(size), m_settings(settings),
      m_forward(camera.forward()) {
    m_pool.setMaxThreadCount(threads > 0 ? threads : std::max(1, QThread::idealThreadCount()));
    const size_t pixels = size_t(std::max(0, size.width())) * size_t(std::max(0, size.height()));
    m_sum.assign(pixels, glm::dvec4(0.0));
    m_count.assign(pixels, 0);
    m_luminance.assign(pixels, glm::dvec2(0.0));
    m_tilesX = (std::max(0, size.width()) + kTileSize - 1) / kTileSize;
    m_tilesY = (std::max(0, size.height()) + kTileSize - 1) / kTileSize;
}

PathTracer::~PathTracer() {
    cancel();
    m_pool.waitForDone();
}

void PathTracer::restart() {
    std::fill(m_sum.begin(), m_sum.end(), glm::dvec4(0.0));
    std::fill(m_count.begin(), m_count.end(), 0);
    std::fill(m_luminance.begin(), m_luminance.end(), glm::dvec2(0.0));
    std::fill(m_groupSum.begin(), m_groupSum.end(), glm::dvec3(0.0));
    std::fill(m_layerSum.begin(), m_layerSum.end(), PixelLayerSums{});
    m_nonFinite.store(0);
    m_cancel.store(false);
}

void PathTracer::setLayers(bool on) {
    if (on == m_layers) return;
    m_layers = on;
    const size_t pixels = m_count.size(), groups = on ? m_scene->groups().size() : 0;
    std::vector<glm::dvec3>(pixels * groups).swap(m_groupSum);
    std::vector<PixelLayerSums>(on ? pixels : 0).swap(m_layerSum);
    restart();
}

std::size_t PathTracer::bytes() const {
    return m_sum.capacity() * sizeof(glm::dvec4) + m_count.capacity() * sizeof(int) +
           m_luminance.capacity() * sizeof(glm::dvec2) + m_groupSum.capacity() * sizeof(glm::dvec3) +
           m_layerSum.capacity() * sizeof(PixelLayerSums);
}

int PathTracer::samplesDone() const {
    return m_count.empty() ? 0 : *std::min_element(m_count.begin(), m_count.end());
}

double PathTracer::noiseEstimate() const {
    if (m_count.empty()) return 0.0;
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    double variance = 0.0, mean = 0.0; // sums over pixels: variance of the mean, mean
    for (size_t i = 0; i < m_count.size(); ++i) {
        const double n = double(m_count[i]);
        if (n < 2.0) return kInfinity;
        variance += std::max(0.0, m_luminance[i].y) / ((n - 1.0) * n);
        mean += m_luminance[i].x;
    }
    if (!(variance > 0.0)) return variance == 0.0 ? 0.0 : kInfinity; // 0, or a NaN from a bad sample
    if (!(mean > 0.0) || !std::isfinite(variance)) return kInfinity;
    const double result = std::sqrt(variance / double(m_count.size())) / (mean / double(m_count.size()));
    return std::isfinite(result) ? result : kInfinity;
}

void PathTracer::renderTile(int tile, int samples) {
    const int x0 = (tile % m_tilesX) * kTileSize, y0 = (tile / m_tilesX) * kTileSize;
    const int x1 = std::min(x0 + kTileSize, m_size.width()), y1 = std::min(y0 + kTileSize, m_size.height());
    std::int64_t nonFinite = 0;
    std::vector<glm::dvec3> groups(m_layers ? m_scene->groups().size() : 0);
    PathSplit split;
    split.groups = groups.data();
    PathSplit* const splitOrNull = m_layers ? &split : nullptr;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const size_t p = size_t(y) * size_t(m_size.width()) + size_t(x);
            glm::dvec4 sum = m_sum[p];
            glm::dvec2 lum = m_luminance[p]; // running mean, sum of squared deviations
            for (int k = 0; k < samples; ++k) {
                Sampler sampler(std::uint32_t(p), std::uint32_t(m_count[p] + k), m_settings.seed);
                const glm::dvec2 j = m_settings.jitter ? sampler.next2() : glm::dvec2(0.5);
                const glm::dvec3 dir = m_camera.direction(x + j.x, y + j.y);
                const PathSample s =
                    tracePath(*m_scene, m_camera.origin(), dir, sampler, m_settings, splitOrNull);
                nonFinite += s.finite ? 0 : 1;
                if (splitOrNull) addLayers(p, dir, split);
                sum += glm::dvec4(s.radiance, s.alpha);
                const double l = envintegrate::luminance(s.radiance);
                const double delta = l - lum.x;
                lum.x += delta / double(m_count[p] + k + 1);
                lum.y += delta * (l - lum.x);
            }
            m_sum[p] = sum;
            m_luminance[p] = lum;
            m_count[p] += samples;
        }
    m_nonFinite += nonFinite;
}

void PathTracer::addLayers(std::size_t pixel, const glm::dvec3& dir, const PathSplit& split) {
    const size_t n = m_scene->groups().size();
    glm::dvec3* sum = m_groupSum.data() + pixel * n;
    for (size_t g = 0; g < n; ++g)
        sum[g] += split.groups[g];
    if (!split.hit) return;
    PixelLayerSums& l = m_layerSum[pixel];
    l.albedo += split.albedo;
    l.normal += split.normal;
    l.depth += split.distance * glm::dot(dir, m_forward);
    ++l.hits;
}

bool PathTracer::render(int samples) {
    if (samples <= 0 || m_sum.empty()) return !m_cancel.load();
    std::vector<int> tiles(size_t(m_tilesX) * size_t(m_tilesY));
    std::iota(tiles.begin(), tiles.end(), 0);
    QtConcurrent::blockingMap(&m_pool, tiles, [this, samples](int tile) {
        if (!m_cancel.load(std::memory_order_relaxed)) renderTile(tile, samples);
    });
    return !m_cancel.load();
}

FloatImage PathTracer::image() const {
    FloatImage out;
    out.width = m_size.width();
    out.height = m_size.height();
    out.pixels.resize(m_sum.size());
    for (size_t i = 0; i < m_sum.size(); ++i)
        out.pixels[i] = m_count[i] > 0 ? glm::vec4(m_sum[i] / double(m_count[i])) : glm::vec4(0.0f);
    return out;
}

RenderLayers PathTracer::layers() const {
    RenderLayers out;
    out.beauty = image();
    if (!m_layers) return out;
    out.groups = m_scene->groups();
    const size_t pixels = m_count.size(), n = out.groups.size();
    const auto blank = [&] {
        FloatImage f;
        f.width = m_size.width();
        f.height = m_size.height();
        f.pixels.resize(pixels);
        return f;
    };
    out.groupImages.assign(n, blank());
    out.albedo = out.normal = out.depth = blank();
    for (size_t i = 0; i < pixels; ++i) {
        const double count = double(m_count[i]);
        const float alpha = out.beauty.pixels[i].w;
        const auto mean = [&](const glm::dvec3& sum, double over) {
            return over > 0.0 ? glm::vec4(glm::vec3(sum / over), alpha) : glm::vec4(0.0f, 0.0f, 0.0f, alpha);
        };
        for (size_t g = 0; g < n; ++g)
            out.groupImages[g].pixels[i] = mean(m_groupSum[i * n + g], count);
        const PixelLayerSums& l = m_layerSum[i];
        out.albedo.pixels[i] = mean(l.albedo, count);
        out.normal.pixels[i] = mean(l.normal, count);
        const float depth = l.hits > 0 ? float(l.depth / double(l.hits)) : kBackgroundDepth;
        out.depth.pixels[i] = glm::vec4(depth, depth, depth, alpha);
    }
    return out;
}

QImage PathTracer::display(double exposureEV, ToneMap toneMap) const {
    QImage out(m_size, QImage::Format_RGBA8888);
    if (out.isNull()) return out;
    const FloatImage img = image();
    const double scale = colour::exposureScale(exposureEV);
    for (int y = 0; y < m_size.height(); ++y) {
        uchar* row = out.scanLine(y);
        for (int x = 0; x < m_size.width(); ++x) {
            const glm::vec4& p = img.at(x, y);
            const double alpha = m_settings.transparent ? lighting::saturate(double(p.a)) : 1.0;
            glm::dvec3 rgb(p);
            if (m_settings.transparent && alpha > 0.0) rgb /= alpha; // the covered share's own colour
            const glm::dvec3 c = colour::displayColour(rgb, scale, toneMap);
            for (int k = 0; k < 3; ++k)
                row[4 * x + k] = uchar(std::lround(lighting::saturate(c[k]) * 255.0));
            row[4 * x + 3] = uchar(std::lround(alpha * 255.0));
        }
    }
    return out;
}

} // namespace lr::trace
