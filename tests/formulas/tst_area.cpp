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
using lighting::ShadeSettings;
using lighting::Surface;

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
        return lighting::shadeAreaLightPbr(
            c.l, c.s, c.st, V, lighting::pbrDiffuseColor(c.s.albedo, c.s.metallic),
            lighting::pbrF0(c.s.albedo, c.s.metallic), lighting::pbrAlpha(c.s.roughness));
    return lighting::shadeAreaLight(c.l, c.s, c.st, V);
}

// A Fit back from the table's cell (ltc.h: M⁻¹ ∝ [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]], M = R(φ)·S).
ltc::Fit fitFromTable(int i, int j) {
    const float* t = ltc::ltcTable() + size_t((j * ltc::kLtcSize + i) * ltc::kLtcFloats);
    const double m00 = t[0], m02 = t[1], m20 = t[2], m22 = t[3];
    ltc::Fit f;
    f.c = std::sqrt(m20 * m20 + m22 * m22);
    f.phi = std::atan2(m20, m22);
    const double cs = std::cos(f.phi), sn = std::sin(f.phi);
    f.a = f.c / (m00 * cs - m02 * sn);
    f.b = -(m00 * sn + m02 * cs) * f.a / f.c;
    f.scale = t[4], f.bias = t[5];
    return f;
}

template <typename T> lighting::ShadeLight<T> castArea(const AreaLight& l) {
    lighting::ShadeLight<T> o;
    o.type = l.type, o.diffuse = l.diffuse, o.twoSided = l.twoSided;
    o.position = Vec3<T>(l.position), o.direction = Vec3<T>(l.direction);
    o.axisX = Vec3<T>(l.axisX), o.axisY = Vec3<T>(l.axisY);
    o.halfWidth = T(l.halfWidth), o.halfHeight = T(l.halfHeight);
    o.color = Vec3<T>(l.color), o.specular = Vec3<T>(l.specular), o.ambient = Vec3<T>(l.ambient);
    return o;
}

template <typename T> lighting::Surface<T> castSurface(const Surface<double>& s) {
    lighting::Surface<T> o;
    o.position = Vec3<T>(s.position), o.normal = Vec3<T>(s.normal), o.albedo = Vec3<T>(s.albedo);
    o.specular = Vec3<T>(s.specular), o.shininess = T(s.shininess), o.roughness = T(s.roughness);
    o.metallic = T(s.metallic);
    return o;
}

template <typename T>
Vec3<T> shadeArea(const lighting::ShadeLight<T>& l, const lighting::Surface<T>& s, ShadingModel m,
                  SpecularModel spec) {
    lighting::ShadeSettings<T> st;
    st.model = m;
    st.specular = spec;
    st.ambient = Vec3<T>(0);
    const lighting::ShadeLight<T> lights[] = {l};
    return lighting::shadeSurface<T>(s, lights, st);
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
        QVERIFY2(std::abs(got.x / c.s.albedo.x - expected) < 1e-9,
                 qPrintable(num(got.x / c.s.albedo.x) + " vs " + num(expected)));
    }

    // Lambert diffuse (classic and PBR without Fresnel: f0 = 0 by a black metal... c_diff with f0 = 0.04
    // at the emitter's mean direction) against the quadrature: exact for the rect up to the quadrature.
    void lambertMatchesQuadrature() {
        for (double view : {0.0, 60.0})
            for (const Vec3d centre :
                 {Vec3d(0, 0, 2), Vec3d(1.5, 0.5, 0.6), Vec3d(2, 0, 0.3), Vec3d(0.5, 0.2, 0.05)}) {
                Scene c = scene(LightType::Rect, view, centre, 0.7, 1, ShadingModel::Classic);
                c.s.specular = Vec3d(0);
                const double got = luminance(direct(c)), ref = luminance(areaQuadrature(c.l, c.s, c.st, 600));
                QVERIFY2(std::abs(got - ref) <= 2e-4 * ref + 1e-9,
                         qPrintable(QStringLiteral("view %1 centre %2: %3 vs %4")
                                        .arg(view)
                                        .arg(vecStr(centre), num(got), num(ref))));
            }
    }

    // GGX specular by LTC against the quadrature over a grid of roughness, view angles and placements.
    // Two errors: relative to the reference (floor 1e-3), and relative to the brightest placement at that
    // roughness and view (what a highlight's visible error is measured against). Prints the table of
    // docs/lighting-models.md; asserts a bound on the second.
    void ggxMatchesQuadrature() {
        const Vec3d placements[] = {Vec3d(0, 0, 2), Vec3d(-1.5, 0, 1.5), Vec3d(-2, 0.5, 0.5), Vec3d(1, 1, 1),
                                    Vec3d(0.3, 0, 0.4)};
        for (double r : {0.25, 0.5, 0.75, 1.0})
            for (double view : {0.0, 30.0, 60.0, 80.0}) {
                double got[5], ref[5], peak = 0;
                for (int k = 0; k < 5; ++k) {
                    Scene c = scene(LightType::Rect, view, placements[k], 0.6, r, ShadingModel::Pbr);
                    c.l.color = Vec3d(0); // specular alone
                    got[k] = luminance(direct(c)), ref[k] = luminance(areaQuadrature(c.l, c.s, c.st, 500));
                    peak = std::max(peak, ref[k]);
                }
                double worstRel = 0, worstPeak = 0;
                for (int k = 0; k < 5; ++k) {
                    worstRel = std::max(worstRel, std::abs(got[k] - ref[k]) / std::max(ref[k], 1e-3));
                    worstPeak = std::max(worstPeak, std::abs(got[k] - ref[k]) / peak);
                    if (qEnvironmentVariableIsSet("LIGHTRIG_AREA_VERBOSE"))
                        qInfo("  at %s: LTC %.6g quadrature %.6g", qPrintable(vecStr(placements[k])), got[k],
                              ref[k]);
                }
                qInfo("GGX r %.2f view %2.0f: max relative error %.3f, max error / brightest %.3f", r, view,
                      worstRel, worstPeak);
                QVERIFY2(worstPeak < (view < 50   ? 0.1
                                      : view < 70 ? 0.3
                                                  : 1.3),
                         qPrintable(QStringLiteral("r %1 view %2").arg(r).arg(view)));
            }
    }

    // Caps along the mirror plane from the grazing mirror direction up to 60°, and a large emitter, at views
    // from 60° down to 2° above the horizon: the mean |log(LTC / quadrature)| over all of them, the figure
    // the fit's metric was chosen by (docs/lighting-models.md "The LTC table": 0.181 for the first, L³
    // table; 0.108 for the L¹ fit of the lobe as shaded).
    void ggxCapsAtGrazingViews() {
        double sum = 0;
        int count = 0;
        for (double r : {0.2, 0.3, 0.5, 0.8})
            for (double elevation : {60.0, 30.0, 10.0, 5.0, 2.0}) {
                struct Cap {
                    double elevation, h;
                };
                const Cap caps[] = {
                    {elevation, 0.1}, {std::min(2 * elevation, 89.0), 0.1}, {30, 0.1}, {60, 0.1}, {45, 1.5}};
                for (const Cap& cap : caps) {
                    const double e = radians(cap.elevation);
                    // The eye is on +x: the mirror side is −x.
                    Scene c = scene(LightType::Rect, 90 - elevation,
                                    2.0 * Vec3d(-std::cos(e), 0, std::sin(e)), cap.h, r, ShadingModel::Pbr);
                    c.l.color = Vec3d(0); // specular alone
                    const double got = luminance(direct(c)),
                                 ref = luminance(areaQuadrature(c.l, c.s, c.st, 200));
                    QVERIFY(std::isfinite(got) && got >= 0);
                    if (ref > 1e-9 && got > 0) {
                        if (qEnvironmentVariableIsSet("LIGHTRIG_AREA_VERBOSE"))
                            qInfo("  r %.1f view %2.0f cap %2.0f h %.1f: LTC %.4g quadrature %.4g", r,
                                  elevation, cap.elevation, cap.h, got, ref);
                        sum += std::abs(std::log(got / ref));
                        ++count;
                    }
                }
            }
        QCOMPARE(count, 100);
        qInfo("mean |log(LTC / quadrature)| over %d caps: %.3f", count, sum / count);
        QVERIFY(sum / count < 0.13);
    }

    // The fit is reproducible: a handful of cells refitted from their neighbour (the warm start the
    // table's fit used) come back as the table has them.
    void tableMatchesRefit() {
        const std::pair<int, int> cells[] = {{63, 10}, {40, 20}, {20, 33}, {8, 12}, {50, 60}};
        for (const auto& [i, j] : cells) {
            const ltc::Fit start = fitFromTable(i, j - 1);
            const ltc::Fit f = ltc::fitCell(i, j, start);
            const std::array<double, 4> inv = f.inverse();
            const float* t = ltc::ltcTable() + size_t((j * ltc::kLtcSize + i) * ltc::kLtcFloats);
            for (int k = 0; k < 4; ++k)
                QVERIFY2(std::abs(inv[size_t(k)] - t[k]) <= 2e-2 * std::max(1.0, std::abs(double(t[k]))),
                         qPrintable(QStringLiteral("cell (%1, %2) entry %3: refit %4, table %5")
                                        .arg(i)
                                        .arg(j)
                                        .arg(k)
                                        .arg(num(inv[size_t(k)]), num(t[k]))));
            QVERIFY(std::abs(f.scale / f.horizon - t[4]) <= 1e-6 * std::max(1.0, double(t[4])));
            QVERIFY(std::abs(f.bias / f.horizon - t[5]) <= 1e-6 * std::max(1.0, double(t[5])));
            QVERIFY(std::abs(f.horizon - ltc::horizonShare(inv[0], inv[2])) <= 1e-9);
        }
    }

    // (scale + bias)·h is the GGX lobe's directional albedo: the split-sum table's A + B (core/envbrdf.h),
    // independently integrated (visible-normal sampling), at a few cells; h the LTC's share above the
    // horizon from the table's own M⁻¹.
    void tableNormMatchesEnvBrdf() {
        for (int i : {10, 32, 63})
            for (int j : {0, 20, 40}) {
                const float* t = ltc::ltcTable() + size_t((j * ltc::kLtcSize + i) * ltc::kLtcFloats);
                const double h = ltc::horizonShare(t[0], t[2]);
                QVERIFY(h > 0.5 && h <= 1);
                const envbrdf::Dfg d = envbrdf::integrate(ltc::cellNDotV(j), ltc::cellRoughness(i), 4096);
                QVERIFY2(std::abs(t[4] * h - d.scale) < 5e-3 && std::abs(t[5] * h - d.bias) < 5e-3,
                         qPrintable(QStringLiteral("cell (%1, %2): scale %3 bias %4 (h %7), envbrdf %5 %6")
                                        .arg(i)
                                        .arg(j)
                                        .arg(t[4] * h)
                                        .arg(t[5] * h)
                                        .arg(d.scale)
                                        .arg(d.bias)
                                        .arg(h)));
            }
    }

    // The disk as an area-preserving octagon, half-Lambert's mean-square cos², and the classic Phong /
    // Blinn-Phong lobes as cosine LTCs: each against the quadrature (printed for the docs' table).
    void approximationsMeasured() {
        const Vec3d placements[] = {Vec3d(0, 0, 2), Vec3d(-1.5, 0, 1.5), Vec3d(-2, 0.5, 0.5), Vec3d(1, 1, 1),
                                    Vec3d(0.3, 0, 0.4)};
        struct Case {
            const char* name;
            LightType type;
            ShadingModel model;
            SpecularModel spec;
            DiffuseModel diffuse;
            bool specularOnly;
            double shininess, roughness, bound;
        };
        const Case cases[] = {
            {"disk Lambert (octagon)", LightType::Disk, ShadingModel::Classic, SpecularModel::Phong,
             DiffuseModel::Lambert, false, 0, 1, 0.05},
            {"disk GGX r0.5 (octagon)", LightType::Disk, ShadingModel::Pbr, SpecularModel::Phong,
             DiffuseModel::Lambert, true, 0, 0.5, 0.65},
            {"rect half-Lambert", LightType::Rect, ShadingModel::Classic, SpecularModel::Phong,
             DiffuseModel::HalfLambert, false, 0, 1, 0.1},
            {"rect PBR diffuse (1-F)", LightType::Rect, ShadingModel::Pbr, SpecularModel::Phong,
             DiffuseModel::Lambert, false, 0, 1, 0.1},
            {"rect Phong n=8", LightType::Rect, ShadingModel::Classic, SpecularModel::Phong,
             DiffuseModel::Lambert, true, 8, 1, 0.6},
            {"rect Phong n=64", LightType::Rect, ShadingModel::Classic, SpecularModel::Phong,
             DiffuseModel::Lambert, true, 64, 1, 0.6},
            {"rect Blinn-Phong n=32", LightType::Rect, ShadingModel::Classic, SpecularModel::BlinnPhong,
             DiffuseModel::Lambert, true, 32, 1, 1e3},
            {"rect Blinn-Phong n=256", LightType::Rect, ShadingModel::Classic, SpecularModel::BlinnPhong,
             DiffuseModel::Lambert, true, 256, 1, 1e3},
        };
        for (const Case& k : cases) {
            double worstRel = 0, worstPeak = 0;
            for (double view : {0.0, 30.0, 60.0, 80.0}) {
                double got[5], ref[5], peak = 0;
                for (int q = 0; q < 5; ++q) {
                    Scene c = scene(k.type, view, placements[q], 0.5, k.roughness, k.model, k.spec);
                    c.l.diffuse = k.diffuse;
                    c.s.shininess = k.shininess;
                    if (k.specularOnly)
                        c.l.color = Vec3d(0);
                    else
                        c.l.specular = Vec3d(0);
                    got[q] = luminance(direct(c)), ref[q] = luminance(areaQuadrature(c.l, c.s, c.st, 400));
                    peak = std::max(peak, ref[q]);
                }
                for (int q = 0; q < 5; ++q) {
                    worstRel = std::max(worstRel, std::abs(got[q] - ref[q]) / std::max(ref[q], 1e-3));
                    worstPeak = std::max(worstPeak, std::abs(got[q] - ref[q]) / peak);
                    if (qEnvironmentVariableIsSet("LIGHTRIG_AREA_VERBOSE"))
                        qInfo("  %s view %.0f at %s: %.6g quadrature %.6g", k.name, view,
                              qPrintable(vecStr(placements[q])), got[q], ref[q]);
                }
            }
            qInfo("%s: max relative error %.4f, max error / brightest %.4f", k.name, worstRel, worstPeak);
            QVERIFY2(worstPeak < k.bound, k.name);
        }
    }

    // Everything finite and non-negative at the extremes, in float and double: a surface crossing the
    // light's plane, on the light, zero width, an emitter 1e4× the scene, grazing and back-facing views,
    // roughness 0, shininess 0 and 1e4.
    void extremesFinite() {
        int count = 0;
        for (LightType type : {LightType::Rect, LightType::Disk})
            for (bool twoSided : {false, true})
                for (ShadingModel m : {ShadingModel::Pbr, ShadingModel::Classic})
                    for (SpecularModel spec : {SpecularModel::Phong, SpecularModel::BlinnPhong})
                        for (DiffuseModel diffuse : {DiffuseModel::Lambert, DiffuseModel::HalfLambert})
                            for (double hw : {0.0, 1e-6, 0.5, 1e4})
                                for (const Vec3d& offset :
                                     {Vec3d(0, 0, 0), Vec3d(0, 0, 1e-7), Vec3d(0.3, 0.2, 0), Vec3d(0.2, 0, 1),
                                      Vec3d(2, 0, -0.1), Vec3d(0, 0, -1)})
                                    for (const Vec3d& N : {Vec3d(0, 0, 1), Vec3d(1, 0, 0), Vec3d(0, 0, -1),
                                                           Vec3d(0.7071, 0, 0.7071)})
                                        for (double param : {0.0, 0.5, 1e4}) {
                                            // The emitter lies in z = 0 facing +z; the eye at the origin.
                                            AreaLight l = makeArea(type, Vec3d(0, 0, -3), Vec3d(0, 0, 1), hw,
                                                                   hw * 0.5, twoSided);
                                            l.diffuse = diffuse;
                                            Surface<double> s =
                                                surfaceAt(l.position + offset, N, param > 1 ? 0 : param);
                                            s.shininess = param;
                                            const Vec3d d = shadeArea<double>(l, s, m, spec);
                                            const Vec3f f = shadeArea<float>(castArea<float>(l),
                                                                             castSurface<float>(s), m, spec);
                                            for (int c = 0; c < 3; ++c) {
                                                QVERIFY2(std::isfinite(d[c]) && d[c] >= 0,
                                                         qPrintable(vecStr(d)));
                                                QVERIFY2(std::isfinite(f[c]) && f[c] >= 0,
                                                         qPrintable(vecStr(toD(f))));
                                            }
                                            ++count;
                                        }
        QVERIFY(count > 1000);
    }

    // Float against double on ordinary placements: within 1e-4 relative (or 1e-6 absolute).
    void floatMatchesDouble() {
        double worst = 0;
        for (LightType type : {LightType::Rect, LightType::Disk})
            for (ShadingModel m : {ShadingModel::Pbr, ShadingModel::Classic})
                for (double view : {0.0, 45.0, 80.0})
                    for (const Vec3d& p : {Vec3d(0, 0, 2), Vec3d(-1.5, 0.3, 1.5), Vec3d(2, 0, 0.2)})
                        for (double r : {0.1, 0.5, 1.0}) {
                            Scene c = scene(type, view, p, 0.6, r, m);
                            const Vec3d d = shadeArea<double>(c.l, c.s, m, SpecularModel::Phong);
                            const Vec3f f = shadeArea<float>(castArea<float>(c.l), castSurface<float>(c.s), m,
                                                             SpecularModel::Phong);
                            for (int k = 0; k < 3; ++k) {
                                const double e =
                                    std::abs(double(f[k]) - d[k]) / std::max(std::abs(d[k]), 1e-2);
                                worst = std::max(worst, e);
                                QVERIFY2(e < 1e-4, qPrintable(vecStr(toD(f)) + " vs " + vecStr(d)));
                            }
                        }
        qInfo("float against double: max relative difference %.3g", worst);
    }
};

QTEST_APPLESS_MAIN(TestArea)
#include "tst_area.moc"
