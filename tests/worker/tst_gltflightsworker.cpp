// Issue 39: a glTF's EXT_lights_ies light and a spot's extras.lightrig (gobo, link) imported through the
// import worker (`lightrig import-worker`, model/isolatedimport.h) arrive as the direct import makes them:
// the profile decoded, checked and cached in the worker, and Light::ies, gobo and link across the codec.
#include "../model/gltflightfixtures.h"
#include "model/isolatedimport.h"
#include "modelcompare.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;

class TestGltfLightsWorker : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir, m_cache;

  private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid() && m_cache.isValid());
        setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE));
        qputenv("LIGHTRIG_IES_CACHE", m_cache.path().toUtf8()); // the worker inherits it
    }

    void shapedLightsCrossTheWorker() {
        Rig rig;
        rig.shading.model = ShadingModel::Pbr;
        Light down = makeLight(LightType::Point, QStringLiteral("Down"));
        down.position = {0.5, 3.0, 0.0};
        down.direction = {0.0, -1.0, 0.0};
        down.ies = IesSpec{QStringLiteral("full.ies"), QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies"),
                           3.0, IesLevel::Profile, 45.0};
        Light spot = makeLight(LightType::Spot, QStringLiteral("Spot"));
        spot.direction = {0.0, -1.0, 0.0};
        spot.position = {0.0, 2.0, 0.0};
        spot.gobo = GoboSpec{QStringLiteral("window.png"), {}, 2.0, 10.0};
        spot.link.lit.exclude = {QStringLiteral("mirror")};
        rig.lights = {down, spot};
        QVERIFY(QFile::copy(QStringLiteral(LIGHTRIG_TEST_DATA "/model/checker.png"),
                            m_dir.filePath(QStringLiteral("window.png"))));
        const QString path = m_dir.filePath(QStringLiteral("shaped.gltf"));
        QVERIFY(test::writeJson(path, test::exportedScene(rig)));

        const ModelLoadResult isolated = importModelIsolated(path);
        QVERIFY2(isolated.ok(), qPrintable(isolated.error));
        const ModelLoadResult direct = loadModel(path);
        QVERIFY2(direct.ok(), qPrintable(direct.error));
        const QString difference = test::modelDifference(*direct.model, *isolated.model, false);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));

        const Light* ies = test::lightNamed(*isolated.model, QStringLiteral("Down"));
        QVERIFY2(ies && ies->ies, qPrintable(isolated.model->warnings.join(QLatin1Char('\n'))));
        QVERIFY(ies->ies->file.startsWith(QDir(m_cache.path()).absolutePath() + QLatin1Char('/')));
        QCOMPARE(lrtest::readFile(ies->ies->file), lrtest::readFile(down.ies->resolved));
        QVERIFY(std::abs(ies->ies->multiplier - 3.0) < 1e-9 && std::abs(ies->ies->rotation - 45.0) < 1e-9);
        const Light* shaped = test::lightNamed(*isolated.model, QStringLiteral("Spot"));
        QVERIFY(shaped && shaped->gobo);
        QCOMPARE(shaped->gobo->file, m_dir.filePath(QStringLiteral("window.png")));
        QCOMPARE(shaped->link, spot.link);
    }
};

QTEST_GUILESS_MAIN(TestGltfLightsWorker)
#include "tst_gltflightsworker.moc"
