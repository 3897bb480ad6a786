// The scene description (src/scene/scenedescription.h): the one GL-free account of what is drawn that the
// raster's lit inputs, the reference and the traced renderers read. Its derived values follow the model
// and the rig; the ground's mesh is rebuilt only when what it is made from changes; an environment still
// loading is taken in by waitForEnvironment, or reported with its error.
#include "render/scenes.h"
#include "scene/environmentloader.h"
#include "scene/scenedescription.h"

#include <QTest>
#include <QtConcurrent/QtConcurrentRun>

using namespace lr;
using namespace lr::test;

class TestSceneDescription : public QObject {
    Q_OBJECT
  private slots:
    void withoutAModelIsTheUnitSphere() {
        SceneDescription s;
        QCOMPARE(s.model(), nullptr);
        QVERIFY(std::abs(s.frame().radius - 1.0) < 1e-12);
        QCOMPARE(s.frame().center, glm::dvec3(0.0));
        Rig rig = rigOf({point({0, 2, 0}, FalloffModel::None)});
        rig.ground.mode = GroundMode::Visible;
        s.setRig(rig);
        QCOMPARE(s.ground(), nullptr); // no model: nothing to stand on
    }

    void boundsFrameAndReachFollowTheModelAndGround() {
        SceneDescription s;
        const auto model = sphereScene();
        s.setModel(model);
        QCOMPARE(s.bounds().min, model->bounds.min);
        QCOMPARE(s.frame().center, model->bounds.center());
        QCOMPARE(s.frame().radius, model->bounds.radius());
        QCOMPARE(s.drawnBounds().min, s.bounds().min); // ground off
        Rig rig = rigOf({point({0, 2, 0}, FalloffModel::None)});
        rig.ground.mode = GroundMode::Catcher;
        s.setRig(rig);
        QVERIFY(s.ground() != nullptr);
        QVERIFY(s.drawnBounds().radius() > s.bounds().radius()); // the ground's square is drawn
        QVERIFY(s.reach().radius > s.frame().radius);
    }

    void theGroundIsRebuiltOnlyWhenItsSourceChanges() {
        SceneDescription s;
        s.setModel(sphereScene());
        Rig rig = rigOf({point({0, 2, 0}, FalloffModel::None)});
        rig.ground.mode = GroundMode::Visible;
        s.setRig(rig);
        const auto first = s.ground();
        const int revision = s.groundRevision();
        rig.lights[0].intensity = 3.0; // a light, not the ground
        s.setRig(rig);
        QCOMPARE(s.ground(), first);
        QCOMPARE(s.groundRevision(), revision);
        rig.ground.mode = GroundMode::Catcher; // the same mesh, drawn otherwise
        s.setRig(rig);
        QCOMPARE(s.ground(), first);
        rig.ground.color = glm::dvec3(0.2);
        s.setRig(rig);
        QVERIFY(s.ground() != first);
        QCOMPARE(s.groundRevision(), revision + 1);
        const int generation = s.modelGeneration();
        s.setModel(planeScene());
        QCOMPARE(s.modelGeneration(), generation + 1);
        QCOMPARE(s.groundRevision(), revision + 2); // over the new model
        rig.ground.mode = GroundMode::Off;
        s.setRig(rig);
        QCOMPARE(s.ground(), nullptr);
    }

    // The lights and settings every renderer shades with are core/prepare.h's, for the description's frame.
    void lightsAreTheCorePreparedOnes() {
        SceneDescription s;
        s.setModel(sphereScene());
        Rig rig = rigOf({point({0, 2, 0}, FalloffModel::None), point({1, 0, 0}, FalloffModel::None)});
        rig.space = RigSpace::Model;
        rig.lights[1].enabled = false;
        s.setRig(rig);
        const glm::dmat4 view = sphereCamera().view();
        const auto lights = s.lights(view);
        const auto expected = prepareLights(rig, s.frame(), view);
        QCOMPARE(lights.size(), size_t(1));
        QCOMPARE(lights.size(), expected.size());
        QCOMPARE(lights[0].position, expected[0].position);
        QCOMPARE(s.shadeSettings().distanceScale, prepareSettings(rig, s.frame()).distanceScale);
        rig.lights[0].shadow.enabled = true;
        rig.lights[1].shadow.enabled = true;
        s.setRig(rig);
        QCOMPARE(s.shadowCasters(), 1); // a disabled light casts nothing
    }

    void aLoadingEnvironmentIsTakenInOrReported() {
        SceneDescription s;
        Rig rig = rigOf({});
        rig.environment.source = EnvironmentSource::Studio;
        s.setRig(rig);
        auto loaded = std::make_shared<LoadedEnvironment>();
        loaded->source = QStringLiteral("test");
        s.setEnvironment(QtConcurrent::run([loaded] {
            EnvironmentLoadResult r;
            r.environment = loaded;
            return r;
        }));
        QVERIFY(s.environmentLoading());
        QCOMPARE(s.environment(), nullptr);
        QVERIFY(!s.environmentLights());
        QVERIFY(s.waitForEnvironment());
        QVERIFY(!s.environmentLoading());
        QCOMPARE(s.environment().get(), loaded.get());
        QVERIFY(s.environmentLights());
        s.setEnvironment(QtConcurrent::run([] {
            EnvironmentLoadResult r;
            r.error = QStringLiteral("sky.exr: truncated");
            return r;
        }));
        QString error;
        QVERIFY(!s.waitForEnvironment(&error));
        QCOMPARE(error, QStringLiteral("sky.exr: truncated"));
        QCOMPARE(s.environment(), nullptr);
        QVERIFY(s.waitForEnvironment()); // nothing loading any more
    }
};

QTEST_GUILESS_MAIN(TestSceneDescription)
#include "tst_scenedescription.moc"
