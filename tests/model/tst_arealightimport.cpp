// Issue 16: a model file's area lights (Assimp's aiLightSource_AREA: Blender area lamps, FBX area lights)
// become rect lights: their node's placement, mSize as width × height, mUp as the roll against areaAxes'
// convention (core/prepare.h), and the rig reader accepts them. The scene is built in memory, since no
// importer LightRig ships a sample for writes area lights in a small file.
#include "core/prepare.h"
#include "core/rigjson.h"
#include "model/importdetail.h"
#include "model/model.h"

#include <QTest>
#include <assimp/light.h>
#include <assimp/scene.h>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>

using namespace lr;

namespace {

aiLight* areaLight(const char* name, aiVector3D up, aiVector2D size) {
    auto* l = new aiLight;
    l->mName = aiString(name);
    l->mType = aiLightSource_AREA;
    l->mPosition = aiVector3D(0.0f, 0.0f, 0.0f);
    l->mDirection = aiVector3D(0.0f, 0.0f, -1.0f); // Blender's lamp: shines along local -Z
    l->mUp = up;
    l->mSize = size;
    l->mColorDiffuse = aiColor3D(6.0f, 3.0f, 1.5f);
    return l;
}

// A scene whose lights hang under nodes of their names, each turned 90° about +Y (local -Z -> world -X) and
// moved to (1, 2, 3).
struct Scene {
    aiScene scene;
    explicit Scene(std::vector<aiLight*> lights) {
        scene.mRootNode = new aiNode("root");
        scene.mRootNode->mNumChildren = unsigned(lights.size());
        scene.mRootNode->mChildren = new aiNode*[lights.size()];
        scene.mNumLights = unsigned(lights.size());
        scene.mLights = new aiLight*[lights.size()];
        for (size_t i = 0; i < lights.size(); ++i) {
            scene.mLights[i] = lights[i];
            auto* node = new aiNode(lights[i]->mName.C_Str());
            node->mParent = scene.mRootNode;
            // Rotation by +90° about Y: x -> -z, z -> x; then the translation.
            node->mTransformation = aiMatrix4x4(0, 0, 1, 1, 0, 1, 0, 2, -1, 0, 0, 3, 0, 0, 0, 1);
            scene.mRootNode->mChildren[i] = node;
        }
    }
};

bool near(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-6) {
    return glm::length(a - b) < eps;
}

} // namespace

class TestAreaLightImport : public QObject {
    Q_OBJECT
  private slots:
    void areaLightsBecomeRects() {
        Scene s({areaLight("Softbox", {0, 1, 0}, {2.0f, 0.5f}), areaLight("Rolled", {1, 0, 0}, {1.0f, 3.0f}),
                 areaLight("Broken", {0, 1, 0}, {std::numeric_limits<float>::quiet_NaN(), 1.0f})});
        Model model;
        detail::convertLightsAndCameras(&s.scene, false, QStringLiteral("box.fbx"), model);
        QCOMPARE(int(model.lights.lights.size()), 3);

        const Light& box = model.lights.lights[0];
        QVERIFY(box.type == LightType::Rect);
        QCOMPARE(box.name, QStringLiteral("Softbox"));
        QVERIFY(near(box.position, {1, 2, 3}));
        QVERIFY(near(box.direction, {-1, 0, 0}));
        QCOMPARE(box.area.width, 2.0);
        QCOMPARE(box.area.height, 0.5);
        QVERIFY(!box.area.twoSided);
        QCOMPARE(box.intensity, 6.0); // colour × intensity split as for every imported light
        QVERIFY(near(box.color, {1.0, 0.5, 0.25}));
        QVERIFY2(std::abs(box.area.roll) < 1e-9, qPrintable(QString::number(box.area.roll)));

        // Local up +X turns into world -Z; the height must run along it and the width along direction × up.
        const Light& rolled = model.lights.lights[1];
        QVERIFY2(std::abs(rolled.area.roll - 90.0) < 1e-6, qPrintable(QString::number(rolled.area.roll)));
        const AreaAxes axes = areaAxes(rolled.direction, rolled.area.roll);
        const glm::dvec3 up(0, 0, -1);
        QVERIFY(near(axes.y, up));
        QVERIFY(near(axes.x, glm::cross(rolled.direction, up)));
        QCOMPARE(rolled.area.height, 3.0);

        const Light& broken = model.lights.lights[2];
        QCOMPARE(broken.area.width, 1.0); // AreaShape's default, with a warning
        QVERIFY2(model.warnings.join(QLatin1Char('\n'))
                     .contains(QStringLiteral("box.fbx: light Broken: area light size")),
                 qPrintable(model.warnings.join(QLatin1Char('\n'))));

        // The imported rig is a valid rig file (version 2: it has rect lights).
        const QByteArray json = writeRigJson(model.lights);
        QVERIFY(json.contains("\"version\": 2"));
        const RigReadResult back = readRigJson(json, QStringLiteral("box.json"));
        QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));
        QVERIFY(back.rig->lights == model.lights.lights);
    }

    // Every roll survives areaAxes -> rollForUp: the import's inverse of the convention.
    void rollRoundTrips() {
        for (double roll : {-179.0, -90.0, -30.0, 0.0, 45.0, 135.0, 180.0}) {
            for (const glm::dvec3 dir :
                 {glm::dvec3(0, 0, -1), glm::normalize(glm::dvec3(1, -2, 0.5)), glm::dvec3(0, -1, 0)}) {
                const AreaAxes a = areaAxes(dir, roll);
                auto* l = areaLight("L", {float(a.y.x), float(a.y.y), float(a.y.z)}, {1, 1});
                l->mDirection = aiVector3D(float(dir.x), float(dir.y), float(dir.z));
                aiScene scene;
                scene.mRootNode = new aiNode("root");
                scene.mNumLights = 1;
                scene.mLights = new aiLight* [1] { l };
                Model model;
                detail::convertLightsAndCameras(&scene, false, QStringLiteral("x.blend"), model);
                QCOMPARE(int(model.lights.lights.size()), 1);
                const AreaAxes back =
                    areaAxes(model.lights.lights[0].direction, model.lights.lights[0].area.roll);
                QVERIFY2(near(back.x, a.x, 1e-5) && near(back.y, a.y, 1e-5),
                         qPrintable(QStringLiteral("roll %1").arg(roll)));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestAreaLightImport)
#include "tst_arealightimport.moc"
