// Issue 39: a light with an IES profile exported as EXT_lights_ies (core/gltflights_ies.cpp, gltfrewrite):
// the profile's bytes in a data: URI, the node an EXT_lights_ies instance (not a punctual light as well),
// the multiplier by level, the node turned so that -Z is the nadir and +X horizontal angle 0, the loss
// listed, and a file that does not read exported as a plain light with the reason.
#include "core/gltfrewrite.h"
#include "core/ies.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTest>
#include <glm/gtc/quaternion.hpp>

using namespace lr;

namespace {

QString data(const QString& name) {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/ies/") + name;
}

Rig rigWithProfile(IesLevel level) {
    Rig rig;
    rig.shading.model = ShadingModel::Pbr;
    Light spot = makeLight(LightType::Spot, QStringLiteral("Down"));
    spot.position = {0.0, 3.0, 0.0};
    spot.direction = {0.0, -1.0, 0.0};
    spot.intensity = 40.0;
    spot.color = {1.0, 0.5, 0.25};
    spot.temperature.reset();
    spot.falloff.model = FalloffModel::InverseSquare;
    spot.falloff.range = -1.0;
    spot.ies = IesSpec{QStringLiteral("full.ies"), data(QStringLiteral("full.ies")), 2.0, level, 30.0};
    Light key = makeLight(LightType::Point, QStringLiteral("Key"));
    key.falloff.model = FalloffModel::InverseSquare;
    key.falloff.range = -1.0;
    rig.lights = {key, spot};
    return rig;
}

QJsonObject parse(const QByteArray& json) {
    return QJsonDocument::fromJson(json).object();
}

} // namespace

class TestGltfIes : public QObject {
    Q_OBJECT
  private slots:
    void profileBecomesAnExtLightsIesInstance() {
        const GltfRigExport e = convertRigToGltf(rigWithProfile(IesLevel::Light), SceneFrame{});
        QCOMPARE(e.lights.size(), std::size_t(2));
        QVERIFY(!e.lights[0].ies);
        QVERIFY(e.lights[1].ies);
        const GltfIes& ies = *e.lights[1].ies;
        QFile f(data(QStringLiteral("full.ies")));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(ies.file, f.readAll());
        // Level "light": intensity × multiplier / peak (× the colour's largest component, 1 here).
        QString error;
        const auto profile = readIesFile(data(QStringLiteral("full.ies")), &error);
        QVERIFY(std::abs(ies.multiplier - 40.0 * 2.0 / profile->peak) < 1e-12);
        QCOMPARE(ies.color, glm::dvec3(1.0, 0.5, 0.25));
        bool listed = false;
        for (const LossyConversion& l : e.losses)
            listed = listed || (l.kind == ExportLoss::Ies && l.subject == QStringLiteral("Down") &&
                                l.detail.contains(QStringLiteral("without its cone")));
        QVERIFY(listed);
        // The node: local -Z onto the nadir (straight down), local +X onto horizontal angle 0.
        const glm::dquat q = e.lights[1].rotation;
        const glm::dvec3 down = q * glm::dvec3(0.0, 0.0, -1.0);
        QVERIFY(glm::length(down - glm::dvec3(0.0, -1.0, 0.0)) < 1e-12);
        const AreaAxes axes = areaAxes({0.0, -1.0, 0.0}, 30.0);
        QVERIFY(glm::length(q * glm::dvec3(1.0, 0.0, 0.0) - axes.x) < 1e-12);
        QVERIFY(glm::length(q * glm::dvec3(0.0, 1.0, 0.0) - axes.y) < 1e-12);
    }

    void levelProfileUsesTheFilesCandela() {
        const GltfRigExport e = convertRigToGltf(rigWithProfile(IesLevel::Profile), SceneFrame{});
        QVERIFY(e.lights[1].ies);
        QCOMPARE(e.lights[1].ies->multiplier, 2.0); // the light's intensity (40) plays no part
    }

    void writtenIntoTheFile() {
        GltfAdditions add;
        const GltfRigExport e = convertRigToGltf(rigWithProfile(IesLevel::Light), SceneFrame{});
        add.lights = e.lights;
        const QByteArray in =
            R"({"asset":{"version":"2.0"},"extensionsUsed":["EXT_x"],"extensions":{"EXT_x":{}}})";
        for (const bool lightsOnly : {false, true}) {
            QByteArray out;
            if (lightsOnly) {
                out = lightsOnlyGltfJson(add);
            } else {
                const GltfRewriteResult r = rewriteGltfJson(in, add);
                QVERIFY2(r.ok(), qPrintable(r.error));
                out = r.json;
            }
            const QJsonObject root = parse(out);
            const QJsonArray used = root.value(QStringLiteral("extensionsUsed")).toArray();
            QVERIFY2(used.contains(QStringLiteral("EXT_lights_ies")) &&
                         used.contains(QStringLiteral("KHR_lights_punctual")),
                     out.constData());
            const QJsonObject exts = root.value(QStringLiteral("extensions")).toObject();
            QCOMPARE(exts.value(QStringLiteral("KHR_lights_punctual"))
                         .toObject()
                         .value(QStringLiteral("lights"))
                         .toArray()
                         .size(),
                     1); // the profile's light is not a punctual light too
            const QJsonArray profiles = exts.value(QStringLiteral("EXT_lights_ies"))
                                            .toObject()
                                            .value(QStringLiteral("lights"))
                                            .toArray();
            QCOMPARE(profiles.size(), 1);
            const QString uri = profiles[0].toObject().value(QStringLiteral("uri")).toString();
            QVERIFY(uri.startsWith(QStringLiteral("data:application/x-ies-lm-63;base64,")));
            QCOMPARE(QByteArray::fromBase64(uri.section(QLatin1Char(','), 1).toLatin1()),
                     e.lights[1].ies->file);
            const QJsonArray nodes = root.value(QStringLiteral("nodes")).toArray();
            const QJsonObject node = nodes[nodes.size() - 1].toObject();
            const QJsonObject instance = node.value(QStringLiteral("extensions"))
                                             .toObject()
                                             .value(QStringLiteral("EXT_lights_ies"))
                                             .toObject();
            QCOMPARE(instance.value(QStringLiteral("light")).toInt(-1), 0);
            QVERIFY(!node.value(QStringLiteral("extensions"))
                         .toObject()
                         .contains(QStringLiteral("KHR_lights_punctual")));
            QVERIFY(std::abs(instance.value(QStringLiteral("multiplier")).toDouble() -
                             e.lights[1].ies->multiplier) < 1e-12);
            const QJsonObject first = nodes[nodes.size() - 2].toObject();
            QCOMPARE(first.value(QStringLiteral("extensions"))
                         .toObject()
                         .value(QStringLiteral("KHR_lights_punctual"))
                         .toObject()
                         .value(QStringLiteral("light"))
                         .toInt(-1),
                     0);
        }
    }

    void aFileThatDoesNotReadIsAPlainLight() {
        Rig rig = rigWithProfile(IesLevel::Light);
        rig.lights[1].ies->resolved = data(QStringLiteral("truncated.ies"));
        const GltfRigExport e = convertRigToGltf(rig, SceneFrame{});
        QVERIFY(!e.lights[1].ies);
        bool listed = false;
        for (const LossyConversion& l : e.losses)
            listed = listed ||
                     (l.kind == ExportLoss::Ies && l.detail.contains(QStringLiteral("truncated.ies:9:")));
        QVERIFY(listed);
    }
};

QTEST_GUILESS_MAIN(TestGltfIes)
#include "tst_gltfies.moc"
