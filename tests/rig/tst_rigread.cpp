// Reading valid rig files: what they mean (every field, defaults, normalisation, the environment and area
// lights), and unknown keys as warnings. Bad input and the reader's limits: tst_rigreaderrors.
#include "rigtest.h"

#include <glm/geometric.hpp>

#include <cmath>

using namespace lr;
using namespace lr::test;

class TestRigRead : public QObject {
    Q_OBJECT
  private slots:
    void issueExample();
    void defaults();
    void physicallyBasedShading();
    void allFields();
    void unknownKeysAreWarnings();
    void utf8BomIsAccepted();
    void environment();
    void areaLights();
    void areaDefaults();
    void environmentDefaultsAndWarnings();
    void directionsAreNormalised();
};

void TestRigRead::issueExample() {
    const RigReadResult r = readRigFile(dataPath(QStringLiteral("good/issue-example.json")));
    LR_VERIFY_OK(r);
    QVERIFY(r.warnings.isEmpty());
    const Rig& rig = *r.rig;
    QCOMPARE(rig.name, QStringLiteral("Studio three-point"));
    LR_COMPARE(rig.space, RigSpace::Model);
    QCOMPARE(rig.ambient, glm::dvec3(0.03));
    LR_COMPARE(rig.shading.specular, SpecularModel::Phong);
    LR_COMPARE(rig.shading.viewer, ViewerModel::Local);
    QCOMPARE(rig.shading.shininess, 32.0);
    LR_COMPARE(rig.shading.model, ShadingModel::Classic); // files before physically based shading
    QCOMPARE(rig.lights.size(), size_t(4));
    const Light& key = rig.lights[0];
    LR_COMPARE(key.type, LightType::Spot);
    QCOMPARE(key.color, glm::dvec3(1, 0.95, 0.9));
    QCOMPARE(key.intensity, 4.0);
    QCOMPARE(key.position, glm::dvec3(2, 2, 2));
    const double s = 1.0 / std::sqrt(3.0);
    QVERIFY(std::abs(key.direction.x + s) < 1e-15 && std::abs(key.direction.y + s) < 1e-15 &&
            std::abs(key.direction.z + s) < 1e-15);
    LR_COMPARE(key.falloff, (Falloff{FalloffModel::RangePower, 8.0, 2.0}));
    LR_COMPARE(key.cone, (Cone{ConeModel::Smooth, 20.0, 35.0, 1.0}));
    const Light& fill = rig.lights[1];
    LR_COMPARE(fill.type, LightType::Point);
    LR_COMPARE(fill.falloff.model, FalloffModel::InversePolynomial);
    QCOMPARE(fill.falloff.constant, 0.0);
    QCOMPARE(fill.falloff.linear, 0.1);
    QCOMPARE(fill.falloff.quadratic, 0.05);
    QVERIFY(!fill.falloff.hasRange());
    LR_COMPARE(rig.lights[2].type, LightType::Directional);
    LR_COMPARE(rig.lights[2].diffuse, DiffuseModel::HalfLambert);
    QCOMPARE(rig.lights[2].direction, glm::dvec3(0, -1, 0));
    LR_COMPARE(rig.lights[3].type, LightType::Rim);
    QCOMPARE(rig.lights[3].rimExponent, 1.3);
    QCOMPARE(rig.lights[3].direction, glm::dvec3(0, 0, -1));
}

void TestRigRead::defaults() {
    const RigReadResult r = readRigFile(dataPath(QStringLiteral("good/minimal.json")));
    LR_VERIFY_OK(r);
    const Rig& rig = *r.rig;
    QCOMPARE(rig.name, QString());
    LR_COMPARE(rig.space, RigSpace::World);
    QCOMPARE(rig.ambient, glm::dvec3(0.0));
    LR_COMPARE(rig.shading, Shading{});
    QCOMPARE(rig.shading.shininess, 32.0);
    LR_COMPARE(rig.shading.model, ShadingModel::Classic); // files before physically based shading
    QCOMPARE(rig.lights.size(), size_t(4));
    for (const Light& l : rig.lights) {
        QCOMPARE(l.enabled, true);
        QCOMPARE(l.intensity, 1.0);
        QCOMPARE(l.color, glm::dvec3(1.0));
        LR_COMPARE(l.diffuse, DiffuseModel::Lambert);
        QCOMPARE(l.specularIsColor, false);
        QCOMPARE(l.specular, glm::dvec3(1.0));
        QVERIFY(!l.ambient.has_value());
        QVERIFY(!l.temperature.has_value());
    }
    LR_COMPARE(rig.lights[0].falloff.model, FalloffModel::None);
    LR_COMPARE(rig.lights[1].falloff.model, FalloffModel::InverseSquare);
    QVERIFY(!rig.lights[1].falloff.hasRange());
    LR_COMPARE(rig.lights[1].cone, (Cone{ConeModel::Smooth, 20.0, 35.0, 1.0})); // a spot without "cone"
    QCOMPARE(rig.lights[1].direction, glm::dvec3(0, -1, 0));
    QCOMPARE(rig.lights[3].rimExponent, 1.3);
}

void TestRigRead::physicallyBasedShading() {
    // The model is read; the classic keys stay at their defaults and are not written back.
    const RigReadResult r =
        readRigJson(rigJson(kPoint, R"("shading": {"model": "pbr"},)"), QStringLiteral("pbr.json"));
    LR_VERIFY_OK(r);
    LR_COMPARE(r.rig->shading.model, ShadingModel::Pbr);
    const QByteArray written = writeRigJson(*r.rig);
    QVERIFY2(written.contains(R"("shading": {"model": "pbr"})"), written.constData());
    QVERIFY(!written.contains("shininess"));
    // Classic rigs are written as before, without a model key.
    Rig classic = *r.rig;
    classic.shading.model = ShadingModel::Classic;
    const QByteArray classicText = writeRigJson(classic);
    QVERIFY(!classicText.contains("\"model\": \"classic\""));
    QVERIFY(classicText.contains(R"("shading": {"specular": "phong", "viewer": "local", "shininess": 32})"));
    const RigReadResult back = readRigJson(classicText, QStringLiteral("classic.json"));
    LR_VERIFY_OK(back);
    QVERIFY(*back.rig == classic);
}

void TestRigRead::allFields() {
    const RigReadResult r = readRigFile(dataPath(QStringLiteral("good/all-fields.json")));
    LR_VERIFY_OK(r);
    const Rig& rig = *r.rig;
    QCOMPARE(rig.name, QString::fromUtf8("Every field \xc3\xa9\xf0\x9f\x92\xa1 \"quoted\"\ttab"));
    LR_COMPARE(rig.shading.viewer, ViewerModel::Infinite);
    const Light& p = rig.lights[0];
    QCOMPARE(p.enabled, false);
    QCOMPARE(p.temperature, std::optional(3200.0));
    QCOMPARE(p.specularIsColor, true);
    QCOMPARE(p.specular, glm::dvec3(0.1, 0.2, 0.3));
    QCOMPARE(p.ambient, std::optional(glm::dvec3(0, 0.1, 0)));
    LR_COMPARE(p.falloff, (Falloff{FalloffModel::InversePolynomial, 40.0, 2.0, 1.0, 0.0, 0.5}));
    QCOMPARE(rig.lights[1].specular, glm::dvec3(0.0));
    QCOMPARE(rig.lights[1].specularIsColor, false);
    LR_COMPARE(rig.lights[1].cone.model, ConeModel::Hard);
    QCOMPARE(rig.lights[1].cone.outer, 90.0);
    LR_COMPARE(rig.lights[2].cone.model, ConeModel::AnglePower);
    QCOMPARE(rig.lights[2].cone.exponent, 1.0);
    QCOMPARE(rig.lights[3].rimExponent, 1e4);
}

void TestRigRead::unknownKeysAreWarnings() {
    const QString file = dataPath(QStringLiteral("good/unknown-keys.json"));
    const RigReadResult r = readRigFile(file);
    LR_VERIFY_OK(r);
    QCOMPARE(r.warnings.size(), 3);
    QVERIFY2(hasMessage(r.warnings, file, QStringLiteral("comment: unknown key")), qPrintable(describe(r)));
    QVERIFY2(hasMessage(r.warnings, file, QStringLiteral("lights[0].colour: unknown key")),
             qPrintable(describe(r)));
    QVERIFY2(hasMessage(r.warnings, file, QStringLiteral("lights[0].falloff-note: unknown key")),
             qPrintable(describe(r)));
    QCOMPARE(r.rig->lights[0].color, glm::dvec3(1.0)); // "colour" is not "color"
}

// Issue 16: rect and disk lights (format version 2), every key of "area", as good/area.json gives them.
void TestRigRead::areaLights() {
    const QString file = dataPath(QStringLiteral("good/area.json"));
    const RigReadResult r = readRigFile(file);
    LR_VERIFY_OK(r);
    QVERIFY(r.warnings.isEmpty());
    QCOMPARE(int(r.rig->lights.size()), 2);
    const Light& rect = r.rig->lights[0];
    QVERIFY(rect.type == LightType::Rect && rect.isArea());
    LR_COMPARE(rect.area, (AreaShape{1.5, 1.0, 0.5, 90.0, false}));
    QVERIFY(rect.shadow.enabled);
    QCOMPARE(rect.shadow.resolution, 2048);
    const Light& disk = r.rig->lights[1];
    QVERIFY(disk.type == LightType::Disk);
    QCOMPARE(disk.area.radius, 0.4);
    QVERIFY(disk.area.twoSided);
    QCOMPARE(disk.area.width, AreaShape{}.width); // kept at its default, unused by a disk
    // The file is canonical: it is written back byte for byte, as version 2.
    QCOMPARE(writeRigJson(*r.rig), readAll(file));
}

// "area" and each of its keys are optional (lr::AreaShape's defaults); sizes 0 and the roll's ends are
// allowed; a version 2 file without area lights is read and written back as version 1 (the oldest version
// that holds it), a rig with one as version 2.
void TestRigRead::areaDefaults() {
    RigReadResult r = readRigJson(rigJson2(kRect + ", " + kDisk), QStringLiteral("a.json"));
    LR_VERIFY_OK(r);
    LR_COMPARE(r.rig->lights[0].area, AreaShape{});
    LR_COMPARE(r.rig->lights[1].area, AreaShape{});
    r = readRigJson(rigJson2(with(kRect, R"("area": {"width": 0, "height": 1e12, "roll": -180})") + ", " +
                             with(kDisk, R"("area": {"radius": 0, "roll": 180})")),
                    QStringLiteral("a.json"));
    LR_VERIFY_OK(r);
    LR_COMPARE(r.rig->lights[0].area, (AreaShape{0.0, 1e12, 0.5, -180.0, false}));
    LR_COMPARE(r.rig->lights[1].area, (AreaShape{1.0, 1.0, 0.0, 180.0, false}));
    QVERIFY(writeRigJson(*r.rig).contains("\"version\": 2,"));
    r = readRigJson(rigJson2(kPoint), QStringLiteral("p.json"));
    LR_VERIFY_OK(r);
    QVERIFY(writeRigJson(*r.rig).contains("\"version\": 1,"));
    // A spot's shadow keeps its size; an area light's unknown-type reading still checks the area's values.
    r = readRigJson(rigJson2(R"({"type": "softbox", "area": {"width": -1}})"), QStringLiteral("u.json"));
    QVERIFY(hasMessage(r.errors, QStringLiteral("u.json"), QStringLiteral("lights[0].type: must be")));
    QVERIFY(hasMessage(r.errors, QStringLiteral("u.json"), QStringLiteral("lights[0].area.width: must be")));
}

// Issue 15: every key of the "environment" block, as good/environment.json gives it.
void TestRigRead::environment() {
    const QString file = dataPath(QStringLiteral("good/environment.json"));
    const RigReadResult r = readRigFile(file);
    LR_VERIFY_OK(r);
    QCOMPARE(writeRigJson(*r.rig), readAll(file)); // in canonical form
    QVERIFY2(r.warnings.isEmpty(), qPrintable(describe(r)));
    const Environment& e = r.rig->environment;
    LR_COMPARE(e.source, EnvironmentSource::Studio);
    QCOMPARE(e.file,
             QStringLiteral("hdr/sky.exr")); // kept as written, resolved against the rig's folder later
    QCOMPARE(e.intensity, -1.5);
    QCOMPARE(e.rotation, 270.0);
    LR_COMPARE(e.background, EnvironmentBackground::Blurred);
    QCOMPARE(e.blur, 0.45);
    LR_COMPARE(e.diffuse, DiffuseModel::HalfLambert);
    QCOMPARE(e.studio.zenith, glm::dvec3(0.2, 0.22, 0.25));
    QCOMPARE(e.studio.horizon, glm::dvec3(0.5));
    QCOMPARE(e.studio.floor, glm::dvec3(0.05));
    QCOMPARE(e.studio.softboxes.size(), size_t(3));
    LR_COMPARE(e.studio.softboxes[1], (Softbox{-60, 10, 15, 80, glm::dvec3(1.0), 2}));
    QCOMPARE(e.spots.size(), size_t(2));
    LR_COMPARE(e.spots[1], (EnvironmentSpot{{0.6, 0.8, 0.0}, 12.5, 0.25}));
}

// Absent keys take lr::Environment's defaults; a spot's direction is normalised; unknown keys anywhere in the
// block are warnings naming their path (as everywhere in the format), and every error is listed.
void TestRigRead::environmentDefaultsAndWarnings() {
    RigReadResult r = readRigJson(rigJson({}, R"("environment": {"source": "studio", "hdr": 1, "studio": {
        "softboxes": [{"azimuth": 90, "glow": 2}]}, "spots": [{"direction": [0, 0, -5], "size": 3}]},)"),
                                  QStringLiteral("e.json"));
    LR_VERIFY_OK(r);
    const Environment& e = r.rig->environment;
    Environment expected;
    expected.source = EnvironmentSource::Studio;
    Softbox box;
    box.azimuth = 90;
    expected.studio.softboxes = {box};
    expected.spots = {EnvironmentSpot{{0, 0, -1}, 5, 0}};
    LR_COMPARE(e, expected);
    QCOMPARE(r.warnings.size(), 3);
    for (const char* w : {"environment.hdr: unknown key", "environment.studio.softboxes[0].glow: unknown key",
                          "environment.spots[0].size: unknown key"})
        QVERIFY2(hasMessage(r.warnings, QStringLiteral("e.json"), QLatin1String(w)), qPrintable(describe(r)));

    r = readRigJson(rigJson({}, R"("environment": {"source": "image", "intensity": 30, "studio": {"softboxes":
        [{"width": -1}]}, "spots": [{"direction": [0, 0, 0]}]},)"),
                    QStringLiteral("e.json"));
    QVERIFY(!r.ok());
    QCOMPARE(r.errors.size(), 4);
    for (const char* m : {"environment.file: missing", "environment.intensity: must be",
                          "environment.studio.softboxes[0].width: must be",
                          "environment.spots[0].direction: must not be the zero vector"})
        QVERIFY2(hasMessage(r.errors, QStringLiteral("e.json"), QLatin1String(m)), qPrintable(describe(r)));
}

void TestRigRead::utf8BomIsAccepted() {
    const RigReadResult r = readRigFile(dataPath(QStringLiteral("good/utf8-bom.json")));
    LR_VERIFY_OK(r);
    QVERIFY(r.rig->lights.empty());
}

void TestRigRead::directionsAreNormalised() {
    const struct {
        const char* json;
        glm::dvec3 expected;
    } cases[] = {
        {"[0, 0, -5]", {0, 0, -1}},
        {"[1e300, 0, 0]", {1, 0, 0}},
        {"[0, -1e-300, 0]", {0, -1, 0}},
        {"[3, 0, 4]", {0.6, 0, 0.8}},
    };
    for (const auto& c : cases) {
        const RigReadResult r = readRigJson(
            rigJson(QByteArray(R"({"type": "rim", "direction": )") + c.json + '}'), QStringLiteral("d.json"));
        LR_VERIFY_OK(r);
        const glm::dvec3 d = r.rig->lights[0].direction;
        QVERIFY2(glm::length(d - c.expected) < 1e-15, c.json);
        QVERIFY(std::abs(glm::dot(d, d) - 1.0) <= 1e-15);
    }
}

QTEST_GUILESS_MAIN(TestRigRead)
#include "tst_rigread.moc"
