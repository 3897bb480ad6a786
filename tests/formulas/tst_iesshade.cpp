// Issue 39: an IES profile in the shading every renderer shares (core/iesshade.h, shade.h lightArrival).
// A point light over a plane: the plane's illuminance is I(θ,φ)·cosθ/d² in closed form per point, exactly
// for the interpolated profile and within the bilinear interpolation's bound for the function the file
// samples; the levels, the rotation and a spot's cone.
#include "core/iesshade.h"
#include "core/prepare.h"
#include "core/shade.h"

#include <QTest>
#include <cmath>

using namespace lr;

namespace {

QString data(const QString& name) {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/ies/") + name;
}

// What tests/data/ies/full.ies samples (every 22.5° vertically, 45° horizontally), before rounding to 1e-3.
double truth(double theta, double phi) {
    const double c = std::cos(theta / 2.0);
    return 1000.0 * c * c * (1.0 + 0.5 * std::cos(2.0 * phi)); // radians
}

// The bilinear interpolation's bound for `truth` (|f - interpolant| <= Δ²/8 · max|f''| in each angle, in
// radians), plus the file's rounding to 1e-3.
double interpolationBound() {
    const double dTheta = 22.5 * M_PI / 180.0, dPhi = 45.0 * M_PI / 180.0;
    const double fThetaTheta = 1000.0 * 0.5 * 1.5; // (1 + cos θ)/2 ·(1 + cos 2φ/2): |∂²/∂θ²| <= 1/2 · 1.5
    const double fPhiPhi = 1000.0 * 1.0 * 0.5 * 4.0;
    return dTheta * dTheta / 8.0 * fThetaTheta + dPhi * dPhi / 8.0 * fPhiPhi + 1e-3;
}

struct Setup {
    Rig rig;
    Light light;
    std::shared_ptr<const IesProfile> profile;
    lighting::ShadeLight<double> shade() const {
        auto o = prepareLight(rig, SceneFrame{}, glm::dmat4(1.0), light);
        applyIesProfile(o, light, profile.get(), glm::dmat4(1.0));
        return o;
    }
};

// A point light `h` above the plane y = 0, pointing down, inverse-square falloff, classic shading.
Setup pointOverPlane(double h, IesLevel level, double intensity, double multiplier) {
    Setup s;
    QString error;
    s.profile = readIesFile(data(QStringLiteral("full.ies")), &error);
    s.light = makeLight(LightType::Point, QStringLiteral("Downlight"));
    s.light.position = {0.0, h, 0.0};
    s.light.direction = {0.0, -1.0, 0.0};
    s.light.intensity = intensity;
    s.light.color = glm::dvec3(1.0);
    s.light.temperature.reset();
    s.light.falloff.model = FalloffModel::InverseSquare;
    s.light.falloff.range = -1.0;
    s.light.ies = IesSpec{QStringLiteral("full.ies"), {}, multiplier, level, 0.0};
    s.rig.shading.model = ShadingModel::Classic;
    return s;
}

// The illuminance the shading gives at (x, 0, z): white Lambert surface, no specular.
double illuminance(const lighting::ShadeLight<double>& l, double x, double z) {
    lighting::Surface<double> surf;
    surf.position = {x, 0.0, z};
    surf.normal = {0.0, 1.0, 0.0};
    surf.albedo = glm::dvec3(1.0);
    surf.specular = glm::dvec3(0.0);
    const lighting::ShadeSettings<double> st;
    return lighting::shadeLight(l, surf, st, glm::dvec3(0.0, 1.0, 0.0)).x;
}

} // namespace

class TestIesShade : public QObject {
    Q_OBJECT
  private slots:
    void planeFollowsTheClosedForm() {
        const double h = 2.0;
        for (const IesLevel level : {IesLevel::Light, IesLevel::Profile}) {
            const Setup s = pointOverPlane(h, level, 7.0, 1.5);
            QVERIFY(s.profile);
            const auto l = s.shade();
            // Level "light": I/peak × multiplier × intensity; "profile": I × multiplier (intensity unused).
            const double scale = level == IesLevel::Light ? 1.5 * 7.0 / s.profile->peak : 1.5;
            double worstTruth = 0.0;
            for (int i = -20; i <= 20; ++i)
                for (int j = -20; j <= 20; ++j) {
                    const double x = 0.37 * i, z = 0.41 * j;
                    const double d = std::sqrt(x * x + h * h + z * z);
                    const double cosTheta = h / d; // at the plane: the incidence equals the vertical angle
                    const double theta = std::acos(cosTheta);
                    // The photometric frame of a light pointing straight down with rotation 0 (areaAxes):
                    // C0 along +x, C90 along -z.
                    const double phi = std::atan2(-z, x);
                    const double e = illuminance(l, x, z);
                    const double interpolated =
                        iesCandela(*s.profile, theta * 180.0 / M_PI, phi * 180.0 / M_PI) * cosTheta / (d * d);
                    QVERIFY2(std::abs(e - scale * interpolated) <= 1e-12 * scale * 1500.0,
                             qPrintable(QStringLiteral("at %1, %2: %3 vs %4")
                                            .arg(x)
                                            .arg(z)
                                            .arg(e)
                                            .arg(scale * interpolated)));
                    const double exact = truth(theta, phi) * cosTheta / (d * d);
                    worstTruth = std::max(worstTruth, std::abs(e / scale - exact) / (cosTheta / (d * d)));
                }
            qInfo("level %s: worst |interpolated - function| %.3f cd, bound %.3f cd",
                  level == IesLevel::Light ? "light" : "profile", worstTruth, interpolationBound());
            QVERIFY2(
                worstTruth <= interpolationBound(),
                qPrintable(QStringLiteral("%1 cd off; bound %2").arg(worstTruth).arg(interpolationBound())));
            QVERIFY(worstTruth > 0.0); // interpolated, not the function itself
        }
    }

    void rotationTurnsTheDistribution() {
        Setup s = pointOverPlane(2.0, IesLevel::Profile, 1.0, 1.0);
        const double plain = illuminance(s.shade(), 1.0, 0.0); // C0
        s.light.ies->rotation = 90.0;                          // C0 now where C90 was: x along -z... turned
        const auto turned = s.shade();
        // Rotation 90 turns the frame right-handedly about the nadir: the old C90 (-z) direction becomes
        // C0's.
        QVERIFY(std::abs(illuminance(turned, 0.0, -1.0) - plain) < 1e-9 * plain);
        QVERIFY(std::abs(illuminance(turned, 1.0, 0.0) - plain) > 0.1 * plain); // C0 and C90 differ
    }

    void pointLightLooksAlongItsDirection() {
        Setup s = pointOverPlane(2.0, IesLevel::Profile, 1.0, 1.0);
        s.light.direction = {0.0, 1.0, 0.0}; // the nadir upwards: the plane sees the top of the profile
        const double up = illuminance(s.shade(), 0.0, 0.0);
        QVERIFY(std::abs(up - iesCandela(*s.profile, 180.0, 0.0) / 4.0) < 1e-9);
        QCOMPARE(iesCandela(*s.profile, 180.0, 0.0), 0.0); // full.ies sends nothing straight up
    }

    void spotKeepsItsConeAndWithoutAProfileNothingChanges() {
        Setup s = pointOverPlane(2.0, IesLevel::Light, 3.0, 1.0);
        s.light.type = LightType::Spot;
        s.light.cone.model = ConeModel::Hard;
        s.light.cone.outer = 30.0;
        const auto l = s.shade();
        QVERIFY(illuminance(l, 0.5, 0.0) > 0.0);
        QCOMPARE(illuminance(l, 2.0, 0.0), 0.0); // 45° off the axis: outside the cone
        // No profile: the light shades exactly as before (the branch is skipped).
        Light plain = s.light;
        plain.ies.reset();
        const auto a = prepareLight(s.rig, SceneFrame{}, glm::dmat4(1.0), plain);
        auto b = a;
        applyIesProfile(b, plain, s.profile.get(), glm::dmat4(1.0));
        QCOMPARE(illuminance(a, 0.5, 0.3), illuminance(b, 0.5, 0.3));
        QVERIFY(!b.ies);
    }

    void zeroProfileIsDark() {
        Setup s = pointOverPlane(2.0, IesLevel::Light, 3.0, 1.0);
        QString error;
        s.profile = readIesFile(data(QStringLiteral("zero.ies")), &error);
        QVERIFY2(s.profile, qPrintable(error));
        const double e = illuminance(s.shade(), 0.3, 0.2);
        QCOMPARE(e, 0.0);
    }
};

QTEST_GUILESS_MAIN(TestIesShade)
#include "tst_iesshade.moc"
