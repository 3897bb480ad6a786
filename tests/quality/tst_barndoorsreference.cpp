// Barn doors in the double-precision reference and the raster tiers (issue 39; core/barndoors.h): a rect
// softbox with long flaps over a Lambertian plane. The spill is cut where geometry says: where every one of
// a grid of emitter points is hidden from the pixel by a flap (the segment test, the definition) the
// reference is exactly black; where every one is seen, it is what the same light without barn doors gives;
// in between it is Lambert's closed form over the window of the emitter the pixel sees. Then each raster
// tier against that reference, and angle 90 (the flaps in the emitter's plane) against no barn doors.
#include "qualityscenes.h"

#include "core/areaintegrate.h"
#include "core/barndoors.h"
#include "render/gbuffer.h"

#include <QTest>

using namespace lr;
using namespace lr::test;
using V = glm::dvec3;

namespace {

const QSize kSize(96, 72);

// ∫ (N·ω)⁺ dω over the rect seen from P (above the plane here).
double rectIrradiance(const lighting::ShadeLight<double>& l, const V& P, const V& N) {
    V c[4];
    int i = 0;
    for (auto [u, v] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
        c[i++] = glm::normalize(l.position + u * l.halfWidth * l.axisX + v * l.halfHeight * l.axisY - P);
    double e = 0.0;
    for (int k = 0; k < 4; ++k) {
        const V x = glm::cross(c[k], c[(k + 1) % 4]);
        e += lighting::safeAcos(glm::dot(c[k], c[(k + 1) % 4])) * glm::dot(glm::normalize(x), N);
    }
    return std::abs(0.5 * e);
}

Rig softboxRig(std::optional<BarnDoors> doors) {
    Rig rig;
    rig.space = RigSpace::World;
    rig.ambient = V(0.0);
    rig.shading.model = ShadingModel::Classic;
    Light l = makeLight(LightType::Rect, QStringLiteral("softbox"));
    l.position = {0.1, 0.05, 0.8};
    l.direction = glm::normalize(V(-0.1, -0.05, -1.0));
    l.area.width = 1.2, l.area.height = 0.6;
    l.intensity = 2.0;
    l.color = V(1.0, 0.9, 0.8);
    l.specular = V(0.0);
    l.ambient = V(0.0);
    l.barnDoors = doors;
    rig.lights.push_back(l);
    return rig;
}

// How many of a 9 × 9 grid of emitter points (cell centres: none on the flaps' hinges) the segment test
// lets through to P.
int seenPoints(const lighting::ShadeLight<double>& l, const V& P) {
    int seen = 0;
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) {
            const V Q = l.position + ((2 * i + 1) / 9.0 - 1.0) * l.halfWidth * l.axisX +
                        ((2 * j + 1) / 9.0 - 1.0) * l.halfHeight * l.axisY;
            seen += barndoors::segmentHitsFlaps(l, Q, P) ? 0 : 1;
        }
    return seen;
}

} // namespace

class TestBarnDoorsReference : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
    }

    void spillIsCutWhereGeometrySays() {
        auto model = gridPlane(2.0, 8);
        model->materials[0].specular = {0.0f, 0.0f, 0.0f};
        const Rig rig = softboxRig(BarnDoors{10.0, 0.6});
        QString error;
        QVERIFY2(m_gl.setModel(model, &error), qPrintable(error));
        m_gl.setRig(rig);
        RenderSettings settings;
        settings.msaaSamples = 0;
        GBuffer g;
        QVERIFY2(m_gl.renderGBuffer(planeCamera(), kSize, settings, &g, &error), qPrintable(error));
        const glm::dmat4 view = m_gl.renderer().effectiveCamera(planeCamera()).view();
        const auto scene =
            makeReferenceScene(*model, rig, m_gl.renderer().sceneFrame(), view, settings, &error);
        QVERIFY2(scene, qPrintable(error));
        const ReferenceImage ref = computeReference(g, *scene);
        QCOMPARE(areaConvergence(ref).over, 0);
        const lighting::ShadeLight<double>& l = scene->lights.front();
        QVERIFY(l.barnDepth > 0.0);
        int dark = 0, full = 0, partial = 0, off = 0;
        for (int y = 0; y < kSize.height(); ++y)
            for (int x = 0; x < kSize.width(); ++x) {
                const size_t i = size_t(y) * size_t(kSize.width()) + size_t(x);
                if (!ref.covered[i]) continue;
                const lighting::Surface<double> s = render::surfaceAt(g, x, y);
                if (!areaintegrate::reaches(l, s)) continue;
                const int seen = seenPoints(l, s.position);
                const V& r = ref.radiance[i];
                if (seen == 0 && barndoors::visibleWindow(l, s.position).empty()) {
                    ++dark;
                    QVERIFY2(r.x == 0.0 && r.y == 0.0 && r.z == 0.0,
                             qPrintable(QStringLiteral("pixel %1, %2 hidden by the flaps but lit: %3")
                                            .arg(x)
                                            .arg(y)
                                            .arg(r.x)));
                    continue;
                }
                const lighting::ShadeLight<double> window = barndoors::visiblePart(l, s.position);
                if (seen == 81)
                    ++full;
                else
                    ++partial;
                // Where every grid point is seen the window holds the outermost ones.
                if (seen == 81) QVERIFY(window.halfWidth >= l.halfWidth * 8.0 / 9.0);
                const V expected =
                    l.color * s.albedo * (rectIrradiance(window, s.position, s.normal) / lighting::kPi);
                const V a = encodeSrgb(expected, 0.0, ToneMap::Clamp), b = encodeSrgb(r, 0.0, ToneMap::Clamp);
                double largest = 0.0;
                for (int ch = 0; ch < 3; ++ch)
                    largest = std::max(largest, std::abs(a[ch] - b[ch]) * 255.0);
                if (largest > 1.5) ++off;
            }
        qInfo("barn doors on the ground: %d pixels dark, %d lit by all the emitter, %d cut, %d off by > 1.5 "
              "levels",
              dark, full, partial, off);
        QVERIFY(dark > 100);
        QVERIFY(full > 100);
        QVERIFY(partial > 100);
        QVERIFY2(off * 100 <= full + partial, qPrintable(QStringLiteral("%1 pixels off").arg(off)));
    }

    // The raster tiers integrate the same window (LTC / the form factor over it): each against the reference.
    void rasterTiersMatchTheReference() {
        auto model = gridPlane(2.0, 16);
        model->materials[0].specular = {0.0f, 0.0f, 0.0f};
        const Rig rig = softboxRig(BarnDoors{10.0, 0.6});
        for (Quality q : {Quality::Fast, Quality::Balanced, Quality::Exact}) {
            const TierFrame f = renderTier(m_gl, model, rig, planeCamera(), kSize, q, 1e-3);
            QVERIFY2(f.error.isEmpty(), qPrintable(f.error));
            qInfo("%s: %s", tierName(q), qPrintable(f.summary()));
            if (q == Quality::Fast) continue; // per vertex: the cut's edge falls between vertices
            QVERIFY2(f.levels.maxLevels <= 3, qPrintable(f.summary()));
            QVERIFY2(f.levels.shareOver1() < 0.01, qPrintable(f.summary()));
        }
    }

    // Flaps at 90° lie in the emitter's plane: the image is exactly the one without barn doors.
    void angle90IsNoBarnDoors() {
        auto model = gridPlane(2.0, 8);
        RenderSettings settings;
        settings.msaaSamples = 0;
        QString error;
        QVERIFY2(m_gl.setModel(model, &error), qPrintable(error));
        m_gl.setRig(softboxRig(std::nullopt));
        const QImage plain = m_gl.renderImage(planeCamera(), kSize, settings, 1, &error);
        QVERIFY2(!plain.isNull(), qPrintable(error));
        m_gl.setRig(softboxRig(BarnDoors{90.0, 0.6}));
        const QImage flat = m_gl.renderImage(planeCamera(), kSize, settings, 1, &error);
        QVERIFY2(!flat.isNull(), qPrintable(error));
        QCOMPARE(flat, plain);
        m_gl.setRig(softboxRig(BarnDoors{10.0, 0.6}));
        const QImage cut = m_gl.renderImage(planeCamera(), kSize, settings, 1, &error);
        QVERIFY(cut != plain);
    }
};

QTEST_MAIN(TestBarnDoorsReference)
#include "tst_barndoorsreference.moc"
