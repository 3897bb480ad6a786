#include "envintegrate.h"

#include "colour.h"
#include "montecarlo.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <queue>

namespace lr::envintegrate {

namespace {

using V = glm::dvec3;
constexpr double kPi = environment::kPi;
constexpr int kMaxSubcellDepth = 6; // texels split down to 64 × 64 sub-cells where the horizon crosses them
// The lobe window (envintegrate.h, "Window"): its cone spans this many lobe scales (GGX: 2·atan(α), where
// 2·atan(4α) holds 94 % of the half-vectors), only below kMaxWindowAngle (~69°: at most ~100,000 texels of
// a 1024 × 512 image, a few ms), its cells at most kMaxWindowSubdivide² per texel.
constexpr double kWindowLobes = 4.0;
constexpr double kMaxWindowAngle = 1.2;
constexpr int kMaxWindowSubdivide = 16;

// A lat-long rectangle of the sphere: latitude in [latLo, latHi], azimuth φ in [phi0, phi1] (the
// equirect mapping's: φ = (u − 1/2)·2π, latitude = (1/2 − v)·π).
struct Cell {
    double latLo, latHi, phi0, phi1;
};

V directionOf(double lat, double phi) {
    return {std::cos(lat) * std::cos(phi), std::sin(lat), std::cos(lat) * std::sin(phi)};
}

Cell texelCell(int x, int y, int w, int h) {
    return {(0.5 - double(y + 1) / h) * kPi, (0.5 - double(y) / h) * kPi, (double(x) / w - 0.5) * 2.0 * kPi,
            (double(x + 1) / w - 0.5) * 2.0 * kPi};
}

double solidAngle(const Cell& c) {
    return (c.phi1 - c.phi0) * (std::sin(c.latHi) - std::sin(c.latLo));
}

// ∫ ω dΩ over the cell, dΩ = cos(lat) dlat dφ.
V firstMoment(const Cell& c) {
    const auto F = [](double l) { return l / 2.0 + std::sin(2.0 * l) / 4.0; }; // ∫ cos²
    const double cc = F(c.latHi) - F(c.latLo);
    const double s1 = std::sin(c.latHi), s0 = std::sin(c.latLo);
    const double sc = (s1 * s1 - s0 * s0) / 2.0; // ∫ sin·cos
    return {cc * (std::sin(c.phi1) - std::sin(c.phi0)), sc * (c.phi1 - c.phi0),
            cc * (std::cos(c.phi0) - std::cos(c.phi1))};
}

// ∫ ω ωᵀ dΩ over the cell: xx, yy, zz, xy, yz, xz.
std::array<double, 6> secondMoment(const Cell& c) {
    const auto at = [&](auto f) { return f(c.latHi) - f(c.latLo); };
    const double c3 = at([](double l) { return std::sin(l) - std::pow(std::sin(l), 3) / 3.0; });
    const double sc2 = at([](double l) { return -std::pow(std::cos(l), 3) / 3.0; });
    const double s2c = at([](double l) { return std::pow(std::sin(l), 3) / 3.0; });
    const auto az = [&](auto f) { return f(c.phi1) - f(c.phi0); };
    const double icc = az([](double p) { return p / 2.0 + std::sin(2.0 * p) / 4.0; });
    const double iss = az([](double p) { return p / 2.0 - std::sin(2.0 * p) / 4.0; });
    const double isc = az([](double p) { return std::sin(p) * std::sin(p) / 2.0; });
    const double ic = az([](double p) { return std::sin(p); });
    const double is = az([](double p) { return -std::cos(p); });
    return {c3 * icc, s2c * (c.phi1 - c.phi0), c3 * iss, sc2 * ic, sc2 * is, c3 * isc};
}

// The cell's centre direction and the largest angle β from it to any point of the cell (its corners
// while the cell spans at most half the azimuths; the whole sphere beyond).
struct Cone {
    V axis;
    double cosBeta, sinBeta;
};
Cone coneOf(const Cell& c) {
    Cone k;
    k.axis = directionOf(0.5 * (c.latLo + c.latHi), 0.5 * (c.phi0 + c.phi1));
    if (c.phi1 - c.phi0 > kPi + 1e-12) return {k.axis, -1.0, 0.0};
    double beta = 0.0;
    for (double lat : {c.latLo, c.latHi})
        for (double phi : {c.phi0, c.phi1})
            beta = std::max(beta, lighting::safeAcos(glm::dot(k.axis, directionOf(lat, phi))));
    beta = std::min(beta * (1.0 + 1e-9) + 1e-12, kPi);
    k.cosBeta = std::cos(beta), k.sinBeta = std::sin(beta);
    return k;
}

using montecarlo::reflectAbout;
using montecarlo::Rng;

double maxOf(const V& v) {
    return std::max({v.x, v.y, v.z});
}

} // namespace

// The largest channel's change, in 8-bit levels, of the display value when x moves by ±e.
double displayErrorLevels(const V& x, const V& e, const Convergence& c) {
    const double scale = colour::exposureScale(c.exposureEV);
    const V d0 = colour::displayColour(x, scale, c.toneMap);
    const V up = colour::displayColour(x + e, scale, c.toneMap);
    const V down = colour::displayColour(glm::max(x - e, V(0.0)), scale, c.toneMap);
    return 255.0 * std::max(maxOf(glm::abs(up - d0)), maxOf(glm::abs(d0 - down)));
}

struct EnvironmentField::Item {
    int level; // >= 1 a stored node, 0 a texel, -1 a sub-texel cell
    int ix, iy;
    int depth;
    Cell cell;
    V radiance;
};

EnvironmentField::EnvironmentField(std::shared_ptr<const EnvironmentImage> image, double intensityEV,
                                   double rotationDegrees, DiffuseModel classicDiffuse)
    : m_image(std::move(image)), m_scale(std::exp2(std::clamp(intensityEV, -60.0, 60.0))),
      m_rotation(rotationDegrees), m_diffuse(classicDiffuse) {
    if (!m_image || m_image->isNull()) {
        static const auto kBlack = std::make_shared<const EnvironmentImage>(EnvironmentImage{2, 1, {{}, {}}});
        m_image = kBlack;
    }
    const int w = m_width = m_image->width, h = m_height = m_image->height;
    m_rowSolidAngle.resize(size_t(h));
    m_rowCc.resize(size_t(h)), m_rowSc.resize(size_t(h));
    m_rowCosBeta.resize(size_t(h)), m_rowSinBeta.resize(size_t(h));
    m_rowCosLat.resize(size_t(h)), m_rowSinLat.resize(size_t(h));
    for (int y = 0; y < h; ++y) {
        const Cell c = texelCell(0, y, w, h);
        m_rowSolidAngle[size_t(y)] = environment::texelSolidAngle(y, w, h);
        const V m = firstMoment({c.latLo, c.latHi, 0.0, 1.0}); // x: dsin, y: Sc·1
        const auto F = [](double l) { return l / 2.0 + std::sin(2.0 * l) / 4.0; };
        m_rowCc[size_t(y)] = F(c.latHi) - F(c.latLo);
        m_rowSc[size_t(y)] = m.y;
        const Cone k = coneOf(c);
        m_rowCosBeta[size_t(y)] = k.cosBeta, m_rowSinBeta[size_t(y)] = k.sinBeta;
        const double lat = 0.5 * (c.latLo + c.latHi);
        m_rowCosLat[size_t(y)] = std::cos(lat), m_rowSinLat[size_t(y)] = std::sin(lat);
    }
    m_colDSin.resize(size_t(w)), m_colDCos.resize(size_t(w)), m_colCos.resize(size_t(w)),
        m_colSin.resize(size_t(w));
    for (int x = 0; x < w; ++x) {
        const Cell c = texelCell(x, 0, w, h);
        m_colDSin[size_t(x)] = std::sin(c.phi1) - std::sin(c.phi0);
        m_colDCos[size_t(x)] = std::cos(c.phi0) - std::cos(c.phi1);
        const double phi = 0.5 * (c.phi0 + c.phi1);
        m_colCos[size_t(x)] = std::cos(phi), m_colSin[size_t(x)] = std::sin(phi);
    }

    // Whole-sphere moments and the luminance distribution.
    m_rowCdf.assign(size_t(h), 0.0);
    m_colCdf.assign(size_t(w) * size_t(h), 0.0);
    double rows = 0.0;
    for (int y = 0; y < h; ++y) {
        double row = 0.0;
        for (int x = 0; x < w; ++x) {
            const V L = texel(x, y);
            const Cell c = texelCell(x, y, w, h);
            const double omega = m_rowSolidAngle[size_t(y)];
            const V m(m_rowCc[size_t(y)] * m_colDSin[size_t(x)], m_rowSc[size_t(y)] * (c.phi1 - c.phi0),
                      m_rowCc[size_t(y)] * m_colDCos[size_t(x)]);
            const std::array<double, 6> q = secondMoment(c);
            m_flux += L * omega;
            for (int ch = 0; ch < 3; ++ch) {
                m_first[size_t(ch)] += L[ch] * m;
                for (int k = 0; k < 6; ++k)
                    m_second[size_t(ch)][size_t(k)] += L[ch] * q[size_t(k)];
            }
            row += luminance(L);
            m_colCdf[size_t(y) * size_t(w) + size_t(x)] = row;
        }
        if (row > 0.0)
            for (int x = 0; x < w; ++x)
                m_colCdf[size_t(y) * size_t(w) + size_t(x)] /= row;
        rows += row * m_rowSolidAngle[size_t(y)];
        m_rowCdf[size_t(y)] = rows;
    }
    m_totalLuminance = rows;
    if (rows > 0.0)
        for (double& r : m_rowCdf)
            r /= rows;
    m_pdf.assign(size_t(w) * size_t(h), 0.0);
    if (rows > 0.0)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                m_pdf[size_t(y) * size_t(w) + size_t(x)] = luminance(texel(x, y)) / rows;

    // The pyramid, up to about 16 × 8 cells.
    int lw = w, lh = h;
    while (lw > 16 && lh > 8) {
        const int k = int(m_levels.size()) + 1;
        const int nw = (lw + 1) / 2, nh = (lh + 1) / 2;
        std::vector<Node> level(size_t(nw) * size_t(nh));
        for (int iy = 0; iy < nh; ++iy)
            for (int ix = 0; ix < nw; ++ix) {
                Node& n = level[size_t(iy) * size_t(nw) + size_t(ix)];
                for (int dy = 0; dy < 2; ++dy)
                    for (int dx = 0; dx < 2; ++dx) {
                        const int cx = 2 * ix + dx, cy = 2 * iy + dy;
                        if (cx >= lw || cy >= lh) continue;
                        if (k == 1) {
                            const V L = texel(cx, cy);
                            n.flux += L * m_rowSolidAngle[size_t(cy)];
                            const V m(m_rowCc[size_t(cy)] * m_colDSin[size_t(cx)],
                                      m_rowSc[size_t(cy)] * (2.0 * kPi / w),
                                      m_rowCc[size_t(cy)] * m_colDCos[size_t(cx)]);
                            for (int ch = 0; ch < 3; ++ch)
                                n.first[size_t(ch)] += L[ch] * m;
                        } else {
                            const Node& c = m_levels.back()[size_t(cy) * size_t(lw) + size_t(cx)];
                            n.flux += c.flux;
                            for (int ch = 0; ch < 3; ++ch)
                                n.first[size_t(ch)] += c.first[size_t(ch)];
                        }
                    }
                const int span = 1 << k;
                const int x0 = ix * span, x1 = std::min(w, (ix + 1) * span);
                const int y0 = iy * span, y1 = std::min(h, (iy + 1) * span);
                const Cell c{texelCell(0, y1 - 1, w, h).latLo, texelCell(0, y0, w, h).latHi,
                             texelCell(x0, 0, w, h).phi0, texelCell(x1 - 1, 0, w, h).phi1};
                const Cone cone = coneOf(c);
                n.axis = cone.axis, n.cosBeta = cone.cosBeta, n.sinBeta = cone.sinBeta;
                n.luminance = luminance(n.flux);
            }
        m_levels.push_back(std::move(level));
        m_levelWidth.push_back(nw), m_levelHeight.push_back(nh);
        lw = nw, lh = nh;
    }
}

V EnvironmentField::texel(int x, int y) const {
    return V(m_image->at(x, y)) * m_scale;
}

V EnvironmentField::imageDirection(const V& world) const {
    return m_rotation == 0.0 ? world : environment::rotateAboutUp(world, -m_rotation);
}

int EnvironmentField::texelIndexOf(const V& d) const {
    double u = std::atan2(d.z, d.x) / (2.0 * kPi) + 0.5;
    if (!(u >= 0.0)) u = 0.0;
    const double v = 0.5 - std::asin(std::clamp(d.y, -1.0, 1.0)) / kPi;
    const int x = std::clamp(int(u * m_width), 0, m_width - 1);
    const int y = std::clamp(int((std::isfinite(v) ? v : 0.5) * m_height), 0, m_height - 1);
    return y * m_width + x;
}

V EnvironmentField::radianceAt(const V& worldDirection) const {
    const int i = texelIndexOf(imageDirection(worldDirection));
    return texel(i % m_width, i / m_width);
}

void EnvironmentField::sampleImage(double u0, double u1, double u2, double u3, V* direction,
                                   int* texelIndex) const {
    const int y = int(
        std::min<size_t>(size_t(std::upper_bound(m_rowCdf.begin(), m_rowCdf.end(), u0) - m_rowCdf.begin()),
                         size_t(m_height - 1)));
    const auto row = m_colCdf.begin() + std::ptrdiff_t(y) * m_width;
    const int x = int(std::min<std::ptrdiff_t>(std::upper_bound(row, row + m_width, u1) - row, m_width - 1));
    const Cell c = texelCell(x, y, m_width, m_height);
    // Uniform in solid angle within the cell: azimuth uniform, sin(latitude) uniform.
    const double phi = c.phi0 + u2 * (c.phi1 - c.phi0);
    const double s0 = std::sin(c.latLo), s1 = std::sin(c.latHi);
    const double s = s0 + u3 * (s1 - s0);
    const double cl = std::sqrt(std::max(0.0, 1.0 - s * s));
    *direction = V(cl * std::cos(phi), s, cl * std::sin(phi));
    *texelIndex = y * m_width + x;
}

double EnvironmentField::imagePdf(int texelIndex) const {
    return m_pdf[size_t(texelIndex)];
}

V EnvironmentField::irradiance(const V& n, double tolerance, V* boundOut) const {
    V sum(0.0);
    if (isBlack()) {
        if (boundOut) *boundOut = V(0.0);
        return sum;
    }
    // Cells the horizon crosses wait in a max-heap by the luminance of their error half-width; the worst
    // is split until the half-widths add up to at most `tolerance` (or nothing can be split further).
    struct Pending {
        Item item;
        V estimate, half;
        double key;
        bool operator<(const Pending& o) const { return key < o.key; }
    };
    std::priority_queue<Pending> heap;
    std::vector<Pending> final; // straddling sub-cells at the depth limit
    double open = 0.0;          // Σ luminance(half) over heap and final
    const auto visit = [&](const Item& it) {
        V flux, axis;
        std::array<V, 3> first;
        double cosBeta, sinBeta;
        if (it.level >= 1) {
            const int lw = m_levelWidth[size_t(it.level - 1)];
            const Node& nd = m_levels[size_t(it.level - 1)][size_t(it.iy) * size_t(lw) + size_t(it.ix)];
            if (!(nd.luminance > 0.0)) return;
            flux = nd.flux, first = nd.first, axis = nd.axis, cosBeta = nd.cosBeta, sinBeta = nd.sinBeta;
        } else if (it.level == 0) {
            const V L = texel(it.ix, it.iy);
            if (!(luminance(L) > 0.0)) return;
            const size_t x = size_t(it.ix), y = size_t(it.iy);
            flux = L * m_rowSolidAngle[y];
            const V m(m_rowCc[y] * m_colDSin[x], m_rowSc[y] * (2.0 * kPi / m_width),
                      m_rowCc[y] * m_colDCos[x]);
            first = {L.x * m, L.y * m, L.z * m};
            axis = V(m_rowCosLat[y] * m_colCos[x], m_rowSinLat[y], m_rowCosLat[y] * m_colSin[x]);
            cosBeta = m_rowCosBeta[y], sinBeta = m_rowSinBeta[y];
        } else {
            flux = it.radiance * solidAngle(it.cell);
            const V m = firstMoment(it.cell);
            first = {it.radiance.x * m, it.radiance.y * m, it.radiance.z * m};
            const Cone k = coneOf(it.cell);
            axis = k.axis, cosBeta = k.cosBeta, sinBeta = k.sinBeta;
        }
        const double cosPsi = std::clamp(glm::dot(n, axis), -1.0, 1.0);
        const double sinPsi = std::sqrt(std::max(0.0, 1.0 - cosPsi * cosPsi));
        const double cosPlus = cosPsi * cosBeta - sinPsi * sinBeta;  // cos(ψ + β)
        const double cosMinus = cosPsi * cosBeta + sinPsi * sinBeta; // cos(ψ − β)
        const bool pastHalf = cosPsi <= -cosBeta;                    // ψ + β >= π
        const bool inside = cosPsi >= cosBeta;                       // ψ <= β
        const V nm(glm::dot(n, first[0]), glm::dot(n, first[1]), glm::dot(n, first[2]));
        if (!pastHalf && cosPlus > 0.0) { // wholly above the horizon: (n·ω)⁺ = n·ω, exactly linear
            sum += nm;
            return;
        }
        if (!inside && cosMinus < 0.0) return; // wholly below
        // Straddling: Σ L (n·ω)⁺ lies between max(0, n·M) and n·M + Φ·max(0, −min n·ω), and below
        // Φ·max n·ω, with the extremes of n·ω over the cone.
        const double lo = pastHalf ? -1.0 : cosPlus, hi = inside ? 1.0 : cosMinus;
        const V lower = glm::max(nm, V(0.0));
        const V upper = glm::max(glm::min(nm + flux * std::max(0.0, -lo), flux * std::max(0.0, hi)), lower);
        const Pending p{it, 0.5 * (upper + lower), 0.5 * (upper - lower), luminance(0.5 * (upper - lower))};
        open += p.key;
        if (it.level < 0 && it.depth >= kMaxSubcellDepth)
            final.push_back(p);
        else
            heap.push(p);
    };
    const int top = int(m_levels.size());
    const int tw = top > 0 ? m_levelWidth.back() : m_width, th = top > 0 ? m_levelHeight.back() : m_height;
    for (int iy = 0; iy < th; ++iy)
        for (int ix = 0; ix < tw; ++ix)
            visit({top, ix, iy, 0, {}, V(0.0)});
    const double budget = std::max(tolerance, 0.0);
    while (!heap.empty() && open > budget) {
        const Pending p = heap.top();
        heap.pop();
        open -= p.key;
        const Item& it = p.item;
        if (it.level >= 2) {
            const int cw = m_levelWidth[size_t(it.level - 2)], ch = m_levelHeight[size_t(it.level - 2)];
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx)
                    if (2 * it.ix + dx < cw && 2 * it.iy + dy < ch)
                        visit({it.level - 1, 2 * it.ix + dx, 2 * it.iy + dy, 0, {}, V(0.0)});
        } else if (it.level == 1) {
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx)
                    if (2 * it.ix + dx < m_width && 2 * it.iy + dy < m_height)
                        visit({0, 2 * it.ix + dx, 2 * it.iy + dy, 0, {}, V(0.0)});
        } else {
            const Cell c = it.level == 0 ? texelCell(it.ix, it.iy, m_width, m_height) : it.cell;
            const V L = it.level == 0 ? texel(it.ix, it.iy) : it.radiance;
            const double lm = 0.5 * (c.latLo + c.latHi), pm = 0.5 * (c.phi0 + c.phi1);
            for (const Cell& sc : {Cell{c.latLo, lm, c.phi0, pm}, Cell{c.latLo, lm, pm, c.phi1},
                                   Cell{lm, c.latHi, c.phi0, pm}, Cell{lm, c.latHi, pm, c.phi1}})
                visit({-1, 0, 0, it.depth + 1, sc, L});
        }
    }
    V bound(0.0);
    for (; !heap.empty(); heap.pop())
        sum += heap.top().estimate, bound += heap.top().half;
    for (const Pending& p : final)
        sum += p.estimate, bound += p.half;
    if (boundOut) *boundOut = bound;
    return sum;
}

lighting::ShadeLight<double> texelLight(const V& viewDirectionToTexel, const V& radiance, double solidAngle,
                                        ShadingModel model, DiffuseModel classicDiffuse) {
    lighting::ShadeLight<double> l;
    l.type = LightType::Directional;
    l.direction = -viewDirectionToTexel; // where the light travels
    const V c = model == ShadingModel::Pbr ? radiance * solidAngle : radiance * (solidAngle / kPi);
    l.color = c, l.specular = c, l.ambient = V(0.0);
    l.diffuse = model == ShadingModel::Pbr ? DiffuseModel::Lambert : classicDiffuse;
    return l;
}

V environmentRadianceBySum(const EnvironmentField& field, const lighting::Surface<double>& s,
                           const lighting::ShadeSettings<double>& st, const glm::dmat3& viewToWorld,
                           int subdivide) {
    const EnvironmentImage& img = field.image();
    const int w = img.width, h = img.height, k = std::max(1, subdivide);
    const glm::dmat3 worldToView = glm::transpose(viewToWorld);
    const V Vv = lighting::viewVector(st, s.position);
    const V cDiff = lighting::pbrDiffuseColor(s.albedo, s.metallic);
    const V f0 = lighting::pbrF0(s.albedo, s.metallic);
    const double alpha = lighting::pbrAlpha(s.roughness);
    V sum(0.0);
    for (int y = 0; y < h * k; ++y) {
        const double omega = environment::texelSolidAngle(y, w * k, h * k);
        for (int x = 0; x < w * k; ++x) {
            const V L = V(img.at(x / k, y / k)) * field.scale();
            if (L == V(0.0)) continue;
            const V world =
                environment::rotateAboutUp(environment::texelDirection(x, y, w * k, h * k), field.rotation());
            const lighting::ShadeLight<double> l =
                texelLight(worldToView * world, L, omega, st.model, field.diffuse());
            sum += st.model == ShadingModel::Pbr ? lighting::shadeLightPbr(l, s, st, Vv, cDiff, f0, alpha)
                                                 : lighting::shadeLight(l, s, st, Vv);
        }
    }
    return sum * lighting::saturate(s.occlusion);
}

Estimate EnvironmentField::integrate(const lighting::Surface<double>& s,
                                     const lighting::ShadeSettings<double>& st, const glm::dmat3& viewToWorld,
                                     std::uint64_t seed, const Convergence& conv, const V& rest) const {
    Estimate e;
    const double occlusion = lighting::saturate(s.occlusion);
    if (isBlack() || !(occlusion > 0.0)) return e;
    const bool pbr = st.model == ShadingModel::Pbr;
    const V viewV = lighting::viewVector(st, s.position);
    const V n = lighting::safeNormalize(imageDirection(viewToWorld * s.normal), V(0.0, 1.0, 0.0));
    const V v = lighting::safeNormalize(imageDirection(viewToWorld * viewV), n);
    lighting::Surface<double> surface = s; // in the image's frame from here on
    surface.normal = n;
    const V cDiff = lighting::pbrDiffuseColor(s.albedo, s.metallic);
    const V f0 = lighting::pbrF0(s.albedo, s.metallic);
    const double alpha = lighting::pbrAlpha(s.roughness);
    const bool halfLambert = !pbr && m_diffuse == DiffuseModel::HalfLambert;
    // The deterministic part: k · ∫ L(ω) kernel(n·ω) dω.
    const V k = pbr ? cDiff * (1.0 - lighting::kDielectricF0) / kPi : s.albedo / kPi;
    const auto kernel = [&](double nDotL) {
        return halfLambert ? lighting::diffuseHalfLambert(nDotL) : lighting::diffuseLambert(nDotL);
    };
    // Irradiance by the band-limited (SH9) cosine, exact from the moments: only to pick the tolerance.
    const auto quadratic = [&](double c0, double c1, double c2) {
        V r;
        for (int ch = 0; ch < 3; ++ch) {
            const std::array<double, 6>& q = m_second[size_t(ch)];
            const double nqn = n.x * n.x * q[0] + n.y * n.y * q[1] + n.z * n.z * q[2] +
                               2.0 * (n.x * n.y * q[3] + n.y * n.z * q[4] + n.x * n.z * q[5]);
            r[ch] = c0 * m_flux[ch] + c1 * glm::dot(n, m_first[size_t(ch)]) + c2 * nqn;
        }
        return r;
    };

    // Monte Carlo: L · (W − k·kernel), W the unit directional light's radiance through shade.h.
    const bool needsMonteCarlo = pbr || maxOf(s.specular) > 0.0;
    lighting::ShadeLight<double> unit;
    unit.type = LightType::Directional;
    unit.color = unit.specular = V(pbr ? 1.0 : 1.0 / kPi);
    unit.ambient = V(0.0);
    unit.diffuse = pbr ? DiffuseModel::Lambert : m_diffuse;
    const double shininess = s.shininess > 0.0 ? std::min(s.shininess, 1e6) : 0.0;
    const V r = lighting::safeNormalize(reflectAbout(v, n), n);
    const auto integrand = [&](const V& w, const V& L) {
        unit.direction = -w;
        const V W = pbr ? lighting::shadeLightPbr(unit, surface, st, v, cDiff, f0, alpha)
                        : lighting::shadeLight(unit, surface, st, v);
        return L * (W - k * kernel(glm::dot(n, w)));
    };
    // The specular lobe's sampling (montecarlo.h): GGX's visible normals under PBR, Phong's or Blinn's lobe.
    const montecarlo::SpecularLobe lobe(n, v, pbr, alpha, st.specular, shininess);
    const auto lobePdf = [&](const V& w) { return lobe.pdf(w); };
    const auto sampleLobe = [&](double u0, double u1) { return lobe.sample(u0, u1); };

    V mean(0.0), se(0.0), windowError(0.0);
    const V guess =
        rest +
        occlusion * k * (halfLambert ? quadratic(0.25, 0.5, 0.25) : quadratic(3.0 / 32.0, 0.5, 15.0 / 32.0));
    // The diffuse kernel first: half-Lambert exactly; Lambert by the quadrature, to a bound of about
    // quadratureLevels where the display is steepest around this pixel's value (as far as it is known
    // before Monte Carlo: the lights and the SH9 diffuse).
    V E, bound(0.0);
    if (halfLambert) {
        E = quadratic(0.25, 0.5, 0.25); // ((n·ω)/2 + 1/2)² = 1/4 + (n·ω)/2 + (n·ω)²/4 over the sphere
    } else {
        const V x0 = guess;
        const double dx = std::max(1e-3 * maxOf(x0), 1e-9);
        double slope = 0.0;
        for (double f : {0.5, 1.0}) {
            const V at = rest + f * (x0 - rest);
            slope = std::max(slope, displayErrorLevels(at, V(dx), conv) / dx);
        }
        const double perIrradiance = occlusion * std::max(maxOf(k), 1e-300);
        const double tolerance = slope > 0.0 ? conv.quadratureLevels / slope / perIrradiance : 1e300;
        E = irradiance(n, tolerance, &bound);
    }
    const V base = rest + occlusion * k * E;
    if (needsMonteCarlo) {
        // Randomised quasi-Monte Carlo: `replicates` copies of a 6-dimensional R-sequence (Roberts'
        // generalised golden ratio), each shifted by its own random vector (Cranley-Patterson); each
        // replicate's mean is an independent unbiased estimate, and the standard error is their spread.
        Rng rng(seed);
        const int replicates = std::max(2, conv.replicates), perBatch = std::max(1, conv.batch);
        std::vector<std::array<double, 6>> shift(static_cast<size_t>(replicates));
        for (auto& sh : shift)
            for (double& x : sh)
                x = rng.next();
        const std::array<double, 6>& kAlpha = montecarlo::rSequence6();
        // One Monte Carlo run of at most `batches` batches over the sphere less `window` (when given: its
        // texels' integrand is counted as 0, the densities stay the whole sphere's, so it stays unbiased).
        const auto run = [&](const Window* window, int batches, const V& added, const V& addedError) {
            std::vector<V> sums(static_cast<size_t>(replicates), V(0.0));
            int points = 0;
            bool converged = false;
            for (int b = 0; b < batches; ++b) {
                for (int rep = 0; rep < replicates; ++rep)
                    for (int i = points; i < points + perBatch; ++i) {
                        std::array<double, 6> u;
                        for (int j = 0; j < 6; ++j) {
                            const double x =
                                shift[size_t(rep)][size_t(j)] + double(i + 1) * kAlpha[size_t(j)];
                            u[size_t(j)] = std::min(x - std::floor(x), 0x1.fffffffffffffp-1);
                        }
                        V y(0.0);
                        V w;
                        int t;
                        sampleImage(u[0], u[1], u[2], u[3], &w, &t);
                        double denom = imagePdf(t) + lobePdf(w);
                        if (denom > 0.0 && !(window && inWindow(*window, t)))
                            y += integrand(w, texel(t % m_width, t / m_width)) / denom;
                        const V wl = sampleLobe(u[4], u[5]);
                        const int tl = texelIndexOf(wl);
                        denom = imagePdf(tl) + lobePdf(wl);
                        if (denom > 0.0 && !(window && inWindow(*window, tl)))
                            y += integrand(wl, texel(tl % m_width, tl / m_width)) / denom;
                        sums[size_t(rep)] += y;
                    }
                points += perBatch;
                V total(0.0), sq(0.0);
                for (const V& sk : sums) {
                    const V m = sk / double(points);
                    total += m, sq += m * m;
                }
                mean = total / double(replicates) + added;
                const V var = glm::max(sq - double(replicates) * (mean - added) * (mean - added), V(0.0)) /
                              double(replicates - 1);
                se = glm::sqrt(var / double(replicates)) + addedError;
                // Stop when the pixel's whole estimated error (this standard error and the quadrature's
                // bound, as errorLevels below) is within the target.
                if (b + 1 >= conv.minBatches &&
                    displayErrorLevels(base + occlusion * mean, occlusion * (se + k * bound), conv) <=
                        conv.targetLevels) {
                    converged = true;
                    break;
                }
            }
            e.samples += points * replicates;
            return converged;
        };
        const int batches = std::max(1, conv.maxBatches);
        // The lobe's angular scale in ω (radians): GGX's and Blinn's half-vector lobes reflect to about twice
        // their half-vectors' spread (Blinn power s ≈ GGX α² = 2/(s + 2)), Phong's lobe spreads about r.
        const double lobeAngle =
            pbr ? 2.0 * std::atan(alpha)
                : (st.specular == SpecularModel::Phong ? std::sqrt(2.0 / (shininess + 2.0))
                                                       : 2.0 * std::atan(std::sqrt(2.0 / (shininess + 2.0))));
        const double texelAngle = kPi / m_height;
        Window window;
        window.axis = r;
        window.halfAngle = kWindowLobes * lobeAngle + 2.0 * texelAngle;
        window.cosHalfAngle = std::cos(window.halfAngle);
        const bool canWindow = window.halfAngle < kMaxWindowAngle;
        if (!run(nullptr, canWindow ? std::max(1, batches / 4) : batches, V(0.0), V(0.0)) && canWindow) {
            // The core by the midpoint rule on cells about a quarter of the lobe wide and on cells half as
            // wide: the finer sum is kept, its error estimated as |fine − coarse| / 3 (the rule's error falls
            // as the cell's width squared; the integrand is smooth within a texel, its radiance constant).
            const int sub = std::clamp(int(std::ceil(4.0 * texelAngle / lobeAngle)), 1, kMaxWindowSubdivide);
            const V coarse = windowSum(window, integrand, sub);
            const V fine = windowSum(window, integrand, 2 * sub);
            windowError = glm::abs(fine - coarse) / 3.0;
            e.windowed = true;
            run(&window, batches, fine, windowError);
            se -= windowError; // reported in the bound, not as a standard error
        }
    }

    e.radiance = occlusion * (k * E + mean);
    e.standardError = occlusion * se;
    e.bound = occlusion * (k * bound + windowError);
    e.errorLevels = displayErrorLevels(rest + e.radiance, e.standardError + e.bound, conv);
    return e;
}

} // namespace lr::envintegrate
