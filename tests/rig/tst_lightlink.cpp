// Issue 38: light and shadow linking in the rig format (core/rigjson_link.cpp) and its resolution into
// classes and per-light masks (core/lightlink.h), which every renderer reads.
#include "rigtest.h"

#include "core/lightlink.h"

#include <QTest>

using namespace lr;
using namespace lr::test;

namespace {

QByteArray rigJson3(const QByteArray& lights) {
    return R"({"format": "lightrig", "version": 3, "lights": [)" + lights + "]}";
}

PartNames part(const QString& node, const QString& mesh, const QString& material) {
    return PartNames::of(node, mesh, material);
}

PartNames ground() {
    return PartNames::theGround();
}

// Body (node), Stand (node, sharing Body's material "Paint"), Glass, and the ground.
std::vector<PartNames> parts() {
    return {part(QStringLiteral("Body"), QStringLiteral("body_mesh"), QStringLiteral("Paint")),
            part(QStringLiteral("Stand"), QStringLiteral("stand_mesh"), QStringLiteral("Paint")),
            part(QStringLiteral("Glass"), QStringLiteral("glass_mesh"), QStringLiteral("Glass")), ground()};
}

} // namespace

class TestLightLink : public QObject {
    Q_OBJECT
  private slots:
    void roundTripsByteForByte() {
        Rig rig;
        Light rim = makeLight(LightType::Rim, QStringLiteral("Rim"));
        rim.link.lit.include = {QStringLiteral("Body"), QStringLiteral("material:Glass")};
        Light key = makeLight(LightType::Spot, QStringLiteral("Key"));
        key.link.lit.exclude = {QStringLiteral("ground")};
        key.link.shadow.exclude = {QStringLiteral("Glass")};
        rig.lights = {rim, key, makeLight(LightType::Point, QStringLiteral("Fill"))};
        const QByteArray text = writeRigJson(rig);
        QVERIFY(text.contains("\"version\": 3"));
        QVERIFY2(text.contains(R"("link": {"include": ["Body", "material:Glass"]})"), text.constData());
        QVERIFY2(text.contains(R"("link": {"exclude": ["ground"], "shadow": {"exclude": ["Glass"]}})"),
                 text.constData());
        QCOMPARE(text.count("\"link\""), 2); // the unlinked light writes none
        const RigReadResult back = readRigJson(text, QStringLiteral("l.json"));
        LR_VERIFY_OK(back);
        for (std::size_t i = 0; i < rig.lights.size(); ++i)
            QVERIFY(back.rig->lights[i].link == rig.lights[i].link);
        QCOMPARE(writeRigJson(*back.rig), text);
    }

    void unlinkedRigsKeepTheirVersion() {
        Rig rig;
        rig.lights = {makeLight(LightType::Point, QStringLiteral("Key"))};
        QVERIFY(writeRigJson(rig).contains("\"version\": 1"));
        rig.lights[0].link.shadow.include = {QStringLiteral("Body")};
        QVERIFY(writeRigJson(rig).contains("\"version\": 3"));
    }

    void errorsNameTheFieldAndTheReason_data() {
        QTest::addColumn<QByteArray>("file");
        QTest::addColumn<QString>("message");
        QTest::newRow("older version") << rigJson2(with(kPoint, R"("link": {"include": ["A"]})"))
                                       << QStringLiteral("lights[0].link: links came with version 3");
        QTest::newRow("not an object") << rigJson3(with(kPoint, R"("link": ["A"])"))
                                       << QStringLiteral("lights[0].link: must be an object");
        QTest::newRow("not a list") << rigJson3(with(kPoint, R"("link": {"include": "A"})"))
                                    << QStringLiteral(
                                           "lights[0].link.include: must be an array of part names");
        QTest::newRow("not a string") << rigJson3(with(kPoint, R"("link": {"exclude": ["A", 2]})"))
                                      << QStringLiteral("lights[0].link.exclude[1]: must be a string");
        QTest::newRow("empty name") << rigJson3(with(kPoint, R"("link": {"include": [""]})"))
                                    << QStringLiteral("lights[0].link.include[0]: is empty");
        QTest::newRow("bare prefix")
            << rigJson3(with(kPoint, R"("link": {"shadow": {"include": ["material:"]}})"))
            << QStringLiteral("lights[0].link.shadow.include[0]: \"material:\" names nothing");
        QTest::newRow("shadow not an object") << rigJson3(with(kPoint, R"("link": {"shadow": true})"))
                                              << QStringLiteral("lights[0].link.shadow: must be an object");
    }
    void errorsNameTheFieldAndTheReason() {
        QFETCH(QByteArray, file);
        QFETCH(QString, message);
        const RigReadResult r = readRigJson(file, QStringLiteral("bad.json"));
        QVERIFY(!r.ok());
        QVERIFY2(hasMessage(r.errors, QStringLiteral("bad.json"), message), qPrintable(describe(r)));
    }

    void unknownKeysAndDuplicatesWarn() {
        const RigReadResult r =
            readRigJson(rigJson3(with(kPoint, R"("link": {"include": ["A", "A"], "incldue": ["B"]})")),
                        QStringLiteral("w.json"));
        QVERIFY2(r.ok(), qPrintable(describe(r)));
        QCOMPARE(r.rig->lights[0].link.lit.include, QStringList{QStringLiteral("A")});
        QVERIFY2(
            hasMessage(r.warnings, QStringLiteral("w.json"), QStringLiteral("lights[0].link.include[1]")),
            qPrintable(describe(r)));
        QVERIFY2(hasMessage(r.warnings, QStringLiteral("w.json"), QStringLiteral("lights[0].link.incldue")),
                 qPrintable(describe(r)));
    }

    void namesMatchNodeMeshOrMaterialAndPrefixesPickOne() {
        const PartNames body = parts()[0];
        QVERIFY(partNameMatches(QStringLiteral("Body"), body));
        QVERIFY(partNameMatches(QStringLiteral("body_mesh"), body));
        QVERIFY(partNameMatches(QStringLiteral("Paint"), body));
        QVERIFY(!partNameMatches(QStringLiteral("body"), body)); // case-sensitive
        QVERIFY(partNameMatches(QStringLiteral("node:Body"), body));
        QVERIFY(!partNameMatches(QStringLiteral("material:Body"), body));
        QVERIFY(!partNameMatches(QStringLiteral("ground"), body));
        QVERIFY(partNameMatches(QStringLiteral("ground"), ground()));
        QVERIFY(!partNameMatches(QStringLiteral("Body"), ground()));
        PartSet set;
        set.include = {QStringLiteral("Paint")};
        set.exclude = {QStringLiteral("Stand")};
        QVERIFY(partSetContains(set, parts()[0]));
        QVERIFY(!partSetContains(set, parts()[1])); // exclusion wins
        QVERIFY(!partSetContains(set, parts()[2])); // not included
    }

    void resolutionGivesEachLightThePartsItReaches() {
        std::vector<Light> lights(4);
        lights[0] = makeLight(LightType::Rim, QStringLiteral("Rim"));
        lights[0].link.lit.include = {QStringLiteral("Body")};
        lights[1] = makeLight(LightType::Spot, QStringLiteral("Key"));
        lights[1].link.shadow.exclude = {QStringLiteral("Glass")};
        lights[2] = makeLight(LightType::Point, QStringLiteral("Fill"));
        lights[2].link.lit.exclude = {QStringLiteral("ground"), QStringLiteral("Stand")};
        lights[3] = makeLight(LightType::Point, QStringLiteral("Plain"));
        const std::vector<PartNames> p = parts();
        const LinkResolution r = resolveLinks(lights, p);
        QVERIFY(r.active);
        QVERIFY(r.warnings.isEmpty());
        const bool lit[4][4] = {{1, 0, 0, 0}, {1, 1, 1, 1}, {1, 0, 1, 0}, {1, 1, 1, 1}};
        for (std::size_t l = 0; l < 4; ++l)
            for (std::size_t q = 0; q < p.size(); ++q) {
                QCOMPARE(r.lights(l, q), lit[l][q]);
                QCOMPARE(r.casts(l, q), !(l == 1 && q == 2));
            }
        // Body, Stand+ground, Glass: three lighting classes; Glass alone in its shadow class.
        QCOMPARE(r.litClasses, 3);
        QCOMPARE(r.shadowClasses, 2);
        QCOMPARE(r.litClass[1], r.litClass[3]);
        QCOMPARE(r.litMask[3], kAllLinkClasses);
    }

    void unlinkedRigsResolveInactive() {
        std::vector<Light> lights{makeLight(LightType::Point, QStringLiteral("Key"))};
        const LinkResolution r = resolveLinks(lights, parts());
        QVERIFY(!r.active);
        QVERIFY(r.lights(0, 2) && r.casts(0, 2));
    }

    void namesMatchingNothingAreKeptAndWarned() {
        std::vector<Light> lights{makeLight(LightType::Point, QStringLiteral("Key"))};
        lights[0].link.lit.include = {QStringLiteral("Visor"), QStringLiteral("Body")};
        const LinkResolution r = resolveLinks(lights, parts());
        QCOMPARE(r.warnings.size(), 1);
        QVERIFY2(r.warnings[0].contains(QStringLiteral("Key: link.include: \"Visor\" matches no part")),
                 qPrintable(r.warnings[0]));
        QVERIFY(r.lights(0, 0) && !r.lights(0, 1));
        const QStringList report = describeLinkMatches(lights, parts());
        QCOMPARE(report.size(), 2);
        QVERIFY2(report[1].contains(QStringLiteral("\"Body\": 1 part (Body)")),
                 qPrintable(report.join('\n')));
    }

    void moreSetsThanClassesFallBackToTheFirstWithAWarning() {
        // 6 lights each linked to a different subset: up to 64 signatures over 64 parts.
        std::vector<PartNames> many;
        for (int i = 0; i < 64; ++i)
            many.push_back(part(QStringLiteral("n%1").arg(i), {}, {}));
        std::vector<Light> lights(6);
        for (int b = 0; b < 6; ++b) {
            lights[size_t(b)] = makeLight(LightType::Point, QStringLiteral("L%1").arg(b));
            for (int i = 0; i < 64; ++i)
                if (i >> b & 1) lights[size_t(b)].link.lit.include << QStringLiteral("n%1").arg(i);
        }
        const LinkResolution r = resolveLinks(lights, many);
        QCOMPARE(r.litClasses, kMaxLinkClasses);
        QVERIFY(r.warnings.join('\n').contains(QStringLiteral("more than 32 sets of lights")));
        for (int i = 0; i < 32; ++i) // the first 32 parts are exact
            for (int b = 0; b < 6; ++b)
                QCOMPARE(r.lights(size_t(b), size_t(i)), bool(i >> b & 1));
    }
};

QTEST_GUILESS_MAIN(TestLightLink)
#include "tst_lightlink.moc"
