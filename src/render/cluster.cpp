#include "cluster.h"

#include "core/fallofftraits.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lr::render {

LightBounds lightBounds(const lighting::ShadeLight<double>& l, double distanceScale) {
    LightBounds b;
    if (!traitsOf(l.type).boundable) return b;
    if (!(distanceScale > 0.0) || !std::isfinite(distanceScale)) return b;
    double range = 0.0;
    switch (falloffTraitsOf(l.falloff).range) {
    case RangeRule::None:
        return b;
    case RangeRule::Required:
        // zero for !(d < range): range <= 0 or NaN lights nothing
        if (std::isinf(l.range) && l.range > 0.0) return b;
        range = l.range > 0.0 ? l.range : 0.0;
        break;
    case RangeRule::Optional:
        // windowed by the range when range >= 0; unbounded below 0
        if (l.range < 0.0 || (std::isinf(l.range) && l.range > 0.0)) return b;
        range = l.range > 0.0 ? l.range : 0.0;
        break;
    }
    if (!std::isfinite(l.position.x) || !std::isfinite(l.position.y) || !std::isfinite(l.position.z))
        return b;
    const double r = range / distanceScale;
    if (!std::isfinite(r)) return b;
    b.bounded = true;
    b.center = l.position;
    // The GPU evaluates d * distanceScale in float from float positions: widen by far more than their
    // rounding so that a fragment the sphere test rejects has d * distanceScale >= range for certain.
    b.radius = r * (1.0 + 1e-3) + 1e-4 * (glm::length(l.position) + r) + 1e-30;
    return b;
}

int ClusterLookup::tile(double fragX, double fragY, int* tx, int* ty) const {
    *tx = std::clamp(int(std::floor(fragX * tileScale.x)), 0, grid.tilesX - 1);
    *ty = std::clamp(int(std::floor(fragY * tileScale.y)), 0, grid.tilesY - 1);
    return *ty * grid.tilesX + *tx;
}

int ClusterLookup::slice(double depth) const {
    if (!(depth > znear)) return 0;
    const double s = std::floor(std::log(depth / znear) * sliceScale);
    if (!(s < double(grid.slices - 1))) return grid.slices - 1;
    return std::max(0, int(s));
}

int ClusterLookup::index(const glm::dvec2& fragCoord, double depth) const {
    int tx = 0, ty = 0;
    return slice(depth) * grid.tilesX * grid.tilesY + tile(fragCoord.x, fragCoord.y, &tx, &ty);
}

ClusterLookup clusterLookup(const ClusterView& view, const ClusterGrid& grid) {
    ClusterLookup k;
    k.grid = grid;
    k.tileScale = {double(grid.tilesX) / std::max(1, view.width),
                   double(grid.tilesY) / std::max(1, view.height)};
    k.znear = view.znear > 0.0 ? view.znear : 1e-6;
    const double ratio = view.zfar > k.znear && std::isfinite(view.zfar) ? view.zfar / k.znear : 1e6;
    k.sliceScale = double(grid.slices) / std::log(std::max(ratio, 1.0 + 1e-9));
    return k;
}

namespace {
bool perspectiveForm(const glm::dmat4& P);
}

ClusterSpan sphereClusters(const glm::dvec3& c, double r, const ClusterView& view, const ClusterLookup& k) {
    const ClusterGrid& g = k.grid;
    ClusterSpan s;
    // Depth: one slice of slack on each side absorbs the shader's float log().
    s.z0 = std::max(0, k.slice(-c.z - r) - 1);
    s.z1 = std::min(g.slices - 1, k.slice(-c.z + r) + 1);
    s.x0 = 0, s.x1 = g.tilesX - 1, s.y0 = 0, s.y1 = g.tilesY - 1;
    double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
    const glm::dmat4& P = view.projection;
    if (perspectiveForm(P)) {
        // Perspective (possibly off-centre): ndc.x = P00 * x/(-z) - P20. The sphere's silhouette is bounded,
        // per axis, by the two lines through the eye tangent to its circle in that plane. A sphere reaching
        // the eye plane (depth <= r) has no bound on that side: the full screen (conservative).
        const double D = -c.z;
        if (!(D > r)) return s;
        const auto slopes = [&](double a, double* lo, double* hi) {
            const double root = r * std::sqrt(a * a + D * D - r * r), den = D * D - r * r;
            *lo = (a * D - root) / den;
            *hi = (a * D + root) / den;
        };
        double lo = 0, hi = 0;
        slopes(c.x, &lo, &hi);
        xmin = std::min(P[0][0] * lo, P[0][0] * hi) - P[2][0];
        xmax = std::max(P[0][0] * lo, P[0][0] * hi) - P[2][0];
        slopes(c.y, &lo, &hi);
        ymin = std::min(P[1][1] * lo, P[1][1] * hi) - P[2][1];
        ymax = std::max(P[1][1] * lo, P[1][1] * hi) - P[2][1];
    } else {
        // Any other projection: the sphere's bounding box, cut at the near plane (nothing nearer is drawn).
        // All its corners in front of the eye: the box's image is the hull of theirs, which holds the
        // sphere's.
        const double zCut = -k.znear * 0.999;
        if (c.z - r > zCut) return s; // wholly in front of the near plane: the full screen (conservative)
        const double zHi = std::min(c.z + r, zCut), zLo = c.z - r;
        for (int i = 0; i < 8; ++i) {
            const glm::dvec4 p((i & 1) ? c.x + r : c.x - r, (i & 2) ? c.y + r : c.y - r, (i & 4) ? zHi : zLo,
                               1.0);
            const glm::dvec4 clip = P * p;
            if (!(clip.w > 1e-300)) return s;
            xmin = std::min(xmin, clip.x / clip.w), xmax = std::max(xmax, clip.x / clip.w);
            ymin = std::min(ymin, clip.y / clip.w), ymax = std::max(ymax, clip.y / clip.w);
        }
    }
    if (!(std::isfinite(xmin) && std::isfinite(xmax) && std::isfinite(ymin) && std::isfinite(ymax))) return s;
    // NDC -> pixels, one pixel of slack (interpolated positions need not project to the pixel centre).
    const auto px = [&](double ndc, int size) { return (ndc * 0.5 + 0.5) * size; };
    const auto tileOf = [](double pixel, double scale, int n) {
        const double t = std::floor(pixel * scale);
        return t < 0.0 ? 0 : t > double(n - 1) ? n - 1 : int(t);
    };
    if (px(xmax, view.width) + 1.0 < 0.0 || px(xmin, view.width) - 1.0 > view.width ||
        px(ymax, view.height) + 1.0 < 0.0 || px(ymin, view.height) - 1.0 > view.height)
        return ClusterSpan{}; // off screen: no fragment can see it
    s.x0 = tileOf(px(xmin, view.width) - 1.0, k.tileScale.x, g.tilesX);
    s.x1 = tileOf(px(xmax, view.width) + 1.0, k.tileScale.x, g.tilesX);
    s.y0 = tileOf(px(ymin, view.height) - 1.0, k.tileScale.y, g.tilesY);
    s.y1 = tileOf(px(ymax, view.height) + 1.0, k.tileScale.y, g.tilesY);
    return s;
}

namespace {

// The view-space box around each cluster's frustum, widened by one pixel and one slice each way (the
// slack that absorbs the shader's float arithmetic). Needs a perspective projection (ndc = P00 x/(-z) - P20).
std::vector<std::pair<glm::dvec3, glm::dvec3>> clusterBoxes(const ClusterView& view, const ClusterLookup& k) {
    const ClusterGrid& g = k.grid;
    const glm::dmat4& P = view.projection;
    std::vector<std::pair<glm::dvec3, glm::dvec3>> boxes(size_t(g.count()));
    const double far = std::isfinite(view.zfar) && view.zfar > k.znear ? view.zfar * 1.01 : 1e300;
    for (int z = 0; z < g.slices; ++z) {
        const double lo = z - 1 <= 0 ? 0.0 : k.znear * std::exp(double(z - 1) / k.sliceScale);
        const double hi = z + 1 >= g.slices - 1 ? far : k.znear * std::exp(double(z + 2) / k.sliceScale);
        for (int y = 0; y < g.tilesY; ++y)
            for (int x = 0; x < g.tilesX; ++x) {
                const double nx0 = 2.0 * (x / k.tileScale.x - 1.0) / view.width - 1.0;
                const double nx1 = 2.0 * ((x + 1) / k.tileScale.x + 1.0) / view.width - 1.0;
                const double ny0 = 2.0 * (y / k.tileScale.y - 1.0) / view.height - 1.0;
                const double ny1 = 2.0 * ((y + 1) / k.tileScale.y + 1.0) / view.height - 1.0;
                glm::dvec3 bmin(std::numeric_limits<double>::infinity()), bmax(-bmin);
                for (double d : {lo, hi})
                    for (double nx : {nx0, nx1})
                        for (double ny : {ny0, ny1}) {
                            const glm::dvec3 p((nx + P[2][0]) / P[0][0] * d, (ny + P[2][1]) / P[1][1] * d,
                                               -d);
                            bmin = glm::min(bmin, p), bmax = glm::max(bmax, p);
                        }
                boxes[size_t((z * g.tilesY + y) * g.tilesX + x)] = {bmin, bmax};
            }
    }
    return boxes;
}

bool perspectiveForm(const glm::dmat4& P) {
    return P[0][3] == 0.0 && P[1][3] == 0.0 && P[2][3] == -1.0 && P[3][3] == 0.0 && P[1][0] == 0.0 &&
           P[0][1] == 0.0 && P[3][0] == 0.0 && P[3][1] == 0.0 && P[0][0] != 0.0 && P[1][1] != 0.0;
}

// Calls f(cluster id) for each cluster of the span whose (widened) box the sphere touches.
template <typename F>
void forEachCluster(const LightBounds& b, const ClusterSpan& span, const ClusterLookup& k,
                    const std::vector<std::pair<glm::dvec3, glm::dvec3>>& boxes, F&& f) {
    for (int z = span.z0; z <= span.z1; ++z)
        for (int y = span.y0; y <= span.y1; ++y)
            for (int x = span.x0; x <= span.x1; ++x) {
                const size_t c = size_t((z * k.grid.tilesY + y) * k.grid.tilesX + x);
                if (!boxes.empty()) {
                    const glm::dvec3 q = glm::clamp(b.center, boxes[c].first, boxes[c].second);
                    const glm::dvec3 e = q - b.center;
                    if (glm::dot(e, e) > b.radius * b.radius) continue;
                }
                f(c);
            }
}

} // namespace

ClusterData binLights(std::span<const LightBounds> lights, const ClusterView& view, const ClusterGrid& grid) {
    ClusterData d;
    d.grid = grid;
    d.lookup = clusterLookup(view, grid);
    const int n = grid.count();
    std::vector<ClusterSpan> spans(lights.size());
    std::vector<std::pair<glm::dvec3, glm::dvec3>> boxes;
    if (perspectiveForm(view.projection)) boxes = clusterBoxes(view, d.lookup);
    std::vector<std::uint32_t> counts(size_t(n), 0);
    for (size_t i = 0; i < lights.size(); ++i) {
        if (!lights[i].bounded) {
            d.indices.push_back(std::uint32_t(i));
            continue;
        }
        ++d.boundedCount;
        const ClusterSpan s = spans[i] = sphereClusters(lights[i].center, lights[i].radius, view, d.lookup);
        forEachCluster(lights[i], s, d.lookup, boxes, [&](size_t c) { ++counts[c]; });
    }
    d.globalCount = int(d.indices.size());
    d.ranges.resize(size_t(2 * n));
    std::uint32_t offset = std::uint32_t(d.globalCount);
    for (int c = 0; c < n; ++c) {
        d.ranges[size_t(2 * c)] = offset;
        d.ranges[size_t(2 * c + 1)] = 0;
        offset += counts[size_t(c)];
    }
    d.indices.resize(offset);
    for (size_t i = 0; i < lights.size(); ++i) { // ascending light order inside every cluster
        if (!lights[i].bounded) continue;
        forEachCluster(lights[i], spans[i], d.lookup, boxes, [&](size_t c) {
            d.indices[d.ranges[2 * c] + d.ranges[2 * c + 1]++] = std::uint32_t(i);
        });
    }
    return d;
}

ClusterGrid clusterGridFor(int width, int height, long long maxClusters) {
    const auto tiles = [](int pixels) {
        return std::clamp((std::max(pixels, 1) + kClusterTilePixels - 1) / kClusterTilePixels, 1,
                          kClusterMaxTiles);
    };
    ClusterGrid g;
    g.tilesX = tiles(width);
    g.tilesY = tiles(height);
    const long long most = std::max<long long>(maxClusters / g.slices, 1);
    if (static_cast<long long>(g.tilesX) * g.tilesY > most) {
        const double shrink = std::sqrt(double(most) / (double(g.tilesX) * g.tilesY));
        g.tilesX = std::max(1, int(std::floor(g.tilesX * shrink)));
        g.tilesY = std::max(1, int(std::floor(g.tilesY * shrink)));
    }
    return g;
}

} // namespace lr::render
