// Issue 12 item 3: new lights are placed relative to the model (any size) and a rig switches between model
// and world space as one undo step without its lights moving in the scene.
#include "core/prepare.h"
#include "core/rigjson.h"
#include "editor/changerigspace.h"
#include "editor/lightproperty.h"
#include "editor/placement.h"
#include "rigfixture.h"

#include <QSignalSpy>
#include <QTest>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

using namespace lr;

namespace {

// The spider's bounding sphere (fbx/spider.fbx: diagonal about 25,770 units), off the origin.
const SceneFrame kBigModel{glm::dvec3(1000.0, -400.0, 250.0), 12885.0};

PlacementView bigView() {
    PlacementView v;
    v.frame = kBigModel;
    v.towardViewer = glm::dvec3(1.0, 0.5, 1.0);
    return v;
}

// World position of a light, and the world range of a bounded falloff.
glm::dvec3 worldPosition(const Rig& rig, const Light& l) {
    return rigToWorld(rig, kBigModel, l.position);
}
double worldRange(const Rig& rig, const Light& l) {
    return l.falloff.range / distanceScale(rig, kBigModel);
}

// Radiance-relevant attenuation of a light at a world point: the same in either space after a switch.
double attenuationAt(const Rig& rig, const Light& l, const glm::dvec3& world) {
    const glm::dmat4 identity(1.0);
    const lighting::ShadeLight<double> s = prepareLight(rig, kBigModel, identity, l);
    const double d = glm::length(s.position - world) * distanceScale(rig, kBigModel);
    return lighting::evalFalloff(s, d) * s.color.x;
}

Rig mixedWorldRig() {
    Rig rig;
    rig.space = RigSpace::World;
    Light p = makeLight(LightType::Point, QStringLiteral("P"));
    p.position = glm::dvec3(30000.0, 5000.0, -2000.0);
    p.falloff = {FalloffModel::RangePower, 60000.0, 2.0};
    Light s = makeLight(LightType::Spot, QStringLiteral("S"));
    s.position = glm::dvec3(-20000.0, 10000.0, 3000.0);
    s.falloff = Falloff{};
    s.falloff.model = FalloffModel::InverseSquare;
    s.falloff.range = 90000.0;
    s.intensity = 4.0e5;
    Light q = makeLight(LightType::Point, QStringLiteral("Q"));
    q.position = glm::dvec3(0.0, 20000.0, 0.0);
    q.falloff = Falloff{};
    q.falloff.model = FalloffModel::InversePolynomial;
    q.falloff.constant = 1.0, q.falloff.linear = 1e-4, q.falloff.quadratic = 1e-9;
    Light d = makeLight(LightType::Directional, QStringLiteral("D"));
    rig.lights = {p, s, q, d};
    return rig;
}

} // namespace

class TestPlacement : public QObject {
    Q_OBJECT
  private slots:
    void newLightsSitAroundTheModel_data() {
        QTest::addColumn<int>("space");
        QTest::newRow("world") << int(RigSpace::World);
        QTest::newRow("model") << int(RigSpace::Model);
    }
    void newLightsSitAroundTheModel() {
        QFETCH(int, space);
        Rig rig;
        rig.space = RigSpace(space);
        const PlacementView view = bigView();
        for (LightType type : {LightType::Point, LightType::Spot}) {
            const Light l = placeNewLight(rig, type, QStringLiteral("L"), view, 0);
            QVERIFY(validateLight(l).isEmpty());
            const glm::dvec3 at = worldPosition(rig, l);
            // On the placement sphere: outside the model, kPlacementDistance radii from its centre.
            QVERIFY(std::abs(glm::length(at - kBigModel.center) - kPlacementDistance * kBigModel.radius) <
                    1e-6 * kBigModel.radius);
            // On the viewer's side and above the centre.
            QVERIFY(glm::dot(at - kBigModel.center, view.towardViewer) > 0.0);
            QVERIFY(at.y > kBigModel.center.y);
            // Its range reaches past the far side of the model.
            QVERIFY(worldRange(rig, l) > (kPlacementDistance + 1.0) * kBigModel.radius);
            if (type == LightType::Spot) {
                const glm::dvec3 toCentre = glm::normalize(kBigModel.center - at);
                QVERIFY(glm::dot(glm::normalize(l.direction), toCentre) > 1.0 - 1e-9);
            }
            // It reaches the model's centre with a useful share of its intensity (not 0 as at (2, 2, 2)).
            QVERIFY(attenuationAt(rig, l, kBigModel.center) > 0.3);
        }
        const Light d = placeNewLight(rig, LightType::Directional, QStringLiteral("D"), view, 0);
        QVERIFY(glm::dot(d.direction, view.towardViewer) < 0.0); // travels from the viewer's side
    }

    // Issue 13: in a physically based rig a new light is KHR_lights_punctual-like (inverse-square with the
    // range window, smooth cone of exponent 2, Lambert) with an intensity in candela / lux that lights the
    // nearest point of the model visibly, neither black nor blown out — in world space on a big model and in
    // model space alike. In a classic rig nothing changes.
    void newLightsInAPbrRig_areKhrLikeAndLightTheModel_data() {
        QTest::addColumn<int>("space");
        QTest::addColumn<int>("type");
        for (RigSpace space : {RigSpace::World, RigSpace::Model})
            for (LightType type : {LightType::Point, LightType::Spot, LightType::Directional})
                QTest::newRow(qPrintable(lr::toString(space) + QLatin1Char(' ') + lr::toString(type)))
                    << int(space) << int(type);
    }

    void newLightsInAPbrRig_areKhrLikeAndLightTheModel() {
        QFETCH(int, space);
        QFETCH(int, type);
        // A model of radius 50 (world units): candela stay within the format's limit in either space.
        const SceneFrame model{kBigModel.center, 50.0};
        PlacementView placement = bigView();
        placement.frame = model;
        Rig rig;
        rig.space = RigSpace(space);
        rig.shading.model = ShadingModel::Pbr;
        const Light l = placeNewLight(rig, LightType(type), QStringLiteral("L"), placement, 0);
        Rig classicRig = rig;
        classicRig.shading.model = ShadingModel::Classic;
        const Light classic = placeNewLight(classicRig, LightType(type), QStringLiteral("L"), placement, 0);
        QCOMPARE(l.position, classic.position);
        QCOMPARE(l.direction, classic.direction);
        QVERIFY(!(l == classic));
        QVERIFY(l.diffuse == DiffuseModel::Lambert);
        if (l.usesFalloff()) {
            QVERIFY(l.falloff.model == FalloffModel::InverseSquare);
            QCOMPARE(l.falloff.range, classic.falloff.range);
            const double d = kPlacementDistance * model.radius * distanceScale(rig, model);
            QVERIFY(std::abs(l.intensity - kPbrPlacementIlluminance * d * d) <= 1e-9 * l.intensity);
        } else {
            QCOMPARE(l.intensity, kPbrPlacementIlluminance);
        }
        if (l.usesCone()) {
            QVERIFY(l.cone.model == ConeModel::Smooth);
            QCOMPARE(l.cone.exponent, 2.0);
        }
        QVERIFY(validateLight(l).isEmpty());

        // The model's surface nearest the light, facing it, seen from the viewer's side: a mid-grey rough
        // dielectric there is lit to a visible, unclipped level.
        rig.lights = {l};
        const glm::dvec3 toLight = l.usesPosition()
                                       ? glm::normalize(rigToWorld(rig, model, l.position) - model.center)
                                       : -l.direction;
        const glm::dvec3 eye = model.center + placement.towardViewer * (4.0 * model.radius);
        const glm::dmat4 view = glm::lookAt(eye, model.center, glm::dvec3(0, 1, 0));
        const auto lights = prepareLights(rig, model, view);
        QCOMPARE(lights.size(), size_t(1));
        lighting::Surface<double> s;
        s.position = glm::dvec3(view * glm::dvec4(model.center + toLight * model.radius, 1.0));
        s.normal = glm::normalize(glm::dvec3(view * glm::dvec4(toLight, 0.0)));
        s.albedo = glm::dvec3(0.5);
        s.roughness = 0.8;
        const glm::dvec3 c = lighting::shadeSurface<double>(s, lights, prepareSettings(rig, model));
        QVERIFY2(c.g > 0.1 && c.g < 1.0, qPrintable(QString::number(c.g)));

        // A model so large (world units) that the candela needed pass the format's limit: clamped to it,
        // still a valid light.
        Rig world;
        world.shading.model = ShadingModel::Pbr;
        const Light far = placeNewLight(world, LightType::Point, QStringLiteral("F"), bigView(), 0);
        QCOMPARE(far.intensity, kMaxRigIntensity);
        QVERIFY(validateLight(far).isEmpty());
    }

    // Issue 16: a new rect or disk light faces the model's centre from the placement sphere, is a softbox of
    // about the model's size, and lights the centre with kPbrPlacementIlluminance lux (physically based) or
    // as a classic directional light of intensity kClassicAreaPlacementLevel would (classic), checked by
    // integrating its emitter numerically rather than through areaIrradianceFactor's closed forms.
    void newAreaLightsAreSoftboxesFacingTheModel_data() {
        QTest::addColumn<int>("space");
        QTest::addColumn<int>("type");
        QTest::addColumn<int>("shading");
        for (RigSpace space : {RigSpace::World, RigSpace::Model})
            for (LightType type : {LightType::Rect, LightType::Disk})
                for (ShadingModel shading : {ShadingModel::Classic, ShadingModel::Pbr})
                    QTest::newRow(qPrintable(lr::toString(space) + QLatin1Char(' ') + lr::toString(type) +
                                             QLatin1Char(' ') + lr::toString(shading)))
                        << int(space) << int(type) << int(shading);
    }
    void newAreaLightsAreSoftboxesFacingTheModel() {
        QFETCH(int, space);
        QFETCH(int, type);
        QFETCH(int, shading);
        const SceneFrame model{kBigModel.center, 50.0};
        PlacementView placement = bigView();
        placement.frame = model;
        Rig rig;
        rig.space = RigSpace(space);
        rig.shading.model = ShadingModel(shading);
        const Light l = placeNewLight(rig, LightType(type), QStringLiteral("Softbox"), placement, 2);
        QVERIFY2(validateLight(l).isEmpty(), qPrintable(validateLight(l)));
        rig.lights = {l};
        QVERIFY(readRigJson(writeRigJson(rig), QStringLiteral("r.json")).ok());
        const glm::dvec3 at = rigToWorld(rig, model, l.position);
        QVERIFY(std::abs(glm::length(at - model.center) - kPlacementDistance * model.radius) <
                1e-9 * model.radius);
        QVERIFY(glm::dot(l.direction, glm::normalize(model.center - at)) > 1.0 - 1e-12);
        const double toWorld = 1.0 / distanceScale(rig, model);
        if (l.type == LightType::Rect) {
            QVERIFY(std::abs(l.area.width * toWorld - kAreaPlacementSize * model.radius) <
                    1e-9 * model.radius);
            QCOMPARE(l.area.height, l.area.width);
        } else {
            QVERIFY(std::abs(2.0 * l.area.radius * toWorld - kAreaPlacementSize * model.radius) <
                    1e-9 * model.radius);
        }
        QVERIFY(!l.area.twoSided);

        // ∫ L cos θ_receiver cos θ_emitter / r² dA over the emitter (midpoint rule, 400² cells), in world
        // units: the irradiance at the model's centre, facing the light.
        const AreaAxes axes = areaAxes(l.direction, l.area.roll);
        const bool disk = l.type == LightType::Disk;
        const double hw = (disk ? l.area.radius : 0.5 * l.area.width) * toWorld;
        const double hh = (disk ? l.area.radius : 0.5 * l.area.height) * toWorld;
        const glm::dvec3 n = glm::normalize(at - model.center); // the receiver's normal
        double factor = 0.0;
        constexpr int kCells = 400;
        for (int i = 0; i < kCells; ++i)
            for (int j = 0; j < kCells; ++j) {
                const double u = (i + 0.5) / kCells * 2.0 - 1.0, v = (j + 0.5) / kCells * 2.0 - 1.0;
                if (disk && u * u + v * v > 1.0) continue;
                const glm::dvec3 p = at + axes.x * (u * hw) + axes.y * (v * hh);
                const glm::dvec3 w = p - model.center;
                const double r2 = glm::dot(w, w);
                const glm::dvec3 wn = w / std::sqrt(r2);
                factor += glm::dot(n, wn) * glm::dot(l.direction, -wn) / r2;
            }
        factor *= (2.0 * hw / kCells) * (2.0 * hh / kCells);
        const double level = l.intensity * factor; // lux (pbr) or π × the classic directional intensity
        const double expected = rig.shading.model == ShadingModel::Pbr
                                    ? kPbrPlacementIlluminance
                                    : std::numbers::pi * kClassicAreaPlacementLevel;
        QVERIFY2(std::abs(level - expected) < 2e-3 * expected,
                 qPrintable(QStringLiteral("%1 vs %2").arg(level).arg(expected)));
        QVERIFY(l.intensity <= kMaxRigIntensity);
    }

    // The closed forms against their small-emitter limit (L·A/d²) and the clamp of an emitter too small.
    void areaIrradianceFactor_limitsAndClamp() {
        Light rect = makeLight(LightType::Rect, QStringLiteral("r"));
        rect.area.width = 0.02, rect.area.height = 0.01;
        QVERIFY(std::abs(areaIrradianceFactor(rect, 10.0) - 0.0002 / 100.0) < 1e-6 * 0.0002 / 100.0);
        Light disk = makeLight(LightType::Disk, QStringLiteral("d"));
        disk.area.radius = 0.01;
        const double a = std::numbers::pi * 1e-4;
        QVERIFY(std::abs(areaIrradianceFactor(disk, 10.0) - a / 100.0) < 1e-6 * a / 100.0);
        disk.area.radius = 1e9; // fills the hemisphere: π
        QVERIFY(std::abs(areaIrradianceFactor(disk, 1.0) - std::numbers::pi) < 1e-9);
        QCOMPARE(areaIrradianceFactor(makeLight(LightType::Spot, QStringLiteral("s")), 1.0), 0.0);
        rect.area.width = 0.0;
        QCOMPARE(areaIrradianceFactor(rect, 1.0), 0.0);
        makePhysicallyBased(rect, 3.0); // an empty emitter: the brightest the format allows, still valid
        QCOMPARE(rect.intensity, kMaxRigIntensity);
        QVERIFY(validateLight(rect).isEmpty());
    }

    // A rect added to a physically based document from the Lights dock's Add menu (at makeLight's (2, 2, 2),
    // facing the origin) gives kPbrPlacementIlluminance there.
    void addRectInAPbrDocument_givesThePlacementIlluminance() {
        Document doc;
        Rig rig;
        rig.shading.model = ShadingModel::Pbr;
        doc.newRig(rig);
        QVERIFY(doc.addLight(LightType::Rect));
        const Light& l = doc.light(0);
        const double e = l.intensity * areaIrradianceFactor(l, glm::length(l.position));
        QVERIFY(std::abs(e - kPbrPlacementIlluminance) < 1e-9);
        QVERIFY(l.intensity > 10.0 && l.intensity < 100.0); // 1 × 1 at 3.46: about 24 nits
    }

    // Switching space scales an area light's size with positions (its luminance stays).
    void switchingSpace_scalesAreaSizes() {
        Rig rig;
        Light rect = makeLight(LightType::Rect, QStringLiteral("R"));
        rect.position = kBigModel.center + glm::dvec3(0, 0, 3.0 * kBigModel.radius);
        rect.area.width = 2.0 * kBigModel.radius, rect.area.height = kBigModel.radius;
        Light disk = makeLight(LightType::Disk, QStringLiteral("D"));
        disk.area.radius = 0.5 * kBigModel.radius;
        rig.lights = {rect, disk};
        QString error;
        const std::optional<Rig> model = convertRigSpace(rig, RigSpace::Model, kBigModel, &error);
        QVERIFY2(model, qPrintable(error));
        QVERIFY(std::abs(model->lights[0].area.width - 2.0) < 1e-12);
        QVERIFY(std::abs(model->lights[0].area.height - 1.0) < 1e-12);
        QVERIFY(std::abs(model->lights[1].area.radius - 0.5) < 1e-12);
        QCOMPARE(model->lights[0].intensity, rect.intensity);
    }

    void addLightInAPbrDocument_isKhrLike() {
        Document doc;
        Rig rig;
        rig.shading.model = ShadingModel::Pbr;
        doc.newRig(rig);
        QVERIFY(doc.addLight(LightType::Spot));
        const Light& l = doc.light(0);
        QVERIFY(l.falloff.model == FalloffModel::InverseSquare);
        QCOMPARE(l.cone.exponent, 2.0);
        QCOMPARE(l.intensity, kPbrPlacementIlluminance * glm::dot(l.position, l.position));
        doc.newRig(Rig{});
        QVERIFY(doc.addLight(LightType::Spot));
        QVERIFY(doc.light(0) == makeLight(LightType::Spot, doc.light(0).name)); // classic: as before
    }

    // Issue 41: adding a light no longer moves the camera, so with the view known a light that would land
    // outside it is placed where it shows (still outside the model, still lighting it); with the view far
    // enough the usual place is kept.
    void newLightsLandInTheViewWithoutMovingIt() {
        const Rig rig;
        PlacementView view = bigView();
        const glm::dvec3 toward = glm::normalize(view.towardViewer);
        view.hasCamera = true;
        view.forward = -toward;
        view.tanHalfFovY = std::tan(glm::radians(45.0) / 2.0);
        view.aspect = 16.0 / 9.0;
        const auto shows = [&](const glm::dvec3& p) {
            const glm::dvec3 d = p - view.eye;
            const double z = glm::dot(d, view.forward);
            const glm::dvec3 right = glm::normalize(glm::cross(view.forward, view.up));
            const glm::dvec3 up = glm::cross(right, view.forward);
            return z > 0.0 && std::abs(glm::dot(d, up)) <= z * view.tanHalfFovY &&
                   std::abs(glm::dot(d, right)) <= z * view.tanHalfFovY * view.aspect;
        };
        for (double eyeRadii : {2.2, 6.0}) { // a close view (the usual place is behind it) and a far one
            view.eye = kBigModel.center + toward * (eyeRadii * kBigModel.radius);
            for (int index = 0; index < 4; ++index) {
                const Light l = placeNewLight(rig, LightType::Point, QStringLiteral("L"), view, index);
                const glm::dvec3 at = worldPosition(rig, l);
                const double radii = glm::length(at - kBigModel.center) / kBigModel.radius;
                QVERIFY2(shows(at), qPrintable(QStringLiteral("eye %1, light %2").arg(eyeRadii).arg(index)));
                QVERIFY(radii >= kMinPlacementDistance - 1e-6);
                QVERIFY(attenuationAt(rig, l, kBigModel.center) > 0.3);
                if (eyeRadii > 5.0) QCOMPARE(std::round(radii * 1e6) / 1e6, kPlacementDistance);
            }
        }
    }

    void successiveLightsDoNotStack() {
        const Rig rig;
        const Light a = placeNewLight(rig, LightType::Point, QStringLiteral("A"), bigView(), 0);
        const Light b = placeNewLight(rig, LightType::Point, QStringLiteral("B"), bigView(), 1);
        QVERIFY(glm::length(a.position - b.position) > kBigModel.radius);
    }

    void addPlacedLight_isOneUndoStepWithAUniqueName() {
        Document doc;
        PlacementView view = bigView();
        QVERIFY(addPlacedLight(&doc, LightType::Spot, view));
        QVERIFY(addPlacedLight(&doc, LightType::Spot, view));
        QCOMPARE(doc.lightCount(), 2);
        QCOMPARE(doc.light(1).name, QStringLiteral("Spot 2"));
        QCOMPARE(doc.selectedRows(), QList<int>{1});
        QVERIFY(glm::length(doc.light(0).position - kBigModel.center) > 2.0 * kBigModel.radius);
        doc.undoStack()->undo();
        QCOMPARE(doc.lightCount(), 1);
    }

    void switchingSpace_keepsEveryLightWhereItWas() {
        const Rig world = mixedWorldRig();
        QString error;
        const std::optional<Rig> model = convertRigSpace(world, RigSpace::Model, kBigModel, &error);
        QVERIFY2(model, qPrintable(error));
        QCOMPARE(int(model->space), int(RigSpace::Model));
        const glm::dvec3 probe(4000.0, 2000.0, -1000.0);
        for (size_t i = 0; i < world.lights.size(); ++i) {
            const Light& a = world.lights[i];
            const Light& b = model->lights[i];
            QCOMPARE(b.direction, a.direction);
            if (!a.usesPosition()) continue;
            QVERIFY(glm::length(worldPosition(world, a) - worldPosition(*model, b)) <
                    1e-9 * kBigModel.radius);
            const double before = attenuationAt(world, a, probe), after = attenuationAt(*model, b, probe);
            QVERIFY2(std::abs(before - after) <= 1e-9 * std::max(1.0, std::abs(before)),
                     qPrintable(QStringLiteral("%1: %2 vs %3").arg(a.name).arg(before).arg(after)));
            QVERIFY(before > 0.0);
        }
        // And back: the original numbers (to rounding).
        const std::optional<Rig> back = convertRigSpace(*model, RigSpace::World, kBigModel, &error);
        QVERIFY(back);
        for (size_t i = 0; i < world.lights.size(); ++i) {
            QVERIFY(glm::length(back->lights[i].position - world.lights[i].position) < 1e-6);
            QVERIFY(std::abs(back->lights[i].intensity - world.lights[i].intensity) <
                    1e-6 * world.lights[i].intensity);
        }
    }

    void switchingSpace_refusesValuesPastTheFormatsLimits() {
        Rig rig;
        rig.space = RigSpace::Model;
        Light l = makeLight(LightType::Point, QStringLiteral("Bright"));
        l.falloff = Falloff{};
        l.falloff.model = FalloffModel::InverseSquare;
        l.intensity = 100.0; // × 12885² in world units: past kMaxRigIntensity
        rig.lights = {l};
        QString error;
        QVERIFY(!convertRigSpace(rig, RigSpace::World, kBigModel, &error));
        QVERIFY2(error.contains(QLatin1String("Bright")) && error.contains(QLatin1String("world")),
                 qPrintable(error));
    }

    void changeRigSpace_isOneUndoStep_keepingIdsAndSelection() {
        Document doc;
        doc.newRig(mixedWorldRig());
        doc.setSelectedRows({1});
        const LightId id = doc.lightId(1);
        QSignalSpy changed(&doc, &Document::rigChanged);
        QString error;
        QVERIFY2(changeRigSpace(&doc, RigSpace::Model, kBigModel, &error), qPrintable(error));
        QCOMPARE(int(doc.rig().space), int(RigSpace::Model));
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.lightId(1), id);
        QCOMPARE(doc.selectedRows(), QList<int>{1});
        QVERIFY(changed.count() >= 2);
        QVERIFY(glm::length(doc.light(0).position) < 10.0);                 // radii now
        QVERIFY(!changeRigSpace(&doc, RigSpace::Model, kBigModel, &error)); // already there
        doc.undoStack()->undo();
        QCOMPARE(doc.rig(), mixedWorldRig());
        doc.undoStack()->redo();
        QCOMPARE(int(doc.rig().space), int(RigSpace::Model));
    }
};

QTEST_GUILESS_MAIN(TestPlacement)
#include "tst_placement.moc"
