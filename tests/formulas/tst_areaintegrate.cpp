// Area lights (issue 16) as the reference integrates them (src/core/areaintegrate.h), against closed forms
// of lighting_area.h's definition: Lambert's polygon irradiance (rect, clipped at the surface's horizon),
// the coaxial disk's form factor, an emitter 1e4× the model filling the hemisphere (a directional light
// head on), a small far emitter (a point light of intensity L·A·cos θe); against a deterministic
// quadrature over the emitter's area for glossy lobes; and the extremes: a surface crossing the light's
// plane, a point on the light, zero width, grazing angles, two-sided, behind a one-sided emitter. The
// same extremes go through shadeAreaLight / shadeAreaLightPbr for finiteness and sign only (their accuracy
// is measured by `lightrig bench`, not asserted here).
#include "common.h"

#include "core/areaintegrate.h"
#include "core/lighting_area.h"

#include <vector>

using namespace lr;
using namespace lr::test;
using V = glm::dvec3;
using Light = lighting::ShadeLight<double>;

namespace {

// A rect (or disk) centred at c, emitting towards `normal`, its width along `x`.
Light area(LightType type, const V& c, const V& normal, const V& x, double hw, double hh,
           double radiance = 1.0) {
    Light l;
    l.type = type;
    l.position = c;
    l.direction = glm::normalize(normal);
    l.axisX = glm::normalize(x - glm::dot(x, l.direction) * l.direction);
    l.axisY = glm::cross(-l.direction, l.axisX); // axisX × axisY = -direction
    l.halfWidth = hw, l.halfHeight = type == LightType::Disk ? hw : hh;
    l.color = l.specular = V(radiance);
    l.ambient = V(0.0);
    return l;
}

lighting::ShadeSettings<double> classic() {
    lighting::ShadeSettings<double> st;
    st.model = ShadingModel::Classic;
    st.viewer = ViewerModel::Local;
    return st;
}

lighting::ShadeSettings<double> pbr() {
    lighting::ShadeSettings<double> st;
    st.model = ShadingModel::Pbr;
    st.viewer = ViewerModel::Local;
    return st;
}

lighting::Surface<double> surface(const V& p, const V& n, const V& albedo = V(0.8), const V& ks = V(0.0)) {
    lighting::Surface<double> s;
    s.position = p;
    s.normal = glm::normalize(n);
    s.albedo = albedo;
    s.specular = ks;
    return s;
}

// A tight stop rule for comparisons with closed forms (0.05 levels at EV 0, clamp).
envintegrate::Convergence tight() {
    envintegrate::Convergence c = areaintegrate::defaultConvergence(0.0, ToneMap::Clamp);
    c.targetLevels = 0.05;
    c.maxBatches = 4096;
    return c;
}

// ∫ (N·ω)⁺ dω over the rect's corners as seen from P, clipped at the plane N·(x − P) = 0 (Lambert 1760;
// Sutherland-Hodgman for the one plane).
double rectIrradiance(const Light& l, const V& P, const V& N) {
    std::vector<V> poly;
    for (auto [u, v] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}})
        poly.push_back(l.position + u * l.halfWidth * l.axisX + v * l.halfHeight * l.axisY - P);
    std::vector<V> clipped;
    for (size_t i = 0; i < poly.size(); ++i) {
        const V a = poly[i], b = poly[(i + 1) % poly.size()];
        const double da = glm::dot(a, N), db = glm::dot(b, N);
        if (da >= 0.0) clipped.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) clipped.push_back(a + (b - a) * (da / (da - db)));
    }
    double e = 0.0;
    for (size_t i = 0; i < clipped.size(); ++i) {
        const V a = glm::normalize(clipped[i]), b = glm::normalize(clipped[(i + 1) % clipped.size()]);
        const V c = glm::cross(a, b);
        const double len = glm::length(c);
        if (len > 0.0) e += lighting::safeAcos(glm::dot(a, b)) * glm::dot(c / len, N);
    }
    return std::abs(0.5 * e);
}

// The definition by the midpoint rule over the emitter's area: Σ response(ω) cos θe / d² dA (× 1/π classic).
V quadrature(const Light& l, const lighting::Surface<double>& s, const lighting::ShadeSettings<double>& st,
             int n) {
    const V Vv = lighting::viewVector(st, s.position);
    const V cDiff =
        st.model == ShadingModel::Pbr ? lighting::pbrDiffuseColor(s.albedo, s.metallic) : s.albedo;
    const V f0 = st.model == ShadingModel::Pbr ? lighting::pbrF0(s.albedo, s.metallic) : s.specular;
    const double alpha = lighting::pbrAlpha(s.roughness);
    V sum(0.0);
    const double dA = 4.0 * l.halfWidth * l.halfHeight / (double(n) * n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double u = (i + 0.5) / n * 2.0 - 1.0, v = (j + 0.5) / n * 2.0 - 1.0;
            if (l.type == LightType::Disk && u * u + v * v > 1.0) continue;
            const V d = l.position + u * l.halfWidth * l.axisX + v * l.halfHeight * l.axisY - s.position;
            const double d2 = glm::dot(d, d);
            const V w = d / std::sqrt(d2);
            const double cosE = std::abs(glm::dot(w, l.direction));
            sum += lighting::directionalResponse(l, s, st, Vv, w, cDiff, f0, alpha) * (cosE / d2 * dA);
        }
    return st.model == ShadingModel::Pbr ? sum : sum / kPi;
}

bool nonNegativeFinite(const V& v) {
    return finite(v) && v.x >= 0.0 && v.y >= 0.0 && v.z >= 0.0;
}

// |got − expected| within k standard errors plus a relative slack, per channel.
void expectWithin(const areaintegrate::Estimate& e, const V& expected, double rel, const char* what) {
    for (int c = 0; c < 3; ++c) {
        const double tol = 4.0 * e.standardError[c] + rel * std::abs(expected[c]) + 1e-12;
        QVERIFY2(std::abs(e.radiance[c] - expected[c]) <= tol,
                 qPrintable(QStringLiteral("%1: got %2 ± %3, expected %4")
                                .arg(QLatin1String(what), vecStr(e.radiance), vecStr(e.standardError),
                                     vecStr(expected))));
    }
}

} // namespace

class TestAreaIntegrate : public QObject {
    Q_OBJECT
  private slots:
    // Lambert's closed form: a rect fully above the horizon, head on, tilted, offset, and one the surface's
    // horizon cuts (clipped: grazing).
    void rectLambertClosedForm() {
        const V P(0.0, 0.0, -3.0);
        struct Case {
            V c, normal, x, n;
            double hw, hh;
            const char* what;
        };
        const Case cases[] = {
            {P + V(0, 2, 0), V(0, -1, 0), V(1, 0, 0), V(0, 1, 0), 0.5, 0.3, "head on"},
            {P + V(1, 2, 0.5), V(-0.3, -1, 0.2), V(1, 0, 0), V(0.2, 1, 0.1), 0.8, 0.4, "tilted, offset"},
            {P + V(0, 0.2, -1), V(0, 0, 1), V(1, 0, 0), V(0, 1, 0), 1.0, 0.6, "horizon cuts it"},
            {P + V(0, 0.01, -2), V(0, 0, 1), V(1, 0, 0), V(0, 1, 0), 1.0, 0.05, "grazing"},
        };
        for (const Case& k : cases) {
            const Light l = area(LightType::Rect, k.c, k.normal, k.x, k.hw, k.hh, 2.0);
            const lighting::Surface<double> s = surface(P, k.n, V(0.8, 0.5, 0.2));
            const V expected = 2.0 * s.albedo * rectIrradiance(l, P, s.normal) / kPi;
            const areaintegrate::Estimate e = areaintegrate::integrateOne(l, s, classic(), 7, tight());
            expectWithin(e, expected, 1e-3, k.what);
            QVERIFY2(e.converged, k.what);
        }
    }

    // A disk parallel to the surface on its normal: ∫ cos dω = π r² / (r² + h²).
    void diskCoaxialClosedForm() {
        const V P(0.0, 0.0, -3.0);
        for (double h : {0.1, 1.0, 10.0}) {
            const double r = 0.7;
            const Light l = area(LightType::Disk, P + V(0, h, 0), V(0, -1, 0), V(1, 0, 0), r, r, 3.0);
            const lighting::Surface<double> s = surface(P, V(0, 1, 0));
            const V expected = 3.0 * s.albedo * (r * r / (r * r + h * h));
            expectWithin(areaintegrate::integrateOne(l, s, classic(), 3, tight()), expected, 1e-3, "disk");
        }
    }

    // An emitter 1e4× the model's size just above the surface fills its hemisphere: the definition's
    // normalisation makes that a directional light of the same intensity head on (albedo × L, Lambert).
    void hugeEmitterIsDirectionalHeadOn() {
        const V P(0.0, 0.0, -3.0);
        for (LightType t : {LightType::Rect, LightType::Disk}) {
            const Light l = area(t, P + V(0, 1, 0), V(0, -1, 0), V(1, 0, 0), 1e4, 1e4, 1.5);
            const lighting::Surface<double> s = surface(P, V(0, 1, 0), V(0.6, 0.3, 0.9));
            expectWithin(areaintegrate::integrateOne(l, s, classic(), 11, tight()), 1.5 * s.albedo, 1e-3,
                         t == LightType::Rect ? "huge rect" : "huge disk");
            // And a surface point on such an emitter, 1e-9 in front of it, facing it.
            const lighting::Surface<double> on = surface(l.position + V(3, -1e-9, 2), V(0, 1, 0), V(0.5));
            expectWithin(areaintegrate::integrateOne(l, on, classic(), 5, tight()), V(1.5 * 0.5), 1e-3,
                         "on the emitter");
        }
    }

    // A small, far emitter is a point light of intensity L·A·cos θe: response(ω_c) × A cos θe / d².
    void smallFarEmitterIsPointLight() {
        const V P(0.0, 0.0, -3.0);
        for (bool glossy : {false, true}) {
            for (LightType t : {LightType::Rect, LightType::Disk}) {
                const Light l = area(t, P + V(10, 20, 5), V(-10, -20, -2), V(0, 0, 1), 0.01, 0.02, 1e4);
                lighting::Surface<double> s = surface(P, V(0.2, 1, 0.1), V(0.7), V(0.5));
                s.roughness = glossy ? 0.3 : 1.0;
                const lighting::ShadeSettings<double> st = glossy ? pbr() : classic();
                const V d = l.position - P;
                const V w = glm::normalize(d);
                const double omega =
                    lighting::areaOf(l) * std::abs(glm::dot(w, l.direction)) / glm::dot(d, d);
                const V Vv = lighting::viewVector(st, P);
                const V cDiff = glossy ? lighting::pbrDiffuseColor(s.albedo, 0.0) : s.albedo;
                const V f0 = glossy ? lighting::pbrF0(s.albedo, 0.0) : s.specular;
                V expected = lighting::directionalResponse(l, s, st, Vv, w, cDiff, f0,
                                                           lighting::pbrAlpha(s.roughness)) *
                             omega;
                if (!glossy) expected /= kPi;
                expectWithin(areaintegrate::integrateOne(l, s, st, 1, tight()), expected, 1e-3, "small far");
            }
        }
    }

    // Glossy lobes (GGX, Phong, Blinn-Phong) of a large close emitter against the quadrature over its area.
    void glossyAgainstQuadrature() {
        const V P(0.0, 0.0, -3.0);
        const Light rect =
            area(LightType::Rect, P + V(0.3, 1.0, 0.6), V(-0.1, -1, -0.4), V(1, 0, 0), 0.6, 0.4, 2.0);
        const Light disk =
            area(LightType::Disk, P + V(0.3, 1.0, 0.6), V(-0.1, -1, -0.4), V(1, 0, 0), 0.5, 0.5, 2.0);
        for (const Light& l : {rect, disk}) {
            for (double roughness : {0.15, 0.5}) {
                lighting::Surface<double> s = surface(P, V(0.1, 1, 0.5), V(0.9, 0.6, 0.3));
                s.roughness = roughness, s.metallic = 0.5;
                const V expected = quadrature(l, s, pbr(), 1200);
                expectWithin(areaintegrate::integrateOne(l, s, pbr(), 9, tight()), expected, 2e-3, "ggx");
            }
            for (SpecularModel m : {SpecularModel::Phong, SpecularModel::BlinnPhong}) {
                lighting::ShadeSettings<double> st = classic();
                st.specular = m;
                lighting::Surface<double> s = surface(P, V(0.1, 1, 0.5), V(0.5), V(0.6));
                s.shininess = 64;
                const V expected = quadrature(l, s, st, 1200);
                expectWithin(areaintegrate::integrateOne(l, s, st, 4, tight()), expected, 2e-3,
                             "phong/blinn");
            }
        }
    }

    // A surface crossing the light's plane: behind a one-sided emitter nothing, in its plane nothing, in
    // front Lambert's clipped form; two-sided: the mirror image behind.
    void surfaceCrossingTheLightsPlane() {
        const Light one = area(LightType::Rect, V(0, 0, -3), V(0, -1, 0), V(1, 0, 0), 1.0, 0.5, 1.0);
        Light two = one;
        two.twoSided = true;
        for (double y : {-1.0, -0.1, -1e-6, 0.0, 1e-6, 0.1, 1.0}) {
            const V P(0.4, y, -2.8); // under the emitter's centre (front: y < 0), normal along +x (grazing)
            const lighting::Surface<double> s = surface(P, V(1, 0.3 * (y < 0 ? 1 : -1), 0.2));
            const areaintegrate::Estimate e1 = areaintegrate::integrateOne(one, s, classic(), 2, tight());
            const areaintegrate::Estimate e2 = areaintegrate::integrateOne(two, s, classic(), 2, tight());
            QVERIFY(nonNegativeFinite(e1.radiance) && nonNegativeFinite(e2.radiance));
            const V expected = y == 0.0 ? V(0.0) : s.albedo * rectIrradiance(one, P, s.normal) / kPi;
            if (y >= 0.0)
                QCOMPARE(e1.radiance, V(0.0)); // behind or in its plane
            else
                expectWithin(e1, expected, 1e-3, "in front");
            expectWithin(e2, expected, 1e-3, "two-sided");
            QVERIFY(e1.errorLevels <= 0.05 + 1e-12 && e2.errorLevels <= 0.05 + 1e-12);
        }
    }

    // Zero width (or height, or radius): exactly nothing, and so from a point on the light itself.
    void zeroWidthAndPointOnTheLight() {
        const V P(0.0, 0.0, -3.0);
        const lighting::Surface<double> s = surface(P, V(0, 1, 0));
        for (auto [hw, hh] : {std::pair{0.0, 1.0}, {1.0, 0.0}, {0.0, 0.0}}) {
            const Light l = area(LightType::Rect, P + V(0, 1, 0), V(0, -1, 0), V(1, 0, 0), hw, hh);
            QCOMPARE(areaintegrate::integrateOne(l, s, classic(), 1, tight()).radiance, V(0.0));
        }
        for (LightType t : {LightType::Rect, LightType::Disk}) {
            Light l = area(t, P, V(0, 1, 0), V(1, 0, 0), 1.0, 1.0);
            l.twoSided = true; // the surface point lies in the emitter: neither side sees it
            QCOMPARE(areaintegrate::integrateOne(l, s, classic(), 1, tight()).radiance, V(0.0));
            QVERIFY(!areaintegrate::reaches(l, s));
        }
    }

    // Everything finite and non-negative over random configurations and both shadings (half-Lambert and
    // grazing views included), within the default stop rule's target, and the LTC placeholder's bodies
    // (shadeAreaLight / shadeAreaLightPbr) finite and non-negative on the same configurations.
    void randomExtremesFiniteAndConverged() {
        Gen rng(16);
        const auto dir = [&] { return rng.unitD(); };
        int over = 0, runs = 0;
        for (int i = 0; i < 300; ++i) {
            const LightType t = i % 2 ? LightType::Rect : LightType::Disk;
            const double size = std::pow(10.0, rng.uniform(-6.0, 4.0));
            Light l = area(t, V(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-6, -1)), dir(), dir(),
                           i % 7 == 0 ? 0.0 : size, size * rng.uniform(0.0, 2.0), rng.uniform(0.0, 5.0));
            l.twoSided = i % 3 == 0;
            l.diffuse = i % 5 == 0 ? DiffuseModel::HalfLambert : DiffuseModel::Lambert;
            l.ambient = V(0.01);
            lighting::Surface<double> s =
                surface(V(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-4, -2)), dir(),
                        V(rng.uniform(0, 1)), V(rng.uniform(0, 1)));
            if (i % 11 == 0) s.position = l.position + 0.3 * l.halfWidth * l.axisX; // on the light
            s.roughness = rng.uniform(0.0, 1.0), s.metallic = rng.uniform(0.0, 1.0);
            s.shininess = std::pow(10.0, rng.uniform(0.0, 3.0));
            lighting::ShadeSettings<double> st = i % 4 < 2 ? pbr() : classic();
            st.specular = i % 3 ? SpecularModel::Phong : SpecularModel::BlinnPhong;
            envintegrate::Convergence c = areaintegrate::defaultConvergence(0.0, ToneMap::Aces);
            const areaintegrate::Estimate e = areaintegrate::integrateOne(l, s, st, std::uint64_t(i), c);
            QVERIFY2(nonNegativeFinite(e.radiance) && finite(e.standardError) && std::isfinite(e.errorLevels),
                     qPrintable(QStringLiteral("case %1: %2").arg(i).arg(vecStr(e.radiance))));
            ++runs;
            if (!e.converged) ++over;
            const V Vv = lighting::viewVector(st, s.position);
            const V a = lighting::shadeAreaLight(l, s, st, Vv);
            const V b = lighting::shadeAreaLightPbr(
                l, s, st, Vv, lighting::pbrDiffuseColor(s.albedo, s.metallic),
                lighting::pbrF0(s.albedo, s.metallic), lighting::pbrAlpha(s.roughness));
            QVERIFY2(nonNegativeFinite(a) && nonNegativeFinite(b),
                     qPrintable(QStringLiteral("case %1").arg(i)));
        }
        // The cap is for pathological pixels; random configurations converge.
        QVERIFY2(over * 50 <= runs, qPrintable(QStringLiteral("%1 of %2 at the cap").arg(over).arg(runs)));
    }

    // The estimate's standard error is honest: over independent seeds, the spread of the estimates
    // matches the reported error (within a factor of 2), and the mean lies on the closed form.
    void standardErrorIsHonest() {
        const V P(0.0, 0.0, -3.0);
        const Light l = area(LightType::Rect, P + V(0.5, 1, 0.2), V(-0.2, -1, 0), V(1, 0, 0), 2.0, 1.0, 1.0);
        const lighting::Surface<double> s = surface(P, V(0, 1, 0.3), V(0.5));
        const double expected = 0.5 * rectIrradiance(l, P, s.normal) / kPi;
        envintegrate::Convergence c = areaintegrate::defaultConvergence(0.0, ToneMap::Clamp);
        c.maxBatches = 1; // a fixed number of points: the error is what it is
        double sum = 0.0, sum2 = 0.0, reported = 0.0;
        const int n = 200;
        for (int i = 0; i < n; ++i) {
            const areaintegrate::Estimate e =
                areaintegrate::integrateOne(l, s, classic(), std::uint64_t(i) * 7919u, c);
            sum += e.radiance.x, sum2 += e.radiance.x * e.radiance.x, reported += e.standardError.x;
        }
        const double mean = sum / n, spread = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
        reported /= n;
        QVERIFY2(std::abs(mean - expected) <= 4.0 * spread / std::sqrt(double(n)) + 1e-12,
                 qPrintable(QStringLiteral("mean %1, expected %2").arg(mean).arg(expected)));
        QVERIFY2(spread <= 2.0 * reported && reported <= 2.0 * spread + 1e-15,
                 qPrintable(QStringLiteral("spread %1, reported %2").arg(spread).arg(reported)));
    }
};

QTEST_APPLESS_MAIN(TestAreaIntegrate)
#include "tst_areaintegrate.moc"
