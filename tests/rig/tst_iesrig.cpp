// Issue 39: a light's "ies" in the rig format (core/rigjson_ies.cpp): read, written canonically, resolved
// against the rig's folder, only on point and spot lights, only from format version 4.
#include "rigtest.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;
using namespace lr::test;

namespace {

QByteArray rigJson4(const QByteArray& lights) {
    return R"({"format": "lightrig", "version": 4, "lights": [)" + lights + "]}";
}

} // namespace

class TestIesRig : public QObject {
    Q_OBJECT
  private slots:
    void readWriteRoundTrip() {
        const RigReadResult r = readRigJson(
            rigJson4(with(kSpot, R"("ies": {"file": "p/down.ies", "multiplier": 2.5, "level": "profile",
                          "rotation": -90})") +
                     ", " + with(kPoint, R"("ies": {"file": "/abs/x.ies"})")),
            QStringLiteral("r.json"));
        LR_VERIFY_OK(r);
        const IesSpec& s = *r.rig->lights[0].ies;
        QCOMPARE(s.file, QStringLiteral("p/down.ies"));
        QCOMPARE(s.multiplier, 2.5);
        QVERIFY(s.level == IesLevel::Profile);
        QCOMPARE(s.rotation, 270.0);
        const IesSpec& d = *r.rig->lights[1].ies; // defaults
        QCOMPARE(d.multiplier, 1.0);
        QVERIFY(d.level == IesLevel::Light);
        QCOMPARE(d.rotation, 0.0);
        const QByteArray text = writeRigJson(*r.rig);
        QVERIFY2(text.contains(R"("ies": {"file": "p/down.ies", "multiplier": 2.5, "level": "profile", )"
                               R"("rotation": 270})"),
                 text.constData());
        QVERIFY(text.contains("\"version\": 4"));
        const RigReadResult back = readRigJson(text, QStringLiteral("back.json"));
        LR_VERIFY_OK(back);
        QVERIFY(back.rig->lights[0].ies == r.rig->lights[0].ies);
        QCOMPARE(writeRigJson(*back.rig), text);
    }

    void aPointLightsProfileLooksAlongItsDirection() {
        const RigReadResult r =
            readRigJson(rigJson4(with(kPoint, R"("direction": [1, 0, 0], "ies": {"file": "a.ies"})")),
                        QStringLiteral("r.json"));
        LR_VERIFY_OK(r);
        QCOMPARE(r.rig->lights[0].direction, glm::dvec3(1.0, 0.0, 0.0));
        QVERIFY(writeRigJson(*r.rig).contains(R"("direction": [1, 0, 0])"));
        const RigReadResult none =
            readRigJson(rigJson4(with(kPoint, R"("direction": [1, 0, 0])")), QStringLiteral("n.json"));
        QVERIFY(!none.ok()); // without a profile a point light has no direction
    }

    void rigsWithoutProfilesKeepTheirVersion() {
        Rig rig;
        rig.lights = {makeLight(LightType::Point, QStringLiteral("Key"))};
        QVERIFY(writeRigJson(rig).contains("\"version\": 1"));
        QVERIFY(!writeRigJson(rig).contains("\"ies\""));
        rig.lights[0].ies = IesSpec{QStringLiteral("a.ies")};
        QVERIFY(writeRigJson(rig).contains("\"version\": 4"));
    }

    void fileIsResolvedAgainstTheRigsFolder() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("rig.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(rigJson4(with(kPoint, R"("ies": {"file": "profiles/../down.ies"})")));
        f.close();
        const RigReadResult r = readRigFile(path);
        LR_VERIFY_OK(r);
        QCOMPARE(r.rig->lights[0].ies->file, QStringLiteral("profiles/../down.ies")); // written as it was
        QCOMPARE(r.rig->lights[0].ies->resolved, QDir(dir.path()).filePath(QStringLiteral("down.ies")));
    }

    void errorsNameTheFieldAndTheReason_data() {
        QTest::addColumn<QByteArray>("file");
        QTest::addColumn<QString>("message");
        QTest::newRow("older version") << rigJson2(with(kPoint, R"("ies": {"file": "a.ies"})"))
                                       << QStringLiteral("lights[0].ies: IES profiles came with version 4");
        QTest::newRow("directional") << rigJson4(with(kDirectional, R"("ies": {"file": "a.ies"})"))
                                     << QStringLiteral(
                                            "lights[0].ies: a directional light has no IES profile");
        QTest::newRow("rect") << rigJson4(with(kRect, R"("ies": {"file": "a.ies"})"))
                              << QStringLiteral("lights[0].ies: a rect light has no IES profile");
        QTest::newRow("no file") << rigJson4(with(kPoint, R"("ies": {"multiplier": 2})"))
                                 << QStringLiteral("lights[0].ies.file: missing");
        QTest::newRow("empty file") << rigJson4(with(kPoint, R"("ies": {"file": ""})"))
                                    << QStringLiteral("lights[0].ies.file: must not be empty");
        QTest::newRow("not an object") << rigJson4(with(kPoint, R"("ies": "a.ies")"))
                                       << QStringLiteral("lights[0].ies: must be an object");
        QTest::newRow("negative multiplier")
            << rigJson4(with(kPoint, R"("ies": {"file": "a.ies", "multiplier": -1})"))
            << QStringLiteral("lights[0].ies.multiplier: must be");
        QTest::newRow("bad level") << rigJson4(with(kPoint, R"("ies": {"file": "a.ies", "level": "lamp"})"))
                                   << QStringLiteral("lights[0].ies.level: must be \"light\"");
    }

    void errorsNameTheFieldAndTheReason() {
        QFETCH(QByteArray, file);
        QFETCH(QString, message);
        const RigReadResult r = readRigJson(file, QStringLiteral("e.json"));
        QVERIFY(!r.ok());
        QVERIFY2(hasMessage(r.errors, QStringLiteral("e.json"), message), qPrintable(describe(r)));
    }
};

QTEST_GUILESS_MAIN(TestIesRig)
#include "tst_iesrig.moc"
