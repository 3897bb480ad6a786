// Issue 39: what `render` says about a rig's light shaping before it renders (scene/shapingreport.h): a file
// that does not load is named with its field, and the raster's missing IES and gobo shaping is said per light
// (never for the path tracer, which shapes them, nor for a disabled light or a rig without shaping).
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
        QVERIFY(shapingWarnings(rig, false).isEmpty());
        QVERIFY(shapingWarnings(rig, true).isEmpty());
    }

    void theRasterSaysItDrawsAnIesLightUnshaped() {
        Rig rig;
        rig.lights.push_back(makeLight(LightType::Point, QStringLiteral("Fill")));
        rig.lights.push_back(spotWithIes(QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies")));
        const QStringList raster = shapingWarnings(rig, false);
        QCOMPARE(raster.size(), 1);
        QVERIFY2(raster[0].startsWith(QStringLiteral("lights[1] (Key): ")), qPrintable(raster[0]));
        QVERIFY2(raster[0].contains(QStringLiteral("IES profile")), qPrintable(raster[0]));
        QVERIFY(shapingWarnings(rig, true).isEmpty()); // the path tracer shapes it
        rig.lights[1].enabled = false;
        QVERIFY(shapingWarnings(rig, false).isEmpty());
    }

    void aFileThatDoesNotLoadIsNamedWithItsField() {
        Rig rig;
        rig.lights.push_back(spotWithIes(QStringLiteral(LIGHTRIG_TEST_DATA "/ies/truncated.ies")));
        rig.lights.push_back(spotWithIes(QStringLiteral("/nonexistent/nothing.ies")));
        for (const bool traced : {false, true}) {
            const QStringList w = shapingWarnings(rig, traced);
            QCOMPARE(w.size(), 2); // the files' errors only: an unshaped light has nothing to warn of
            QVERIFY2(w[0].startsWith(QStringLiteral("lights[0].ies.file: ")) &&
                         w[0].contains("truncated.ies"),
                     qPrintable(w[0]));
            QVERIFY2(w[1].startsWith(QStringLiteral("lights[1].ies.file: ")) && w[1].contains("nothing.ies"),
                     qPrintable(w[1]));
        }
    }
};

QTEST_GUILESS_MAIN(TestShapingReport)
#include "tst_shapingreport.moc"
