// Issue 41 item 16: the rig's camera "view" and its named "views" (docs/rig-format.md): read and written
// canonically (a round trip is exact), every bad value reported with its path and reason, rigs without them
// load as before, and `lightrig validate` / `format` check and keep them.
#include "rigtest.h"
#include "support/cli.h"

#include <QTemporaryDir>

using namespace lr;
using namespace lr::test;

namespace {
const QByteArray kView = R"("view": {"eye": [0, 1, 5], "target": [0, 0.5, 0], "up": [0, 1, 0], "yfov": 35},)";
const QByteArray kViews =
    R"("views": [{"name": "Front", "eye": [0, 0, 4], "target": [0, 0, 0]},)"
    R"({"name": "Top", "eye": [0, 6, 0.001], "target": [0, 0, 0], "up": [0, 0, -1], "yfov": 50}],)";
} // namespace

class TestRigViews : public QObject {
    Q_OBJECT
  private slots:
    void readsViewAndViews() {
        const RigReadResult r = readRigJson(rigJson(kPoint, kView + kViews), QStringLiteral("a.json"));
        LR_VERIFY_OK(r);
        QVERIFY(r.warnings.isEmpty());
        QVERIFY(r.rig->view.has_value());
        QVERIFY(r.rig->view->name.isEmpty());
        QVERIFY(r.rig->view->eye == glm::dvec3(0, 1, 5));
        QVERIFY(r.rig->view->target == glm::dvec3(0, 0.5, 0));
        QCOMPARE(r.rig->view->yfovDeg, 35.0);
        QCOMPARE(r.rig->views.size(), size_t(2));
        QCOMPARE(r.rig->views[0].name, QStringLiteral("Front"));
        QVERIFY(r.rig->views[0].up == glm::dvec3(0, 1, 0)); // the defaults
        QCOMPARE(r.rig->views[0].yfovDeg, 45.0);
        QVERIFY(r.rig->views[1].up == glm::dvec3(0, 0, -1));
    }

    void oldRigsHaveNoView() {
        const RigReadResult r = readRigJson(rigJson(kPoint), QStringLiteral("old.json"));
        LR_VERIFY_OK(r);
        QVERIFY(!r.rig->view);
        QVERIFY(r.rig->views.empty());
        const QByteArray text = writeRigJson(*r.rig);
        QVERIFY(!text.contains("\"view\"") && !text.contains("\"views\"")); // and none is written
    }

    void roundTripIsExact() {
        const RigReadResult r = readRigJson(rigJson(kPoint, kView + kViews), QStringLiteral("a.json"));
        LR_VERIFY_OK(r);
        const QByteArray text = writeRigJson(*r.rig);
        QVERIFY2(text.contains(
                     R"("view": {"eye": [0, 1, 5], "target": [0, 0.5, 0], "up": [0, 1, 0], "yfov": 35})"),
                 text.constData());
        QVERIFY2(text.contains(R"({"name": "Front", "eye": [0, 0, 4])"), text.constData());
        const RigReadResult again = readRigJson(text, QStringLiteral("b.json"));
        LR_VERIFY_OK(again);
        LR_COMPARE(*again.rig, *r.rig);
        QCOMPARE(writeRigJson(*again.rig), text);
    }

    void badValuesNameTheField_data() {
        QTest::addColumn<QByteArray>("extra");
        QTest::addColumn<QString>("message");
        QTest::newRow("view not an object") << QByteArray(R"("view": 3,)") << QStringLiteral("view: must be");
        QTest::newRow("eye missing") << QByteArray(R"("view": {"target": [0, 0, 0]},)")
                                     << QStringLiteral("view.eye: missing");
        QTest::newRow("eye is target") << QByteArray(R"("view": {"eye": [1, 1, 1], "target": [1, 1, 1]},)")
                                       << QStringLiteral("view.target: must differ from \"eye\"");
        QTest::newRow("eye too far") << QByteArray(R"("view": {"eye": [2e12, 0, 0], "target": [0, 0, 0]},)")
                                     << QStringLiteral("view.eye[0]: must be a finite number");
        QTest::newRow("up along the view")
            << QByteArray(R"("view": {"eye": [0, 5, 0], "target": [0, 0, 0], "up": [0, 1, 0]},)")
            << QStringLiteral("view.up: must not be parallel");
        QTest::newRow("up zero")
            << QByteArray(R"("view": {"eye": [0, 0, 5], "target": [0, 0, 0], "up": [0, 0, 0]},)")
            << QStringLiteral("view.up: ");
        QTest::newRow("fov 0") << QByteArray(R"("view": {"eye": [0, 0, 5], "target": [0, 0, 0], "yfov": 0},)")
                               << QStringLiteral("view.yfov: must be a finite number > 0 and <= 170");
        QTest::newRow("fov 180") << QByteArray(
                                        R"("view": {"eye": [0, 0, 5], "target": [0, 0, 0], "yfov": 180},)")
                                 << QStringLiteral("view.yfov: ");
        QTest::newRow("views not an array")
            << QByteArray(R"("views": {},)") << QStringLiteral("views: must be");
        QTest::newRow("view without a name")
            << QByteArray(R"("views": [{"eye": [0, 0, 5], "target": [0, 0, 0]}],)")
            << QStringLiteral("views[0].name: missing");
        QTest::newRow("empty name")
            << QByteArray(R"("views": [{"name": " ", "eye": [0, 0, 5], "target": [0, 0, 0]}],)")
            << QStringLiteral("views[0].name: must not be empty");
        QTest::newRow("same name twice")
            << QByteArray(R"("views": [{"name": "A", "eye": [0, 0, 5], "target": [0, 0, 0]},)"
                          R"({"name": "A", "eye": [0, 0, 6], "target": [0, 0, 0]}],)")
            << QStringLiteral("views[1].name: \"A\" is the name of an earlier view");
    }
    void badValuesNameTheField() {
        QFETCH(QByteArray, extra);
        QFETCH(QString, message);
        const RigReadResult r = readRigJson(rigJson(kPoint, extra), QStringLiteral("bad.json"));
        QVERIFY(!r.ok());
        QVERIFY2(hasMessage(r.errors, QStringLiteral("bad.json"), message), qPrintable(describe(r)));
    }

    void tooManyViews() {
        QByteArray views = R"("views": [)";
        for (int i = 0; i <= kMaxRigViews; ++i)
            views += (i ? "," : "") + QByteArray("{\"name\": \"V") + QByteArray::number(i) +
                     "\", \"eye\": [0, 0, 5], \"target\": [0, 0, 0]}";
        const RigReadResult r = readRigJson(rigJson(kPoint, views + "],"), QStringLiteral("many.json"));
        QVERIFY(!r.ok());
        QVERIFY2(
            hasMessage(r.errors, QStringLiteral("many.json"), QStringLiteral("views: 65 views; at most 64")),
            qPrintable(describe(r)));
    }

    // `lightrig validate` reports a bad view with the file, the field and the reason; `format` keeps views.
    void validateAndFormat() {
        QVERIFY2(QFile::exists(QStringLiteral(LIGHTRIG_EXECUTABLE)), LIGHTRIG_EXECUTABLE);
        QTemporaryDir dir;
        const QString bad = dir.filePath(QStringLiteral("bad.json"));
        const QString good = dir.filePath(QStringLiteral("good.json"));
        QFile b(bad), g(good);
        QVERIFY(b.open(QIODevice::WriteOnly) && g.open(QIODevice::WriteOnly));
        b.write(rigJson(kPoint, R"("view": {"eye": [1, 1, 1], "target": [1, 1, 1]},)"));
        g.write(rigJson(kPoint, kView + kViews));
        b.close();
        g.close();
        const lrtest::CliRun v = lrtest::runLightrig({QStringLiteral("validate"), good, bad}, nullptr, 30000);
        QVERIFY2(v.code == 1, qPrintable(v.show()));
        QVERIFY2(v.lines().contains(good + QStringLiteral(": ok")), qPrintable(v.show()));
        bool named = false;
        for (const QString& line : v.lines())
            named = named || line.startsWith(bad + QStringLiteral(": view.target: must differ"));
        QVERIFY2(named, qPrintable(v.show()));
        const lrtest::CliRun f = lrtest::runLightrig({QStringLiteral("format"), good}, nullptr, 30000);
        QVERIFY2(f.code == 0, qPrintable(f.show()));
        const RigReadResult formatted = readRigFile(good);
        LR_VERIFY_OK(formatted);
        QVERIFY(formatted.rig->view.has_value());
        QCOMPARE(formatted.rig->views.size(), size_t(2));
        QCOMPARE(formatted.rig->views[1].name, QStringLiteral("Top"));
    }
};

QTEST_GUILESS_MAIN(TestRigViews)
#include "tst_rigviews.moc"
