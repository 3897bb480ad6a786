// Issue 39: a rect light's "barnDoors" in the rig format (core/rigjson_barndoors.cpp): read, written
// canonically and back, format version 4 (an older reader would light the whole spill), every error with its
// path.
#include "rigtest.h"

#include <QTest>

using namespace lr;
using namespace lr::test;

namespace {

QByteArray rigJson4(const QByteArray& lights) {
    return R"({"format": "lightrig", "version": 4, "lights": [)" + lights + "]}";
}

} // namespace

class TestBarnDoorsJson : public QObject {
    Q_OBJECT
  private slots:
    void readsAngleAndLength() {
        const RigReadResult r =
            readRigJson(rigJson4(with(kRect, R"("barnDoors": {"angle": 45, "length": 0.3})")), "b.json");
        LR_VERIFY_OK(r);
        QVERIFY(r.rig->lights[0].barnDoors.has_value());
        QCOMPARE(r.rig->lights[0].barnDoors->angle, 45.0);
        QCOMPARE(r.rig->lights[0].barnDoors->length, 0.3);
        // Keys left out take UE's angle and the rig's default length.
        const RigReadResult d = readRigJson(rigJson4(with(kRect, R"("barnDoors": {})")), "b.json");
        LR_VERIFY_OK(d);
        LR_COMPARE(*d.rig->lights[0].barnDoors, BarnDoors{});
        // No key: no barn doors.
        const RigReadResult none = readRigJson(rigJson4(kRect), "b.json");
        LR_VERIFY_OK(none);
        QVERIFY(!none.rig->lights[0].barnDoors);
    }

    void roundTripsAndSaysVersion4() {
        Rig rig;
        Light softbox = makeLight(LightType::Rect, QStringLiteral("Softbox"));
        softbox.barnDoors = BarnDoors{30.0, 0.25};
        rig.lights = {softbox, makeLight(LightType::Rect, QStringLiteral("Plain"))};
        const QByteArray text = writeRigJson(rig);
        QVERIFY2(text.contains("\"version\": 4"), text.constData());
        QVERIFY2(text.contains(R"("barnDoors": {"angle": 30, "length": 0.25})"), text.constData());
        QCOMPARE(text.count("barnDoors"), 1);
        const RigReadResult back = readRigJson(text, "b.json");
        LR_VERIFY_OK(back);
        QVERIFY(back.rig->lights[0].barnDoors == softbox.barnDoors);
        QVERIFY(!back.rig->lights[1].barnDoors);
        QCOMPARE(writeRigJson(*back.rig), text);
        // Without barn doors the rig keeps its older version, byte for byte.
        rig.lights[0].barnDoors.reset();
        QVERIFY(writeRigJson(rig).contains("\"version\": 2"));
    }

    void refusesBadValues_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("message");
        const auto row = [](const char* name, const QByteArray& json, const char* message) {
            QTest::newRow(name) << json << QString::fromUtf8(message);
        };
        row("older version", rigJson2(with(kRect, R"("barnDoors": {"angle": 45})")),
            "lights[0].barnDoors: barn doors came with version 4 of the format, but the file says "
            "\"version\": 2");
        row("angle over 90", rigJson4(with(kRect, R"("barnDoors": {"angle": 91})")),
            "lights[0].barnDoors.angle: must be");
        row("negative angle", rigJson4(with(kRect, R"("barnDoors": {"angle": -1})")),
            "lights[0].barnDoors.angle: must be");
        row("negative length", rigJson4(with(kRect, R"("barnDoors": {"length": -0.1})")),
            "lights[0].barnDoors.length: must be");
        row("length not a number", rigJson4(with(kRect, R"("barnDoors": {"length": "long"})")),
            "lights[0].barnDoors.length: must be");
        row("not an object", rigJson4(with(kRect, R"("barnDoors": 45)")), "lights[0].barnDoors: must be");
        row("on a disk", rigJson4(with(kDisk, R"("barnDoors": {"angle": 45})")),
            "lights[0].barnDoors: a disk light has no barn doors");
        row("on a spot", rigJson4(with(kSpot, R"("barnDoors": {"angle": 45})")),
            "lights[0].barnDoors: a spot light has no barn doors");
    }
    void refusesBadValues() {
        QFETCH(QByteArray, json);
        QFETCH(QString, message);
        const RigReadResult r = readRigJson(json, "b.json");
        QVERIFY2(!r.ok(), qPrintable(describe(r)));
        QVERIFY2(hasMessage(r.errors, "b.json", message), qPrintable(describe(r)));
    }

    void warnsAboutUnknownKeys() {
        const RigReadResult r =
            readRigJson(rigJson4(with(kRect, R"("barnDoors": {"angle": 45, "lenght": 0.3})")), "b.json");
        QVERIFY(r.ok());
        QVERIFY2(hasMessage(r.warnings, "b.json", "lights[0].barnDoors.lenght"), qPrintable(describe(r)));
    }
};

QTEST_GUILESS_MAIN(TestBarnDoorsJson)
#include "tst_barndoorsjson.moc"
