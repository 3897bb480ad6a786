// The extremes of issue 2 §2 and issue 5: range 0, 1e-30, 1e30; d = 0 (light on the surface); outer =
// inner; outer -> 0 and 90°; cosθ a hair above 1; exponent 0 with base 0; zero-length and denormal
// vectors; intensities up to 1e6; huge distances. Every result must be finite, inside the formula's
// documented range, equal to the documented value where there is one, and agree with the double
// evaluation of the same (float-representable) inputs within the mixed bound stated below.
//
// Mixed bound (docs/quality.md): the float result lies within the double results for the formula's
// parameter perturbed by up to kRelIn (relative), widened by (4 + 2·exponent)·eps·|result| + kAbsOut.
// kAbsOut covers results below float's normal range (1.2e-38), which float may flush to 0.
#include "common.h"
#include "core/prepare.h"

#include <glm/gtc/epsilon.hpp>
#include <glm/vector_relational.hpp>
#include <vector>

using namespace lr;
using namespace lr::lighting;
using namespace lr::test;

namespace {

constexpr double kRelIn = 4 * kEpsF;
constexpr double kAbsOut = 1e-37;
constexpr float kFMax = std::numeric_limits<float>::max();
const float kOnePlus = std::nextafter(1.0f, 2.0f);  // cosθ a hair above 1
const float kOneMinus = std::nextafter(1.0f, 0.0f); // and a hair below

double relOut(double exponent) {
    return (4 + 2 * std::max(exponent, 0.0)) * kEpsF;
}

const std::vector<float> kDistances = {0,   kDenormF, 1e-30f, 1e-7f, 0.5f,  1,    99.99999f,
                                       100, 400,      1e6f,   1e20f, 1e30f, kFMax};
const std::vector<float> kRanges = {-1, 0, kDenormF, 1e-30f, 1e-7f, 1, 100, 400, 1e30f, kFMax};
const std::vector<float> kExponents = {0, 1e-7f, 0.5f, 1, 2, 3.2f, 32, 1000};
const std::vector<float> kCosines = {-1,       -0.5f,     0, 6.1e-17f, 0.5f,     0.9063078f /* cos 25° */,
                                     0.99999f, kOneMinus, 1, kOnePlus, 1.000001f};
const std::vector<double> kAnglesDeg = {0, 1e-30, 1e-6, 1e-3, 0.5, 25, 30, 50, 89.9999, 90};

// Counts checks and reports the first failure with its inputs (QVERIFY inside loops would stop at once
// without saying how many cases failed).
struct Checker {
    long checks = 0, failures = 0;
    QString first;
    void expect(bool ok, const std::function<QString()>& what) {
        ++checks;
        if (!ok && failures++ == 0) first = what();
    }
    void verify(const char* name) const {
        QVERIFY2(failures == 0, qPrintable(QStringLiteral("%1: %2 of %3 checks failed; first: %4")
                                               .arg(QLatin1String(name))
                                               .arg(failures)
                                               .arg(checks)
                                               .arg(first)));
        qInfo("%s: %ld checks passed", name, checks);
    }
};

// Finite, inside [lo, hi], and within the mixed bound of the double result.
void checkScalar(Checker& c, const std::function<double(double)>& fd, double t, double rf, double rd,
                 double lo, double hi, double exponent, const std::function<QString()>& inputs) {
    double elo = 0, ehi = 0;
    const bool ok = std::isfinite(rf) && std::isfinite(rd) && rf >= lo && rf <= hi && rd >= lo && rd <= hi &&
                    withinEnvelope(fd, t, rf, kRelIn, relOut(exponent), kAbsOut, &elo, &ehi);
    c.expect(ok, [&] {
        return inputs() + QStringLiteral(": float %1, double %2, allowed [%3, %4]")
                              .arg(num(rf), num(rd), num(elo), num(ehi));
    });
}

ShadeLight<double> pointLight(FalloffModel f, double range, const Vec3d& position) {
    ShadeLight<double> l;
    l.type = LightType::Point, l.falloff = f, l.range = range, l.position = position;
    l.constant = 0, l.linear = 0.1, l.quadratic = 0.05;
    return l;
}

// Shade one light in double and in float (from the float-rounded inputs, so both see the same numbers).
struct Pair {
    Vec3d d, f;
};
Pair shadeBoth(const ShadeLight<double>& l, Surface<double> s, ShadeSettings<double> st) {
    const ShadeLight<float> lf = castLight<float>(l);
    Surface<float> sf;
    sf.position = Vec3f(s.position), sf.normal = Vec3f(s.normal), sf.albedo = Vec3f(s.albedo);
    sf.specular = Vec3f(s.specular), sf.emissive = Vec3f(s.emissive), sf.shininess = float(s.shininess);
    ShadeSettings<float> stf;
    stf.specular = st.specular, stf.viewer = st.viewer, stf.ambient = Vec3f(st.ambient);
    stf.distanceScale = float(st.distanceScale);
    const ShadeLight<double> ld = toDouble(lf); // the float-rounded light, in double
    s.position = Vec3d(sf.position), s.normal = Vec3d(sf.normal), s.shininess = double(sf.shininess);
    st.distanceScale = double(stf.distanceScale);
    return {shadeLight(ld, s, st, viewVector(st, s.position)),
            toD(shadeLight(lf, sf, stf, viewVector(stf, sf.position)))};
}

} // namespace

class TestExtremes : public QObject {
    Q_OBJECT
  private slots:
    void safeHelpers() {
        // pow(0, 0) = 1 by convention; negative or NaN bases give 0; exponents <= 0 or NaN give 1.
        QCOMPARE(safePow(0.0f, 0.0f), 1.0f);
        QCOMPARE(safePow(0.0, 2.0), 0.0);
        QCOMPARE(safePow(-1.0, 0.5), 0.0);
        QCOMPARE(safePow(std::nan(""), 2.0), 0.0);
        QCOMPARE(safePow(0.5, -1.0), 1.0);
        // acos clamps: a hair above 1 is 0, a hair below -1 is π, NaN is π (and so outside any cone).
        QCOMPARE(safeAcos(kOnePlus), 0.0f);
        QCOMPARE(safeAcos(-kOnePlus), std::acos(-1.0f));
        QVERIFY(std::isnan(std::acos(kOnePlus))); // what the guard prevents
        // saturate / positive map NaN to 0.
        QCOMPARE(saturate(std::nan("")), 0.0);
        QCOMPARE(positive(std::nan("")), 0.0);
        // normalise: zero, denormal, huge, Inf, NaN.
        const Vec3f fb(0, 0, 1);
        QCOMPARE(safeNormalize(Vec3f(0), fb), fb);
        LR_NEAR_VEC(safeNormalize(Vec3f(kDenormF, 0, 0), fb), Vec3d(1, 0, 0), 0);
        LR_NEAR_VEC(safeNormalize(Vec3f(kDenormF, kDenormF, 0), fb), Vec3d(std::sqrt(0.5), std::sqrt(0.5), 0),
                    1e-7);
        LR_NEAR_VEC(safeNormalize(Vec3f(3e38f, 2e38f, 0), fb), Vec3d(3, 2, 0) / std::sqrt(13.0), 1e-7);
        QVERIFY(glm::length(glm::normalize(Vec3f(kDenormF, 0, 0))) != 1.0f); // naive normalize fails here
        const float inf = std::numeric_limits<float>::infinity(), nan = std::nanf("");
        QCOMPARE(safeNormalize(Vec3f(inf, 1, 0), fb), fb);
        QCOMPARE(safeNormalize(Vec3f(1, inf, 0), fb), fb);
        QCOMPARE(safeNormalize(Vec3f(nan, 1, 0), fb), fb);
        QCOMPARE(safeNormalize(Vec3f(1, nan, 0), fb), fb); // max() skips a NaN here: caught by the dot test
        QCOMPARE(safeNormalize(Vec3f(0, 0, nan), fb), fb);
    }

    void falloffsAllExtremes() {
        Checker c;
        for (float d : kDistances)
            for (float range : kRanges) {
                const auto where = [&](const char* f, double p = 0) {
                    return [=] {
                        return QStringLiteral("%1(d=%2, range=%3, p=%4)")
                            .arg(QLatin1String(f), num(d), num(range), num(p));
                    };
                };
                for (float p : kExponents) {
                    if (range < 0) break; // range-power has no optional range
                    checkScalar(
                        c, [&](double t) { return falloffRangePower(t, double(range), double(p)); }, d,
                        falloffRangePower(d, range, p), falloffRangePower<double>(d, range, p), 0, 1, p,
                        where("rangePower", p));
                }
                if (range >= 0)
                    checkScalar(
                        c, [&](double t) { return falloffRangeQuadratic(t, double(range)); }, d,
                        falloffRangeQuadratic(d, range), falloffRangeQuadratic<double>(d, range), 0, 1, 2,
                        where("rangeQuadratic"));
                checkScalar(
                    c, [&](double t) { return falloffInverseSquare(t, double(range)); }, d,
                    falloffInverseSquare(d, range), falloffInverseSquare<double>(d, range), 0, 1e4, 2,
                    where("inverseSquare"));
                for (float k : {0.0f, 1e-30f, 1.0f, 1e30f})
                    for (float l : {0.0f, 0.1f, 1e30f})
                        for (float q : {0.0f, 0.05f, 1e30f}) {
                            if (k == 0 && l == 0 && q == 0) continue; // rejected by the rig reader
                            checkScalar(
                                c,
                                [&](double t) { return falloffInversePolynomial<double>(t, k, l, q, range); },
                                d, falloffInversePolynomial(d, k, l, q, range),
                                falloffInversePolynomial<double>(d, k, l, q, range), 0, 1e4, 2,
                                [=] {
                                    return QStringLiteral("inversePolynomial(d=%1, %2, %3, %4, range=%5)")
                                        .arg(num(d), num(k), num(l), num(q), num(range));
                                });
                        }
            }
        c.verify("falloffs");
    }

    void falloffDocumentedValues() {
        for (float d : kDistances) {
            // range 0: no light at all, not even at d = 0 (the range ends before it begins).
            QCOMPARE(falloffRangePower(d, 0.0f, 2.0f), 0.0f);
            QCOMPARE(falloffRangeQuadratic(d, 0.0f), 0.0f);
            QCOMPARE(falloffInverseSquare(d, 0.0f), 0.0f);
            QCOMPARE(falloffInversePolynomial(d, 1.0f, 0.0f, 0.0f, 0.0f), 0.0f);
            // Exponent 0: 1 inside the range, 0 from the range on (pow(0, 0) never reached).
            QCOMPARE(falloffRangePower(d, 400.0f, 0.0f), d < 400 ? 1.0f : 0.0f);
        }
        // range 1e-30: full strength only closer than 1e-30.
        QCOMPARE(falloffRangePower(0.0f, 1e-30f, 2.0f), 1.0f);
        QCOMPARE(falloffRangePower(1e-31f, 1e-30f, 1.0f), 0.9f);
        QCOMPARE(falloffRangePower(1e-30f, 1e-30f, 2.0f), 0.0f);
        // range 1e30: no visible falloff at ordinary distances.
        QCOMPARE(falloffRangePower(1e6f, 1e30f, 2.0f), 1.0f);
        QCOMPARE(falloffInverseSquare(1e6f, 1e30f), 1e-12f);
        // d = 0 with an unbounded 1/d² or 1/(l d): the floor 1e-4 caps the attenuation at 1e4.
        QCOMPARE(falloffInverseSquare(0.0f, -1.0f), 1e4f);
        QCOMPARE(falloffInversePolynomial(0.0f, 0.0f, 0.1f, 0.05f, -1.0f), 1e4f);
        // Overflowing denominators give 0, never NaN: (1e30 d²) at d = 1e30.
        QCOMPARE(falloffInversePolynomial(1e30f, 1.0f, 0.0f, 1e30f, -1.0f), 0.0f);
        QCOMPARE(falloffInverseSquare(kFMax, -1.0f), 0.0f);
    }

    void conesAllExtremes() {
        Checker c;
        for (float cosT : kCosines)
            for (double outerDeg : kAnglesDeg) {
                const float outer = float(radians(outerDeg)), cosOuter = float(std::cos(radians(outerDeg)));
                for (float p : kExponents) {
                    const double theta = std::acos(std::clamp(double(cosT), -1.0, 1.0));
                    checkScalar(
                        c,
                        [&](double t) {
                            return safePow(saturate(1 - t / double(outer)), double(p)) * (t < outer);
                        },
                        theta, coneAnglePower(cosT, outer, p), coneAnglePower<double>(cosT, outer, p), 0, 1,
                        p,
                        [=] {
                            return QStringLiteral("anglePower(cos=%1, outer=%2°, p=%3)")
                                .arg(num(cosT), num(outerDeg), num(p));
                        });
                    for (double innerDeg : kAnglesDeg) {
                        if (innerDeg > outerDeg) break;
                        const float cosInner = float(std::cos(radians(innerDeg)));
                        const double w = double(cosInner) - double(cosOuter);
                        const float rf = coneSmooth(cosT, cosInner, cosOuter, p);
                        const double rd = coneSmooth<double>(cosT, cosInner, cosOuter, p);
                        const auto what = [=] {
                            return QStringLiteral("smooth(cos=%1, inner=%2°, outer=%3°, p=%4)")
                                .arg(num(cosT), num(innerDeg), num(outerDeg), num(p));
                        };
                        if (!(w > 1e-7)) { // degenerate in both types: exactly the hard cone
                            c.expect(rf == coneHard(cosT, cosOuter) && rd == rf, what);
                            continue;
                        }
                        // Parameter: cosθ - cos outer (one rounding, then one division by the width).
                        checkScalar(
                            c, [&](double t) { return t > 0 ? safePow(saturate(t / w), double(p)) : 0.0; },
                            double(cosT) - double(cosOuter), rf, rd, 0, 1, p, what);
                    }
                }
                // The hard cone is a comparison of the same two floats: bit-identical in both types.
                c.expect(coneHard(cosT, cosOuter) == float(coneHard<double>(cosT, cosOuter)), [=] {
                    return QStringLiteral("hard(cos=%1, outer=%2°)").arg(num(cosT), num(outerDeg));
                });
            }
        c.verify("cones");
    }

    void coneDocumentedValues() {
        const float co = float(std::cos(radians(25)));
        // cosθ a hair above 1: on the axis for every model.
        QCOMPARE(coneAnglePower(kOnePlus, float(radians(25)), 0.5f), 1.0f);
        QCOMPARE(coneSmooth(kOnePlus, float(std::cos(radians(10))), co, 2.0f), 1.0f);
        QCOMPARE(coneHard(kOnePlus, co), 1.0f);
        // outer = inner: the smooth cone is the hard cone, edge included, any exponent.
        for (float p : kExponents) {
            QCOMPARE(coneSmooth(co, co, co, p), 1.0f);
            QCOMPARE(coneSmooth(std::nextafter(co, 0.0f), co, co, p), 0.0f);
            QCOMPARE(coneSmooth(0.99f, co, co, p), 1.0f);
        }
        // outer -> 0 (cos outer rounds to 1): only the exact axis is lit, by all three models.
        const float tiny = 1e-30f, cosTiny = float(std::cos(1e-30));
        QCOMPARE(cosTiny, 1.0f);
        QCOMPARE(coneAnglePower(1.0f, tiny, 0.5f), 1.0f);
        QCOMPARE(coneAnglePower(kOneMinus, tiny, 0.5f), 0.0f);
        QCOMPARE(coneSmooth(1.0f, cosTiny, cosTiny, 2.0f), 1.0f);
        QCOMPARE(coneSmooth(kOneMinus, cosTiny, cosTiny, 2.0f), 0.0f);
        QCOMPARE(coneHard(1.0f, cosTiny), 1.0f);
        // outer = 90°: the whole front half-space; exactly sideways (cosθ = 0 < cos 90° = 6e-17) is out.
        const float right = float(radians(90)), cosRight = float(std::cos(radians(90)));
        QCOMPARE(coneAnglePower(0.5f, right, 1.0f), 1.0f - float(radians(60)) / right);
        QCOMPARE(coneHard(0.001f, cosRight), 1.0f);
        QCOMPARE(coneHard(0.0f, cosRight), 0.0f);
        QCOMPARE(coneSmooth(-0.001f, float(std::cos(radians(60))), cosRight, 1.0f), 0.0f);
        // Exponent 0: 1 strictly inside, 0 on and outside the edge.
        // (Exactly on the edge float may land an ulp either side: acos(float(cos 25°)) vs float(25°).)
        QCOMPARE(coneAnglePower(float(std::cos(radians(25.01))), float(radians(25)), 0.0f), 0.0f);
        QCOMPARE(coneAnglePower(float(std::cos(radians(24.99))), float(radians(25)), 0.0f), 1.0f);
        QCOMPARE(coneSmooth(co, float(std::cos(radians(10))), co, 0.0f), 0.0f);
        QCOMPARE(coneSmooth(0.95f, float(std::cos(radians(10))), co, 0.0f), 1.0f);
    }

    void surfaceTermsWithDegenerateVectors() {
        // Zero, denormal and huge (unnormalised) N, L, V: finite, inside [0, 1], never NaN.
        const std::vector<Vec3f> vs = {Vec3f(0),
                                       Vec3f(kDenormF, 0, 0),
                                       Vec3f(0, 0, kDenormF),
                                       Vec3f(0, 0, 1),
                                       Vec3f(1, 0, 0),
                                       Vec3f(0, 0, -1),
                                       Vec3f(0.6f, 0, 0.8f),
                                       Vec3f(-0.6f, 0, 0.8f),
                                       Vec3f(0, kOnePlus, 0)};
        Checker c;
        for (const Vec3f& N : vs)
            for (const Vec3f& L : vs)
                for (const Vec3f& V : vs)
                    for (float n : {0.0f, 1.0f, 32.0f, 1e4f}) {
                        const float r[] = {specularPhong(N, L, V, n), specularBlinnPhong(N, L, V, n),
                                           rimTerm(L, N, V, n), diffuseLambert(glm::dot(N, L)),
                                           diffuseHalfLambert(glm::dot(N, L))};
                        for (float x : r)
                            c.expect(std::isfinite(x) && x >= 0 && x <= 1, [&] {
                                return QStringLiteral("N=%1 L=%2 V=%3 n=%4 -> %5")
                                    .arg(vecStr(toD(N)), vecStr(toD(L)), vecStr(toD(V)), num(n), num(x));
                            });
                    }
        c.verify("surface terms");
        // Exponent 0 with base 0: pow(0, 0) = 1. Shininess 0 lights every point the light reaches; rim
        // exponent 0 rims everything, even a camera-facing normal.
        QCOMPARE(specularPhong(Vec3f(0, 0, 1), Vec3f(0.6f, 0, 0.8f), Vec3f(0.6f, 0, -0.8f), 0.0f), 1.0f);
        QCOMPARE(rimTerm(Vec3f(0, 0, -1), Vec3f(0, 0, 1), Vec3f(0, 0, 1), 0.0f), 1.0f);
        QCOMPARE(rimTerm(Vec3f(0, 0, -1), Vec3f(0, 0, 1), Vec3f(0, 0, 1), 1.3f), 0.0f);
    }

    void outputStage() {
        // Tone maps and sRGB encoding: every input, Inf and NaN included, lands in [0, 1].
        const float inf = std::numeric_limits<float>::infinity();
        for (float x : {-inf, -1.0f, 0.0f, kDenormF, 1e-30f, 0.0031308f, 0.5f, 1.0f, 1e6f, 1e30f, kFMax, inf,
                        std::nanf("")})
            for (int i = 0; i < enumCount<ToneMap>(); ++i) {
                const ToneMap op = ToneMap(i);
                const Vec3f c = colour::toneMapRgb(op, Vec3f(x, 0.5f, 1.0f));
                const float r[] = {toneMap(op, x),
                                   linearToSrgb(x),
                                   srgbToLinear(x),
                                   linearToSrgb(toneMap(op, x)),
                                   c.x,
                                   c.y,
                                   c.z};
                for (float y : r)
                    QVERIFY2(std::isfinite(y) && y >= 0 && y <= 1,
                             qPrintable(QStringLiteral("%1(%2) -> %3").arg(toString(op), num(x), num(y))));
            }
        QCOMPARE(toneMap(ToneMap::Reinhard, kFMax), 1.0f);
        QCOMPARE(toneMap(ToneMap::Aces, 1e30f), 1.0f);
        QCOMPARE(toneMap(ToneMap::Reinhard, 1.0f), 0.5f);
    }

    void wholeLight_data() {
        QTest::addColumn<int>("kind");
        QTest::addColumn<double>("tolerance"); // relative to max(|double result|, 1e-30)
        const char* names[] = {"light on the surface, every falloff and type",
                               "range 0",
                               "range 1e-30, light 1e-31 away",
                               "range 1e30, light 1e6 away",
                               "huge distance 1e20..1e37 within range 1e38",
                               "intensity 1e6, inverse-square at d = 0",
                               "zero and denormal normals",
                               "surface at the eye (zero view vector)",
                               "zero spot direction",
                               "outer = inner, outer -> 0, outer = 90°",
                               "exponent 0 everywhere",
                               "positions whose difference overflows float"};
        // Stated tolerances, relative: 1e-5 covers the specular (shininess 32 multiplies the ~2 ulps of
        // N·V or R·V by 32); the measured maximum is printed. -1: only finite and non-negative asserted.
        const double tol[] = {1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, 1e-5, -1};
        for (int i = 0; i < int(std::size(names)); ++i)
            QTest::newRow(names[i]) << i << tol[i];
    }

    void wholeLight() {
        QFETCH(int, kind);
        QFETCH(double, tolerance);
        const Vec3d P(0.3, -0.2, -5);
        Surface<double> s;
        s.position = P, s.normal = glm::normalize(Vec3d(0.2, 0.1, 1)), s.albedo = Vec3d(0.8, 0.5, 0.2);
        ShadeSettings<double> st;
        std::vector<std::pair<ShadeLight<double>, Surface<double>>> cases;
        std::vector<ShadeSettings<double>> settings = {st};
        const FalloffModel falloffs[] = {FalloffModel::None, FalloffModel::RangePower,
                                         FalloffModel::InversePolynomial, FalloffModel::RangeQuadratic,
                                         FalloffModel::InverseSquare};
        auto add = [&](ShadeLight<double> l, const Surface<double>& surf) {
            for (LightType t : {LightType::Point, LightType::Spot}) {
                l.type = t;
                cases.push_back({l, surf});
            }
        };
        switch (kind) {
        case 0: { // d = 0: L falls back to N, so N·L = 1; the falloff takes d = 0.
            Surface<double> matte = s;
            matte.specular = Vec3d(0);
            for (FalloffModel f : falloffs)
                add(pointLight(f, 10, P), matte), add(pointLight(f, 10, P), s);
            break;
        }
        case 1:
            for (FalloffModel f : falloffs)
                add(pointLight(f, 0, P + Vec3d(0, 0, 1)), s);
            break;
        case 2: { // near the eye so that float can tell 1e-31 apart
            Surface<double> z = s;
            z.position = Vec3d(0, 0, -1e-29);
            for (FalloffModel f : falloffs)
                add(pointLight(f, 1e-30, z.position + Vec3d(0, 0, 1e-31)), z);
            break;
        }
        case 3:
            for (FalloffModel f : falloffs)
                add(pointLight(f, 1e30, P + Vec3d(0, 1e6, 1e6)), s);
            break;
        case 4:
            for (double far : {1e20, 1e25, 1e30, 1e37})
                for (FalloffModel f :
                     {FalloffModel::RangePower, FalloffModel::RangeQuadratic, FalloffModel::None})
                    add(pointLight(f, 1e38, P + far * s.normal), s);
            break;
        case 5: {
            ShadeLight<double> l = pointLight(FalloffModel::InverseSquare, -1, P);
            l.color = Vec3d(15, 1, 0) * 1e6, l.specular = l.color, l.ambient = Vec3d(1e6);
            add(l, s);
            break;
        }
        case 6:
            for (const Vec3d& n : {Vec3d(0), Vec3d(1e-40, 0, 0), Vec3d(0, 1e-45, 1e-45)}) {
                Surface<double> z = s;
                z.normal = n;
                add(pointLight(FalloffModel::RangePower, 10, P + Vec3d(0, 0, 1)), z);
                ShadeLight<double> rim;
                rim.type = LightType::Rim;
                cases.push_back({rim, z});
            }
            break;
        case 7: {
            Surface<double> z = s;
            z.position = Vec3d(0);
            add(pointLight(FalloffModel::RangePower, 10, Vec3d(0, 1, 0)), z);
            break;
        }
        case 8: {
            ShadeLight<double> l = pointLight(FalloffModel::None, -1, P + Vec3d(0, 0, 1));
            l.direction = Vec3d(0);
            add(l, s);
            l.type = LightType::Directional;
            cases.push_back({l, s});
            break;
        }
        case 9:
            for (ConeModel cone : {ConeModel::AnglePower, ConeModel::Smooth, ConeModel::Hard})
                for (double outerDeg : {1e-30, 1e-3, 25.0, 90.0}) {
                    ShadeLight<double> l = pointLight(FalloffModel::None, -1, P + Vec3d(0, 0, 1));
                    l.type = LightType::Spot, l.cone = cone, l.direction = Vec3d(0, 0, -1);
                    l.outer = radians(outerDeg), l.cosOuter = l.cosInner = std::cos(l.outer);
                    cases.push_back({l, s});
                }
            break;
        case 10: {
            ShadeLight<double> l = pointLight(FalloffModel::RangePower, 10, P + Vec3d(0, 0, 1));
            l.falloffExponent = 0, l.coneExponent = 0, l.rimExponent = 0, l.cone = ConeModel::AnglePower;
            Surface<double> z = s;
            z.shininess = 0;
            add(l, z);
            l.type = LightType::Rim;
            cases.push_back({l, z});
            break;
        }
        case 11: {
            Surface<double> z = s;
            z.position = Vec3d(3e38, 0, -1);
            for (FalloffModel f : falloffs)
                add(pointLight(f, 10, Vec3d(-3e38, 0, -1)), z);
            break;
        }
        }
        double worst = 0;
        for (const auto& [l, surf] : cases)
            for (SpecularModel sm : {SpecularModel::Phong, SpecularModel::BlinnPhong})
                for (ViewerModel vm : {ViewerModel::Local, ViewerModel::Infinite})
                    for (DiffuseModel dm : {DiffuseModel::Lambert, DiffuseModel::HalfLambert}) {
                        ShadeLight<double> light = l;
                        light.diffuse = dm;
                        ShadeSettings<double> set;
                        set.specular = sm, set.viewer = vm;
                        const Pair r = shadeBoth(light, surf, set);
                        const QString what = QStringLiteral("type %1 falloff %2 cone %3: double %4 float %5")
                                                 .arg(toString(light.type), toString(light.falloff),
                                                      toString(light.cone), vecStr(r.d), vecStr(r.f));
                        QVERIFY2(finite(r.d) && finite(r.f), qPrintable(what));
                        QVERIFY2(std::min({r.d.x, r.d.y, r.d.z, r.f.x, r.f.y, r.f.z}) >= 0, qPrintable(what));
                        for (int i = 0; i < 3; ++i) {
                            const double rel = std::abs(r.f[i] - r.d[i]) / std::max(std::abs(r.d[i]), 1e-30);
                            worst = std::max(worst, rel);
                            if (tolerance >= 0) QVERIFY2(rel <= tolerance, qPrintable(what));
                        }
                        if (kind == 1 && light.falloff != FalloffModel::None)
                            QCOMPARE(r.d, Vec3d(0)); // range 0: documented as no light
                        if (kind == 0 && light.type == LightType::Point && surf.specular == Vec3d(0)) {
                            // d = 0: L = N so D = 1 in both diffuse models; a(0) = 1e4 for the unbounded
                            // falloffs (floored denominator), 1 for the others. No specular (ks = 0).
                            const bool unbounded = light.falloff == FalloffModel::InverseSquare ||
                                                   light.falloff == FalloffModel::InversePolynomial;
                            const Vec3d expected = (unbounded ? 1e4 : 1.0) * surf.albedo;
                            QVERIFY2(glm::all(glm::epsilonEqual(r.d, expected, 1e-6 * expected.x)),
                                     qPrintable(what));
                        }
                    }
        if (tolerance >= 0)
            qInfo("%zu lights x 8 shading variants, max relative error float vs double %.3g (%.1f eps)",
                  cases.size(), worst, worst / kEpsF);
    }
};

QTEST_GUILESS_MAIN(TestExtremes)
#include "tst_extremes.moc"
