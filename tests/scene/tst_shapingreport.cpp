// Issue 39: what `render` says about a rig's light shaping before it renders (scene/shapingreport.h): a file
// that does not load is named with its field; a rig whose files load, or without shaping, says nothing.
#include "core/rig.h"
#include "scene/shapingreport.h"

#include <QTest>

using namespace lr;

class TestShapingReport : public QObject {
    Q_OBJECT

    static Light spotWithIes(const QString& file) {
        Light l = makeLight(LightType::Spot, QStringLiteral("Key"));
        l.ies = IesSpec{};
        l.ies->file = file;
        return l;
    }

  private slots:
    void aRigWithoutShapingSaysNothing() {
        Rig rig;
        rig.lights.push_back(makeLight(LightType::Spot, QStringLiteral("Key")));
        QVERIFY(shapingWarnings(rig).isEmpty());
    }

    void aProfileThatLoadsSaysNothing() { // every renderer shapes it
        Rig rig;
        rig.lights.push_back(makeLight(LightType::Point, QStringLiteral("Fill")));
        rig.lights.push_back(spotWithIes(QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies")));
        QVERIFY(shapingWarnings(rig).isEmpty());
    }

    void aFileThatDoesNotLoadIsNamedWithItsField() {
        Rig rig;
        rig.lights.push_back(spotWithIes(QStringLiteral(LIGHTRIG_TEST_DATA "/ies/truncated.ies")));
        rig.lights.push_back(spotWithIes(QStringLiteral("/nonexistent/nothing.ies")));
        const QStringList w = shapingWarnings(rig);
        QCOMPARE(w.size(), 2);
        QVERIFY2(w[0].startsWith(QStringLiteral("lights[0].ies.file: ")) && w[0].contains("truncated.ies"),
                 qPrintable(w[0]));
        QVERIFY2(w[1].startsWith(QStringLiteral("lights[1].ies.file: ")) && w[1].contains("nothing.ies"),
                 qPrintable(w[1]));
    }
};

QTEST_GUILESS_MAIN(TestShapingReport)
#include "tst_shapingreport.moc"
