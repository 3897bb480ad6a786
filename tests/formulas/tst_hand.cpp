// Every lighting formula against values worked out by hand from the design documents (000: HLSL book
// ch. 5, 001: Direct3D point/spot, 003: Korean DirectX tutorial, 004: Direct3D 8 lighting docs, glTF
// KHR_lights_punctual). The expected numbers are written out here, derived in the comments; none is
// copied from the implementation. Tolerances: 1e-12 relative in double (a few ulps of the operations),
// 1e-6 where the float twin is checked too.
#include "common.h"
#include "core/prepare.h"
#include "core/rig.h"

#include <glm/gtc/matrix_transform.hpp>

using namespace lr;
using namespace lr::lighting;
using namespace lr::test;

namespace {

constexpr double kTol = 1e-12; // double: the hand values are exact to ~1e-16, formulas add a few ulps
constexpr double kTolF = 2e-6; // float twin (values <= 1): a few float ulps

double cosDeg(double deg) {
    return std::cos(radians(deg));
}

// Both scalar types at once: the double result to kTol, the float result to kTolF (relative above 1).
#define LR_BOTH(expr_of_T, expected)                                                                         \
    do {                                                                                                     \
        using T = double;                                                                                    \
        LR_NEAR(expr_of_T, expected, kTol* std::max(1.0, std::abs(double(expected))));                       \
    } while (0);                                                                                             \
    do {                                                                                                     \
        using T = float;                                                                                     \
        LR_NEAR(expr_of_T, expected, kTolF* std::max(1.0, std::abs(double(expected))));                      \
    } while (0)

Light pointLight(const glm::dvec3& position, const glm::dvec3& color, double intensity, Falloff falloff) {
    Light l;
    l.type = LightType::Point;
    l.position = position, l.color = color, l.intensity = intensity, l.falloff = falloff;
    return l;
}

} // namespace

class TestHand : public QObject {
    Q_OBJECT
  private slots:
    // ---- distance falloff ----
    void rangePowerTables51And52() {
        // Doc 000 table 5.1: A = 1 - D/R with R = 400 (exponent 1); table 5.2 squares it (exponent 2).
        const double d[] = {0, 100, 200, 300, 400};
        const double linear[] = {1, 0.75, 0.5, 0.25, 0};
        const double squared[] = {1, 0.5625, 0.25, 0.0625, 0};
        for (int i = 0; i < 5; ++i) {
            LR_BOTH(falloffRangePower(T(d[i]), T(400), T(1)), linear[i]);
            LR_BOTH(falloffRangePower(T(d[i]), T(400), T(2)), squared[i]);
        }
        // Beyond the range the book clamps the negative A to 0 (its `if (affect < 0)`).
        LR_BOTH(falloffRangePower(T(500), T(400), T(2)), 0.0);
        // The book's sample cubes it (range 100): d = 50 -> 0.5^3.
        LR_BOTH(falloffRangePower(T(50), T(100), T(3)), 0.125);
    }

    void inversePolynomialDoc001() {
        // Doc 001: Att = 1 / (0 + 0.1 d + 0.05 d²).
        LR_BOTH(falloffInversePolynomial(T(1), T(0), T(0.1), T(0.05), T(-1)), 1.0 / 0.15); // 6.667
        LR_BOTH(falloffInversePolynomial(T(2), T(0), T(0.1), T(0.05), T(-1)), 2.5);        // 1/(0.2+0.2)
        LR_BOTH(falloffInversePolynomial(T(10), T(0), T(0.1), T(0.05), T(-1)), 1.0 / 6.0); // 1/(1+5)
        // d = 0: the denominator is 0 (doc 001 divides by zero); floored at 1e-4 -> 1e4.
        LR_BOTH(falloffInversePolynomial(T(0), T(0), T(0.1), T(0.05), T(-1)), 1e4);
        // Direct3D's default (1, 0, 0): no falloff at any distance.
        LR_BOTH(falloffInversePolynomial(T(123), T(1), T(0), T(0), T(-1)), 1.0);
        // With range 10 at d = 5: window (1 - 0.5^4)^2 = 0.87890625, over 1.75.
        LR_BOTH(falloffInversePolynomial(T(5), T(0), T(0.1), T(0.05), T(10)), 0.87890625 / 1.75);
        LR_BOTH(falloffInversePolynomial(T(10), T(0), T(0.1), T(0.05), T(10)), 0.0);
        LR_BOTH(falloffInversePolynomial(T(12), T(0), T(0.1), T(0.05), T(10)), 0.0);
    }

    void rangeQuadraticDoc003() {
        // Doc 003: saturate(1 - (dist/range)^2).
        LR_BOTH(falloffRangeQuadratic(T(0), T(10)), 1.0);
        LR_BOTH(falloffRangeQuadratic(T(5), T(10)), 0.75);
        LR_BOTH(falloffRangeQuadratic(T(10), T(10)), 0.0);
        LR_BOTH(falloffRangeQuadratic(T(20), T(10)), 0.0);
        // Doc 003's red point light at (150,150,150), range 10000, seen from the origin: d = 150·√3.
        LR_BOTH(falloffRangeQuadratic(T(150 * std::sqrt(3.0)), T(10000)), 1.0 - 3 * 150.0 * 150.0 / 1e8);
    }

    void inverseSquareGltf() {
        // KHR_lights_punctual: 1/d², windowed by clamp(1 - (d/range)^4, 0, 1)^2 when a range is given.
        LR_BOTH(falloffInverseSquare(T(2), T(-1)), 0.25);
        LR_BOTH(falloffInverseSquare(T(0.5), T(-1)), 4.0);
        LR_BOTH(falloffInverseSquare(T(0), T(-1)), 1e4);                             // d² floored at 1e-4
        LR_BOTH(falloffInverseSquare(T(0.001), T(-1)), 1e4);                         // d² = 1e-6 < 1e-4
        LR_BOTH(falloffInverseSquare(T(2), T(4)), 0.25 * (15.0 / 16) * (15.0 / 16)); // (1 - 1/16)^2 / 4
        LR_BOTH(falloffInverseSquare(T(1), T(2)), (15.0 / 16) * (15.0 / 16));
        LR_BOTH(falloffInverseSquare(T(4), T(4)), 0.0);
        LR_BOTH(falloffInverseSquare(T(9), T(4)), 0.0);
    }

    // ---- spot cones ----
    void anglePowerDoc000() {
        // Doc 000: affect = (1 - angle/spAngle)^0.5 with spAngle = 25°.
        const double outer = radians(25);
        LR_BOTH(coneAnglePower(T(1), T(outer), T(0.5)), 1.0);
        LR_BOTH(coneAnglePower(T(cosDeg(12.5)), T(outer), T(0.5)), std::sqrt(0.5)); // 0.70711
        LR_BOTH(coneAnglePower(T(cosDeg(20)), T(outer), T(0.5)), std::sqrt(0.2));   // 0.44721
        // On the edge: 0 in double. In float, acos(float(cos 25°)) lands an ulp inside the cone and the
        // exponent 0.5 turns 1 - θ/outer ~ 1e-7 into ~3e-4: exponents below 1 are ill-conditioned at the
        // edge (the mixed bound of tst_precision covers it).
        LR_NEAR(coneAnglePower(cosDeg(25), outer, 0.5), 0.0, kTol);
        LR_NEAR(coneAnglePower(float(cosDeg(25)), float(outer), 0.5f), 0.0, std::sqrt(4 * kEpsF));
        LR_BOTH(coneAnglePower(T(cosDeg(30)), T(outer), T(0.5)), 0.0);
        LR_BOTH(coneAnglePower(T(-1), T(outer), T(0.5)), 0.0); // behind the light
        LR_BOTH(coneAnglePower(T(cosDeg(20)), T(outer), T(1)), 0.2);
    }

    void smoothDoc001() {
        // Doc 001: saturate(((cosθ - cosφ)/(cosΘ - cosφ))^3.2), Θ = 30°, φ = 50°.
        // θ = 40°: (0.766044 - 0.642788)/(0.866025 - 0.642788) = 0.552132; ^3.2 = 0.149465.
        const double ci = cosDeg(30), co = cosDeg(50);
        LR_BOTH(coneSmooth(T(1), T(ci), T(co), T(3.2)), 1.0);
        LR_BOTH(coneSmooth(T(cosDeg(20)), T(ci), T(co), T(3.2)), 1.0);
        LR_BOTH(coneSmooth(T(cosDeg(35)), T(ci), T(co), T(3.2)), 0.47039047773438863);
        LR_BOTH(coneSmooth(T(cosDeg(40)), T(ci), T(co), T(3.2)), 0.149464656355794);
        LR_BOTH(coneSmooth(T(cosDeg(40)), T(ci), T(co), T(1)), 0.5521324645341427);
        LR_BOTH(coneSmooth(T(cosDeg(45)), T(ci), T(co), T(3.2)), 0.01864801892858317);
        LR_BOTH(coneSmooth(T(cosDeg(50)), T(ci), T(co), T(3.2)), 0.0);
        LR_BOTH(coneSmooth(T(cosDeg(60)), T(ci), T(co), T(3.2)), 0.0);
    }

    void hardDoc003() {
        // Doc 003: lit while angle <= halfAngle; its spot has angle XM_PI/4 (full), so outer = 22.5°.
        const double co = cosDeg(22.5);
        LR_BOTH(coneHard(T(1), T(co)), 1.0);
        LR_BOTH(coneHard(T(cosDeg(22)), T(co)), 1.0);
        LR_BOTH(coneHard(T(cosDeg(23)), T(co)), 0.0);
        LR_BOTH(coneHard(T(co), T(co)), 1.0); // on the edge: lit (>=)
        LR_BOTH(coneHard(T(0), T(co)), 0.0);
    }

    // ---- surface terms ----
    void diffuse() {
        LR_BOTH(diffuseLambert(T(1)), 1.0);
        LR_BOTH(diffuseLambert(T(0.5)), 0.5);
        LR_BOTH(diffuseLambert(T(0)), 0.0);
        LR_BOTH(diffuseLambert(T(-0.5)), 0.0);
        LR_BOTH(diffuseLambert(T(1.0000002)), 1.0); // docs 003/004 saturate: never above 1
        // Doc 001: (N·L·0.5 + 0.5)².
        LR_BOTH(diffuseHalfLambert(T(1)), 1.0);
        LR_BOTH(diffuseHalfLambert(T(0.5)), 0.5625);
        LR_BOTH(diffuseHalfLambert(T(0)), 0.25);
        LR_BOTH(diffuseHalfLambert(T(-0.5)), 0.0625);
        LR_BOTH(diffuseHalfLambert(T(-1)), 0.0);
    }

    void phong() {
        // N = +Z, L = (0.6, 0, 0.8): R = reflect(-L, N) = 2·0.8·N - L = (-0.6, 0, 0.8).
        const Vec3d N(0, 0, 1), L(0.6, 0, 0.8);
        LR_BOTH(specularPhong(Vec3<T>(N), Vec3<T>(L), Vec3<T>(0, 0, 1), T(1)), 0.8); // R·V = 0.8
        LR_BOTH(specularPhong(Vec3<T>(N), Vec3<T>(L), Vec3<T>(0, 0, 1), T(32)),
                0.0007922816251426448);                                                    // 0.8^32
        LR_BOTH(specularPhong(Vec3<T>(N), Vec3<T>(L), Vec3<T>(-0.6, 0, 0.8), T(32)), 1.0); // V = R
        LR_BOTH(specularPhong(Vec3<T>(N), Vec3<T>(L), Vec3<T>(L), T(2)), 0.28 * 0.28); // R·L = -0.36 + 0.64
        LR_BOTH(specularPhong(Vec3<T>(N), Vec3<T>(L), Vec3<T>(0.6, 0, -0.8), T(2)), 0.0); // R·V < 0
    }

    void blinnPhong() {
        // Doc 004: H = norm(L + V). L = (0.6,0,0.8), V = +Z: L + V = (0.6, 0, 1.8), N·H = 1.8/√3.6 = 3/√10.
        const Vec3d N(0, 0, 1), L(0.6, 0, 0.8);
        LR_BOTH(specularBlinnPhong(Vec3<T>(N), Vec3<T>(L), Vec3<T>(0, 0, 1), T(1)), 3 / std::sqrt(10.0));
        LR_BOTH(specularBlinnPhong(Vec3<T>(N), Vec3<T>(L), Vec3<T>(0, 0, 1), T(32)), 0.1853020188851839);
        LR_BOTH(specularBlinnPhong(Vec3<T>(N), Vec3<T>(L), Vec3<T>(L), T(32)),
                0.0007922816251426448); // H = L
        // L = -V: L + V = 0 and H falls back to N, so N·H = 1.
        LR_BOTH(specularBlinnPhong(Vec3<T>(N), Vec3<T>(L), Vec3<T>(-L), T(32)), 1.0);
    }

    void localVersusInfiniteViewer() {
        // Doc 004: local viewer V = norm(eye - P); infinite viewer V = +Z in our view space (Direct3D's
        // I = (0,0,-1) in its left-handed space, where the camera looks down +Z).
        ShadeSettings<double> local, infinite;
        infinite.viewer = ViewerModel::Infinite;
        const Vec3d P(4, 0, -3);
        LR_NEAR_VEC(viewVector(local, P), Vec3d(-0.8, 0, 0.6), kTol);
        LR_NEAR_VEC(viewVector(infinite, P), Vec3d(0, 0, 1), 0);
        // A directional light from L = (0.6, 0, 0.8) on N = +Z at P, specular only (albedo 0):
        // R = (-0.6, 0, 0.8); local R·V = 0.48 + 0.48 = 0.96, infinite R·V = 0.8 (shininess 1).
        ShadeLight<double> l;
        l.type = LightType::Directional;
        l.direction = Vec3d(-0.6, 0, -0.8);
        Surface<double> s;
        s.position = P, s.albedo = Vec3d(0), s.shininess = 1;
        LR_NEAR_VEC(shadeLight(l, s, local, viewVector(local, P)), Vec3d(0.96), kTol);
        LR_NEAR_VEC(shadeLight(l, s, infinite, viewVector(infinite, P)), Vec3d(0.8), kTol);
        // Blinn-Phong: local H = norm((0.6,0,0.8) + (-0.8,0,0.6)) = norm(-0.2,0,1.4), N·H = 1.4/√1.96+0.04.
        local.specular = infinite.specular = SpecularModel::BlinnPhong;
        LR_NEAR_VEC(shadeLight(l, s, local, viewVector(local, P)), Vec3d(1.4 / std::sqrt(2.0)), kTol);
        LR_NEAR_VEC(shadeLight(l, s, infinite, viewVector(infinite, P)), Vec3d(3 / std::sqrt(10.0)), kTol);
    }

    void rimSignConvention() {
        // Doc 000: power1 = 1 - max(0, dot(lightDir, N)), power2 = 1 - max(0, normalInView.z · -1) in
        // Direct3D's left-handed view space, where a camera-facing normal has z < 0. In ours it has z > 0,
        // so power2 = 1 - max(0, N·V) with V = +Z: a camera-facing normal gets NO rim from the view term.
        const Vec3d away(0, 0, -1), V(0, 0, 1);
        LR_BOTH(rimTerm(Vec3<T>(away), Vec3<T>(0, 0, 1), Vec3<T>(V), T(1.3)),
                0.0); // copying -N.z would give 1
        LR_BOTH(rimTerm(Vec3<T>(away), Vec3<T>(1, 0, 0), Vec3<T>(V), T(1.3)), 1.0); // silhouette
        // N = (0.6, 0, 0.8): power1 = 1 - max(0, -0.8) = 1, power2 = 0.2 -> 0.2^1.3 = 0.123407.
        LR_BOTH(rimTerm(Vec3<T>(away), Vec3<T>(0.6, 0, 0.8), Vec3<T>(V), T(1.3)), 0.12340677254400192);
        // A back light travelling towards the camera: power1 = 1 - 0.8 = 0.2 too -> 0.04^1.3 = 0.015229.
        LR_BOTH(rimTerm(Vec3<T>(0, 0, 1), Vec3<T>(0.6, 0, 0.8), Vec3<T>(V), T(1.3)), 0.015229231509727026);
        // Through shadeLight: a rim light adds color · intensity · rim, no albedo.
        ShadeLight<double> l;
        l.type = LightType::Rim, l.direction = away, l.color = Vec3d(2, 1, 0.5), l.rimExponent = 1.3;
        Surface<double> s;
        s.normal = Vec3d(0.6, 0, 0.8), s.albedo = Vec3d(0.1);
        LR_NEAR_VEC(shadeLight(l, s, ShadeSettings<double>{}, V), Vec3d(2, 1, 0.5) * 0.12340677254400192,
                    kTol);
    }

    void directionalHasNoFalloff() {
        // L = -direction wherever the surface is: N·L = 0.8 at P near the eye and 1e5 away alike.
        ShadeLight<double> l;
        l.type = LightType::Directional, l.direction = Vec3d(0, -0.6, -0.8);
        l.falloff = FalloffModel::RangePower, l.range = 1; // ignored by a directional light
        ShadeSettings<double> st;
        st.viewer = ViewerModel::Infinite;
        Surface<double> s;
        s.specular = Vec3d(0);
        for (const Vec3d& P : {Vec3d(0, 0, -1), Vec3d(1e3, 0, -1e5)}) {
            s.position = P;
            LR_NEAR_VEC(shadeLight(l, s, st, Vec3d(0, 0, 1)), Vec3d(0.8), kTol);
        }
        l.diffuse = DiffuseModel::HalfLambert; // (0.8·0.5 + 0.5)² = 0.81
        LR_NEAR_VEC(shadeLight(l, s, st, Vec3d(0, 0, 1)), Vec3d(0.81), kTol);
    }

    // ---- a whole light, from a Rig through prepareLights, in double and float ----
    void contributionThroughRig() {
        // View = identity (eye at the origin looking down -Z), world = view space. Surface at (0,0,-10),
        // N = +Z, albedo (0.5, 0.25, 1), ks 0.5, emissive (0.01, 0.02, 0.03), shininess 32. Scene ambient
        // 0.1.
        Rig rig;
        rig.ambient = glm::dvec3(0.1);
        // 1) Point at (3,0,-6): to light (3,0,4), d = 5, L = (0.6,0,0.8). Range-power 10, exp 2: a = 0.25.
        //    D = 0.8; R = (-0.6,0,0.8), V = +Z, S = 0.8^32. Colour (1,0.5,0.25)·2, specular factor 1,
        //    ambient (0.1)·2.
        Light p = pointLight({3, 0, -6}, {1, 0.5, 0.25}, 2, {FalloffModel::RangePower, 10, 2});
        p.ambient = glm::dvec3(0.1);
        // 2) Spot at (0,5,-5) shining down (0,-1,0): to light (0,5,5), d² = 50, L = (0,√½,√½),
        //    cosθ = dot(-L, dir) = √½ (45°). Inverse-square a = 1/50; angle-power 50°, exp 0.5:
        //    s = √(1 - 45/50) = √0.1. Half-lambert D = (√½·½ + ½)²; R = (0,-√½,√½), S = √½^32 = 2^-16.
        //    Specular as a colour (0.3, 0.6, 0.9), intensity 3.
        Light sp = pointLight({0, 5, -5}, {1, 1, 1}, 3, {FalloffModel::InverseSquare, -1, 2});
        sp.type = LightType::Spot, sp.direction = {0, -1, 0};
        sp.cone = {ConeModel::AnglePower, 10, 50, 0.5};
        sp.diffuse = DiffuseModel::HalfLambert;
        sp.specularIsColor = true, sp.specular = {0.3, 0.6, 0.9};
        // 3) Rim: on a camera-facing normal it adds nothing (see rimSignConvention).
        Light rim;
        rim.type = LightType::Rim, rim.direction = {0, 0, -1}, rim.intensity = 5;
        // 4) Disabled: prepareLights drops it.
        Light off = pointLight({0, 0, -9}, {1, 1, 1}, 100, {});
        off.enabled = false;
        rig.lights = {p, sp, rim, off};

        const Vec3d albedo(0.5, 0.25, 1), ks(0.5), emissive(0.01, 0.02, 0.03);
        const double h = std::sqrt(0.5);
        // intensity · a · s · (color · albedo · D + Sc · ks · S + Ac · albedo)
        const Vec3d c1 = 0.25 * (Vec3d(2, 1, 0.5) * albedo * 0.8 + Vec3d(2, 1, 0.5) * ks * std::pow(0.8, 32) +
                                 Vec3d(0.2) * albedo);
        const double D2 = (h * 0.5 + 0.5) * (h * 0.5 + 0.5);
        const Vec3d c2 = (1.0 / 50) * std::sqrt(0.1) *
                         (Vec3d(3) * albedo * D2 + Vec3d(0.9, 1.8, 2.7) * ks * std::pow(2.0, -16));
        const Vec3d expected = Vec3d(0.1) * albedo + c1 + c2 + emissive;
        QVERIFY(std::abs(c1.x - 0.22519807040628567) < 1e-15); // the arithmetic above, done separately

        const SceneFrame frame;
        const auto lights = prepareLights(rig, frame, glm::dmat4(1.0));
        QCOMPARE(lights.size(), size_t(3));
        const ShadeSettings<double> st = prepareSettings(rig, frame);
        Surface<double> s;
        s.position = Vec3d(0, 0, -10), s.albedo = albedo, s.specular = ks, s.emissive = emissive;
        LR_NEAR_VEC(shadeLight(lights[0], s, st, Vec3d(0, 0, 1)), c1, kTol);
        LR_NEAR_VEC(shadeLight(lights[1], s, st, Vec3d(0, 0, 1)), c2, kTol);
        LR_NEAR_VEC(shadeLight(lights[2], s, st, Vec3d(0, 0, 1)), Vec3d(0), kTol);
        LR_NEAR_VEC(shadeSurface<double>(s, lights, st), expected, kTol);

        // The float twin, from the same prepared lights.
        std::vector<ShadeLight<float>> lf;
        for (const auto& l : lights)
            lf.push_back(castLight<float>(l));
        ShadeSettings<float> stf;
        stf.ambient = Vec3f(st.ambient);
        Surface<float> sf;
        sf.position = Vec3f(s.position), sf.albedo = Vec3f(albedo), sf.specular = Vec3f(ks);
        sf.emissive = Vec3f(emissive);
        LR_NEAR_VEC(shadeSurface<float>(sf, lf, stf), expected, 1e-6);

        // No lights: scene ambient · albedo + emissive (doc 001: emissive + amb + diff).
        LR_NEAR_VEC(shadeSurface<double>(s, {}, st), Vec3d(0.05, 0.025, 0.1) + emissive, kTol);
    }

    void viewTransformAndFarOrigin() {
        // Camera at (0,0,10) looking at the origin: a world light at (0,0,5) is 5 in front, (0,0,-5) in view.
        Rig rig;
        Light l = pointLight({0, 0, 5}, {1, 1, 1}, 1, {});
        l.type = LightType::Spot, l.direction = {0, 0, -2}; // unnormalised: prepare normalises
        rig.lights = {l};
        const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 10), glm::dvec3(0), glm::dvec3(0, 1, 0));
        const ShadeLight<double> v = prepareLight(rig, SceneFrame{}, view, rig.lights[0]);
        LR_NEAR_VEC(v.position, Vec3d(0, 0, -5), kTol);
        LR_NEAR_VEC(v.direction, Vec3d(0, 0, -1), kTol);

        // The same scene 1e6 units from the world origin, shaded in float after a double prepare, gives
        // what it gives at the origin: view space keeps float precision where the action is.
        for (const double offset : {0.0, 1e6}) {
            Rig r;
            Light pl = pointLight({offset + 3, 0, -6}, {1, 1, 1}, 1, {FalloffModel::RangePower, 10, 2});
            r.lights = {pl};
            const glm::dvec3 eye(offset, 0, 0);
            const glm::dmat4 vm = glm::lookAt(eye, eye + glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
            const ShadeLight<float> lf = castLight<float>(prepareLight(r, SceneFrame{}, vm, r.lights[0]));
            Surface<float> s;
            s.position = Vec3f(glm::dvec3(vm * glm::dvec4(offset, 0, -10, 1)));
            s.specular = Vec3f(0);
            LR_NEAR_VEC(shadeLight(lf, s, ShadeSettings<float>{}, Vec3f(0, 0, 1)), Vec3d(0.25 * 0.8), 1e-6);
        }
    }

    void modelSpaceRig() {
        // A rig in model space is anchored on the bounding sphere: centre (10,0,-20), radius 4.
        Rig rig;
        rig.space = RigSpace::Model;
        const SceneFrame frame{glm::dvec3(10, 0, -20), 4.0};
        LR_NEAR_VEC(rigToWorld(rig, frame, {0, 0, 1}), Vec3d(10, 0, -16), kTol);
        LR_NEAR_VEC(worldToRig(rig, frame, {10, 0, -16}), Vec3d(0, 0, 1), kTol);
        LR_NEAR(distanceScale(rig, frame), 0.25, kTol);
        // Light one radius above the centre, range 2 radii, exponent 2; surface at the centre facing it:
        // world d = 4 = 1 radius -> a = (1 - 1/2)^2 = 0.25; D = 1; V = norm(-P), N = +Z, L = +Z.
        Light l = pointLight({0, 0, 1}, {1, 1, 1}, 1, {FalloffModel::RangePower, 2, 2});
        rig.lights = {l};
        const auto lights = prepareLights(rig, frame, glm::dmat4(1.0));
        LR_NEAR_VEC(lights[0].position, Vec3d(10, 0, -16), kTol);
        LR_NEAR(lights[0].range, 2.0, 0); // ranges stay in rig units ...
        const ShadeSettings<double> st = prepareSettings(rig, frame);
        LR_NEAR(st.distanceScale, 0.25, kTol); // ... and distances are scaled to them
        Surface<double> s;
        s.position = Vec3d(10, 0, -20), s.specular = Vec3d(0);
        LR_NEAR_VEC(shadeLight(lights[0], s, st, viewVector(st, s.position)), Vec3d(0.25), kTol);
        // lightReaches: range 2 radii = 8 world units from the light; the sphere is 4 away -> reaches.
        QVERIFY(lightReaches(rig, frame, rig.lights[0], frame.center, frame.radius));
        // 4 radii away (16 world units): 8 + 4 < 16 -> cannot reach.
        Light far = l;
        far.position = {0, 0, 4};
        QVERIFY(!lightReaches(rig, frame, far, frame.center, frame.radius));
        // A world-space rig ignores the frame.
        Rig world;
        LR_NEAR_VEC(rigToWorld(world, frame, {0, 0, 1}), Vec3d(0, 0, 1), 0);
        LR_NEAR(distanceScale(world, frame), 1.0, 0);
    }

    // ---- colour temperature ----
    void temperature() {
        const glm::dvec3 d65 = temperatureToRgb(6500); // ~ white (sRGB ~ (255, 254, 250) before linearising)
        QVERIFY2(d65.x > 0.95 && d65.y > 0.95 && d65.z > 0.9, qPrintable(vecStr(d65)));
        const glm::dvec3 k1000 = temperatureToRgb(1000); // candle: red, little green, no blue
        QVERIFY2(k1000.x == 1.0 && k1000.y < 0.1 && k1000.z == 0.0, qPrintable(vecStr(k1000)));
        const glm::dvec3 k40000 = temperatureToRgb(40000); // blue sky: blue dominant
        QVERIFY2(k40000.z == 1.0 && k40000.x < 0.4 && k40000.y < k40000.z, qPrintable(vecStr(k40000)));
        // Trends from 1000 K to 40000 K in 10 K steps: red never rises, blue never falls, blue/red rises;
        // green peaks near 6600 K. Everything finite, in [0, 1], largest component 1. Clamped outside.
        glm::dvec3 prev = temperatureToRgb(1000);
        double peakT = 0, peakG = -1;
        for (double t = 1010; t <= 40000; t += 10) {
            const glm::dvec3 c = temperatureToRgb(t);
            QVERIFY2(finite(c) && std::min({c.x, c.y, c.z}) >= 0 && std::max({c.x, c.y, c.z}) == 1.0,
                     qPrintable(num(t) + QLatin1Char(' ') + vecStr(c)));
            QVERIFY2(c.x <= prev.x + 1e-12 && c.z >= prev.z - 1e-12, qPrintable(num(t) + vecStr(c)));
            QVERIFY2(c.z / c.x >= prev.z / prev.x - 1e-12, qPrintable(num(t) + vecStr(c)));
            if (c.y > peakG) peakG = c.y, peakT = t;
            prev = c;
        }
        QVERIFY2(peakT >= 6000 && peakT <= 7000, qPrintable(num(peakT)));
        LR_NEAR_VEC(temperatureToRgb(100), k1000, 0);
        LR_NEAR_VEC(temperatureToRgb(1e9), k40000, 0);
        QVERIFY(finite(temperatureToRgb(std::numeric_limits<double>::quiet_NaN())));
        // A light's effective colour is its colour tinted by the temperature.
        Light l;
        l.color = {0.5, 0.5, 0.5}, l.temperature = 1000;
        LR_NEAR_VEC(l.effectiveColor(), 0.5 * k1000, kTol);
    }
};

QTEST_GUILESS_MAIN(TestHand)
#include "tst_hand.moc"
