// The light-type traits table (core/lighttypes.h): every row is consistent with the rig reader and writer,
// makeLight keeps the defaults the hand-written switch had, and the derived texts and lookups read the table.
#include "core/lighttypes.h"
#include "core/prepare.h"
#include "core/rigjson.h"

#include <QSet>
#include <QTest>
#include <glm/geometric.hpp>

using namespace lr;

class TestLightTypes : public QObject {
    Q_OBJECT
  private slots:
    void usesReadTheTable() {
        for (const LightTypeTraits& t : kLightTypeTraits) {
            Light l;
            l.type = t.type;
            QCOMPARE(l.usesPosition(), t.usesPosition);
            QCOMPARE(l.usesDirection(), t.usesDirection);
            QCOMPARE(l.usesFalloff(), t.usesFalloff);
            QCOMPARE(l.usesCone(), t.usesCone);
            QCOMPARE(l.usesSurfaceModels(), t.usesSurfaceModels);
            QCOMPARE(l.usesRimExponent(), t.usesRimExponent);
            // Only a light with a position can have a range or a cone around it.
            QVERIFY(t.usesPosition || (!t.usesFalloff && !t.usesCone && !t.boundable));
        }
    }

    // makeLight's defaults are those of the switch it replaced (position (2, 2, 2); a spot aims at the
    // origin; range-power falloff of range 8 for point and spot; the default cone).
    void makeLightDefaults() {
        const Light point = makeLight(LightType::Point, QStringLiteral("p"));
        QCOMPARE(point.falloff, (Falloff{FalloffModel::RangePower, 8.0, 2.0}));
        QCOMPARE(point.position, glm::dvec3(2.0));
        const Light spot = makeLight(LightType::Spot, QStringLiteral("s"));
        QVERIFY(glm::length(spot.direction - glm::normalize(glm::dvec3(-1.0))) < 1e-15);
        QCOMPARE(spot.falloff, (Falloff{FalloffModel::RangePower, 8.0, 2.0}));
        QCOMPARE(spot.cone, (Cone{ConeModel::Smooth, 20.0, 35.0, 1.0}));
        const Light sun = makeLight(LightType::Directional, QStringLiteral("d"));
        QVERIFY(glm::length(sun.direction - glm::normalize(glm::dvec3(-1.0))) < 1e-15);
        QCOMPARE(sun.falloff, Falloff{});
        const Light rim = makeLight(LightType::Rim, QStringLiteral("r"));
        QCOMPARE(rim.direction, glm::dvec3(0, 0, -1));
        QCOMPARE(rim.rimExponent, 1.3);
    }

    // Every type's default light is written and read back as the same file: the table and the file format
    // agree on what each type uses (a value the writer leaves out would not come back).
    void everyTypeRoundTrips() {
        Rig rig;
        for (const LightType t : allLightTypes())
            rig.lights.push_back(makeLight(t, toString(t)));
        QCOMPARE(int(rig.lights.size()), kLightTypeCount);
        const RigReadResult back = readRigJson(writeRigJson(rig), QStringLiteral("types.json"));
        QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));
        QCOMPARE(writeRigJson(*back.rig), writeRigJson(rig));
        for (int i = 0; i < kLightTypeCount; ++i)
            QVERIFY(back.rig->lights[size_t(i)].type == LightType(i));
    }

    void derivedTexts() {
        QCOMPARE(lightTypesWith(&LightTypeTraits::usesPosition),
                 QStringLiteral("point, spot, rect and disk"));
        QCOMPARE(lightTypesWith(&LightTypeTraits::isArea), QStringLiteral("rect and disk"));
        QCOMPARE(lightTypesWith(&LightTypeTraits::usesCone), QStringLiteral("spot"));
        QCOMPARE(lightTypesWith(&LightTypeTraits::usesDirection),
                 QStringLiteral("spot, directional, rim, rect and disk"));
        QCOMPARE(lightTypeLabel(LightType::Directional), QStringLiteral("Directional"));
        QSet<QString> labels;
        QSet<int> shapes;
        for (const LightTypeTraits& t : kLightTypeTraits) {
            labels.insert(lightTypeLabel(t.type));
            shapes.insert(int(t.gizmo));
        }
        QCOMPARE(labels.size(), kLightTypeCount); // tell them apart in the UI and the viewport
        QCOMPARE(shapes.size(), kLightTypeCount);
    }

    void gltfTypes() {
        QCOMPARE(lightTypeFromGltf(QStringLiteral("point")), std::optional(LightType::Point));
        QCOMPARE(lightTypeFromGltf(QStringLiteral("spot")), std::optional(LightType::Spot));
        QCOMPARE(lightTypeFromGltf(QStringLiteral("directional")), std::optional(LightType::Directional));
        QVERIFY(!lightTypeFromGltf(QStringLiteral("area")));
        QVERIFY(!lightTypeFromGltf(QStringLiteral("rim"))); // glTF has no rim light
        QVERIFY(!lightTypeFromGltf(QString()));
    }

    // The reader's messages name the types from the table.
    void readerMessagesNameTheTypes() {
        const QByteArray json =
            R"({"format": "lightrig", "version": 1, "lights": [{"type": "directional", "direction": [0, -1, 0],
                "position": [0, 1, 0], "cone": {"model": "hard", "outer": 30}, "exponent": 2}]})";
        const RigReadResult r = readRigJson(json, QStringLiteral("bad.json"));
        QVERIFY(!r.ok());
        const QString all = r.errors.join(QLatin1Char('\n'));
        QVERIFY2(
            all.contains(QStringLiteral("a directional light has no position (only point, spot, rect and "
                                        "disk lights have one)")),
            qPrintable(all));
        QVERIFY2(all.contains(QStringLiteral("(only spot lights have one)")), qPrintable(all));
        QVERIFY2(all.contains(QStringLiteral("only rim lights have an exponent")), qPrintable(all));
    }
};

QTEST_GUILESS_MAIN(TestLightTypes)
#include "tst_lighttypes.moc"
