// A rig as KHR_lights_punctual (core/gltflights.h): units, angles, positions and directions in the file's
// frame, ranges, the falloff rule, and which lossy conversions are listed for which lights.
#include "core/gltflights.h"

#include <QJsonArray>
#include <QTest>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

using namespace lr;

namespace {

constexpr double kPi = std::numbers::pi;

Light pointLight(const glm::dvec3& position, double intensity, FalloffModel model, double range) {
    Light l = makeLight(LightType::Point, QStringLiteral("P"));
    l.position = position;
    l.intensity = intensity;
    l.falloff = {model, range};
    return l;
}

Rig pbrRig(std::vector<Light> lights, RigSpace space = RigSpace::World) {
    Rig rig;
    rig.shading.model = ShadingModel::Pbr;
    rig.space = space;
    rig.lights = std::move(lights);
    return rig;
}

int count(const GltfRigExport& e, ExportLoss kind) {
    return int(std::count_if(e.losses.begin(), e.losses.end(),
                             [&](const LossyConversion& l) { return l.kind == kind; }));
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double eps = 1e-9) {
    return glm::length(a - b) <= eps;
}

} // namespace

class TestGltfLights : public QObject {
    Q_OBJECT
  private slots:
    void lossTableHasOneRowPerKind() {
        for (int i = 0; i < int(ExportLoss::Count); ++i) {
            QCOMPARE(int(kExportLosses[i].kind), i);
            QVERIFY(kExportLosses[i].key && *kExportLosses[i].key);
            QVERIFY(kExportLosses[i].title && *kExportLosses[i].written);
        }
    }

    void physicalWorldPointIsExact() {
        Light l = pointLight({1, 2, 3}, 10.0, FalloffModel::InverseSquare, 5.0);
        l.color = {2.0, 1.0, 0.5};
        const GltfRigExport e = convertRigToGltf(pbrRig({l}), {});
        QCOMPARE(e.lights.size(), size_t(1));
        const GltfLight& g = e.lights[0];
        QCOMPARE(g.type, QStringLiteral("point"));
        QVERIFY(near(g.color, {1.0, 0.5, 0.25}));
        QCOMPARE(g.intensity, 20.0); // the colour's scale moves into the intensity
        QCOMPARE(g.range, 5.0);
        QVERIFY(near(g.translation, {1, 2, 3}));
        QVERIFY(e.losses.empty());
        const QJsonObject json = g.lightJson();
        QCOMPARE(json.value(QStringLiteral("intensity")).toDouble(), 20.0);
        QCOMPARE(json.value(QStringLiteral("range")).toDouble(), 5.0);
        QVERIFY(!json.contains(QStringLiteral("spot")));
    }

    void modelSpaceScalesPositionRangeAndCandela() {
        // Three radii in front of a sphere of radius 2 at (1, 0, 0); 1/d² in radii is R²/d² in metres.
        const Light l = pointLight({0, 0, 3}, 4.0, FalloffModel::InverseSquare, 8.0);
        const GltfRigExport e = convertRigToGltf(pbrRig({l}, RigSpace::Model), {{1, 0, 0}, 2.0});
        const GltfLight& g = e.lights.at(0);
        QVERIFY(near(g.translation, {1, 0, 6}));
        QCOMPARE(g.range, 16.0);
        QCOMPARE(g.intensity, 16.0);
    }

    void spotAnglesAndDirection() {
        Light l = makeLight(LightType::Spot, QStringLiteral("S"));
        l.falloff = {FalloffModel::InverseSquare, -1.0};
        l.direction = glm::normalize(glm::dvec3(1, -1, 0));
        l.cone = {ConeModel::Smooth, 20.0, 35.0, 2.0};
        const GltfRigExport e = convertRigToGltf(pbrRig({l}), {});
        const GltfLight& g = e.lights.at(0);
        QCOMPARE(g.type, QStringLiteral("spot"));
        QVERIFY(std::abs(g.innerConeAngle - 20.0 * kPi / 180.0) < 1e-12);
        QVERIFY(std::abs(g.outerConeAngle - 35.0 * kPi / 180.0) < 1e-12);
        QVERIFY(near(g.rotation * glm::dvec3(0, 0, -1), l.direction, 1e-12)); // glTF lights shine along -Z
        QCOMPARE(g.range, -1.0);
        QVERIFY(!g.lightJson().contains(QStringLiteral("range")));
        QVERIFY(e.losses.empty());
    }

    // Issue 16: glTF has no area lights. A one-sided rect or disk becomes a spot at its centre along its axis
    // of the emitter's on-axis intensity L·A candela and a 90° cone; far away on its axis it gives what the
    // emitter gives (checked against the exact on-axis irradiance of a disk, π L R² / (R² + D²)); a
    // two-sided one a point light of L·A/2 (the same flux); each listed as an area-light loss. Sizes follow
    // a model-space rig's scale; the intensity is not multiplied by π under classic shading.
    void areaLightsBecomeSpotsOrPoints() {
        Light rect = makeLight(LightType::Rect, QStringLiteral("Softbox"));
        rect.position = {0, 0, 3};
        rect.direction = {0, 0, -1};
        rect.area = {1.5, 0.5, 0.5, 30.0, false};
        rect.intensity = 20.0;
        rect.color = {1.0, 0.5, 0.5};
        Light disk = makeLight(LightType::Disk, QStringLiteral("Dish"));
        disk.position = {0, 4, 0};
        disk.direction = {0, -1, 0};
        disk.area.radius = 0.25;
        disk.area.twoSided = true;
        disk.intensity = 8.0;
        Light off = makeLight(LightType::Rect, QStringLiteral("Off"));
        off.enabled = false;
        const SceneFrame frame{{1, 0, 0}, 2.0}; // model space: 2 world units per rig unit
        const GltfRigExport e = convertRigToGltf(pbrRig({rect, disk, off}, RigSpace::Model), frame);
        QCOMPARE(e.lights.size(), size_t(2));
        const GltfLight& spot = e.lights[0];
        QCOMPARE(spot.type, QStringLiteral("spot"));
        QVERIFY(near(spot.translation, {1, 0, 6}));
        QVERIFY(near(spot.rotation * glm::dvec3(0, 0, -1), rect.direction, 1e-12));
        QVERIFY(std::abs(spot.intensity - 20.0 * 1.5 * 0.5 * 4.0) < 1e-9); // L × A in m² (× 2²)
        QVERIFY(near(spot.color, {1.0, 0.5, 0.5}));
        QCOMPARE(spot.innerConeAngle, 0.0);
        QCOMPARE(spot.outerConeAngle, kPi / 2.0);
        QCOMPARE(spot.range, -1.0);
        const QJsonObject json = spot.lightJson();
        QCOMPARE(json.value(QStringLiteral("type")).toString(), QStringLiteral("spot"));
        QVERIFY(json.value(QStringLiteral("spot")).toObject().contains(QStringLiteral("outerConeAngle")));
        const GltfLight& point = e.lights[1];
        QCOMPARE(point.type, QStringLiteral("point"));
        const double diskArea = kPi * 0.25 * 0.25 * 4.0;
        QVERIFY(std::abs(point.intensity - 0.5 * 8.0 * diskArea) < 1e-9);
        QCOMPARE(count(e, ExportLoss::AreaLight), 2);
        QCOMPARE(count(e, ExportLoss::Disabled), 1);
        QVERIFY(describeLoss(e.losses[0])
                    .startsWith(QStringLiteral("Softbox: rect or disk light: rect 1.5 × 0.5")));

        // Far on its axis the one-sided stand-in matches the emitter: a disk of radius R (world) at D.
        Light far = disk;
        far.area.twoSided = false;
        const GltfRigExport f = convertRigToGltf(pbrRig({far}), {});
        const double R = 0.25, L = 8.0;
        for (double D : {2.5, 10.0, 100.0}) {
            const double exact = kPi * L * R * R / (R * R + D * D), standIn = f.lights[0].intensity / (D * D);
            QVERIFY2(std::abs(standIn / exact - 1.0) < 1.01 * R * R / (D * D),
                     qPrintable(QStringLiteral("D %1: %2 vs %3").arg(D).arg(standIn).arg(exact)));
        }
        // Classic: an area light's intensity means the same under both shadings.
        Rig classic = pbrRig({far});
        classic.shading.model = ShadingModel::Classic;
        QCOMPARE(convertRigToGltf(classic, {}).lights[0].intensity, f.lights[0].intensity);
    }

    void classicIntensityTimesPi() {
        Rig rig;
        Light sun = makeLight(LightType::Directional, QStringLiteral("Sun"));
        sun.intensity = 2.0;
        rig.lights = {sun, sun};
        const GltfRigExport e = convertRigToGltf(rig, {});
        QCOMPARE(e.lights.at(0).intensity, 2.0 * kPi);   // lux
        QCOMPARE(count(e, ExportLoss::ClassicUnits), 1); // once for the rig
    }

    void otherFalloffMatchesAtTheModelCentre() {
        // range-power, range 10, exponent 2, 4 m from the centre: glTF's I·window/d² there equals LightRig's.
        const Light l = pointLight({0, 0, 4}, 3.0, FalloffModel::RangePower, 10.0);
        const GltfRigExport e = convertRigToGltf(pbrRig({l}), {{0, 0, 0}, 1.0});
        const GltfLight& g = e.lights.at(0);
        QCOMPARE(g.range, 10.0);
        const double r = 0.4, window = (1 - r * r * r * r) * (1 - r * r * r * r);
        QVERIFY(std::abs(g.intensity * window / 16.0 - 3.0 * 0.36) < 1e-12);
        QCOMPARE(count(e, ExportLoss::Falloff), 1);
    }

    void lossesPerLight() {
        Light rim = makeLight(LightType::Rim, QStringLiteral("Rim"));
        Light off = pointLight({0, 1, 0}, 1.0, FalloffModel::InverseSquare, -1.0);
        off.enabled = false;
        Light soft = pointLight({0, 1, 0}, 1.0, FalloffModel::InverseSquare, -1.0);
        soft.diffuse = DiffuseModel::HalfLambert;
        soft.specular = glm::dvec3(0.5);
        soft.ambient = glm::dvec3(0.1);
        soft.shadow = {.enabled = true, .size = 0.2};
        Light hard = makeLight(LightType::Spot, QStringLiteral("Hard"));
        hard.falloff = {FalloffModel::InverseSquare, -1.0};
        hard.cone = {ConeModel::Hard, 30.0, 30.0, 1.0};
        Light power = hard;
        power.cone = {ConeModel::AnglePower, 20.0, 40.0, 1.0};
        const GltfRigExport e = convertRigToGltf(pbrRig({rim, off, soft, hard, power}), {});
        QCOMPARE(e.lights.size(), size_t(3)); // no rim, nothing switched off
        for (ExportLoss k :
             {ExportLoss::Rim, ExportLoss::Disabled, ExportLoss::HalfLambert, ExportLoss::Specular,
              ExportLoss::LightAmbient, ExportLoss::Shadow, ExportLoss::Area})
            QVERIFY2(count(e, k) == 1, exportLossInfo(k).key);
        QCOMPARE(count(e, ExportLoss::Cone), 2);
        QCOMPARE(count(e, ExportLoss::Falloff), 0);
        const GltfLight& h = e.lights[1];
        QVERIFY(h.innerConeAngle < h.outerConeAngle); // glTF needs inner < outer
        QVERIFY(h.innerConeAngle > 0.98 * h.outerConeAngle);
        QCOMPARE(e.lights[2].innerConeAngle, 0.0);
        for (const LossyConversion& loss : e.losses)
            QVERIFY(describeLoss(loss).startsWith(loss.subject + QStringLiteral(": ")));
    }

    // Issue 39: glTF has no barn doors; they go into the rect's node extras and are reported.
    void barnDoorsGoIntoTheNodesExtras() {
        Light box = makeLight(LightType::Rect, QStringLiteral("Box"));
        box.barnDoors = BarnDoors{30.0, 0.25};
        const Light plain = makeLight(LightType::Rect, QStringLiteral("Plain"));
        const GltfRigExport e = convertRigToGltf(pbrRig({box, plain}), {});
        QCOMPARE(count(e, ExportLoss::BarnDoors), 1);
        QCOMPARE(e.lights.size(), size_t(2));
        const QJsonObject doors = e.lights[0]
                                      .nodeJson(0)
                                      .value(QStringLiteral("extras"))
                                      .toObject()
                                      .value(QStringLiteral("lightrig"))
                                      .toObject()
                                      .value(QStringLiteral("barnDoors"))
                                      .toObject();
        QCOMPARE(doors.value(QStringLiteral("angle")).toDouble(), 30.0);
        QCOMPARE(doors.value(QStringLiteral("length")).toDouble(), 0.25);
        QVERIFY(!e.lights[1].nodeJson(1).contains(QStringLiteral("extras")));
    }

    // Issue 38: glTF has no linking; the link goes into the light node's extras and is reported.
    void linkingGoesIntoTheNodesExtras() {
        Light key = pointLight({0, 1, 0}, 1.0, FalloffModel::InverseSquare, -1.0);
        key.link.lit.include = {QStringLiteral("Body")};
        key.link.shadow.exclude = {QStringLiteral("Glass"), QStringLiteral("ground")};
        Light rect = makeLight(LightType::Rect, QStringLiteral("Box"));
        rect.link.lit.exclude = {QStringLiteral("Stand")};
        const Light plain = pointLight({0, 2, 0}, 1.0, FalloffModel::InverseSquare, -1.0);
        const GltfRigExport e = convertRigToGltf(pbrRig({key, rect, plain}), {});
        QCOMPARE(count(e, ExportLoss::Link), 2);
        QCOMPARE(e.lights.size(), size_t(3));
        const QJsonObject node = e.lights[0].nodeJson(0);
        const QJsonObject link = node.value(QStringLiteral("extras"))
                                     .toObject()
                                     .value(QStringLiteral("lightrig"))
                                     .toObject()
                                     .value(QStringLiteral("link"))
                                     .toObject();
        QCOMPARE(link.value(QStringLiteral("include")).toArray(), QJsonArray{QStringLiteral("Body")});
        QCOMPARE(link.value(QStringLiteral("shadow")).toObject().value(QStringLiteral("exclude")).toArray(),
                 (QJsonArray{QStringLiteral("Glass"), QStringLiteral("ground")}));
        QVERIFY(!link.contains(QStringLiteral("exclude")));
        QVERIFY(e.lights[1].nodeJson(1).contains(QStringLiteral("extras"))); // the area stand-in keeps it
        QVERIFY(!e.lights[2].nodeJson(2).contains(QStringLiteral("extras")));
    }

    // Issue 39: glTF has no gobos; the spot's gobo goes into its node's extras, beside a link, and is
    // reported.
    void goboGoesIntoTheNodesExtras() {
        Light spot = makeLight(LightType::Spot, QStringLiteral("Window"));
        spot.gobo = GoboSpec{QStringLiteral("gobos/window.png"), {}, 0.5, 30.0};
        spot.link.lit.include = {QStringLiteral("Body")};
        const Light plain = makeLight(LightType::Spot, QStringLiteral("Plain"));
        const GltfRigExport e = convertRigToGltf(pbrRig({spot, plain}), {});
        QCOMPARE(count(e, ExportLoss::Gobo), 1);
        const QJsonObject lightrig = e.lights[0]
                                         .nodeJson(0)
                                         .value(QStringLiteral("extras"))
                                         .toObject()
                                         .value(QStringLiteral("lightrig"))
                                         .toObject();
        const QJsonObject gobo = lightrig.value(QStringLiteral("gobo")).toObject();
        QCOMPARE(gobo.value(QStringLiteral("file")).toString(), QStringLiteral("gobos/window.png"));
        QCOMPARE(gobo.value(QStringLiteral("scale")).toDouble(), 0.5);
        QCOMPARE(gobo.value(QStringLiteral("rotation")).toDouble(), 30.0);
        QVERIFY(lightrig.contains(QStringLiteral("link")));
        QVERIFY(!e.lights[1].nodeJson(1).contains(QStringLiteral("extras")));
        for (const LossyConversion& loss : e.losses)
            if (loss.kind == ExportLoss::Gobo)
                QVERIFY(describeLoss(loss).contains(QStringLiteral("gobos/window.png")));
    }

    void rigLevelLossesAndNote() {
        Rig rig = pbrRig({});
        rig.ambient = glm::dvec3(0.25);
        rig.environment.source = EnvironmentSource::Studio;
        rig.environment.studio.softboxes = {Softbox{}, Softbox{}};
        rig.ground.mode = GroundMode::Catcher;
        const GltfRigExport e = convertRigToGltf(rig, {});
        for (ExportLoss k :
             {ExportLoss::Ambient, ExportLoss::Environment, ExportLoss::Area, ExportLoss::Ground})
            QVERIFY2(count(e, k) == 1, exportLossInfo(k).key);
        QCOMPARE(count(e, ExportLoss::ClassicUnits), 0);
        QCOMPARE(
            e.note.value(QStringLiteral("environment")).toObject().value(QStringLiteral("source")).toString(),
            QStringLiteral("studio"));
        QCOMPARE(e.note.value(QStringLiteral("ambientLux")).toArray().at(0).toDouble(), 0.25);
        QVERIFY(e.note.contains(QStringLiteral("ground")));
    }

    void fileFrameUndoesTheEditorsRotation() {
        // The editor turned a Z-up file Y-up (x, y, z) -> (x, z, -y); the export turns it back.
        const glm::dmat3 worldFromFile(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
        Light l = makeLight(LightType::Spot, QStringLiteral("S"));
        l.falloff = {FalloffModel::InverseSquare, -1.0};
        l.position = worldFromFile * glm::dvec3(1, 2, 3);
        l.direction = worldFromFile * glm::dvec3(0, 0, -1);
        const GltfRigExport e = convertRigToGltf(pbrRig({l}), {}, glm::transpose(worldFromFile));
        QVERIFY(near(e.lights.at(0).translation, {1, 2, 3}, 1e-12));
        QVERIFY(near(e.lights[0].rotation * glm::dvec3(0, 0, -1), {0, 0, -1}, 1e-12));
    }

    void cameraLooksAlongItsView() {
        const GltfCamera front =
            makeGltfCamera(QStringLiteral("c"), {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 45.0, 0.1, 100.0);
        QVERIFY(near(front.rotation * glm::dvec3(0, 0, -1), {0, 0, -1}, 1e-12));
        QVERIFY(!front.nodeJson(0).contains(QStringLiteral("rotation")));
        const GltfCamera side =
            makeGltfCamera(QStringLiteral("c"), {-5, 1, 0}, {1, 0, 0}, {0, 1, 0}, 30.0, 0.1, 0.0);
        QVERIFY(near(side.rotation * glm::dvec3(0, 0, -1), {1, 0, 0}, 1e-12));
        QVERIFY(near(side.rotation * glm::dvec3(0, 1, 0), {0, 1, 0}, 1e-12));
        QVERIFY(std::abs(side.yfov - kPi / 6.0) < 1e-12);
        const QJsonObject p = side.cameraJson().value(QStringLiteral("perspective")).toObject();
        QVERIFY(!p.contains(QStringLiteral("zfar"))); // infinite
        QCOMPARE(p.value(QStringLiteral("znear")).toDouble(), 0.1);
    }
};

QTEST_APPLESS_MAIN(TestGltfLights)
#include "tst_gltflights.moc"
