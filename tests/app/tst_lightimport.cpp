// Importing a model's own (world-space) lights into a model-space rig keeps their light on the model:
// the falloff at every distance and the light's position in the world are unchanged.
#include "app/lightimport.h"
#include "core/prepare.h"
#include "core/shade.h"

#include <QTest>

using namespace lr;

class TestLightImport : public QObject {
    Q_OBJECT
  private slots:
    void modelSpace_keepsTheLighting_data() {
        QTest::addColumn<int>("falloff");
        QTest::addColumn<double>("range");
        for (int f = 0; f < enumCount<FalloffModel>(); ++f) {
            QTest::addRow("%s", qPrintable(toString(FalloffModel(f)))) << f << 40.0;
            if (FalloffModel(f) == FalloffModel::InversePolynomial ||
                FalloffModel(f) == FalloffModel::InverseSquare)
                QTest::addRow("%s-no-range", qPrintable(toString(FalloffModel(f)))) << f << -1.0;
        }
    }
    void modelSpace_keepsTheLighting() {
        QFETCH(int, falloff);
        QFETCH(double, range);
        Rig world;
        Light l = makeLight(LightType::Point, "p");
        l.position = glm::dvec3(3, 7, -2);
        l.intensity = 5.0;
        l.falloff.model = FalloffModel(falloff);
        l.falloff.range = range;
        l.falloff.exponent = 2.0;
        l.falloff.constant = 0.5, l.falloff.linear = 0.25, l.falloff.quadratic = 0.125;
        world.lights.push_back(l);

        Rig target;
        target.space = RigSpace::Model;
        const SceneFrame frame{glm::dvec3(1, 2, 3), 4.0};
        const std::vector<Light> converted = lightsInRigSpace(world, target, frame);
        QCOMPARE(converted.size(), size_t(1));
        Rig modelRig = target;
        modelRig.lights = converted;

        const glm::dmat4 view(1.0);
        const auto a = prepareLight(world, frame, view, world.lights[0]);
        const auto b = prepareLight(modelRig, frame, view, modelRig.lights[0]);
        QVERIFY(glm::length(a.position - b.position) < 1e-12); // same place in the world
        const auto sa = prepareSettings(world, frame), sb = prepareSettings(modelRig, frame);
        for (double d : {0.5, 3.0, 10.0, 25.0, 39.0, 60.0}) {
            const double fa = lighting::evalFalloff(a, d * sa.distanceScale) * a.color.x;
            const double fb = lighting::evalFalloff(b, d * sb.distanceScale) * b.color.x;
            QVERIFY2(std::abs(fa - fb) <= 1e-12 * std::max(1.0, std::abs(fa)),
                     qPrintable(QStringLiteral("d=%1: %2 vs %3").arg(d).arg(fa).arg(fb)));
        }
    }

    void worldSpace_isUnchanged() {
        Rig world;
        world.lights.push_back(makeLight(LightType::Spot, "s"));
        world.lights[0].position = glm::dvec3(1, 2, 3);
        Rig target; // world space
        const auto converted = lightsInRigSpace(world, target, SceneFrame{glm::dvec3(5), 3.0});
        QVERIFY(converted[0] == world.lights[0]);
    }
};

QTEST_APPLESS_MAIN(TestLightImport)
#include "tst_lightimport.moc"
