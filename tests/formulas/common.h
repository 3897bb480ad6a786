// Shared helpers of the formula tests: tolerant comparisons with readable messages, error statistics,
// a seeded generator of ordinary and adversarial inputs, and the "envelope" check used to state the
// mixed (forward-backward) error bound of a scalar formula.
#pragma once

#include "core/lighting.h"
#include "core/shade.h"

#include <QString>
#include <QTest>
#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <random>

namespace lr::test {

using lighting::Vec3;
using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;

// Unit roundoff of float (2^-24) and its machine epsilon (2^-23): the bounds are stated in these.
inline constexpr double kEpsF = std::numeric_limits<float>::epsilon();
inline constexpr double kUlpF = kEpsF / 2;
inline constexpr float kDenormF = 1e-40f; // a float denormal (min normal is 1.18e-38)
using lighting::kPi;

inline double radians(double deg) {
    return deg * kPi / 180.0;
}

inline QString num(double x) {
    return QString::number(x, 'g', 10);
}
inline QString vecStr(const Vec3d& v) {
    return QStringLiteral("(%1, %2, %3)").arg(num(v.x), num(v.y), num(v.z));
}
// `v` as stored: an optimisation barrier the compiler cannot see through. Without it GCC 12's SLP
// vectorizer (-O3, the release preset; -O2 does not do it) folds double -> float -> double back into the
// original double when both conversions are inlined into one function: the "same float inputs" in double
// were then the unrounded ones, and tst_precision compared the float result with a reference and a bound
// for inputs the float path never saw (release only: 47 "above the light's full strength" cases).
template <typename T> T asStored(T v) {
    asm volatile("" : "+m"(v));
    return v;
}
inline Vec3d toD(const Vec3f& v) {
    return Vec3d(asStored(v));
}
// A float-prepared light back in double, so both evaluations see exactly the same numbers.
inline lighting::ShadeLight<double> toDouble(const lighting::ShadeLight<float>& stored) {
    const lighting::ShadeLight<float> l = asStored(stored);
    lighting::ShadeLight<double> o;
    o.type = l.type, o.falloff = l.falloff, o.cone = l.cone, o.diffuse = l.diffuse;
    o.position = Vec3d(l.position), o.direction = Vec3d(l.direction), o.color = Vec3d(l.color);
    o.specular = Vec3d(l.specular), o.ambient = Vec3d(l.ambient);
    o.range = l.range, o.falloffExponent = l.falloffExponent;
    o.constant = l.constant, o.linear = l.linear, o.quadratic = l.quadratic;
    o.cosInner = l.cosInner, o.cosOuter = l.cosOuter, o.outer = l.outer, o.coneExponent = l.coneExponent;
    o.rimExponent = l.rimExponent;
    return o;
}

inline bool finite(const Vec3d& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
inline bool finite(const Vec3f& v) {
    return finite(toD(v));
}

} // namespace lr::test

// |actual - expected| <= tol (fails on NaN), naming the expression and both values.
#define LR_NEAR(actual, expected, tol)                                                                       \
    do {                                                                                                     \
        const double lrA = double(actual), lrE = double(expected), lrT = double(tol);                        \
        QVERIFY2(std::abs(lrA - lrE) <= lrT, qPrintable(QStringLiteral("%1 = %2, expected %3 +- %4")         \
                                                            .arg(QLatin1String(#actual), lr::test::num(lrA), \
                                                                 lr::test::num(lrE), lr::test::num(lrT))));  \
    } while (0)

#define LR_NEAR_VEC(actual, expected, tol)                                                                   \
    do {                                                                                                     \
        const lr::test::Vec3d lrA = lr::test::Vec3d(actual), lrE = lr::test::Vec3d(expected);                \
        const double lrT = double(tol);                                                                      \
        QVERIFY2(std::abs(lrA.x - lrE.x) <= lrT && std::abs(lrA.y - lrE.y) <= lrT &&                         \
                     std::abs(lrA.z - lrE.z) <= lrT,                                                         \
                 qPrintable(QStringLiteral("%1 = %2, expected %3 +- %4")                                     \
                                .arg(QLatin1String(#actual), lr::test::vecStr(lrA), lr::test::vecStr(lrE),   \
                                     lr::test::num(lrT))));                                                  \
    } while (0)

namespace lr::test {

// Largest absolute and relative error seen, with a description of the worst case (built lazily).
struct ErrorStats {
    QString name;
    double maxAbs = 0, maxRel = 0;
    QString worstAbs, worstRel;
    long count = 0;

    // rel is measured against max(|ref|, relFloor) so that results near 0 are judged absolutely.
    void add(double got, double ref, double relFloor, const std::function<QString()>& where) {
        ++count;
        const double a = std::abs(got - ref), r = a / std::max(std::abs(ref), relFloor);
        if (a > maxAbs) maxAbs = a, worstAbs = where();
        if (r > maxRel) maxRel = r, worstRel = where();
    }
    QString summary() const {
        return QStringLiteral("%1: %2 cases, max abs %3 (%4 eps), max rel %5 (%6 eps); worst abs at %7")
            .arg(name)
            .arg(count)
            .arg(num(maxAbs), num(maxAbs / kEpsF), num(maxRel), num(maxRel / kEpsF), worstAbs);
    }
};

// Mixed error bound of a scalar formula f in one parameter t: the float result lies within the range of
// the double results for t perturbed by up to relT (relative), widened by relOut·|result| + absOut.
// This is the honest statement where f is ill-conditioned (near a range edge, or pow with exponent < 1
// near 0): float then returns the exact value of a nearby input, which no forward bound can promise.
// The range is sampled at 17 points of [t(1-relT), t(1+relT)] (the formulas are monotone in t there).
inline bool withinEnvelope(const std::function<double(double)>& fd, double t, double got, double relT,
                           double relOut, double absOut, double* loOut = nullptr, double* hiOut = nullptr) {
    double lo = fd(t), hi = lo;
    for (int i = -8; i <= 8; ++i) {
        const double v = fd(t * (1.0 + relT * i / 8.0));
        lo = std::min(lo, v), hi = std::max(hi, v);
    }
    const double slack = relOut * std::max(std::abs(lo), std::abs(hi)) + absOut;
    if (loOut) *loOut = lo - slack;
    if (hiOut) *hiOut = hi + slack;
    return got >= lo - slack && got <= hi + slack;
}

// Seeded generator of ordinary and adversarial inputs (std::mt19937, so runs are reproducible).
class Gen {
  public:
    explicit Gen(std::uint32_t seed) : rng_(seed) {}

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }
    // Magnitude spread evenly over decades: lo..hi > 0.
    double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
    template <typename T> T pick(std::initializer_list<T> values) {
        return *(values.begin() + integer(0, int(values.size()) - 1));
    }

    // A direction uniform on the sphere, computed in double and rounded to float: its float length is
    // 1 within an ulp or two, as with any normal a renderer receives.
    Vec3d unitD() {
        for (;;) {
            const Vec3d v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            const double l2 = glm::dot(v, v);
            if (l2 > 1e-6 && l2 <= 1.0) return v / std::sqrt(l2);
        }
    }
    Vec3f unitF() { return Vec3f(unitD()); }

    // A unit vector at angle theta (radians) from the unit axis a, rotated randomly about it.
    Vec3d around(const Vec3d& a, double theta) {
        const Vec3d helper = std::abs(a.x) < 0.9 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
        const Vec3d u = glm::normalize(glm::cross(a, helper)), w = glm::cross(a, u);
        const double phi = uniform(0, 2 * kPi);
        return std::cos(theta) * a + std::sin(theta) * (std::cos(phi) * u + std::sin(phi) * w);
    }

    // Vectors that break naive code: zero, denormal, tiny, huge, axis-aligned and almost axis-aligned,
    // unnormalised, and values with mixed magnitudes.
    Vec3f adversarialVector() {
        switch (integer(0, 7)) {
        case 0:
            return Vec3f(0.0f);
        case 1:
            return Vec3f(kDenormF * float(uniform(-1, 1)), kDenormF, 0.0f);
        case 2:
            return unitF() * float(logUniform(1e-38, 1e-30));
        case 3:
            return unitF() * float(logUniform(1e30, 1e37));
        case 4:
            return Vec3f(pick({-1.0f, 1.0f}), 0.0f, 0.0f);
        case 5:
            return Vec3f(1.0f, pick({1e-7f, -1e-7f, 1e-20f, kDenormF}), 0.0f);
        case 6:
            return unitF() * float(logUniform(1e-3, 1e3));
        default:
            return Vec3f(float(logUniform(1e-30, 1e30)), float(-logUniform(1e-30, 1e30)), 1.0f);
        }
    }

  private:
    std::mt19937 rng_;
};

} // namespace lr::test
