// Every quality tier at the extremes, on the GPU: rigs with range 0, 1e-30 and 1e30, a light exactly on
// the surface (on a vertex, too), inner = outer, outer -> 0 and 90°, exponents 0, intensities 1e6, zero
// and denormal vertex normals, a model and its lights 1e6 units from the origin, and a camera 1e-3 units
// from the surface. Each frame is read back as float radiance (RGBA32F).
//
// Asserted per case and tier: no NaN/Inf pixel, no negative radiance, and, for the per-pixel tiers,
// agreement with lighting::shadeSurface<double> at the G-buffer's surface points over the well-conditioned
// pixels (glfixture.h: a nudge of the point by 1e-6 of its distance must not move the reference by more
// than the tolerance; at most 5 % of the covered pixels may be skipped so):
//   exact     |gpu − ref| <= 1e-3 · max(1, |ref|) per channel
//   balanced  |gpu − ref| <= 2e-3 · max(1, |ref|) per channel (docs/quality.md: its approximations)
//   fast      per-vertex lighting: no per-pixel agreement is claimed; finite and non-negative only.
// The 1e-3 (rather than tests/render's 1e-4) covers 1e6 intensities and d -> 0, which amplify float rounding.
#include "qualityscenes.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace lr::test;

namespace {

const QSize kSize(80, 60);

struct ExtremeCase {
    const char* name;
    std::function<Rig()> rig;
    bool sphereToo = true; // also on the sphere (else only the grid plane)
    std::function<std::shared_ptr<Model>()> model = {};
    std::function<ViewCamera()> camera = {};
};

const FalloffModel kFalloffs[] = {FalloffModel::None, FalloffModel::RangePower,
                                  FalloffModel::InversePolynomial, FalloffModel::RangeQuadratic,
                                  FalloffModel::InverseSquare};

Rig withAllFalloffs(glm::dvec3 at, double range) {
    std::vector<Light> ls;
    for (FalloffModel f : kFalloffs)
        ls.push_back(point(at, f, range));
    Light s = spot(at + glm::dvec3(-0.3, 0.0, 0.0), {0, 0, 0}, ConeModel::Smooth, 10.0, 20.0, 1.0);
    s.falloff = {FalloffModel::RangePower, range, 2.0};
    ls.push_back(s);
    return rigOf(ls);
}

Rig translated(Rig rig, const glm::dvec3& offset) {
    for (Light& l : rig.lights)
        l.position += offset;
    return rig;
}

Rig everyModel() {
    for (const RigCase& c : rigCases())
        if (QLatin1String(c.name) == QLatin1String("mixed-all-types")) return c.make();
    return {};
}

std::vector<ExtremeCase> cases() {
    const glm::dvec3 far(1e6, -1e6, 1e6);
    return {
        {"range-0",
         [] {
             return withAllFalloffs({0.3, 0.2, 1.0}, 0.0);
         }},
        {"range-1e-30",
         [] {
             return withAllFalloffs({0.3, 0.2, 1.0}, 1e-30);
         }},
        {"range-1e30",
         [] {
             return withAllFalloffs({0.3, 0.2, 1.0}, 1e30);
         }},
        {"light-on-surface",
         [] {
             // (0, 0, 0) is a vertex of the grid and a point of the plane; (0, 0, 1) the sphere's pole.
             Rig r = withAllFalloffs({0.0, 0.0, 0.0}, 2.0);
             r.lights.push_back(point({0.0, 0.0, 1.0}, FalloffModel::InverseSquare));
             r.lights.push_back(
                 spot({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, ConeModel::AnglePower, 0.0, 30.0, 1.0));
             return r;
         }},
        {"inner-equals-outer",
         [] {
             return rigOf({spot({0, 0, 2}, {0, 0, 0}, ConeModel::Smooth, 25.0, 25.0, 1.0),
                           spot({0.5, 0, 2}, {0.5, 0, 0}, ConeModel::Smooth, 0.0, 0.0, 1.0)});
         }},
        {"outer-to-0",
         [] {
             return rigOf({spot({0, 0, 2}, {0, 0, 0}, ConeModel::Smooth, 0.0, 1e-6, 1.0),
                           spot({0, 0, 2}, {0, 0, 0}, ConeModel::AnglePower, 0.0, 1e-6, 1.0),
                           spot({0, 0, 2}, {0, 0, 0}, ConeModel::Hard, 0.0, 1e-6, 1.0),
                           directional({-0.3, -0.4, -1.0}, DiffuseModel::Lambert)});
         }},
        {"outer-90",
         [] {
             return rigOf({spot({0, 0, 0.5}, {0, 0, 0}, ConeModel::Smooth, 0.0, 90.0, 1.0),
                           spot({0, 0.2, 0.5}, {0, 0, 0}, ConeModel::AnglePower, 0.0, 90.0, 2.0),
                           spot({0.3, 0, 0.5}, {0, 0, 0}, ConeModel::Hard, 0.0, 90.0, 1.0)});
         }},
        {"exponent-0",
         [] {
             Light a = point({0.3, 0.2, 1.0}, FalloffModel::RangePower, 3.0);
             a.falloff.exponent = 0.0;
             Light b = spot({0, 0, 2}, {0, 0, 0}, ConeModel::Smooth, 10.0, 20.0, 0.0);
             Light c = spot({0, 0, 2}, {0, 0, 0}, ConeModel::AnglePower, 0.0, 20.0, 0.0);
             Light d = rim({0, 0, -1}, 0.0);
             Rig r = rigOf({a, b, c, d});
             r.shading.shininess = 0.0;
             return r;
         }},
        {"intensity-1e6",
         [] {
             Light a = point({0.3, 0.2, 1.0}, FalloffModel::InverseSquare);
             a.intensity = 1e6;
             Light b = point({0.0, 0.0, 0.3}, FalloffModel::InversePolynomial); // floored denominator
             b.intensity = 1e6;
             b.falloff.constant = b.falloff.linear = b.falloff.quadratic = 0.0;
             Light c = directional({0, 0, -1}, DiffuseModel::HalfLambert);
             c.intensity = 1e6;
             c.ambient = glm::dvec3(1.0);
             Light d = rim({0, 0, -1}, 1.0);
             d.intensity = 1e6;
             Rig r = rigOf({a, b, c, d});
             r.shading.specular = SpecularModel::BlinnPhong;
             return r;
         }},
        {"zero-and-denormal-normals", [] { return everyModel(); }, false,
         [] {
             // Left third: zero normals; middle: denormal ones (1e-40 is below float's normal range);
             // right: huge ones. Interpolation between the bands gives every length in between.
             return gridPlane(2.0, 24, glm::dvec3(0.0), [](float x, float) {
                 if (x < -0.6f) return glm::vec3(0.0f);
                 if (x < 0.6f) return glm::vec3(1e-40f, 0.0f, 1e-40f);
                 return glm::vec3(0.0f, 3e38f, 3e38f);
             });
         }},
        {"model-and-lights-1e6-from-origin", [far] { return translated(everyModel(), far); }, false,
         [far] { return gridPlane(2.0, 24, far); },
         [far] {
             ViewCamera c = planeCamera();
             c.eye += far;
             c.target += far;
             return c;
         }},
        {"camera-1e-3-from-surface", [] { return everyModel(); }, false, [] { return gridPlane(2.0, 24); },
         [] {
             ViewCamera c;
             c.eye = {0.1, 0.05, 1e-3};
             c.target = {0.1, 0.05, 0.0};
             c.yfovDeg = 60.0;
             return c;
         }},
        {"camera-1e-3-from-surface-grazing", [] { return everyModel(); }, false,
         [] { return gridPlane(2.0, 24); },
         [] {
             ViewCamera c;
             c.eye = {-1.0, -1.0, 1e-3};
             c.target = {0.5, 0.5, 0.0};
             c.yfovDeg = 60.0;
             return c;
         }},
    };
}

} // namespace

class TestQualityExtremes : public QObject {
    Q_OBJECT
    OffscreenRenderer m_gl;

  private slots:
    void initTestCase() {
        LR_REQUIRE_DISPLAY();
        QString error;
        QVERIFY2(m_gl.initialize(&error), qPrintable(error));
    }

    void extremes_data() {
        QTest::addColumn<int>("caseIndex");
        QTest::addColumn<bool>("sphere");
        QTest::addColumn<int>("quality");
        const auto all = cases();
        for (int i = 0; i < int(all.size()); ++i)
            for (bool sphere : {false, true})
                for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast})
                    if (!sphere || all[size_t(i)].sphereToo)
                        QTest::addRow("%s/%s/%s", sphere ? "sphere" : "grid", all[size_t(i)].name,
                                      tierName(q))
                            << i << sphere << int(q);
    }

    void extremes() {
        QFETCH(int, caseIndex);
        QFETCH(bool, sphere);
        QFETCH(int, quality);
        const ExtremeCase c = cases()[size_t(caseIndex)];
        const Quality q = Quality(quality);
        auto model = c.model ? c.model() : sphere ? sphereScene() : gridPlane(2.0, 24);
        const ViewCamera cam = c.camera ? c.camera() : sphere ? sphereCamera() : planeCamera();
        const double tolerance = q == Quality::Exact ? 1e-3 : q == Quality::Balanced ? 2e-3 : 1e300;
        RenderSettings s;
        s.toneMap = ToneMap::Reinhard;
        const TierFrame f = renderTier(m_gl, model, c.rig(), cam, kSize, q, tolerance, s);
        qInfo().noquote() << f.summary();
        QVERIFY2(f.error.isEmpty(), qPrintable(f.error));
        QCOMPARE(f.linear.nonFinite, 0);
        QCOMPARE(f.levels.nonFinite, 0);
        QVERIFY2(f.linear.covered > kSize.width() * kSize.height() / 10, qPrintable(f.summary()));
        if (q != Quality::Fast) {
            QVERIFY2(f.linear.failures == 0, qPrintable(f.summary()));
            QVERIFY2(f.linear.skipped <= f.linear.covered / 20, qPrintable(f.summary()));
        }
    }

    // Radiance is never negative, in any tier (a negative value would be a sign error, not rounding).
    void neverNegative() {
        for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast}) {
            RenderSettings s;
            s.msaaSamples = 0;
            s.hdrFloat32 = true;
            s.quality = q;
            QString error;
            QVERIFY(m_gl.setModel(gridPlane(2.0, 24), &error));
            m_gl.setRig(everyModel());
            FloatImage radiance;
            QVERIFY2(m_gl.renderRadiance(planeCamera(), kSize, s, &radiance, &error), qPrintable(error));
            for (const glm::vec4& p : radiance.pixels)
                QVERIFY2(p.x >= 0.0f && p.y >= 0.0f && p.z >= 0.0f, tierName(q));
        }
    }
};

LR_GL_TEST_MAIN(TestQualityExtremes)

#include "tst_qualityextremes.moc"
