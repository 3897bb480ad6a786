// The CPU light binning of clustered shading (src/render/cluster.h): conservative (every point inside a
// light's sphere finds the light in its cluster) and tight (a light lands only near the clusters its
// sphere actually reaches), for lights in front of, around and behind the camera.
#include "render/cluster.h"
#include "scene/camera.h"

#include <QTest>
#include <glm/gtc/matrix_transform.hpp>
#include <random>
#include <set>

using namespace lr;
using namespace lr::render;

namespace {

ClusterView testView(int w, int h) {
    ViewCamera cam;
    cam.eye = {0, 0, 0};
    cam.target = {0, 0, -1};
    cam.znear = 0.1;
    cam.zfar = 50.0;
    ClusterView v;
    v.projection = cam.projection(double(w) / h);
    v.width = w, v.height = h;
    v.znear = cam.znear, v.zfar = cam.zfar;
    return v;
}

// Window coordinates of a view-space point, as gl_FragCoord would hold them; false when not on screen.
bool toWindow(const ClusterView& v, const glm::dvec3& p, glm::dvec2* frag) {
    const glm::dvec4 c = v.projection * glm::dvec4(p, 1.0);
    if (!(c.w > 0.0)) return false;
    const glm::dvec3 ndc = glm::dvec3(c) / c.w;
    if (std::abs(ndc.x) > 1 || std::abs(ndc.y) > 1 || std::abs(ndc.z) > 1) return false;
    *frag = {(ndc.x * 0.5 + 0.5) * v.width, (ndc.y * 0.5 + 0.5) * v.height};
    return true;
}

// Whether the sphere reaches the cluster's frustum widened by one pixel and one slice, tested against the
// frustum's bounding box: its 8 corners come from the inverse projection at the slab's depths.
bool clusterReach(const ClusterView& v, const ClusterLookup& k, int x, int y, int z, const LightBounds& b) {
    const glm::dmat4 inv = glm::inverse(v.projection);
    const double lo = z <= 1 ? 0.0 : k.znear * std::exp((z - 1) / k.sliceScale);
    const double hi = z + 1 >= k.grid.slices - 1 ? v.zfar * 1.01 : k.znear * std::exp((z + 2) / k.sliceScale);
    glm::dvec3 bmin(1e300), bmax(-1e300);
    for (double px : {x / k.tileScale.x - 1.0, (x + 1) / k.tileScale.x + 1.0})
        for (double py : {y / k.tileScale.y - 1.0, (y + 1) / k.tileScale.y + 1.0}) {
            // the view ray through this window point, scaled to each depth
            glm::dvec4 p = inv * glm::dvec4(2.0 * px / v.width - 1.0, 2.0 * py / v.height - 1.0, 0.0, 1.0);
            const glm::dvec3 dir = glm::dvec3(p) / p.w / (-(p.z / p.w));
            for (double depth : {lo, hi}) {
                bmin = glm::min(bmin, dir * depth);
                bmax = glm::max(bmax, dir * depth);
            }
        }
    const glm::dvec3 q = glm::clamp(b.center, bmin, bmax);
    return glm::length(q - b.center) <= b.radius * (1.0 + 1e-9) + 1e-12;
}

lighting::ShadeLight<double> pointLight(FalloffModel f, double range, glm::dvec3 pos) {
    lighting::ShadeLight<double> l;
    l.type = LightType::Point;
    l.falloff = f;
    l.range = range;
    l.position = pos;
    return l;
}

} // namespace

class TestClusterBin : public QObject {
    Q_OBJECT
  private slots:
    void boundsFollowTheFalloffs() {
        const glm::dvec3 p(1, 2, -3);
        QVERIFY(!lightBounds(pointLight(FalloffModel::None, 5, p), 1).bounded);
        QVERIFY(!lightBounds(pointLight(FalloffModel::InverseSquare, -1, p), 1).bounded);
        QVERIFY(!lightBounds(pointLight(FalloffModel::InversePolynomial, -1, p), 1).bounded);
        auto dir = pointLight(FalloffModel::RangePower, 2, p);
        dir.type = LightType::Directional;
        QVERIFY(!lightBounds(dir, 1).bounded);
        dir.type = LightType::Rim;
        QVERIFY(!lightBounds(dir, 1).bounded);
        for (FalloffModel f : {FalloffModel::RangePower, FalloffModel::RangeQuadratic,
                               FalloffModel::InverseSquare, FalloffModel::InversePolynomial}) {
            const LightBounds b = lightBounds(pointLight(f, 2, p), 0.5); // d * 0.5 >= 2 from d = 4 on
            QVERIFY(b.bounded);
            QVERIFY(b.radius >= 4.0);
            QVERIFY(b.radius < 4.1);
            // Just outside the bound, the core falloff really is zero; just inside it is not (tight).
            auto l = pointLight(f, 2, p);
            QCOMPARE(lighting::evalFalloff(l, b.radius * 0.5), 0.0);
            QVERIFY(lighting::evalFalloff(l, 3.9 * 0.5) > 0.0);
        }
        auto spot = pointLight(FalloffModel::RangeQuadratic, 1, p);
        spot.type = LightType::Spot;
        QVERIFY(lightBounds(spot, 1).bounded);
        QVERIFY(!lightBounds(pointLight(FalloffModel::RangePower, 1, p), 0.0).bounded); // no distance scale
    }

    void conservativeAndTight_data() {
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("height");
        QTest::addColumn<quint32>("seed");
        QTest::newRow("720p") << 1280 << 720 << 1u;
        QTest::newRow("portrait") << 333 << 777 << 2u;
        QTest::newRow("tiny") << 7 << 5 << 3u;
    }
    void conservativeAndTight() {
        QFETCH(int, width);
        QFETCH(int, height);
        QFETCH(quint32, seed);
        const ClusterView view = testView(width, height);
        std::mt19937 rng(seed);
        std::uniform_real_distribution<double> u(-1.0, 1.0);
        std::vector<LightBounds> lights;
        for (int i = 0; i < 64; ++i) {
            LightBounds b;
            b.bounded = i % 16 != 5;                                  // a few global lights
            b.center = {u(rng) * 6, u(rng) * 4, -7.0 + u(rng) * 8.0}; // some behind the eye
            b.radius = i % 7 == 0 ? 0.0 : std::exp(u(rng) * 2.5);     // 0.08 .. 12
            lights.push_back(b);
        }
        const ClusterData d = binLights(lights, view);
        QCOMPARE(int(d.ranges.size()), 2 * d.grid.count());
        QCOMPARE(d.globalCount, 4);
        for (int i = 0; i < d.globalCount; ++i)
            QVERIFY(!lights[d.indices[size_t(i)]].bounded);

        int checked = 0;
        for (size_t i = 0; i < lights.size(); ++i) {
            const LightBounds& b = lights[i];
            if (!b.bounded) continue;
            std::set<int> hit;
            int loX = 1 << 30, hiX = -1, loY = 1 << 30, hiY = -1, loZ = 1 << 30, hiZ = -1;
            for (int s = 0; s < 4000; ++s) { // points inside the sphere (and on its surface)
                glm::dvec3 q(u(rng), u(rng), u(rng));
                if (glm::length(q) > 1.0) continue;
                if (s % 4 == 0 && glm::length(q) > 0.0) q = glm::normalize(q) * 0.999999;
                const glm::dvec3 p = b.center + q * b.radius;
                glm::dvec2 frag;
                if (!toWindow(view, p, &frag)) continue;
                const int c = d.lookup.index(frag, -p.z);
                const auto list = d.cluster(c);
                QVERIFY2(std::find(list.begin(), list.end(), std::uint32_t(i)) != list.end(),
                         qPrintable(QStringLiteral("light %1 missing from cluster %2").arg(i).arg(c)));
                hit.insert(c);
                int tx = 0, ty = 0;
                d.lookup.tile(frag.x, frag.y, &tx, &ty);
                const int tz = d.lookup.slice(-p.z);
                loX = std::min(loX, tx), hiX = std::max(hiX, tx), loY = std::min(loY, ty),
                hiY = std::max(hiY, ty);
                loZ = std::min(loZ, tz), hiZ = std::max(hiZ, tz);
                ++checked;
            }
            // Tight: every cluster listing the light has its frustum (widened by the binning's slack of one
            // pixel and one depth slice) within reach of the sphere; the frustum is unprojected here from
            // the inverse projection, independently of the binning's arithmetic.
            for (int c = 0; c < d.grid.count(); ++c) {
                const auto list = d.cluster(c);
                if (std::find(list.begin(), list.end(), std::uint32_t(i)) == list.end()) continue;
                const int x = c % d.grid.tilesX, y = (c / d.grid.tilesX) % d.grid.tilesY,
                          z = c / (d.grid.tilesX * d.grid.tilesY);
                QVERIFY2(clusterReach(view, d.lookup, x, y, z, b),
                         qPrintable(QStringLiteral("light %1 in distant cluster %2 (%3,%4,%5)")
                                        .arg(i)
                                        .arg(c)
                                        .arg(x)
                                        .arg(y)
                                        .arg(z)));
            }
            (void)hit;
            (void)loX, (void)hiX, (void)loY, (void)hiY, (void)loZ, (void)hiZ;
        }
        QVERIFY(checked > 1000);
    }

    // Issue 40: tiles of about 40 pixels whatever the size (32 x 18 at 1280x720, as before; 96 x 54 at 4K),
    // never more than the range buffer holds, never none.
    void gridFollowsTheTargetSize() {
        const ClusterGrid hd = clusterGridFor(1280, 720);
        QCOMPARE(hd.tilesX, 32);
        QCOMPARE(hd.tilesY, 18);
        const ClusterGrid uhd = clusterGridFor(3840, 2160, 1 << 27);
        QCOMPARE(uhd.tilesX, 96);
        QCOMPARE(uhd.tilesY, 54);
        const ClusterGrid capped = clusterGridFor(3840, 2160); // GL 3.3's 65,536 texels
        QVERIFY2(capped.count() <= 65536 && capped.tilesX >= 32,
                 qPrintable(QStringLiteral("%1 x %2").arg(capped.tilesX).arg(capped.tilesY)));
        const ClusterGrid tiny = clusterGridFor(0, -5, 0);
        QVERIFY(tiny.tilesX >= 1 && tiny.tilesY >= 1 && tiny.slices >= 1);
        QCOMPARE(clusterGridFor(100000, 100000, 1 << 30).tilesX, kClusterMaxTiles);
        // A 4K grid bins the same lights to the same pixels (the lookup is the shader's): spot-check that a
        // light's clusters still cover its sphere's footprint in the finer grid.
        ClusterView v;
        v.projection = glm::perspective(glm::radians(45.0), 16.0 / 9.0, 0.1, 100.0);
        v.width = 3840;
        v.height = 2160;
        LightBounds b;
        b.bounded = true;
        b.center = {0.0, 0.0, -5.0};
        b.radius = 0.5;
        const ClusterData d = binLights(std::span<const LightBounds>(&b, 1), v, uhd);
        QCOMPARE(d.grid, uhd);
        const int centre = d.lookup.index({1920.0, 1080.0}, 5.0);
        QVERIFY(!d.cluster(centre).empty());
    }

    void smallLightTouchesFewClusters() {
        const ClusterView view = testView(1280, 720);
        LightBounds b;
        b.bounded = true;
        b.center = {0.3, -0.2, -5.0};
        b.radius = 0.1;
        const ClusterData d = binLights(std::span(&b, 1), view);
        size_t total = 0;
        for (int c = 0; c < d.grid.count(); ++c)
            total += d.cluster(c).size();
        QVERIFY(total >= 1);
        QVERIFY2(total <= 4 * 4 * 4, qPrintable(QString::number(total)));
        // Off screen and behind the eye: nowhere (behind: at most slice 0 near the eye, never beyond).
        b.center = {100.0, 0.0, -5.0};
        QCOMPARE(binLights(std::span(&b, 1), view).indices.size(), size_t(0));
    }
};

QTEST_GUILESS_MAIN(TestClusterBin)
#include "tst_clusterbin.moc"
