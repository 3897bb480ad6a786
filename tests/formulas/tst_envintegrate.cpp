// The environment's contribution as the reference integrates it (src/core/envintegrate.h), against
// closed forms of the definition above `struct Environment` (environment.h): the furnace (classic and
// physically based), an environment bright above the horizon only, half-Lambert, Phong and Blinn-Phong
// in a uniform environment, a single texel against the directional light it is defined to be, rotation
// and intensity; and the numerical integrator against the exact sum over texels, with its standard error
// checked for honesty.
#include "common.h"

#include "core/envintegrate.h"

#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>
#include <vector>

using namespace lr;
using namespace lr::envintegrate;
using namespace lr::test;
using V = glm::dvec3;

namespace {

std::shared_ptr<EnvironmentImage> image(int w, int h, const std::function<glm::vec3(int, int)>& at) {
    auto img = std::make_shared<EnvironmentImage>();
    img->width = w, img->height = h;
    img->texels.resize(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img->at(x, y) = at(x, y);
    return img;
}

std::shared_ptr<EnvironmentImage> uniform(double value, int w = 64, int h = 32) {
    return image(w, h, [&](int, int) { return glm::vec3(float(value)); });
}

lighting::ShadeSettings<double> classic(SpecularModel sm = SpecularModel::Phong) {
    lighting::ShadeSettings<double> st;
    st.model = ShadingModel::Classic;
    st.specular = sm;
    st.viewer = ViewerModel::Infinite; // V = +Z (view space)
    return st;
}

lighting::ShadeSettings<double> pbr() {
    lighting::ShadeSettings<double> st;
    st.model = ShadingModel::Pbr;
    st.viewer = ViewerModel::Local;
    return st;
}

// A surface 3 units in front of the eye (so V = +Z under either viewer) with the given normal.
lighting::Surface<double> surface(const V& normal, const V& albedo, const V& ks = V(0.0),
                                  double shininess = 32) {
    lighting::Surface<double> s;
    s.position = V(0.0, 0.0, -3.0);
    s.normal = glm::normalize(normal);
    s.albedo = albedo;
    s.specular = ks;
    s.shininess = shininess;
    return s;
}

V randomUnit(std::mt19937& rng) {
    std::normal_distribution<double> g;
    return glm::normalize(V(g(rng), g(rng), g(rng)));
}

// A normal that faces the viewer (+Z) enough for a well-defined surface.
V facingNormal(std::mt19937& rng) {
    for (;;) {
        const V n = randomUnit(rng);
        if (n.z > 0.2) return n;
    }
}

const glm::dmat3 kIdentity(1.0);

// 0.1 level aimed at, at −3 EV: values up to 8 stay below the display's white (where a clamped display
// would stop the sampling, since no error can be seen there).
Convergence tight() {
    Convergence c;
    c.exposureEV = -3.0;
    c.targetLevels = 0.1;
    c.maxBatches = 256;
    return c;
}

// |a − b| within k standard errors plus the hard bound (per channel).
bool within(const V& a, const V& b, const Estimate& e, double k = 4.0, double slack = 1e-12) {
    for (int c = 0; c < 3; ++c)
        if (!(std::abs(a[c] - b[c]) <= k * e.standardError[c] + e.bound[c] + slack * (1.0 + std::abs(b[c]))))
            return false;
    return true;
}

QString describe(const V& got, const V& want, const Estimate& e) {
    return QStringLiteral("got %1 want %2 (se %3, bound %4, %5 samples)")
        .arg(vecStr(got), vecStr(want), vecStr(e.standardError), vecStr(e.bound))
        .arg(e.samples);
}

// ∫ over the hemisphere around +Z of f(cos θ), by Simpson's rule in θ (f smooth).
double hemisphere(const std::function<double(double theta)>& f, int n = 200000) {
    const double h = (kPi / 2) / n;
    double s = f(0.0) * 0.0 + f(kPi / 2) * 1.0; // × sin θ
    for (int i = 1; i < n; ++i)
        s += (i % 2 ? 4.0 : 2.0) * f(i * h) * std::sin(i * h);
    return 2.0 * kPi * s * h / 3.0;
}

} // namespace

class TestEnvIntegrate : public QObject {
    Q_OBJECT
  private slots:
    // (1) Classic Lambert in a uniform environment of 1 gives exactly the albedo, at any normal.
    void furnaceClassic() {
        const EnvironmentField field(uniform(1.0), 0.0, 0.0);
        std::mt19937 rng(7);
        for (int i = 0; i < 50; ++i) {
            const V albedo(0.2 + 0.8 * (i % 5) / 4.0, 0.5, 1.0);
            const lighting::Surface<double> s = surface(facingNormal(rng), albedo);
            const Estimate e = field.integrate(s, classic(), kIdentity, std::uint64_t(i), tight());
            QVERIFY2(e.samples == 0, "no specular: the diffuse quadrature alone");
            QVERIFY2(within(e.radiance, albedo, e, 0.0), qPrintable(describe(e.radiance, albedo, e)));
            QVERIFY2(e.errorLevels <= tight().targetLevels, qPrintable(num(e.errorLevels)));
            // The definition itself (a light per texel centre) agrees to the discretisation's O(Δ²).
            const V sum = environmentRadianceBySum(field, s, classic(), kIdentity);
            QVERIFY2(glm::length(sum - albedo) < 2e-3, qPrintable(vecStr(sum)));
        }
    }

    // (1) Physically based, white dielectric (metallic 0), uniform 1, seen head-on. The diffuse lobe is
    // (1 − F)·c_diff/π·N·L with F Schlick's at V·H, so the furnace does NOT give the albedo: it gives
    // (1 − F0)·(1 − (1/π)∫(1 − V·H)⁵ N·L dω) = 0.96·(1 − …) for the diffuse, computed here in closed
    // form; the lobe without Fresnel (c_diff/π ∫ N·L) integrates to the albedo exactly; diffuse plus
    // specular of a rough white dielectric stays at or below 1.
    void furnacePbr() {
        const EnvironmentField field(uniform(1.0), 0.0, 0.0);
        // The Fresnel share, with v = n = +Z: h halfway between ω (polar angle θ) and v, V·H = cos(θ/2).
        const double fresnelShare =
            hemisphere([](double t) { return std::pow(1.0 - std::cos(t / 2), 5) * std::cos(t); }) / kPi;
        const double diffuseExpected = (1.0 - lighting::kDielectricF0) * (1.0 - fresnelShare);
        qInfo("PBR furnace, white dielectric, head-on: diffuse lobe = 0.96 × (1 − %.9f) = %.9f", fresnelShare,
              diffuseExpected);
        QVERIFY(fresnelShare > 0.0 && fresnelShare < 0.01);
        // The diffuse lobe alone (specular removed by a 2D quadrature of pbrLobes' diffuse term).
        const V n(0, 0, 1), v(0, 0, 1);
        double diffuse = 0.0;
        const int nt = 2000, np = 64;
        for (int i = 0; i < nt; ++i)
            for (int j = 0; j < np; ++j) {
                const double t = (i + 0.5) * (kPi / 2) / nt, p = (j + 0.5) * 2 * kPi / np;
                const V w(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
                const auto lobes = lighting::pbrLobes(n, w, v, V(1.0), V(0.04), 1.0, std::cos(t));
                diffuse += lobes.diffuse.x * std::sin(t) * (kPi / 2 / nt) * (2 * kPi / np);
            }
        QVERIFY2(std::abs(diffuse - diffuseExpected) < 1e-6, qPrintable(num(diffuse)));
        // Without Fresnel: c_diff/π · ∫ L (n·ω)⁺ = albedo.
        V bound;
        const V E = field.irradiance(n, 1e-9, &bound);
        QVERIFY2(std::abs(E.x / kPi - 1.0) <= bound.x / kPi + 1e-12, qPrintable(vecStr(E)));
        // The whole BRDF, head-on, against an independent 2D quadrature of pbrLobes (diffuse + specular):
        // rough white dielectrics reflect at most 1 and more than the diffuse lobe alone. (At roughness 0.2
        // the glTF BRDF, whose diffuse (1 − F) uses the light's half-vector, reflects slightly more than 1:
        // printed, not asserted.)
        for (double rough : {1.0, 0.5, 0.2}) {
            const double alpha = lighting::pbrAlpha(rough);
            double total = 0.0;
            const int nt2 = 6000;
            for (int i = 0; i < nt2; ++i)
                for (int j = 0; j < np; ++j) {
                    const double t = (i + 0.5) * (kPi / 2) / nt2, p = (j + 0.5) * 2 * kPi / np;
                    const V w(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
                    const auto lobes = lighting::pbrLobes(n, w, v, V(1.0), V(0.04), alpha, std::cos(t));
                    total +=
                        (lobes.diffuse.x + lobes.specular.x) * std::sin(t) * (kPi / 2 / nt2) * (2 * kPi / np);
                }
            lighting::Surface<double> s = surface(V(0, 0, 1), V(1.0));
            s.metallic = 0.0, s.roughness = rough;
            const Estimate e = field.integrate(s, pbr(), kIdentity, 3, tight());
            qInfo(
                "roughness %.1f: white dielectric in the furnace reflects %.6f (se %.2g); 2D quadrature %.6f",
                rough, e.radiance.x, e.standardError.x, total);
            QVERIFY2(within(e.radiance, V(total), e, 4.0, 2e-5),
                     qPrintable(describe(e.radiance, V(total), e)));
            QVERIFY(total > diffuseExpected);
            if (rough >= 0.5) QVERIFY2(total <= 1.0, qPrintable(num(total)));
        }
    }

    // (2) Radiance 1 above the horizon, 0 below: E(n) = π(1 + n·up)/2, Lambert = albedo(1 + n·up)/2.
    void upperHalf() {
        const EnvironmentField field(
            image(64, 32, [](int, int y) { return glm::vec3(y < 16 ? 1.0f : 0.0f); }), 0.0, 0.0);
        std::mt19937 rng(11);
        for (int i = 0; i < 100; ++i) {
            const V n = randomUnit(rng);
            V bound;
            const V E = field.irradiance(n, 1e-7, &bound);
            const double want = kPi * (1.0 + n.y) / 2.0;
            QVERIFY2(std::abs(E.x - want) <= bound.x + 1e-12 && bound.x < 1e-5,
                     qPrintable(QStringLiteral("n %1: %2 vs %3 (bound %4)")
                                    .arg(vecStr(n), num(E.x), num(want), num(bound.x))));
        }
        for (int i = 0; i < 30; ++i) {
            const V albedo(0.9, 0.5, 0.1);
            const lighting::Surface<double> s = surface(facingNormal(rng), albedo);
            const Estimate e = field.integrate(s, classic(), kIdentity, 1, tight());
            const V want = albedo * (1.0 + s.normal.y) / 2.0;
            QVERIFY2(within(e.radiance, want, e, 0.0), qPrintable(describe(e.radiance, want, e)));
        }
    }

    // (3) A single bright texel IS a directional light of its direction and of irradiance L·Ω (physically
    // based: lux; classic: intensity L·Ω/π), through shadeSurface, to double precision; also rotated, at
    // +1.5 EV and with the camera turned.
    void singleTexelIsDirectionalLight() {
        const int W = 32, H = 16, tx = 5, ty = 4;
        const glm::vec3 L(3.0f, 2.0f, 0.5f);
        const double ev = 1.5, rotation = 30.0;
        const auto img = image(W, H, [&](int x, int y) { return x == tx && y == ty ? L : glm::vec3(0.0f); });
        const EnvironmentField field(img, ev, rotation, DiffuseModel::Lambert);
        const EnvironmentField fieldHalf(img, ev, rotation, DiffuseModel::HalfLambert);
        const glm::dmat3 viewToWorld(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(V(1, 2, 3))));
        const V world = environment::rotateAboutUp(environment::texelDirection(tx, ty, W, H),
                                                   rotation); // towards the texel
        const V toTexelView = glm::transpose(viewToWorld) * world;
        const double omega = environment::texelSolidAngle(ty, W, H);
        const V radiance = V(L) * std::exp2(ev);
        std::mt19937 rng(5);
        for (int i = 0; i < 40; ++i) {
            lighting::Surface<double> s =
                surface(facingNormal(rng), V(0.8, 0.6, 0.4), V(0.5, 0.6, 0.7), 12.0);
            s.roughness = 0.3 + 0.02 * i, s.metallic = (i % 3) / 2.0, s.occlusion = 0.8;
            for (const auto& st :
                 {classic(SpecularModel::Phong), classic(SpecularModel::BlinnPhong), pbr()}) {
                for (DiffuseModel dm : {DiffuseModel::Lambert, DiffuseModel::HalfLambert}) {
                    if (st.model == ShadingModel::Pbr && dm == DiffuseModel::HalfLambert) continue;
                    lighting::ShadeLight<double> l;
                    l.type = LightType::Directional;
                    l.direction = -toTexelView;
                    l.color = l.specular =
                        st.model == ShadingModel::Pbr ? radiance * omega : radiance * omega / kPi;
                    l.ambient = V(0.0);
                    l.diffuse = dm;
                    const std::vector<lighting::ShadeLight<double>> lights{l};
                    const V want = lighting::shadeSurface<double>(s, lights, st) * 0.8; // × occlusion
                    const V got = environmentRadianceBySum(dm == DiffuseModel::Lambert ? field : fieldHalf, s,
                                                           st, viewToWorld);
                    QVERIFY2(glm::length(got - want) <= 1e-13 * (1.0 + glm::length(want)),
                             qPrintable(QStringLiteral("%1 vs %2").arg(vecStr(got), vecStr(want))));
                }
            }
        }
    }

    // (4) Half-Lambert in a uniform environment: ∫((n·ω)/2 + 1/2)² dω / π = 4/3, exactly (moments).
    void halfLambertUniform() {
        const EnvironmentField field(uniform(1.0), 0.0, 0.0, DiffuseModel::HalfLambert);
        std::mt19937 rng(3);
        for (int i = 0; i < 30; ++i) {
            const V albedo(0.3, 0.6, 0.9);
            const Estimate e =
                field.integrate(surface(facingNormal(rng), albedo), classic(), kIdentity, 1, tight());
            QVERIFY2(glm::length(e.radiance - albedo * (4.0 / 3.0)) < 1e-12, qPrintable(vecStr(e.radiance)));
        }
    }

    // (5) Phong and Blinn-Phong lobes in a uniform environment, seen head-on (v = n):
    //   Phong   ks/π ∫ (r·ω)^s dω over the hemisphere = 2 ks/(s + 1)
    //   Blinn   ks/π ∫ (n·h)^s dω = 8 ks (1 − 2^(−(s+2)/2)) / (s + 2)
    void phongAndBlinnUniform() {
        const EnvironmentField field(uniform(1.0), 0.0, 0.0);
        for (double sh : {1.0, 8.0, 64.0, 500.0}) {
            const V ks(1.0, 0.5, 0.25);
            const lighting::Surface<double> s = surface(V(0, 0, 1), V(0.0), ks, sh);
            const Estimate phong = field.integrate(s, classic(SpecularModel::Phong), kIdentity, 21, tight());
            const V wantPhong = ks * (2.0 / (sh + 1.0));
            QVERIFY2(within(phong.radiance, wantPhong, phong),
                     qPrintable(describe(phong.radiance, wantPhong, phong)));
            const Estimate blinn =
                field.integrate(s, classic(SpecularModel::BlinnPhong), kIdentity, 22, tight());
            const V wantBlinn = ks * (8.0 * (1.0 - std::pow(2.0, -(sh + 2.0) / 2.0)) / (sh + 2.0));
            QVERIFY2(within(blinn.radiance, wantBlinn, blinn),
                     qPrintable(describe(blinn.radiance, wantBlinn, blinn)));
            qInfo("shininess %g: Phong %.6f (closed form %.6f, se %.2g), Blinn %.6f (%.6f, se %.2g), %d/%d "
                  "samples",
                  sh, phong.radiance.x, wantPhong.x, phong.standardError.x, blinn.radiance.x, wantBlinn.x,
                  blinn.standardError.x, phong.samples, blinn.samples);
            // Converged (0.1 level aimed at, 16384 pairs at most) or at the sample limit.
            QVERIFY2(phong.errorLevels <= 0.1 || phong.samples == 16 * 4 * 256,
                     qPrintable(num(phong.errorLevels)));
            QVERIFY2(blinn.errorLevels <= 0.1 || blinn.samples == 16 * 4 * 256,
                     qPrintable(num(blinn.errorLevels)));
        }
    }

    // Shininess 0 on a surface seen obliquely: both lobes are 1 over the whole upper hemisphere, so 2·ks;
    // the Phong sampler covers only the hemisphere about the reflection, and its density must be 0 behind
    // it (a density counted where the sampler never goes biases the MIS weights).
    void shininessZeroOblique() {
        const EnvironmentField field(uniform(1.0), 0.0, 0.0);
        const V ks(0.5);
        const lighting::Surface<double> s = surface(V(0.0, std::sin(1.1), std::cos(1.1)), V(0.0), ks, 0.0);
        for (SpecularModel sm : {SpecularModel::Phong, SpecularModel::BlinnPhong}) {
            const Estimate e = field.integrate(s, classic(sm), kIdentity, 4, tight());
            QVERIFY2(within(e.radiance, 2.0 * ks, e), qPrintable(describe(e.radiance, 2.0 * ks, e)));
        }
    }

    // (6) The integrator against the definition's limit (the sum over 16 × 16 sub-cells of every texel) on
    // a small random environment with a bright source, every model: within 4 standard errors (+ the
    // quadrature's bound) at all but 2 of 120 pixels and within 6 at every one, and the standard error
    // honest: the mean squared z-score near 1 (neither hidden nor inflated error).
    void integratorAgreesWithTheSum() {
        std::mt19937 rng(2024);
        std::lognormal_distribution<double> value(-0.5, 1.0);
        const auto img = image(16, 8, [&](int, int) {
            const float r = float(value(rng)), g = float(value(rng)), b = float(value(rng));
            return glm::vec3(r, g, b);
        });
        img->at(3, 2) = glm::vec3(40.0f, 35.0f, 30.0f); // a small bright source
        Convergence few; // fixed 256 pairs (16 replicates × 16): noise large enough to be measured
        few.replicates = 16, few.batch = 16, few.minBatches = 1, few.maxBatches = 1;
        double z2 = 0.0;
        int count = 0, over2 = 0, over4 = 0;
        for (int i = 0; i < 120; ++i) {
            const DiffuseModel dm = i % 4 == 1 ? DiffuseModel::HalfLambert : DiffuseModel::Lambert;
            const EnvironmentField field(img, 0.0, 17.0 * i, dm);
            lighting::Surface<double> s =
                surface(facingNormal(rng), V(0.7, 0.5, 0.3), V(0.4), 2.0 + i % 7 * 3.0);
            s.roughness = 0.35 + 0.65 * (i % 5) / 4.0, s.metallic = i % 2;
            const auto st =
                i % 3 == 0 ? pbr() : classic(i % 3 == 1 ? SpecularModel::Phong : SpecularModel::BlinnPhong);
            const V exact = environmentRadianceBySum(field, s, st, kIdentity, 16);
            const Estimate e = field.integrate(s, st, kIdentity, std::uint64_t(i), few);
            // Student's t with 15 degrees of freedom (16 replicates): beyond 4σ about 1 in 3000, beyond 6σ
            // about 1 in 10⁵; heavier tails would mean the standard error hides error.
            QVERIFY2(within(e.radiance, exact, e, 6.0, 1e-9),
                     qPrintable(QStringLiteral("case %1: %2").arg(i).arg(describe(e.radiance, exact, e))));
            if (!within(e.radiance, exact, e, 4.0, 1e-9)) ++over4;
            for (int c = 0; c < 3; ++c)
                if (e.standardError[c] > 1e-9 * exact[c]) {
                    const double z = (e.radiance[c] - exact[c]) / e.standardError[c];
                    z2 += z * z, ++count;
                    if (std::abs(z) > 2.0) ++over2;
                }
        }
        qInfo("integrator vs sum: %d channel estimates, mean z² %.3f, %.1f%% beyond 2σ", count, z2 / count,
              100.0 * over2 / count);
        QVERIFY(count > 150);
        QVERIFY2(over4 <= 2, qPrintable(QString::number(over4)));
        QVERIFY2(z2 / count > 0.4 && z2 / count < 2.5, qPrintable(num(z2 / count)));
    }

    // Narrow lobes over the sharp edges of small bright sources — one across the azimuth's seam, one by
    // the pole — where Monte Carlo alone converges slowly: the integrator sums the lobe's core texel by
    // texel (EnvironmentField's window) and agrees with the exact sum within its standard error and its
    // midpoint-rule estimate.
    void narrowLobeWindowAgreesWithTheSum() {
        const int w = 32, h = 16;
        std::mt19937 rng(77);
        std::uniform_real_distribution<double> dim(0.05, 0.2), jitter(-0.15, 0.15);
        const auto img = image(w, h, [&](int x, int y) {
            const bool seam = (x >= 30 || x <= 1) && y >= 6 && y <= 8;
            const bool side = x >= 12 && x <= 15 && y >= 4 && y <= 6;
            const bool pole = x >= 5 && x <= 9 && y <= 1;
            return seam || side || pole ? glm::vec3(50.0f, 45.0f, 40.0f) : glm::vec3(float(dim(rng)));
        });
        const auto texelDirection = [&](double x, double y) { // centre of a (fractional) texel position
            const double phi = (x / w - 0.5) * 2.0 * kPi, lat = (0.5 - y / h) * kPi;
            return V(std::cos(lat) * std::cos(phi), std::sin(lat), std::cos(lat) * std::sin(phi));
        };
        // Edges to aim the mirror direction at: the seam source's right edge, the side source's corner, the
        // polar source's lower edge.
        const std::array<std::pair<double, double>, 3> edges{{{2.0, 7.0}, {12.0, 4.0}, {7.0, 2.0}}};
        Convergence c = tight();
        c.targetLevels = 1e-6; // never met: every case takes the window once the first quarter is spent
        c.exposureEV = -7.0;   // and the sources (50) stay below the display's white, where errors show
        c.maxBatches = 16;
        int windowed = 0;
        for (int i = 0; i < 15; ++i) {
            const auto [ex, ey] = edges[size_t(i % 3)];
            const V target = texelDirection(ex + jitter(rng), ey + jitter(rng));
            lighting::Surface<double> s =
                surface(glm::normalize(V(0, 0, 1) + target), V(0.9, 0.7, 0.5), V(0.5));
            lighting::ShadeSettings<double> st = pbr();
            const int kind = (i / 3) % 5;
            if (kind < 3) {
                s.roughness = 0.2 + 0.05 * kind, s.metallic = kind == 2 ? 0.0 : 1.0;
            } else {
                st = classic(kind == 3 ? SpecularModel::Phong : SpecularModel::BlinnPhong);
                s.shininess = kind == 3 ? 400.0 : 1000.0;
            }
            const EnvironmentField field(img, 0.0, 0.0);
            const V exact = environmentRadianceBySum(field, s, st, kIdentity, 64);
            const Estimate e = field.integrate(s, st, kIdentity, std::uint64_t(i), c);
            windowed += e.windowed ? 1 : 0;
            QVERIFY2(within(e.radiance, exact, e, 6.0, 1e-9),
                     qPrintable(QStringLiteral("case %1: %2").arg(i).arg(describe(e.radiance, exact, e))));
        }
        QCOMPARE(windowed, 15);
    }

    // (7) Rotation by 90° equals looking up the direction turned back by 90°.
    void rotation() {
        const auto img =
            image(32, 16, [](int x, int y) { return glm::vec3(float(x), float(y), float(x * y % 7)); });
        const EnvironmentField turned(img, 0.0, 90.0), plain(img, 0.0, 0.0);
        std::mt19937 rng(9);
        for (int i = 0; i < 200; ++i) {
            const V d = randomUnit(rng);
            QCOMPARE(turned.radianceAt(d), plain.radianceAt(environment::rotateAboutUp(d, -90.0)));
            // +X (the image's centre column) turned 90° counter-clockwise seen from +Y looks along −Z.
        }
        QCOMPARE(turned.radianceAt(V(0, 0, -1)), plain.radianceAt(V(1, 0, 0)));
        for (int i = 0; i < 20; ++i) {
            const lighting::Surface<double> s = surface(facingNormal(rng), V(0.6), V(0.3), 10.0);
            // The viewer turns too: use an infinite viewer seen through a turned camera.
            const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), -kPi / 2, V(0, 1, 0)));
            const Estimate a = turned.integrate(s, classic(), kIdentity, 5, tight());
            const Estimate b = plain.integrate(s, classic(), turn, 5, tight());
            QVERIFY2(glm::length(a.radiance - b.radiance) <=
                         4.0 * glm::length(a.standardError + b.standardError) +
                             glm::length(a.bound + b.bound) + 1e-9,
                     qPrintable(describe(a.radiance, b.radiance, a)));
            QVERIFY(glm::length(environmentRadianceBySum(turned, s, classic(), kIdentity) -
                                environmentRadianceBySum(plain, s, classic(), turn)) < 1e-9);
        }
    }

    // (8) +1 EV doubles the contribution.
    void intensityDoubles() {
        const auto img = image(
            32, 16, [](int x, int y) { return glm::vec3(0.1f * float(x % 5), 0.2f, float(y) / 16.0f); });
        const EnvironmentField zero(img, 0.0, 0.0), one(img, 1.0, 0.0);
        lighting::Surface<double> s = surface(V(0.3, 0.5, 0.8), V(0.6, 0.5, 0.4), V(0.2), 20.0);
        s.roughness = 0.5;
        for (const auto& st : {classic(), pbr()}) {
            const V a = environmentRadianceBySum(zero, s, st, kIdentity);
            const V b = environmentRadianceBySum(one, s, st, kIdentity);
            QVERIFY2(glm::length(b - 2.0 * a) <= 1e-14 * glm::length(b), qPrintable(vecStr(b - 2.0 * a)));
            const Estimate ea = zero.integrate(s, st, kIdentity, 8, tight());
            const Estimate eb = one.integrate(s, st, kIdentity, 8, tight());
            QVERIFY2(glm::length(eb.radiance - 2.0 * ea.radiance) <=
                         4.0 * glm::length(eb.standardError + 2.0 * ea.standardError) +
                             glm::length(eb.bound + 2.0 * ea.bound) + 1e-12,
                     qPrintable(describe(eb.radiance, 2.0 * ea.radiance, eb)));
        }
    }

    // Occlusion scales everything; a black environment adds nothing; an empty image is black.
    void occlusionAndBlack() {
        const EnvironmentField field(uniform(1.0), 0.0, 0.0);
        lighting::Surface<double> s = surface(V(0, 0, 1), V(0.5));
        s.occlusion = 0.25;
        const Estimate e = field.integrate(s, classic(), kIdentity, 1, tight());
        QVERIFY2(glm::length(e.radiance - V(0.125)) <= glm::length(e.bound) + 1e-12,
                 qPrintable(vecStr(e.radiance)));
        const EnvironmentField black(uniform(0.0), 0.0, 0.0);
        QVERIFY(black.isBlack());
        QCOMPARE(black.integrate(surface(V(0, 0, 1), V(1)), pbr(), kIdentity, 1, tight()).radiance, V(0.0));
        const EnvironmentField empty(nullptr, 0.0, 0.0);
        QVERIFY(empty.isBlack());
    }

  private:
    static double maxOf3(const V& v) { return std::max({v.x, v.y, v.z}); }
};

QTEST_APPLESS_MAIN(TestEnvIntegrate)
#include "tst_envintegrate.moc"
