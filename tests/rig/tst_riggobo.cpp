// Issue 39: a spot's "gobo" in the rig file (core/rigjson_gobo.cpp): read, written back byte for byte,
// version 4 required and written, only on spots, and every bad value named with its field and reason.
#include "core/rigjson.h"
#include "rigtest.h"

#include <QTest>

using namespace lr;
using namespace lr::test;

namespace {

QByteArray rigJson4(const QByteArray& lights) {
    return R"({"format": "lightrig", "version": 4, "lights": [)" + lights + "]}";
}

} // namespace

class TestRigGobo : public QObject {
    Q_OBJECT
  private slots:
    void readsAndWritesBack() {
        const RigReadResult r = readRigJson(
            rigJson4(with(kSpot, R"("gobo": {"file": "gobos/window.png", "scale": 0.5, "rotation": 30})")),
            QStringLiteral("g.json"));
        QVERIFY2(r.ok(), qPrintable(describe(r)));
        const Light& l = r.rig->lights[0];
        QVERIFY(l.gobo);
        QCOMPARE(l.gobo->file, QStringLiteral("gobos/window.png"));
        QCOMPARE(l.gobo->scale, 0.5);
        QCOMPARE(l.gobo->rotation, 30.0);
        const QByteArray text = writeRigJson(*r.rig);
        QVERIFY(text.contains("\"version\": 4"));
        QVERIFY(text.contains(R"("gobo": {"file": "gobos/window.png", "scale": 0.5, "rotation": 30})"));
        const RigReadResult back = readRigJson(text, QStringLiteral("back.json"));
        QVERIFY2(back.ok(), qPrintable(describe(back)));
        QVERIFY(back.rig->lights[0].gobo == l.gobo);
        QCOMPARE(writeRigJson(*back.rig), text);
    }
    void defaultsAndNoGoboKeepTheVersion() {
        const RigReadResult r =
            readRigJson(rigJson4(with(kSpot, R"("gobo": {"file": "a.exr"})")), QStringLiteral("g.json"));
        QVERIFY2(r.ok(), qPrintable(describe(r)));
        QCOMPARE(r.rig->lights[0].gobo->scale, 1.0);
        QCOMPARE(r.rig->lights[0].gobo->rotation, 0.0);
        Rig rig = *r.rig;
        rig.lights[0].gobo.reset();
        QVERIFY(writeRigJson(rig).contains("\"version\": 1")); // a spot without a gobo stays version 1
    }
    void errorsNameTheFieldAndTheReason_data() {
        QTest::addColumn<QByteArray>("file");
        QTest::addColumn<QString>("message");
        QTest::newRow("older version") << rigJson(with(kSpot, R"("gobo": {"file": "a.png"})"))
                                       << QStringLiteral("lights[0].gobo: gobos came with version 4");
        QTest::newRow("not a spot") << rigJson4(with(kPoint, R"("gobo": {"file": "a.png"})"))
                                    << QStringLiteral("lights[0].gobo: only spot lights have a gobo");
        QTest::newRow("no file") << rigJson4(with(kSpot, R"("gobo": {"scale": 2})"))
                                 << QStringLiteral("lights[0].gobo.file: missing");
        QTest::newRow("empty file") << rigJson4(with(kSpot, R"("gobo": {"file": ""})"))
                                    << QStringLiteral("lights[0].gobo.file: must not be empty");
        QTest::newRow("file a number") << rigJson4(with(kSpot, R"("gobo": {"file": 3})"))
                                       << QStringLiteral("lights[0].gobo.file: must be a file name");
        QTest::newRow("scale 0") << rigJson4(with(kSpot, R"("gobo": {"file": "a.png", "scale": 0})"))
                                 << QStringLiteral("lights[0].gobo.scale: ");
        QTest::newRow("rotation 400")
            << rigJson4(with(kSpot, R"("gobo": {"file": "a.png", "rotation": 400})"))
            << QStringLiteral("lights[0].gobo.rotation: ");
        QTest::newRow("not an object") << rigJson4(with(kSpot, R"("gobo": "a.png")"))
                                       << QStringLiteral("lights[0].gobo: must be an object");
    }
    void errorsNameTheFieldAndTheReason() {
        QFETCH(QByteArray, file);
        QFETCH(QString, message);
        const RigReadResult r = readRigJson(file, QStringLiteral("bad.json"));
        QVERIFY(!r.ok());
        QVERIFY2(hasMessage(r.errors, QStringLiteral("bad.json"), message), qPrintable(describe(r)));
    }
    void filesResolveAgainstTheRigFolder() {
        Rig rig;
        Light l;
        l.type = LightType::Spot;
        l.gobo = GoboSpec{QStringLiteral("gobos/a.png"), {}, 1.0, 0.0};
        rig.lights.push_back(l);
        resolveLightFiles(rig, QStringLiteral("/rigs/studio"));
        QCOMPARE(rig.lights[0].gobo->resolved, QStringLiteral("/rigs/studio/gobos/a.png"));
    }
};

QTEST_APPLESS_MAIN(TestRigGobo)
#include "tst_riggobo.moc"
