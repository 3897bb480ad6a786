// The built-in presets: embedded in lightrig_core and found from a test executable, valid, canonical
// (byte-identical after load -> save), identical to resources/presets/, and holding the design documents'
// numbers from issue 2.
#include "rigtest.h"

#include <glm/geometric.hpp>

#include "core/prepare.h"
#include "core/shade.h"

#include <QDir>
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

using namespace lr;
using namespace lr::test;

namespace {
const QStringList kExpected = {
    QStringLiteral("book-point-spot"), QStringLiteral("butterfly"),  QStringLiteral("d3d-spot"),
    QStringLiteral("default"),         QStringLiteral("rembrandt"),  QStringLiteral("rgb-three"),
    QStringLiteral("rim-backlight"),   QStringLiteral("silhouette"), QStringLiteral("three-point"),
};

Rig preset(const QString& name) {
    const RigReadResult r = readBuiltinPreset(name);
    if (!r.ok()) qFatal("%s", qPrintable(describe(r)));
    return *r.rig;
}

bool near(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::length(a - b) < 1e-12;
}
glm::dvec3 unit(double x, double y, double z) {
    return glm::normalize(glm::dvec3(x, y, z));
}
} // namespace

class TestRigPresets : public QObject {
    Q_OBJECT
  private slots:
    void names();
    void everyPreset_data();
    void everyPreset();
    void unknownPreset();
    void bookPointSpot();
    void d3dSpot();
    void rgbThree();
    void rimBacklight();
    void studioRigsAreInModelSpace();
    void defaultRigLightsTheFront();
};

void TestRigPresets::names() {
    QCOMPARE(builtinPresetNames(), kExpected);
    QCOMPARE(builtinPresetPath(QStringLiteral("default")),
             QStringLiteral(":/resources/presets/default.json"));
    QStringList onDisk = QDir(QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/presets"))
                             .entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
    for (QString& f : onDisk)
        f.chop(5);
    QCOMPARE(onDisk, kExpected);
}

void TestRigPresets::everyPreset_data() {
    QTest::addColumn<QString>("name");
    for (const QString& n : kExpected)
        QTest::newRow(qPrintable(n)) << n;
}

void TestRigPresets::everyPreset() {
    QFETCH(QString, name);
    const RigReadResult r = readBuiltinPreset(name);
    LR_VERIFY_OK(r);
    QVERIFY2(r.warnings.isEmpty(), qPrintable(describe(r)));
    QVERIFY(!r.rig->name.isEmpty());
    QVERIFY(!r.rig->lights.empty());
    const QByteArray embedded = readAll(builtinPresetPath(name));
    QCOMPARE(writeRigJson(*r.rig), embedded); // canonical: load -> save is byte-identical
    QCOMPARE(
        readAll(QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/presets/") + name + QStringLiteral(".json")),
        embedded);
    QStringList names;
    for (const Light& l : r.rig->lights) {
        QVERIFY2(!names.contains(l.name), qPrintable(l.name));
        names << l.name;
    }
}

void TestRigPresets::unknownPreset() {
    const RigReadResult r = readBuiltinPreset(QStringLiteral("nope"));
    QVERIFY(!r.ok());
    QCOMPARE(r.errors.size(), 1);
    QVERIFY2(r.errors[0].startsWith(QStringLiteral("nope.json: no such built-in preset")),
             qPrintable(r.errors[0]));
}

// Doc 000: point at (0,50,50), colour (15,0,0), range 100, exponent 3; spot at (0,50,0), colour
// (10,10,10), direction (1,-1,1), range 300, angle-power outer 25 degrees.
void TestRigPresets::bookPointSpot() {
    const Rig rig = preset(QStringLiteral("book-point-spot"));
    QCOMPARE(rig.lights.size(), size_t(2));
    const Light& point = rig.lights[0];
    LR_COMPARE(point.type, LightType::Point);
    QCOMPARE(point.position, glm::dvec3(0, 50, 50));
    QCOMPARE(point.color * point.intensity, glm::dvec3(15, 0, 0));
    LR_COMPARE(point.falloff, (Falloff{FalloffModel::RangePower, 100.0, 3.0}));
    const Light& spot = rig.lights[1];
    LR_COMPARE(spot.type, LightType::Spot);
    QCOMPARE(spot.position, glm::dvec3(0, 50, 0));
    QCOMPARE(spot.color * spot.intensity, glm::dvec3(10, 10, 10));
    QVERIFY(near(spot.direction, unit(1, -1, 1)));
    LR_COMPARE(spot.falloff.model, FalloffModel::RangePower);
    QCOMPARE(spot.falloff.range, 300.0);
    LR_COMPARE(spot.cone.model, ConeModel::AnglePower);
    QCOMPARE(spot.cone.outer, 25.0);
    QCOMPARE(spot.cone.exponent, 0.5); // the book's pow(affect, 0.5)
}

// Doc 001: spot at (0,2.5,0), direction (0,-1,0.6), inverse-polynomial (0, 0.1, 0.05), smooth cone
// 30/50 degrees, exponent 3.2, and a half-Lambert directional light.
void TestRigPresets::d3dSpot() {
    const Rig rig = preset(QStringLiteral("d3d-spot"));
    QCOMPARE(rig.lights.size(), size_t(2));
    const Light& spot = rig.lights[0];
    LR_COMPARE(spot.type, LightType::Spot);
    QCOMPARE(spot.position, glm::dvec3(0, 2.5, 0));
    QVERIFY(near(spot.direction, unit(0, -1, 0.6)));
    LR_COMPARE(spot.falloff.model, FalloffModel::InversePolynomial);
    QCOMPARE(spot.falloff.constant, 0.0);
    QCOMPARE(spot.falloff.linear, 0.1);
    QCOMPARE(spot.falloff.quadratic, 0.05);
    LR_COMPARE(spot.cone, (Cone{ConeModel::Smooth, 30.0, 50.0, 3.2}));
    LR_COMPARE(rig.lights[1].type, LightType::Directional);
    LR_COMPARE(rig.lights[1].diffuse, DiffuseModel::HalfLambert);
}

// Doc 003: green directional down, red point at (150,150,150) range 10000, blue spot at (-150,0,150)
// towards +X with a 45 degree full cone (22.5 degree half-angle), range 10000.
void TestRigPresets::rgbThree() {
    const Rig rig = preset(QStringLiteral("rgb-three"));
    QCOMPARE(rig.lights.size(), size_t(3));
    const Light& sun = rig.lights[0];
    LR_COMPARE(sun.type, LightType::Directional);
    QCOMPARE(sun.direction, glm::dvec3(0, -1, 0));
    QVERIFY(sun.color.g > sun.color.r && sun.color.g > sun.color.b);
    const Light& red = rig.lights[1];
    LR_COMPARE(red.type, LightType::Point);
    QCOMPARE(red.position, glm::dvec3(150, 150, 150));
    QCOMPARE(red.falloff.range, 10000.0);
    QVERIFY(red.color.r > red.color.g && red.color.r > red.color.b);
    const Light& blue = rig.lights[2];
    LR_COMPARE(blue.type, LightType::Spot);
    QCOMPARE(blue.position, glm::dvec3(-150, 0, 150));
    QCOMPARE(blue.direction, glm::dvec3(1, 0, 0));
    QCOMPARE(blue.falloff.range, 10000.0);
    QCOMPARE(blue.cone.outer, 22.5);
    QVERIFY(blue.color.b > blue.color.r && blue.color.b > blue.color.g);
    for (const Light& l : rig.lights)
        QVERIFY(l.specularIsColor); // doc 003's separate specular colour
}

// Doc 000's rim: a directional light and a rim light sharing its direction and colour, exponent 1.3.
void TestRigPresets::rimBacklight() {
    const Rig rig = preset(QStringLiteral("rim-backlight"));
    const auto dir = std::find_if(rig.lights.begin(), rig.lights.end(),
                                  [](const Light& l) { return l.type == LightType::Directional; });
    const auto rim = std::find_if(rig.lights.begin(), rig.lights.end(),
                                  [](const Light& l) { return l.type == LightType::Rim; });
    QVERIFY(dir != rig.lights.end() && rim != rig.lights.end());
    QCOMPARE(rim->rimExponent, 1.3);
    QCOMPARE(rim->direction, dir->direction);
    QCOMPARE(rim->color, dir->color);
}

void TestRigPresets::studioRigsAreInModelSpace() {
    for (const char* n : {"default", "three-point", "rembrandt", "butterfly", "silhouette"})
        QVERIFY2(preset(QString::fromLatin1(n)).space == RigSpace::Model, n);
    for (const char* n : {"book-point-spot", "d3d-spot", "rgb-three"})
        QVERIFY2(preset(QString::fromLatin1(n)).space == RigSpace::World, n);
}

// The default rig, on a unit sphere seen from +Z (the editor's default camera): the front is lit to a
// readable level, brighter than the sides, and no light is pointlessly far or aimed away.
void TestRigPresets::defaultRigLightsTheFront() {
    const Rig rig = defaultRig();
    LR_COMPARE(rig, preset(QStringLiteral("default")));
    QVERIFY(rig.lights.size() >= 3);
    const SceneFrame frame{glm::dvec3(0.0), 1.0};
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 4), glm::dvec3(0.0), glm::dvec3(0, 1, 0));
    const auto lights = prepareLights(rig, frame, view);
    auto settings = prepareSettings(rig, frame);
    auto luminance = [&](const glm::dvec3& n) {
        lighting::Surface<double> s;
        s.position = glm::dvec3(view * glm::dvec4(n, 1.0));
        s.normal = glm::normalize(glm::dvec3(view * glm::dvec4(n, 0.0)));
        s.albedo = glm::dvec3(0.8);
        const glm::dvec3 c = lighting::shadeSurface<double>(s, lights, settings);
        return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
    };
    const double front = luminance({0, 0, 1});
    const double upperRight = luminance(glm::normalize(glm::dvec3(1, 1, 1)));
    QVERIFY2(front > 0.25 && front < 1.2, qPrintable(QString::number(front)));
    QVERIFY2(upperRight > 0.25 && upperRight < 1.5, qPrintable(QString::number(upperRight)));
    QVERIFY2(luminance({0, -1, 0}) < front, "the underside should be darker than the front");
    for (const Light& l : rig.lights)
        if (l.usesPosition())
            QVERIFY2(glm::length(l.position) < 10.0 && glm::length(l.position) > 1.5, qPrintable(l.name));
}

QTEST_GUILESS_MAIN(TestRigPresets)
#include "tst_rigpresets.moc"
