// Issue 37: light groups (core/lightgroups.h) in the rig format and as a scene splits into them, and light
// mixes (core/lightmix.h): the mix file's reader and writer, and a mix written back into a rig.
#include "rigtest.h"

#include "core/lightgroups.h"
#include "core/lightmix.h"
#include "core/prepare.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace lr::test;

namespace {

Light light(const QString& name, const QString& group = {}) {
    Light l = makeLight(LightType::Point, name);
    l.group = group;
    return l;
}

// What a light adds under either shading, as prepare.h hands it to every renderer.
struct Emission {
    glm::dvec3 color, specular, ambient;
};
Emission emission(const Rig& rig, int i) {
    const Light& l = rig.lights[size_t(i)];
    const glm::dvec3 c = l.effectiveColor();
    return {c * l.intensity, (l.specularIsColor ? l.specular : c * l.specular.x) * l.intensity,
            l.ambient.value_or(glm::dvec3(0.0)) * l.intensity};
}

void compareVec(const glm::dvec3& a, const glm::dvec3& b) {
    for (int c = 0; c < 3; ++c)
        QVERIFY2(std::abs(a[c] - b[c]) <= 1e-12 * std::max(1.0, std::abs(b[c])),
                 qPrintable(QStringLiteral("%1 vs %2").arg(a[c], 0, 'g', 17).arg(b[c], 0, 'g', 17)));
}

} // namespace

class TestLightMix : public QObject {
    Q_OBJECT
  private slots:
    void groupRoundTripsAndIsOptional() {
        Rig rig;
        rig.lights = {light(QStringLiteral("Key"), QStringLiteral("key")), light(QStringLiteral("Fill"))};
        const QByteArray text = writeRigJson(rig);
        QVERIFY(text.contains(R"("group": "key")"));
        QCOMPARE(text.count("\"group\""), 1); // a light without one writes none
        const RigReadResult back = readRigJson(text, QStringLiteral("g.json"));
        QVERIFY2(back.ok(), qPrintable(back.errors.join('\n')));
        QCOMPARE(back.rig->lights[0].group, QStringLiteral("key"));
        QCOMPARE(writeRigJson(*back.rig), text);
        QVERIFY(text.contains("\"version\": 1")); // an addition with a default: no newer version
        const RigReadResult bad =
            readRigJson(rigJson(with(kPoint, R"("group": 3)")), QStringLiteral("b.json"));
        QVERIFY(!bad.ok());
        QVERIFY2(bad.errors.join('\n').contains(QStringLiteral("b.json: lights[0].group: must be a string")),
                 qPrintable(bad.errors.join('\n')));
    }

    void groupsOfAScene() {
        Rig rig;
        rig.lights = {light(QStringLiteral("Key"), QStringLiteral("main")),
                      light(QStringLiteral("Fill")),
                      light(QStringLiteral("Kick"), QStringLiteral("main")),
                      light(QString()),
                      light(QStringLiteral("Off")),
                      light(QStringLiteral("x"), QStringLiteral("Background"))};
        rig.lights[4].enabled = false;
        rig.lights.push_back(makeLight(LightType::Rim, QStringLiteral("Rim")));
        rig.environment.source = EnvironmentSource::Studio;
        rig.ambient = glm::dvec3(0.1);
        const std::vector<LightGroup> groups = lightGroups(rig, {.hasEmissive = true});
        QCOMPARE(groupNames(groups), QStringList({"main", "Fill", "light 4", "Background (lights)", "Rim",
                                                  "environment", "emissive", "ambient", "background"}));
        QCOMPARE(groups[0].lights, std::vector<int>({0, 2}));
        const std::vector<int> of = groupOfLights(rig, groups);
        QCOMPARE(of, std::vector<int>({0, 1, 0, 2, -1, 3, 4}));
        // The path tracer leaves rims out; no environment, emission or ambient: no such groups.
        Rig plain = rig;
        plain.environment = {};
        plain.ambient = glm::dvec3(0.0);
        QCOMPARE(groupNames(lightGroups(plain, {.includeRims = false})),
                 QStringList({"main", "Fill", "light 4", "Background (lights)", "background"}));
    }

    void mixFileRoundTrip() {
        LightMix mix;
        mix.groups[QStringLiteral("key")] = {true, 1.5, {1.0, 0.5, 0.25}};
        mix.groups[QStringLiteral("rim")] = {false, 0.0, glm::dvec3(1.0)};
        mix.groups[QStringLiteral("same")] = {};
        const QByteArray text = writeLightMix(mix);
        QVERIFY(!text.contains("same")); // identity groups are not written
        const LightMixReadResult r = readLightMix(text, QStringLiteral("m.json"));
        QVERIFY2(r.mix, qPrintable(r.errors.join('\n')));
        LightMix expected = mix;
        expected.groups.erase(QStringLiteral("same"));
        QCOMPARE(*r.mix, expected);
        QCOMPARE(writeLightMix(*r.mix), text);
        QCOMPARE(r.mix->of(QStringLiteral("absent")), GroupMix{});
    }

    void mixFileErrorsNameFileAndField_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("error");
        const QByteArray head = R"({"format": "lightrig-mix", "version": 1, "groups": )";
        QTest::newRow("ev") << head + R"({"key": {"ev": 40}})" + "}"
                            << "m.json: groups.key.ev: must be a finite number from -20 to 20, got 40";
        QTest::newRow("tint") << head + R"({"key": {"tint": [1, -1, 0]}})" + "}"
                              << "m.json: groups.key.tint[1]: must be a finite number from 0 to 1000, got -1";
        QTest::newRow("tint shape") << head + R"({"key": {"tint": 2}})" + "}"
                                    << "m.json: groups.key.tint: must be a colour [r, g, b], got 2";
        QTest::newRow("enabled") << head + R"({"key": {"enabled": "yes"}})" + "}"
                                 << "m.json: groups.key.enabled: must be";
        QTest::newRow("unknown group")
            << head + R"({"keyy": {}})" + "}"
            << "m.json: groups.keyy: no such light group in the image; it has key, rim";
        QTest::newRow("format") << QByteArray(R"({"format": "lightrig", "version": 1, "groups": {}})")
                                << "m.json: format: must be \"lightrig-mix\"";
        QTest::newRow("version") << QByteArray(R"({"format": "lightrig-mix", "version": 2, "groups": {}})")
                                 << "m.json: version: the file is version 2, newer";
        QTest::newRow("no groups") << QByteArray(R"({"format": "lightrig-mix", "version": 1})")
                                   << "m.json: groups: missing";
        QTest::newRow("syntax") << QByteArray(R"({"format": )") << "m.json:";
        QTest::newRow("array") << QByteArray("[]") << "m.json: (top level): must be a JSON object";
    }
    void mixFileErrorsNameFileAndField() {
        QFETCH(QByteArray, json);
        QFETCH(QString, error);
        const LightMixReadResult r =
            readLightMix(json, QStringLiteral("m.json"), {QStringLiteral("key"), QStringLiteral("rim")});
        QVERIFY(!r.mix);
        QVERIFY2(r.errors.join('\n').contains(error), qPrintable(r.errors.join('\n')));
    }

    // A group mixed by tint × 2^ev and applied to the rig: every light of it emits exactly that much more
    // (colour, specular colour, ambient), the others the same.
    void applyScalesWhatTheGroupEmits() {
        Rig rig;
        rig.lights = {light(QStringLiteral("Key"), QStringLiteral("key")),
                      light(QStringLiteral("Kick"), QStringLiteral("key")), light(QStringLiteral("Fill"))};
        rig.lights[0].color = {0.9, 0.8, 0.7};
        rig.lights[0].intensity = 3.0;
        rig.lights[0].temperature = 4500.0;
        rig.lights[1].specularIsColor = true;
        rig.lights[1].specular = {0.5, 0.6, 0.7};
        rig.lights[1].ambient = glm::dvec3(0.05);
        rig.ambient = glm::dvec3(0.1, 0.2, 0.3);
        rig.environment.source = EnvironmentSource::Studio;
        rig.environment.intensity = 1.0;
        const std::vector<LightGroup> groups = lightGroups(rig, {.hasEmissive = true});
        LightMix mix;
        const glm::dvec3 tint(2.0, 0.5, 1.25);
        mix.groups[QStringLiteral("key")] = {true, 1.5, tint};
        mix.groups[QStringLiteral("Fill")] = {false, 0.0, glm::dvec3(1.0)};
        mix.groups[QStringLiteral("ambient")] = {true, -1.0, glm::dvec3(1.0, 2.0, 1.0)};
        mix.groups[QStringLiteral("environment")] = {true, 0.5, glm::dvec3(1.0, 0.9, 1.0)};
        mix.groups[QStringLiteral("emissive")] = {true, 1.0, glm::dvec3(1.0)};
        QStringList notes;
        const Rig out = applyLightMix(rig, groups, mix, &notes);
        const glm::dvec3 k = tint * std::exp2(1.5);
        for (int i : {0, 1}) {
            const Emission before = emission(rig, i), after = emission(out, i);
            compareVec(after.color, before.color * k);
            compareVec(after.specular, before.specular * k);
            compareVec(after.ambient, before.ambient * k);
            QVERIFY(std::max({out.lights[size_t(i)].color.x, out.lights[size_t(i)].color.y,
                              out.lights[size_t(i)].color.z}) <= 1.0);
        }
        QVERIFY(!out.lights[2].enabled);
        compareVec(out.ambient, glm::dvec3(0.05, 0.2, 0.15));
        QCOMPARE(out.environment.intensity, 1.5);
        QCOMPARE(notes.size(), 2); // the environment's tint, the emission
        QVERIFY(notes.join('\n').contains(QStringLiteral("environment: a rig's environment has no tint")));
        QVERIFY(notes.join('\n').contains(QStringLiteral("emissive:")));
        // Over the format's limit: left as it was, and said.
        LightMix huge;
        huge.groups[QStringLiteral("Fill")] = {true, 20.0, glm::dvec3(1.0)};
        rig.lights[2].intensity = 10.0;
        notes.clear();
        const Rig same = applyLightMix(rig, groups, huge, &notes);
        QCOMPARE(same.lights[2].intensity, 10.0);
        QVERIFY(notes.join('\n').contains(QStringLiteral("over the limit")));
    }
};

QTEST_GUILESS_MAIN(TestLightMix)
#include "tst_lightmix.moc"
