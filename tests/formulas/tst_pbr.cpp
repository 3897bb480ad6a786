// The physically based BRDF of src/core/lighting.h (glTF 2.0 Appendix B) and its use in shade.h, checked
// against independent evaluations written here straight from the specification's formulas (D, V and F
// written naively, the visibility from Smith's Λ), against numerical properties derived from them (the
// GGX distribution integrates to 1 in projected solid angle; the specular lobe's directional albedo with
// F = 1 is at most 1: a white furnace), and at the extremes of issue 13 (roughness 0 and 1, metallic 0
// and 1, N·V -> 0 and < 0, a light on the surface, black and over-1 base colours, NaN inputs), in float and
// double.
#include "common.h"

#include <vector>

using namespace lr;
using namespace lr::lighting;
using namespace lr::test;

namespace {

// ---- the specification's formulas, written naively (double) ----

double naiveD(double nDotH, double alpha) { // α² / (π ((N·H)² (α² − 1) + 1)²) χ+(N·H)
    if (nDotH <= 0) return 0;
    const double a2 = alpha * alpha;
    const double b = nDotH * nDotH * (a2 - 1) + 1;
    return a2 / (kPi * b * b);
}

// Height-correlated Smith G2 = 1 / (1 + Λ(v) + Λ(l)), Λ(θ) = (−1 + sqrt(1 + α² tan²θ)) / 2 (Heitz 2014,
// eq. 99), and V = G2 / (4 N·L N·V): a different route to the same number as smithVisibility's.
double naiveV(double nDotL, double nDotV, double alpha) {
    const auto lambda = [&](double c) {
        const double tan2 = (1 - c * c) / (c * c);
        return (-1 + std::sqrt(1 + alpha * alpha * tan2)) / 2;
    };
    return 1.0 / (1 + lambda(nDotV) + lambda(nDotL)) / (4 * nDotL * nDotV);
}

double naiveF(double f0, double vDotH) {
    return f0 + (1 - f0) * std::pow(1 - vDotH, 5);
}

Vec3d dir(double thetaDeg, double phiDeg) {
    const double t = radians(thetaDeg), p = radians(phiDeg);
    return Vec3d(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

// ∫ f over μ = cos θ in [0, 1], on a grid dense near μ = 1 (s = log(1 − μ)), composite Simpson.
double integrateMu(const std::function<double(double)>& f, int n = 40000) { // n even
    const double s0 = std::log(1e-15), s1 = 0.0, h = (s1 - s0) / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double s = s0 + i * h, e = std::exp(s);
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        sum += w * f(1 - e) * e;
    }
    return sum * h / 3;
}

const std::vector<double> kRoughness = {0.0, kMinRoughness, 0.1, 0.25, 0.5, 0.75, 1.0};

} // namespace

class TestPbr : public QObject {
    Q_OBJECT
  private slots:
    void alphaFloorsAndClamps() {
        LR_NEAR(pbrAlpha(0.0), kMinRoughness * kMinRoughness, 1e-15);
        LR_NEAR(pbrAlpha(-1.0), kMinRoughness * kMinRoughness, 1e-15);
        LR_NEAR(pbrAlpha(0.5), 0.25, 1e-15);
        LR_NEAR(pbrAlpha(1.0), 1.0, 0);
        LR_NEAR(pbrAlpha(7.0), 1.0, 0);
        LR_NEAR(pbrAlpha(std::nan("")), 1.0, 0);
        LR_NEAR(pbrAlpha(std::numeric_limits<float>::quiet_NaN()), 1.0f, 0);
    }

    // D, V and F against the naive formulas at many angles and roughnesses.
    void termsMatchSpecification() {
        Gen g(13);
        for (double r : kRoughness) {
            const double alpha = pbrAlpha(r);
            for (int i = 0; i < 2000; ++i) {
                const Vec3d N = g.unitD(), H = g.around(N, g.uniform(0, kPi / 2 * 0.999));
                const double nDotH = glm::dot(N, H);
                const double d = ggxDistribution(N, H, alpha), e = naiveD(nDotH, alpha);
                QVERIFY2(
                    std::abs(d - e) <= 1e-9 * std::max(1.0, e),
                    qPrintable(
                        QStringLiteral("D(%1, α %2) = %3, spec %4").arg(nDotH).arg(alpha).arg(d).arg(e)));
                const double nl = g.uniform(1e-3, 1), nv = g.uniform(1e-3, 1);
                LR_NEAR(smithVisibility(nl, nv, alpha), naiveV(nl, nv, alpha), 1e-9 * naiveV(nl, nv, alpha));
                const double vh = g.uniform(0, 1), f0 = g.uniform(0, 1);
                LR_NEAR(fresnelSchlick(Vec3d(f0), vh).x, naiveF(f0, vh), 1e-12);
            }
        }
        // Behind the surface D is 0; F at grazing is 1, at normal incidence F0.
        QCOMPARE(ggxDistribution(Vec3d(0, 0, 1), Vec3d(1, 0, 0), 0.25), 0.0);
        QCOMPARE(ggxDistribution(Vec3d(0, 0, 1), Vec3d(0, 0, -1), 0.25), 0.0);
        LR_NEAR_VEC(fresnelSchlick(Vec3d(0.04), 0.0), Vec3d(1.0), 1e-15);
        LR_NEAR_VEC(fresnelSchlick(Vec3d(0.04), 1.0), Vec3d(0.04), 1e-15);
    }

    // The material is the specification's mix(dielectric_brdf, metal_brdf, metallic) (Appendix B.3.5, issue
    // 42): the lobes at any metallic are the metallic-weighted mean of the pure dielectric's and the pure
    // metal's, and the dielectric's diffuse is c_diff (1 − F_dielectric) / π with F0 = 0.04, written out
    // here from B.3.5's fresnel_mix. The simplified "final" form (1 − F with the mixed F0) fails the first
    // on a partly metallic material by the metal's Fresnel: at metallic 0.5, base 1 and V·H = 0.1 its
    // diffuse is half the mix's.
    void materialIsTheSpecificationsMix() {
        Gen g(42);
        for (int i = 0; i < 2000; ++i) {
            const Vec3d N(0, 0, 1), L = g.around(N, g.uniform(0, kPi / 2 * 0.99)),
                                    V = g.around(N, g.uniform(0, kPi / 2 * 0.99));
            const Vec3d base(g.uniform(0, 1), g.uniform(0, 1), g.uniform(0, 1));
            const double m = g.uniform(0, 1), alpha = pbrAlpha(g.uniform(0, 1)), cosTerm = glm::dot(N, L);
            const auto lobes = [&](double metallic) {
                return pbrLobes(N, L, V, pbrDiffuseColor(base, metallic), pbrF0(base, metallic), alpha,
                                cosTerm);
            };
            const PbrLobes<double> f = lobes(m), dielectric = lobes(0.0), metal = lobes(1.0);
            LR_NEAR_VEC(f.diffuse + f.specular,
                        (1 - m) * (dielectric.diffuse + dielectric.specular) +
                            m * (metal.diffuse + metal.specular),
                        1e-12 * (1 + glm::length(f.specular)));
            const Vec3d H = glm::normalize(L + V);
            const double fDielectric = naiveF(kDielectricF0, glm::dot(V, H));
            LR_NEAR_VEC(f.diffuse, base * (1 - m) * (1 - fDielectric) * cosTerm / kPi, 1e-12);
            QCOMPARE(metal.diffuse, Vec3d(0.0)); // a metal has no diffuse lobe
        }
        // The "final" form differs: base 1, metallic 0.5 (mixed F0 0.52), V·H = 0.1 (Schlick's weight 0.59).
        const Vec3d N(0, 0, 1), V = dir(84.26, 0), L = dir(84.26, 180);
        const double vh = glm::dot(V, glm::normalize(L + V));
        const PbrLobes<double> f =
            pbrLobes(N, L, V, pbrDiffuseColor(Vec3d(1), 0.5), pbrF0(Vec3d(1), 0.5), 0.25, 1.0);
        const double finalForm = 0.5 * (1 - naiveF(0.52, vh)) / kPi,
                     mixForm = 0.5 * (1 - naiveF(0.04, vh)) / kPi;
        LR_NEAR(f.diffuse.x, mixForm, 1e-12);
        QVERIFY2(mixForm > 1.1 * finalForm,
                 qPrintable(QStringLiteral("%1 vs %2").arg(mixForm).arg(finalForm)));
    }

    // ∫ D(h) (n·h) dω = 2π ∫₀¹ D(μ) μ dμ = 1: the microfacets' projected area is the macro-surface's.
    void distributionIsNormalised() {
        for (double r : kRoughness) {
            const double alpha = pbrAlpha(r);
            const double integral = 2 * kPi * integrateMu([&](double mu) {
                                        const double s = std::sqrt(std::max(0.0, 1 - mu * mu));
                                        return ggxDistribution(Vec3d(0, 0, 1), Vec3d(s, 0, mu), alpha) * mu;
                                    });
            qInfo("roughness %.4f: ∫D(n·h)dω = %.9f", r, integral);
            LR_NEAR(integral, 1.0, 1e-6);
        }
    }

    // White furnace: the specular lobe's directional albedo with F = 1, ∫ D V (n·l) dω_l (written over
    // half vectors, dω_l = 4 (v·h) dω_h), is at most 1 (height-correlated Smith loses energy to multiple
    // scattering, never gains it), and close to 1 for a smooth surface seen head-on.
    void specularAlbedoAtMostOne() {
        const Vec3d N(0, 0, 1);
        for (double r : kRoughness) {
            const double alpha = pbrAlpha(r);
            for (double thetaV : {0.0, 30.0, 60.0, 80.0, 89.0}) {
                const Vec3d V = dir(thetaV, 0);
                const int nPhi = 64;
                double albedo = 0;
                for (int k = 0; k < nPhi; ++k) {
                    const double phi = (k + 0.5) * 2 * kPi / nPhi;
                    albedo += integrateMu(
                                  [&](double mu) {
                                      const double s = std::sqrt(std::max(0.0, 1 - mu * mu));
                                      const Vec3d H(s * std::cos(phi), s * std::sin(phi), mu);
                                      const double vh = glm::dot(V, H);
                                      if (vh <= 0) return 0.0;
                                      const Vec3d L = 2 * vh * H - V;
                                      const double nl = glm::dot(N, L), nv = glm::dot(N, V);
                                      if (nl <= 0) return 0.0;
                                      return ggxDistribution(N, H, alpha) * smithVisibility(nl, nv, alpha) *
                                             nl * 4 * vh;
                                  },
                                  4000) *
                              2 * kPi / nPhi;
                }
                QVERIFY2(albedo <= 1.0 + 1e-4, qPrintable(QStringLiteral("roughness %1, θv %2: albedo %3")
                                                              .arg(r)
                                                              .arg(thetaV)
                                                              .arg(albedo, 0, 'g', 9)));
                qInfo("roughness %.4f, θv %2.0f°: specular albedo %.4f", r, thetaV, albedo);
                QVERIFY(albedo > 0.3);
                if (alpha < 0.01 && thetaV <= 30) LR_NEAR(albedo, 1.0, 0.01);
                // α = 1 seen head-on: D = 1/π and V = 1/(2(1 + cos θl)), so the integral is
                // ∫₀¹ c/(1 + c) dc = 1 − ln 2 (derived by hand).
                if (alpha == 1.0 && thetaV == 0.0) LR_NEAR(albedo, 1.0 - std::log(2.0), 1e-4);
            }
        }
    }

    // A hand-worked value: N = L = V, dielectric: F = 0.04, D = 1/(πα²), V = 1/4.
    void headOnByHand() {
        const Vec3d N(0, 0, 1), base(0.5, 0.25, 1.0);
        const double alpha = pbrAlpha(0.5);
        const PbrLobes<double> f =
            pbrLobes(N, N, N, pbrDiffuseColor(base, 0.0), pbrF0(base, 0.0), alpha, diffuseLambert(1.0));
        LR_NEAR_VEC(f.specular, Vec3d(0.04 / (kPi * alpha * alpha) * 0.25), 1e-12);
        LR_NEAR_VEC(f.diffuse, base * (0.96 / kPi), 1e-12);
        // A metal: no diffuse, F0 = the base colour.
        const PbrLobes<double> m =
            pbrLobes(N, N, N, pbrDiffuseColor(base, 1.0), pbrF0(base, 1.0), alpha, diffuseLambert(1.0));
        LR_NEAR_VEC(m.diffuse, Vec3d(0.0), 0);
        LR_NEAR_VEC(m.specular, base / (kPi * alpha * alpha) * 0.25, 1e-12);
    }

    // shadeSurface under PBR against an independent composition: a glTF point light (inverse square with
    // the KHR range window), ambient on the diffuse lobe, emissive.
    void shadeSurfaceMatchesComposition() {
        Gen g(7);
        ShadeSettings<double> st;
        st.model = ShadingModel::Pbr;
        st.ambient = Vec3d(0.03, 0.02, 0.01);
        for (int i = 0; i < 500; ++i) {
            Surface<double> s;
            s.position = Vec3d(g.uniform(-1, 1), g.uniform(-1, 1), g.uniform(-6, -3));
            s.normal = g.unitD();
            if (glm::dot(s.normal, -s.position) < 0) s.normal = -s.normal;
            s.albedo = Vec3d(g.uniform(0, 1), g.uniform(0, 1), g.uniform(0, 1));
            s.metallic = g.uniform(0, 1), s.roughness = g.uniform(0, 1), s.occlusion = g.uniform(0, 1);
            s.emissive = Vec3d(0.1, 0.0, 0.2);
            ShadeLight<double> l;
            l.type = LightType::Point, l.falloff = FalloffModel::InverseSquare, l.range = 20;
            l.position = s.position + g.unitD() * g.uniform(0.5, 5);
            l.color = l.specular = Vec3d(3, 2, 1);
            const ShadeLight<double> lights[] = {l};
            const Vec3d got = shadeSurface<double>(s, lights, st);

            const Vec3d toL = l.position - s.position;
            const double d = glm::length(toL);
            const Vec3d L = toL / d, V = -s.position / glm::length(s.position), H = glm::normalize(L + V);
            const double win = std::pow(std::clamp(1 - std::pow(d / 20, 4), 0.0, 1.0), 2) / (d * d);
            const double nl = glm::dot(s.normal, L), nv = glm::dot(s.normal, V), nh = glm::dot(s.normal, H);
            const double a = std::pow(std::max(s.roughness, kMinRoughness), 2);
            Vec3d expected = st.ambient * s.albedo * (1 - s.metallic) * s.occlusion / kPi + s.emissive;
            if (nl > 0) {
                for (int c = 0; c < 3; ++c) {
                    const double f0 = 0.04 * (1 - s.metallic) + s.albedo[c] * s.metallic;
                    const double F = naiveF(f0, glm::dot(V, H));
                    // The specification's mix: the dielectric's own Fresnel (F0 0.04) weighs the diffuse.
                    const double fDielectric = naiveF(0.04, glm::dot(V, H));
                    const double diffuse = (1 - fDielectric) * s.albedo[c] * (1 - s.metallic) / kPi;
                    const double spec = F * naiveD(nh, a) * naiveV(nl, std::max(nv, 1e-5), a);
                    expected[c] += win * l.color[c] * (diffuse + spec) * nl;
                }
            }
            LR_NEAR_VEC(got, expected, 1e-9 * std::max(1.0, glm::length(expected)));
        }
    }

    // The extremes: every result finite and non-negative, in float and in double.
    void extremesStayFinite() {
        const double nan = std::nan("");
        const std::vector<double> roughness = {0, 1e-30, kMinRoughness, 1, 2, -1, nan};
        const std::vector<double> metallic = {0, 1, -1, 2, nan};
        const std::vector<Vec3d> bases = {Vec3d(0), Vec3d(1), Vec3d(5, 20, 1e6), Vec3d(-1, 0.5, nan)};
        const Vec3d N(0, 0, 1);
        const std::vector<Vec3d> views = {Vec3d(0, 0, 1), dir(89.999, 0), dir(90, 0),
                                          dir(90.001, 0), dir(120, 30),   Vec3d(1, 0, 1e-30)};
        const std::vector<Vec3d> lightsAt = {Vec3d(0, 0, 2), Vec3d(0), Vec3d(1e-30, 0, 0), Vec3d(2, 0, 1e-7),
                                             Vec3d(0, 0, -1)}; // the last: on the surface, and behind it
        long checks = 0;
        for (double r : roughness)
            for (double m : metallic)
                for (const Vec3d& base : bases)
                    for (const Vec3d& view : views)
                        for (const Vec3d& at : lightsAt) {
                            Surface<double> sd;
                            sd.normal = N, sd.albedo = base, sd.metallic = m, sd.roughness = r;
                            sd.occlusion = m; // NaN and out-of-range occlusion too
                            sd.position = Vec3d(0);
                            ShadeSettings<double> st;
                            st.model = ShadingModel::Pbr;
                            st.ambient = Vec3d(0.1);
                            ShadeLight<double> l;
                            l.type = LightType::Point, l.falloff = FalloffModel::InverseSquare, l.range = -1;
                            l.position = at, l.color = l.specular = l.ambient = Vec3d(1e6);
                            // The viewer along `view`, far: V = view.
                            sd.position = -view * 10.0;
                            l.position += sd.position;
                            const ShadeLight<double> ld[] = {l};
                            const Vec3d rd = shadeSurface<double>(sd, ld, st);

                            Surface<float> sf;
                            sf.normal = Vec3f(N), sf.albedo = Vec3f(base), sf.metallic = float(m);
                            sf.roughness = float(r), sf.occlusion = float(m),
                            sf.position = Vec3f(sd.position);
                            ShadeSettings<float> stf;
                            stf.model = ShadingModel::Pbr;
                            stf.ambient = Vec3f(0.1f);
                            ShadeLight<float> lf;
                            lf.type = LightType::Point, lf.falloff = FalloffModel::InverseSquare,
                            lf.range = -1;
                            lf.position = Vec3f(l.position),
                            lf.color = lf.specular = lf.ambient = Vec3f(1e6f);
                            const ShadeLight<float> lfs[] = {lf};
                            const Vec3f rf = shadeSurface<float>(sf, lfs, stf);
                            const auto where = [&] {
                                return QStringLiteral(
                                           "roughness %1 metallic %2 base %3 view %4 light %5: double "
                                           "%6 float %7")
                                    .arg(r)
                                    .arg(m)
                                    .arg(vecStr(base), vecStr(view), vecStr(at), vecStr(rd), vecStr(toD(rf)));
                            };
                            QVERIFY2(finite(rd) && finite(rf), qPrintable(where()));
                            QVERIFY2(rd.x >= 0 && rd.y >= 0 && rd.z >= 0 && rf.x >= 0 && rf.y >= 0 &&
                                         rf.z >= 0,
                                     qPrintable(where()));
                            ++checks;
                        }
        qInfo("%ld extreme cases finite and non-negative in float and double", checks);
    }

    // Float against double for ordinary inputs: the GPU's precision is float.
    void floatAgreesWithDouble() {
        Gen g(21);
        double worst = 0;
        for (int i = 0; i < 20000; ++i) {
            const Vec3f N = g.unitF(), V = Vec3f(g.around(toD(N), g.uniform(0, 1.5)));
            const Vec3f L = Vec3f(g.around(toD(N), g.uniform(0, 1.55)));
            const float r = float(g.uniform(0, 1)), m = float(g.uniform(0, 1));
            const Vec3f base(float(g.uniform(0, 1)), float(g.uniform(0, 1)), float(g.uniform(0, 1)));
            const PbrLobes<float> f = pbrLobes(N, L, V, pbrDiffuseColor(base, m), pbrF0(base, m), pbrAlpha(r),
                                               diffuseLambert(glm::dot(N, L)));
            const PbrLobes<double> d = pbrLobes(toD(N), toD(L), toD(V), pbrDiffuseColor(toD(base), double(m)),
                                                pbrF0(toD(base), double(m)), pbrAlpha(double(r)),
                                                diffuseLambert(glm::dot(toD(N), toD(L))));
            for (int c = 0; c < 3; ++c) {
                const double e =
                    std::abs(double(f.specular[c]) - d.specular[c]) / std::max(1.0, d.specular[c]) +
                    std::abs(double(f.diffuse[c]) - d.diffuse[c]);
                worst = std::max(worst, e);
            }
        }
        qInfo("float vs double, worst relative error %.3g", worst);
        QVERIFY2(worst < 1e-4, qPrintable(QString::number(worst)));
    }
};

QTEST_APPLESS_MAIN(TestPbr)
#include "tst_pbr.moc"
