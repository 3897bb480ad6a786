// Float against double for every formula: a grid of ordinary inputs per formula, then property-style
// tests over 100k seeded random and adversarial scenes through shadeLight, then the float overshoot of
// dot(normalize(a), normalize(a)) past 1. Both types always evaluate the same float-representable inputs,
// so the differences measured are the float arithmetic's own; upload rounding (double-prepared light ->
// float) is measured separately. The bounds asserted here are the ones docs/quality.md states; each
// test prints what it measured (ctest -V, or run the executable).
#include "common.h"
#include "core/prepare.h"

#include <vector>

using namespace lr;
using namespace lr::lighting;
using namespace lr::test;

namespace {

constexpr double kRelIn = 4 * kEpsF; // mixed bound: input perturbation (see tst_extremes.cpp)
constexpr double kAbsOut = 1e-37;
double relOut(double exponent) {
    return (4 + 2 * std::max(exponent, 0.0)) * kEpsF;
}

std::vector<double> linspace(double a, double b, int n) {
    std::vector<double> v;
    for (int i = 0; i < n; ++i)
        v.push_back(a + (b - a) * i / (n - 1));
    return v;
}

// A forward bound |float - double| <= bound · scale, with scale chosen per formula (e.g. p·eps, or eps
// times the unwindowed value). Records the largest ratio seen, so the test prints the measured figure
// next to the asserted one.
struct Forward {
    QString name;
    double bound;
    double worst = 0;
    long count = 0;
    QString where;
    void add(double f, double d, double scale, const std::function<QString()>& at) {
        ++count;
        const double r = std::abs(f - d) / scale;
        if (!(r <= worst))
            worst = r, where = at() + QStringLiteral(": float %1 double %2").arg(num(f), num(d));
    }
    void verify() const {
        qInfo("%s: %ld cases, max error %.3g x scale (bound %g) at %s", qPrintable(name), count, worst, bound,
              qPrintable(where));
        QVERIFY2(
            worst <= bound,
            qPrintable(name + QStringLiteral(": %1 > bound %2 at %3").arg(num(worst), num(bound), where)));
    }
};

struct Envelope {
    QString name;
    long count = 0, violations = 0;
    QString first;
    void check(const std::function<double(double)>& fd, double t, double f, double exponent,
               const std::function<QString()>& where) {
        ++count;
        double lo, hi;
        if (!withinEnvelope(fd, t, f, kRelIn, relOut(exponent), kAbsOut, &lo, &hi) && violations++ == 0)
            first = where() + QStringLiteral(": float %1 outside [%2, %3]").arg(num(f), num(lo), num(hi));
    }
    void verify() const {
        qInfo("%s: mixed bound holds in %ld cases", qPrintable(name), count);
        QVERIFY2(violations == 0,
                 qPrintable(name + QStringLiteral(": %1 violations; first %2").arg(violations).arg(first)));
    }
};

} // namespace

class TestPrecision : public QObject {
    Q_OBJECT
  private slots:
    void falloffGrid() {
        // Forward bounds, in eps = 2^-23: range-power (p >= 1) |err| <= p·eps; range-quadratic |err| <=
        // eps; inverse-square and inverse-polynomial |err| <= 4 eps · (the value without range window),
        // i.e. relative 4 eps without a range, absolute in units of 1/(c + l d + q d²) with one (the
        // window's 1 - (d/range)^4 cancels near the range). Every case, exponents < 1 included, also
        // satisfies the mixed bound.
        Forward rp{QStringLiteral("range-power p>=1 [scale p eps]"), 1.0};
        Forward rq{QStringLiteral("range-quadratic [scale eps]"), 1.0};
        Forward is{QStringLiteral("inverse-square [scale eps/max(d^2,1e-4)]"), 4.0};
        Forward ip{QStringLiteral("inverse-polynomial [scale eps/denominator]"), 4.0};
        Envelope env{QStringLiteral("falloffs")};
        for (double R : {1e-3, 1.0, 400.0, 1e6})
            for (double u : linspace(0, 1.2, 2401)) {
                const float d = float(u * R), r = float(R);
                const auto where = [&] { return QStringLiteral("d=%1 range=%2").arg(num(d), num(r)); };
                for (float p : {0.25f, 0.5f, 1.0f, 2.0f, 3.0f, 8.0f}) {
                    const float f = falloffRangePower(d, r, p);
                    env.check([&](double t) { return falloffRangePower<double>(t, r, p); }, d, f, p, where);
                    if (p >= 1) rp.add(f, falloffRangePower<double>(d, r, p), p * kEpsF, where);
                }
                rq.add(falloffRangeQuadratic(d, r), falloffRangeQuadratic<double>(d, r), kEpsF, where);
                env.check([&](double t) { return falloffRangeQuadratic<double>(t, r); }, d,
                          falloffRangeQuadratic(d, r), 2, where);
                for (float range : {-1.0f, r}) {
                    const double dd = d;
                    is.add(falloffInverseSquare(d, range), falloffInverseSquare<double>(d, range),
                           kEpsF / std::max(dd * dd, 1e-4), where);
                    env.check([&](double t) { return falloffInverseSquare<double>(t, range); }, d,
                              falloffInverseSquare(d, range), 2, where);
                    for (const Vec3f& k :
                         {Vec3f(0, 0.1f, 0.05f), Vec3f(1, 0, 0), Vec3f(1, 0.09f, 0.032f), Vec3f(0, 0, 1)}) {
                        const float f = falloffInversePolynomial(d, k.x, k.y, k.z, range);
                        const double denom = std::max(k.x + k.y * dd + k.z * dd * dd, 1e-4);
                        ip.add(f, falloffInversePolynomial<double>(d, k.x, k.y, k.z, range), kEpsF / denom,
                               where);
                        env.check(
                            [&](double t) {
                                return falloffInversePolynomial<double>(t, k.x, k.y, k.z, range);
                            },
                            d, f, 2, where);
                    }
                }
            }
        rp.verify(), rq.verify(), is.verify(), ip.verify(), env.verify();
    }

    void coneGrid() {
        // Forward bounds: angle-power (p >= 1) |err| <= 2 p eps / outer[rad] (acos is accurate to an ulp of
        // θ <= π, the slope of 1 - θ/outer is 1/outer); smooth |err| <= (1 + p) eps; hard: bit-identical.
        // Exponents < 1 (the book's 0.5) are ill-conditioned at the edge: the mixed bound covers them.
        Forward ap{QStringLiteral("angle-power p>=1 [scale p eps/outer]"), 2.0};
        Forward sm{QStringLiteral("smooth [scale (1+p) eps]"), 1.0};
        Envelope env{QStringLiteral("cones")};
        long hardMismatch = 0, hardCount = 0;
        for (double outerDeg : {1.0, 10.0, 25.0, 50.0, 90.0})
            for (double u : linspace(0, 1.2, 2401)) {
                const double thetaDeg = u * outerDeg;
                const float c = float(std::cos(radians(thetaDeg))), outer = float(radians(outerDeg));
                const float co = float(std::cos(radians(outerDeg)));
                const auto where = [&] {
                    return QStringLiteral("θ=%1° outer=%2°").arg(num(thetaDeg), num(outerDeg));
                };
                for (float p : {0.5f, 1.0f, 2.0f, 3.2f, 8.0f}) {
                    const float f = coneAnglePower(c, outer, p);
                    if (p >= 1) ap.add(f, coneAnglePower<double>(c, outer, p), p * kEpsF / outer, where);
                    env.check(
                        [&](double t) {
                            return t < double(outer) ? safePow(saturate(1 - t / double(outer)), double(p))
                                                     : 0.0;
                        },
                        std::acos(std::min(double(c), 1.0)), f, p, where);
                    for (double innerFrac : {0.0, 0.5, 0.9, 0.99}) {
                        const float ci = float(std::cos(radians(innerFrac * outerDeg)));
                        const double w = double(ci) - double(co);
                        if (!(w > 1e-7)) continue;
                        const float fs = coneSmooth(c, ci, co, p);
                        sm.add(fs, coneSmooth<double>(c, ci, co, p), (1 + p) * kEpsF, where);
                        env.check([&](double t) { return t > 0 ? safePow(saturate(t / w), double(p)) : 0.0; },
                                  double(c) - double(co), fs, p, where);
                    }
                }
                ++hardCount;
                if (coneHard(c, co) != float(coneHard<double>(c, co))) ++hardMismatch;
            }
        ap.verify(), sm.verify(), env.verify();
        QCOMPARE(hardMismatch, 0L);
        qInfo("hard: %ld cases bit-identical", hardCount);
    }

    void surfaceTermGrid() {
        // Unit vectors rounded to float (length 1 within ~1 ulp), the dot products computed in each type.
        // Forward bounds: lambert |err| <= 2 eps, half-lambert <= 2 eps; phong <= (1 + n) · 4 eps (R·V has
        // an error of a few eps, x^n multiplies it by at most n); blinn-phong <= (1 + n) · 4 eps / |L+V|
        // (normalising L + V loses precision when L ~ -V); rim (p >= 1) <= (1 + p) · 2 eps.
        Forward lam{QStringLiteral("lambert [scale eps]"), 2},
            half{QStringLiteral("half-lambert [scale eps]"), 2};
        Forward ph{QStringLiteral("phong [scale (1+n) eps]"), 4},
            bp{QStringLiteral("blinn-phong [scale (1+n) eps/|L+V|]"), 4};
        Forward rim{QStringLiteral("rim p>=1 [scale (1+p) eps]"), 2};
        ErrorStats rimLow{QStringLiteral("rim p<1 (reported, not bounded: pow(x, p<1) near x = 0)")};
        Gen g(5);
        for (int i = 0; i < 20000; ++i) {
            const Vec3d Nd = g.unitD();
            const Vec3f N(Nd), L(g.around(Nd, g.uniform(0, kPi))), V(g.around(Nd, g.uniform(0, kPi)));
            const Vec3d n(N), l(L), v(V);
            const auto where = [&] {
                return QStringLiteral("N=%1 L=%2 V=%3").arg(vecStr(n), vecStr(l), vecStr(v));
            };
            lam.add(diffuseLambert(glm::dot(N, L)), diffuseLambert(glm::dot(n, l)), kEpsF, where);
            half.add(diffuseHalfLambert(glm::dot(N, L)), diffuseHalfLambert(glm::dot(n, l)), kEpsF, where);
            for (float sh : {1.0f, 8.0f, 32.0f, 128.0f, 1024.0f}) {
                ph.add(specularPhong(N, L, V, sh), specularPhong(n, l, v, double(sh)), (1 + sh) * kEpsF,
                       where);
                bp.add(specularBlinnPhong(N, L, V, sh), specularBlinnPhong(n, l, v, double(sh)),
                       (1 + sh) * kEpsF / std::max(glm::length(l + v), 1e-30), where);
            }
            for (float p : {0.25f, 0.5f, 1.0f, 1.3f, 3.0f}) {
                const float f = rimTerm(L, N, V, p);
                const double d = rimTerm(l, n, v, double(p));
                if (p >= 1)
                    rim.add(f, d, (1 + p) * kEpsF, where);
                else
                    rimLow.add(f, d, 1e-30, where);
            }
        }
        lam.verify(), half.verify(), ph.verify(), bp.verify(), rim.verify();
        qInfo("%s", qPrintable(rimLow.summary()));
    }

    void toneAndEncodingGrid() {
        // Output stage (lighting.h): tone maps and sRGB encoding, relative error against double.
        Forward tm{QStringLiteral("tone maps [scale eps·|result|]"), 4};
        Forward enc{QStringLiteral("linear <-> sRGB [scale eps·|result|]"), 4};
        for (int e = -300; e <= 300; ++e) {
            const float x = float(std::pow(10.0, e / 50.0)); // 1e-6 .. 1e6
            const auto where = [&] { return QStringLiteral("x=%1").arg(num(x)); };
            for (ToneMap op : {ToneMap::Clamp, ToneMap::Reinhard, ToneMap::Aces}) {
                const double d = toneMap<double>(op, x);
                tm.add(toneMap(op, x), d, kEpsF * std::max(std::abs(d), 1e-30), where);
            }
            const double ls = linearToSrgb<double>(x), sl = srgbToLinear<double>(x);
            enc.add(linearToSrgb(x), ls, kEpsF * std::max(std::abs(ls), 1e-30), where);
            enc.add(srgbToLinear(x), sl, kEpsF * std::max(std::abs(sl), 1e-30), where);
        }
        tm.verify(), enc.verify();
    }

    // 100k seeded scenes through shadeLight, every light type and model, 20% of them adversarial.
    void propertyShadeLight() {
        Gen g(20240611);
        constexpr int kCases = 100000;
        Forward fwd{QStringLiteral("shadeLight, well-conditioned [scale M·eps·(4 + condition)]"), 1};
        // Upload rounding: the light prepared in double, rounded to float for the GPU, against the same
        // light unrounded (surface inputs identical). Its conditioning is |light position| / d: a light
        // close to a surface far from the eye moves by an ulp of its position, relative to d.
        Forward upload{
            QStringLiteral("upload rounding, well-conditioned [scale M·eps·(4 + condition)·(1 + |Pl|/d)]"),
            1};
        long strict = 0, adversarial = 0, nonFinite = 0, negative = 0, overBound = 0;
        QString firstBad;
        const auto bad = [&](long& counter, const QString& what) {
            if (counter++ == 0 && firstBad.isEmpty()) firstBad = what;
        };
        for (int i = 0; i < kCases; ++i) {
            const bool adv = i % 5 == 0;
            adversarial += adv;
            // ---- a random scene in double ----
            Surface<double> s;
            const double z = -g.logUniform(1e-3, 1e6);
            s.position = Vec3d(z * g.uniform(-1, 1), z * g.uniform(-1, 1), z);
            s.normal = g.unitD();
            s.albedo = Vec3d(g.uniform(0, 1), g.uniform(0, 1), g.uniform(0, 1));
            s.specular = Vec3d(g.uniform(0, 1));
            s.shininess = g.pick({1.0, 8.0, 32.0, 128.0, g.logUniform(1, 1024)});
            ShadeSettings<double> st;
            st.specular = g.chance(0.5) ? SpecularModel::Phong : SpecularModel::BlinnPhong;
            st.viewer = g.chance(0.5) ? ViewerModel::Local : ViewerModel::Infinite;
            ShadeLight<double> l;
            l.type = LightType(g.integer(0, 3));
            const double intensity = g.logUniform(1e-3, 1e6);
            l.color = intensity * Vec3d(g.uniform(0, 1), g.uniform(0, 1), g.uniform(0, 1));
            l.specular = intensity * Vec3d(g.uniform(0, 1));
            l.ambient = g.chance(0.3) ? intensity * Vec3d(g.uniform(0, 0.2)) : Vec3d(0);
            l.diffuse = g.chance(0.5) ? DiffuseModel::Lambert : DiffuseModel::HalfLambert;
            l.rimExponent = g.pick({1.3, 1.0, 2.0, g.uniform(1, 4)});
            const double dist = g.logUniform(1e-4, 1e4);
            const Vec3d toLight = g.unitD();
            l.position = s.position + dist * toLight;
            l.falloff = FalloffModel(g.integer(0, 4));
            l.range = l.falloff == FalloffModel::InversePolynomial || l.falloff == FalloffModel::InverseSquare
                          ? (g.chance(0.5) ? -1.0 : dist * g.uniform(0.5, 3))
                          : dist * g.uniform(0.5, 3);
            l.falloffExponent = g.pick({1.0, 2.0, 3.0, 3.2, 8.0, g.uniform(1, 8), 0.5});
            l.constant = g.uniform(0, 1), l.linear = g.uniform(0, 1), l.quadratic = g.uniform(0, 1);
            l.cone = ConeModel(g.integer(0, 2));
            const double outerDeg = g.uniform(1, 90);
            l.outer = radians(outerDeg), l.cosOuter = std::cos(l.outer);
            l.cosInner = std::cos(l.outer * g.uniform(0, 0.95));
            l.coneExponent = g.pick({0.5, 1.0, 2.0, 3.2, g.uniform(1, 8)});
            l.direction =
                l.type == LightType::Spot ? g.around(-toLight, g.uniform(0, 1.2) * l.outer) : g.unitD();
            if (adv) { // push one or more inputs to an extreme
                switch (g.integer(0, 9)) {
                case 0:
                    l.position = s.position;
                    break;
                case 1:
                    l.range = g.pick({0.0, 1e-30, 1e30});
                    break;
                case 2:
                    s.normal = toD(g.adversarialVector());
                    break;
                case 3:
                    l.direction = toD(g.adversarialVector());
                    break;
                case 4:
                    l.falloffExponent = l.coneExponent = l.rimExponent = s.shininess = 0;
                    break;
                case 5:
                    l.cosInner = l.cosOuter = std::cos(l.outer = g.pick({1e-30, 1e-6, radians(90)}));
                    break;
                case 6:
                    l.color *= 1e6 / intensity, l.specular *= 1e6 / intensity;
                    break;
                case 7:
                    l.position = s.position + toD(g.adversarialVector());
                    break;
                case 8:
                    s.position *= g.logUniform(1e10, 1e30), l.position = s.position + 1e25 * toLight;
                    break;
                default:
                    s.shininess = 1e4, l.falloffExponent = 1e3, l.coneExponent = 1e-3;
                    break;
                }
            }
            // ---- float twin and the double evaluation of the same float inputs ----
            const ShadeLight<float> lf = castLight<float>(l);
            Surface<float> sf;
            sf.position = Vec3f(s.position), sf.normal = Vec3f(s.normal), sf.albedo = Vec3f(s.albedo);
            sf.specular = Vec3f(s.specular), sf.shininess = float(s.shininess);
            ShadeSettings<float> stf;
            stf.specular = st.specular, stf.viewer = st.viewer;
            const ShadeLight<double> lr = toDouble(lf);
            Surface<double> sr = s;
            sr.position = toD(sf.position), sr.normal = toD(sf.normal), sr.albedo = toD(sf.albedo);
            sr.specular = toD(sf.specular), sr.shininess = asStored(sf.shininess);
            const Vec3d Vr = viewVector(st, sr.position);
            const Vec3d rf = toD(shadeLight(lf, sf, stf, viewVector(stf, sf.position)));
            const Vec3d rd = shadeLight(lr, sr, st, Vr);
            const Vec3d rx = shadeLight(l, sr, st, Vr);
            const auto what = [&] {
                return QStringLiteral("case %1 (%2, %3, %4, %5, %6): double %7 float %8")
                    .arg(i)
                    .arg(toString(l.type), toString(l.falloff), toString(l.cone), toString(st.specular),
                         toString(st.viewer), vecStr(rd), vecStr(rf));
            };
            if (!finite(rf) || !finite(rd) || !finite(rx)) bad(nonFinite, what());
            if (std::min({rf.x, rf.y, rf.z, rd.x, rd.y, rd.z}) < 0) bad(negative, what());

            // ---- M: the light's full strength here (D = S = 1, no cone, no range window) ----
            const double d = glm::length(lr.position - sr.position);
            double unit = 1; // the falloff's scale without window: 1, 1/max(d², 1e-4) or 1/denominator
            if (lr.type == LightType::Point || lr.type == LightType::Spot) {
                if (lr.falloff == FalloffModel::InverseSquare) unit = 1 / std::max(d * d, 1e-4);
                if (lr.falloff == FalloffModel::InversePolynomial)
                    unit = 1 / std::max(lr.constant + lr.linear * d + lr.quadratic * d * d, 1e-4);
            }
            if (lr.type == LightType::Rim) unit = 1;
            const Vec3d M =
                lr.type == LightType::Rim
                    ? lr.color
                    : unit * (lr.color * sr.albedo + lr.specular * sr.specular + lr.ambient * sr.albedo);
            // Upper bound: D, S, s <= 1; a <= unit · 1 (window <= 1). Holds for adversarial cases too.
            for (int c = 0; c < 3; ++c)
                if (!(rf[c] <= M[c] * (1 + 1e-5) + 1e-30))
                    bad(overBound, what() + QStringLiteral(" > M %1").arg(vecStr(M)));

            // ---- strict forward bound where the formulas are well-conditioned ----
            if (adv) continue;
            const Vec3d Lr = safeNormalize(lr.position - sr.position, sr.normal);
            const Vec3d L = lr.type == LightType::Directional ? -lr.direction : Lr;
            const double nDotL = glm::dot(sr.normal, L);
            double cond = 0;
            if (lr.type != LightType::Rim) {
                if (std::abs(nDotL) < 1e-5) continue; // the specular gate N·L > 0 may flip
                cond += 2 * (1 + sr.shininess) *
                        (st.specular == SpecularModel::BlinnPhong ? 1 / std::max(glm::length(L + Vr), 1e-30)
                                                                  : 1.0);
            } else {
                cond += 2 * (1 + lr.rimExponent);
            }
            if (lr.type == LightType::Point || lr.type == LightType::Spot) {
                const double pf = lr.falloffExponent;
                if (lr.falloff == FalloffModel::RangePower || lr.falloff == FalloffModel::RangeQuadratic ||
                    lr.range >= 0) {
                    if (std::abs(d - lr.range) < 1e-4 * lr.range) continue; // the range edge
                    if (lr.falloff == FalloffModel::RangePower && pf < 1 && d > lr.range * (1 - 1e-3))
                        continue;
                }
                cond += 2 + 2 * (lr.falloff == FalloffModel::RangePower ? pf : 2);
            }
            if (lr.type == LightType::Spot) {
                const double c = glm::dot(-Lr, lr.direction), pc = lr.coneExponent;
                const double theta = std::acos(std::clamp(c, -1.0, 1.0));
                const double dc = 4 * kEpsF; // error of cosθ = dot(-L, direction) in float
                switch (lr.cone) {
                case ConeModel::AnglePower: {
                    if (pc < 1 && theta > lr.outer * (1 - 1e-3)) continue;
                    if (std::abs(theta - lr.outer) < 1e-6) continue;
                    const double dTheta = std::min(std::sqrt(2 * dc), dc / std::max(std::sin(theta), 1e-30));
                    cond += pc * dTheta / lr.outer / kEpsF;
                    break;
                }
                case ConeModel::Smooth: {
                    const double w = lr.cosInner - lr.cosOuter;
                    if (pc < 1 && c - lr.cosOuter < 1e-3 * w) continue;
                    if (std::abs(c - lr.cosOuter) < dc) continue;
                    cond += (1 + pc) * dc / w / kEpsF;
                    break;
                }
                case ConeModel::Hard:
                    if (std::abs(c - lr.cosOuter) < dc) continue; // the edge may flip
                    break;
                }
            }
            ++strict;
            const bool positioned = lr.type == LightType::Point || lr.type == LightType::Spot;
            const double kappa = positioned ? 1 + glm::length(l.position) / std::max(d, 1e-300) : 1;
            for (int c = 0; c < 3; ++c) {
                const double scale = std::max(M[c], 1e-300) * kEpsF * (4 + cond);
                fwd.add(rf[c], rd[c], scale, what);
                upload.add(rd[c], rx[c], scale * kappa, what);
            }
        }
        qInfo("%d cases: %ld adversarial, %ld under the strict bound", kCases, adversarial, strict);
        QVERIFY2(nonFinite == 0 && negative == 0 && overBound == 0,
                 qPrintable(QStringLiteral(
                                "%1 non-finite, %2 negative, %3 above the light's full strength; first %4")
                                .arg(nonFinite)
                                .arg(negative)
                                .arg(overBound)
                                .arg(firstBad)));
        QVERIFY2(strict > kCases / 2, "too few well-conditioned cases to mean anything");
        fwd.verify(), upload.verify();
    }

    // dot(normalize(a), normalize(a)) > 1 happens in float; every formula must stay in range anyway.
    void normalizeOvershoot() {
        Gen g(1);
        long found = 0, foundSafe = 0, tried = 0;
        float worst = 1;
        for (int i = 0; i < 100000; ++i) {
            Vec3f a = g.unitF() * float(g.logUniform(1e-3, 1e3));
            if (i % 4 == 0) a = g.adversarialVector();
            ++tried;
            for (const bool safe : {false, true}) {
                const Vec3f n = safe ? safeNormalize(a, Vec3f(0, 0, 1)) : glm::normalize(a);
                if (!finite(n))
                    continue; // glm::normalize(0) and denormals: NaN/Inf — why safeNormalize exists
                const float nn = glm::dot(n, n);
                if (!(nn > 1.0f)) continue;
                (safe ? foundSafe : found)++;
                worst = std::max(worst, nn);
                QVERIFY(std::isnan(std::acos(nn))); // what an unguarded acos would return
                const auto at = [&](float x) {
                    return qPrintable(
                        QStringLiteral("a=%1 n·n=%2 -> %3").arg(vecStr(toD(a)), num(nn), num(x)));
                };
                const float r[] = {diffuseLambert(nn),
                                   diffuseHalfLambert(nn),
                                   specularPhong(n, n, n, 32.0f),
                                   specularBlinnPhong(n, n, n, 32.0f),
                                   rimTerm(n, n, n, 1.3f),
                                   rimTerm(-n, n, n, 0.5f),
                                   coneAnglePower(nn, 0.5f, 0.5f),
                                   coneSmooth(nn, 0.9f, 0.8f, 3.2f),
                                   coneHard(nn, 0.8f),
                                   falloffRangePower(0.0f, 1.0f, 0.5f)};
                for (float x : r)
                    QVERIFY2(std::isfinite(x) && x >= 0 && x <= 1, at(x));
                // Through a whole light: a directional light straight down the normal, and a spot on the
                // axis.
                ShadeLight<float> l;
                l.type = LightType::Directional, l.direction = -n, l.color = Vec3f(1), l.specular = Vec3f(1);
                Surface<float> s;
                s.normal = n, s.position = n * 3.0f;
                const Vec3f out = shadeLight(l, s, ShadeSettings<float>{}, n);
                QVERIFY2(finite(out) && out.x <= 2 && out.x >= 0, at(out.x)); // D <= 1, S <= 1
                l.type = LightType::Spot, l.position = s.position + n, l.cone = ConeModel::AnglePower;
                const Vec3f spot = shadeLight(l, s, ShadeSettings<float>{}, n);
                QVERIFY2(finite(spot) && spot.x <= 2 && spot.x >= 0, at(spot.x));
            }
        }
        qInfo("%ld of %ld vectors: float dot(normalize(a), normalize(a)) > 1 (glm::normalize %ld, "
              "safeNormalize "
              "%ld); largest %.9g = 1 + %.2f eps",
              found + foundSafe, tried, found, foundSafe, double(worst), (double(worst) - 1) / kEpsF);
        QVERIFY2(found > 0 && foundSafe > 0, "expected float normalize to overshoot 1 for some vectors");
        QVERIFY2(double(worst) - 1 <= 4 * kEpsF, "float normalize overshoots 1 by more than 4 eps");
    }
};

QTEST_GUILESS_MAIN(TestPrecision)
#include "tst_precision.moc"
