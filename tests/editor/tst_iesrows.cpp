// Issue 39: the IES rows of the light-property table (editor/lightproperty_ies.cpp): a profile set and
// cleared through the document (one undo step each), its other rows shown only while it has one, values
// checked, and the file resolved against the rig's folder for the renderers.
#include "rigfixture.h"

#include "editor/lightproperty.h"

#include <QDir>
#include <QTest>

using namespace lr;

class TestIesRows : public QObject {
    Q_OBJECT
  private slots:
    void setAndClearAProfile() {
        Document doc;
        Rig rig;
        rig.lights = {makeLight(LightType::Point, QStringLiteral("Key")),
                      makeLight(LightType::Directional, QStringLiteral("Sun"))};
        doc.newRig(rig);
        const LightPropertyInfo* file = lightPropertyInfo(LightProperty::IesFile);
        const LightPropertyInfo* mult = lightPropertyInfo(LightProperty::IesMultiplier);
        QVERIFY(file && mult);
        QVERIFY(file->applies(doc.rig().lights[0]));
        QVERIFY(!file->applies(doc.rig().lights[1])); // a directional light has none
        QVERIFY(!mult->isShown(doc.rig().lights[0])); // no profile yet
        QString error;
        QVERIFY2(doc.setLightValue({0}, LightProperty::IesFile, QStringLiteral("p/down.ies"), &error),
                 qPrintable(error));
        QVERIFY(doc.rig().lights[0].ies);
        QCOMPARE(doc.rig().lights[0].ies->file, QStringLiteral("p/down.ies"));
        QVERIFY(mult->isShown(doc.rig().lights[0]));
        QVERIFY(doc.setLightValue({0}, LightProperty::IesMultiplier, 2.5, &error));
        QVERIFY(doc.setLightValue({0}, LightProperty::IesLevel, 0, &error));
        QVERIFY(doc.setLightValue({0}, LightProperty::IesRotation, 45.0, &error));
        const IesSpec s = *doc.rig().lights[0].ies;
        QCOMPARE(s.multiplier, 2.5);
        QVERIFY(s.level == IesLevel::Profile);
        QCOMPARE(s.rotation, 45.0);
        QVERIFY(!doc.setLightValue({0}, LightProperty::IesMultiplier, -1.0, &error));
        QVERIFY(!doc.setLightValue({0}, LightProperty::IesLevel, 7, &error));
        // The renderers get the file resolved (untitled: against the current folder).
        QCOMPARE(doc.renderRig().lights[0].ies->resolved,
                 QDir::current().absoluteFilePath(QStringLiteral("p/down.ies")));
        // Cleared: no profile; undo brings it back with its values.
        QVERIFY(doc.setLightValue({0}, LightProperty::IesFile, QString(), &error));
        QVERIFY(!doc.rig().lights[0].ies);
        doc.undoStack()->undo();
        QVERIFY(doc.rig().lights[0].ies && doc.rig().lights[0].ies->multiplier == 2.5);
    }

    // A point light's nadir (its direction) is edited while it has a profile; a spot's is its Direction row,
    // so the nadir row does not apply to it. The nadir is normalised, and zero is refused.
    void aPointLightsNadirIsItsDirection() {
        Document doc;
        Rig rig;
        rig.lights = {makeLight(LightType::Point, QStringLiteral("Down")),
                      makeLight(LightType::Spot, QStringLiteral("Spot"))};
        doc.newRig(rig);
        const LightPropertyInfo* nadir = lightPropertyInfo(LightProperty::IesNadir);
        QVERIFY(nadir && nadir->applies(doc.rig().lights[0]) && !nadir->applies(doc.rig().lights[1]));
        QVERIFY(!nadir->isShown(doc.rig().lights[0])); // no profile yet
        QString error;
        QVERIFY(doc.setLightValue({0}, LightProperty::IesFile, QStringLiteral("down.ies"), &error));
        QVERIFY(nadir->isShown(doc.rig().lights[0]));
        QVERIFY2(doc.setLightValue({0}, LightProperty::IesNadir,
                                   QVariant::fromValue(glm::dvec3(0.0, 0.0, -2.0)), &error),
                 qPrintable(error));
        QCOMPARE(doc.rig().lights[0].direction, glm::dvec3(0.0, 0.0, -1.0));
        QVERIFY(
            !doc.setLightValue({0}, LightProperty::IesNadir, QVariant::fromValue(glm::dvec3(0.0)), &error));
        QVERIFY2(error.contains(QStringLiteral("must not be zero")), qPrintable(error));
        QCOMPARE(doc.rig().lights[0].direction, glm::dvec3(0.0, 0.0, -1.0));
    }
};

QTEST_GUILESS_MAIN(TestIesRows)
#include "tst_iesrows.moc"
