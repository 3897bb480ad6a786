// Issue 39 (and 38): LightRig's extras.lightrig on a glTF's light nodes, which `lightrig export` writes,
// read back by the import (model/gltflightextras.cpp) with the rig's own readers: a spot's gobo (its file
// resolved against the glTF's folder) and a light's link come back; barn doors, written for a rect light
// whose glTF stand-in is a spot, cannot (warned); bad values are the rig reader's errors with the glTF's
// JSON path, and leave the rest of the node's extras and the light itself in place.
#include "gltflightfixtures.h"

#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;
using lr::test::lightNamed;
using lr::test::nodeNamed;
using lr::test::setIn;
using lr::test::warningWith;

namespace {

LightLink someLink() {
    LightLink link;
    link.lit.include = {QStringLiteral("child"), QStringLiteral("material:paint")};
    link.shadow.exclude = {QStringLiteral("mirror")};
    return link;
}

// "Spot" with a gobo and a link, "Box" a rect softbox with barn doors, "Bulb" a point light with a link.
Rig rigWithExtras() {
    Rig rig;
    rig.shading.model = ShadingModel::Pbr;
    Light spot = makeLight(LightType::Spot, QStringLiteral("Spot"));
    spot.position = {0.0, 4.0, 1.0};
    spot.direction = {0.0, -1.0, 0.0};
    spot.gobo = GoboSpec{QStringLiteral("gobos/window.png"), {}, 1.5, 20.0};
    spot.link = someLink();
    Light box = makeLight(LightType::Rect, QStringLiteral("Box"));
    box.position = {2.0, 2.0, 0.0};
    box.direction = {-1.0, 0.0, 0.0};
    box.barnDoors = BarnDoors{45.0, 0.3};
    Light bulb = makeLight(LightType::Point, QStringLiteral("Bulb"));
    bulb.link.lit.exclude = {QStringLiteral("mirror")};
    rig.lights = {spot, box, bulb};
    return rig;
}

} // namespace

class TestGltfLightExtrasImport : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_gobo;

    std::shared_ptr<Model> load(const QString& name, const QJsonObject& root) {
        const QString path = m_dir.filePath(name + QStringLiteral(".gltf"));
        if (!test::writeJson(path, root)) return nullptr;
        ModelLoadResult r = loadModel(path);
        if (!r.ok()) qWarning("%s", qPrintable(r.error));
        return r.model;
    }

  private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("gobos")));
        m_gobo = m_dir.filePath(QStringLiteral("gobos/window.png"));
        QVERIFY(QFile::copy(QStringLiteral(LIGHTRIG_TEST_DATA "/model/checker.png"), m_gobo));
    }

    void goboAndLinkComeBack() {
        const std::shared_ptr<Model> m = load(QStringLiteral("extras"), test::exportedScene(rigWithExtras()));
        QVERIFY(m);
        const QString warnings = m->warnings.join(QLatin1Char('\n'));
        const Light* spot = lightNamed(*m, QStringLiteral("Spot"));
        QVERIFY2(spot, qPrintable(warnings));
        QVERIFY(spot->type == LightType::Spot);
        QVERIFY2(spot->gobo, qPrintable(warnings));
        QCOMPARE(spot->gobo->file, QFileInfo(m_gobo).absoluteFilePath()); // against the glTF's folder
        QCOMPARE(spot->gobo->scale, 1.5);
        QCOMPARE(spot->gobo->rotation, 20.0);
        QCOMPARE(spot->link, someLink());
        const Light* bulb = lightNamed(*m, QStringLiteral("Bulb"));
        QVERIFY(bulb);
        QCOMPARE(bulb->link.lit.exclude, QStringList{QStringLiteral("mirror")});
        QVERIFY(bulb->link.lit.include.isEmpty());
    }

    void barnDoorsOfARectStandInAreNamedNotApplied() {
        QJsonObject root = test::exportedScene(rigWithExtras());
        const int node = nodeNamed(root, QStringLiteral("Box"));
        QVERIFY(node >= 0);
        const QString at = QStringLiteral("nodes[%1].extras.lightrig").arg(node);
        // As exported: the stand-in spot's innerConeAngle is 0 (glTF's default), imported as the smallest
        // inner angle the rig's smooth cone takes; its barn doors are named as ignored.
        std::shared_ptr<Model> m = load(QStringLiteral("barn"), root);
        QVERIFY(m);
        const Light* box = lightNamed(*m, QStringLiteral("Box"));
        QVERIFY2(box, qPrintable(m->warnings.join(QLatin1Char('\n'))));
        QVERIFY(box->cone.inner > 0.0 && box->cone.inner <= 1e-3);
        QVERIFY(box->type == LightType::Spot); // glTF has no area lights: the export's stand-in
        QVERIFY(!box->barnDoors);
        const QString w =
            warningWith(*m, {QStringLiteral("barn.gltf: ") + at + QStringLiteral(".barnDoors: ignored"),
                             QStringLiteral("stands in for")});
        QVERIFY2(!w.isEmpty(), qPrintable(m->warnings.join(QLatin1Char('\n'))));
    }

    void badGoboIsTheRigReadersErrorAndTheLinkStays() {
        QJsonObject root = test::exportedScene(rigWithExtras());
        const int node = nodeNamed(root, QStringLiteral("Spot"));
        QVERIFY(node >= 0);
        setIn(root, {"nodes", QString::number(node), "extras", "lightrig", "gobo", "scale"}, 500);
        const std::shared_ptr<Model> m = load(QStringLiteral("badgobo"), root);
        QVERIFY(m);
        const Light* spot = lightNamed(*m, QStringLiteral("Spot"));
        QVERIFY(spot);
        QVERIFY(!spot->gobo);
        QCOMPARE(spot->link, someLink());
        const QString w = warningWith(
            *m, {QStringLiteral("badgobo.gltf: nodes[%1].extras.lightrig.gobo.scale: must be").arg(node),
                 QStringLiteral("got 500"), QStringLiteral("(ignored)")});
        QVERIFY2(!w.isEmpty(), qPrintable(m->warnings.join(QLatin1Char('\n'))));
    }

    void missingGoboFileAndBadLink() {
        QJsonObject root = test::exportedScene(rigWithExtras());
        const int spotNode = nodeNamed(root, QStringLiteral("Spot"));
        const int bulbNode = nodeNamed(root, QStringLiteral("Bulb"));
        QVERIFY(spotNode >= 0 && bulbNode >= 0);
        setIn(root, {"nodes", QString::number(spotNode), "extras", "lightrig", "gobo", "file"},
              QStringLiteral("gobos/gone.png"));
        setIn(root, {"nodes", QString::number(bulbNode), "extras", "lightrig", "link", "exclude"}, 7);
        const std::shared_ptr<Model> m = load(QStringLiteral("missing"), root);
        QVERIFY(m);
        const QString all = m->warnings.join(QLatin1Char('\n'));
        const Light* spot = lightNamed(*m, QStringLiteral("Spot"));
        QVERIFY(spot && !spot->gobo);
        QVERIFY2(
            !warningWith(*m, {QStringLiteral("nodes[%1].extras.lightrig.gobo.file: ignored").arg(spotNode),
                              QStringLiteral("gone.png: no such file")})
                 .isEmpty(),
            qPrintable(all));
        const Light* bulb = lightNamed(*m, QStringLiteral("Bulb"));
        QVERIFY(bulb && bulb->link.isDefault());
        QVERIFY2(!warningWith(
                      *m, {QStringLiteral("nodes[%1].extras.lightrig.link.exclude: must be").arg(bulbNode)})
                      .isEmpty(),
                 qPrintable(all));
    }

    void goboOnAnIesPointIsNamed() {
        Rig rig = rigWithExtras();
        rig.lights[0].ies =
            IesSpec{QStringLiteral("full.ies"), QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies"), 1.0,
                    IesLevel::Profile, 0.0};
        qputenv("LIGHTRIG_IES_CACHE", m_dir.filePath(QStringLiteral("cache")).toUtf8());
        const std::shared_ptr<Model> m = load(QStringLiteral("iesgobo"), test::exportedScene(rig));
        QVERIFY(m);
        const Light* spot = lightNamed(*m, QStringLiteral("Spot"));
        QVERIFY(spot);
        QVERIFY(spot->type == LightType::Point);
        QVERIFY(spot->ies && !spot->gobo);
        QCOMPARE(spot->link, someLink()); // the link applies to any light
        QVERIFY2(
            !warningWith(*m, {QStringLiteral(".extras.lightrig.gobo: ignored: only spot lights")}).isEmpty(),
            qPrintable(m->warnings.join(QLatin1Char('\n'))));
    }
};

QTEST_GUILESS_MAIN(TestGltfLightExtrasImport)
#include "tst_gltflightextrasimport.moc"
