// `lightrig render`'s scene options as the user runs them (QProcess on the built executable): --shading,
// --ground and --shadows, --environment, the default rig that follows the model's materials, and what render
// reports of a rig before it renders (light linking's matches, light shaping's warnings).
#include "core/defaultrig.h"
#include "core/rigjson.h"
#include "glfixture.h"
#include "model/isolatedimport.h"
#include "support/cli.h"
#include "support/files.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>

namespace {

using Run = lrtest::CliRun;

QString suzanne() {
    return QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/suzanne/Suzanne.gltf");
}
QString shared(const char* path) {
    return QStringLiteral(LIGHTRIG_SHARED_MODELS "/") + QLatin1String(path);
}

} // namespace

class TestRenderCliOptions : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QProcessEnvironment m_env = QProcessEnvironment::systemEnvironment();

    Run lightrig(const QStringList& args, const QProcessEnvironment* env = nullptr) {
        return lrtest::runLightrig(QStringList{QStringLiteral("render")} + args, env ? env : &m_env);
    }
    QString path(const QString& name) const { return m_dir.filePath(name); }

  private slots:
    void initTestCase() {
        QVERIFY2(QFile::exists(QStringLiteral(LIGHTRIG_EXECUTABLE)), LIGHTRIG_EXECUTABLE);
        QVERIFY(m_dir.isValid());
        QDir(m_dir.path()).mkdir(QStringLiteral("xdg"));
        QFile::setPermissions(path(QStringLiteral("xdg")),
                              QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        m_env.insert(QStringLiteral("XDG_RUNTIME_DIR"), path(QStringLiteral("xdg")));
    }

    // Issue 13: --shading classic|pbr, a usage error for anything else (naming the option).
    void shadingOption() {
        const Run bad = lightrig({suzanne(), QStringLiteral("--shading"), QStringLiteral("phong"),
                                  QStringLiteral("-o"), path(QStringLiteral("never.png"))});
        QVERIFY2(bad.code == 2, qPrintable(bad.show()));
        QVERIFY2(bad.err.contains(QLatin1String("--shading must be \"classic\" or \"pbr\", got 'phong'")),
                 qPrintable(bad.show()));
        QVERIFY(!QFile::exists(path(QStringLiteral("never.png"))));
        LR_REQUIRE_DISPLAY();
        const QStringList small{QStringLiteral("--size"), QStringLiteral("64x48"), QStringLiteral("-o"),
                                path(QStringLiteral("shading.png"))};
        Run r = lightrig(QStringList{suzanne()} + small);
        QVERIFY2(r.code == 0 && r.out.contains(QLatin1String("(the default rig, classic shading)")),
                 qPrintable(r.show()));
        r = lightrig(QStringList{suzanne(), QStringLiteral("--shading"), QStringLiteral("pbr")} + small);
        QVERIFY2(r.code == 0 &&
                     r.out.contains(QLatin1String("(the physically based default rig, pbr shading)")),
                 qPrintable(r.show()));
        const QString rig = QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/presets/three-point.json");
        r = lightrig(QStringList{suzanne(), QStringLiteral("--rig"), rig, QStringLiteral("--shading"),
                                 QStringLiteral("pbr")} +
                     small);
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("(%1, pbr shading)").arg(rig)),
                 qPrintable(r.show()));
    }

    // Issue 14: --ground off|visible|catcher overrides the rig's ground and --shadows on|off its shadows, a
    // usage error naming the option for anything else; the summary names a ground that is there and the
    // shadows cast.
    void groundAndShadowOptions() {
        for (const auto& [option, value, message] :
             {std::tuple{"--ground", "shadow",
                         "--ground must be \"off\", \"visible\" or \"catcher\", got 'shadow'"},
              std::tuple{"--shadows", "soft", "--shadows must be \"on\" or \"off\", got 'soft'"}}) {
            const Run bad = lightrig({suzanne(), QString::fromLatin1(option), QString::fromLatin1(value),
                                      QStringLiteral("-o"), path(QStringLiteral("never.png"))});
            QVERIFY2(bad.code == 2, qPrintable(bad.show()));
            QVERIFY2(bad.err.contains(QLatin1String(message)), qPrintable(bad.show()));
            QVERIFY(!QFile::exists(path(QStringLiteral("never.png"))));
        }
        // More casters than maps: the work fails (exit 1) with the limit, nothing written.
        lr::Rig many;
        for (int i = 0; i <= lr::kMaxShadowCasters; ++i)
            many.lights.push_back(lr::makeLight(lr::LightType::Spot, QStringLiteral("S%1").arg(i)));
        const QString manyPath = path(QStringLiteral("many.json"));
        QString error;
        QVERIFY2(lr::saveRigFile(many, manyPath, &error), qPrintable(error));
        const Run tooMany =
            lightrig({suzanne(), QStringLiteral("--rig"), manyPath, QStringLiteral("--shadows"),
                      QStringLiteral("on"), QStringLiteral("-o"), path(QStringLiteral("never.png"))});
        QVERIFY2(tooMany.code == 1, qPrintable(tooMany.show()));
        QVERIFY2(tooMany.err.contains(QLatin1String("17 lights of the rig can cast shadows; at most 16")),
                 qPrintable(tooMany.show()));
        QVERIFY(!QFile::exists(path(QStringLiteral("never.png"))));

        LR_REQUIRE_DISPLAY();
        const QStringList small{QStringLiteral("--size"), QStringLiteral("64x48"), QStringLiteral("-o"),
                                path(QStringLiteral("ground.png"))};
        Run r =
            lightrig(QStringList{suzanne(), QStringLiteral("--ground"), QStringLiteral("catcher")} + small);
        QVERIFY2(r.code == 0 &&
                     r.out.contains(QLatin1String("(the default rig, classic shading, catcher ground)")),
                 qPrintable(r.show()));
        // The product preset has a catcher and two casters of its own; the options take them away.
        const QString sweep = QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/presets/pbr-white-sweep.json");
        r = lightrig(QStringList{suzanne(), QStringLiteral("--rig"), sweep} + small);
        QVERIFY2(r.code == 0 &&
                     r.out.contains(QStringLiteral("(%1, pbr shading, catcher ground, shadows from 2 "
                                                   "lights)")
                                        .arg(sweep)),
                 qPrintable(r.show()));
        r = lightrig(QStringList{suzanne(), QStringLiteral("--rig"), sweep, QStringLiteral("--ground"),
                                 QStringLiteral("off"), QStringLiteral("--shadows"), QStringLiteral("off")} +
                     small);
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("(%1, pbr shading)").arg(sweep)),
                 qPrintable(r.show()));
        // --shadows on: every light of the default rig that can cast.
        int casters = 0;
        for (const lr::Light& l : lr::defaultRig().lights)
            casters += l.castsShadows();
        QVERIFY(casters > 1);
        r = lightrig(QStringList{suzanne(), QStringLiteral("--shadows"), QStringLiteral("on")} + small);
        QVERIFY2(r.code == 0 &&
                     r.out.contains(QStringLiteral("(the default rig, classic shading, shadows from %1 "
                                                   "lights)")
                                        .arg(casters)),
                 qPrintable(r.show()));
    }

    // Issue 15: --environment and its settings: a usage error naming the option for a bad value; a file that
    // does not load fails the render naming it (nothing written); the studio renders and is named in the
    // summary. (What the environment adds to the image is the renderer's: tests/render.)
    void environmentOptions() {
        for (const auto& [option, value, message] :
             {std::tuple{"--environment-intensity", "25",
                         "--environment-intensity must be a number of EV in -20..20, got '25'"},
              std::tuple{"--environment-rotation", "north",
                         "--environment-rotation must be a finite number of degrees, got 'north'"},
              std::tuple{
                  "--environment-background", "grey",
                  "--environment-background must be \"visible\", \"blurred\" or \"color\", got 'grey'"},
              std::tuple{"--environment", "", "--environment needs a file, builtin:NAME, studio or none"}}) {
            const Run bad = lightrig({suzanne(), QString::fromLatin1(option), QString::fromLatin1(value),
                                      QStringLiteral("-o"), path(QStringLiteral("never.png"))});
            QVERIFY2(bad.code == 2, qPrintable(bad.show()));
            QVERIFY2(bad.err.contains(QLatin1String(message)), qPrintable(bad.show()));
            QVERIFY(!QFile::exists(path(QStringLiteral("never.png"))));
        }
        LR_REQUIRE_DISPLAY();
        QFile kept(path(QStringLiteral("kept-env.png")));
        QVERIFY(kept.open(QIODevice::WriteOnly));
        kept.write("previous");
        kept.close();
        const Run missing =
            lightrig({suzanne(), QStringLiteral("--environment"), path(QStringLiteral("no-sky.exr")),
                      QStringLiteral("-o"), path(QStringLiteral("kept-env.png"))});
        QVERIFY2(missing.code == 1, qPrintable(missing.show()));
        QVERIFY2(missing.errorLines().size() == 1 &&
                     missing.errorLines().first().contains(QStringLiteral("no-sky.exr")),
                 qPrintable(missing.show()));
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("previous"));

        const QStringList small{QStringLiteral("--size"), QStringLiteral("64x48"), QStringLiteral("-o"),
                                path(QStringLiteral("environment.png"))};
        const Run studio =
            lightrig(QStringList{suzanne(), QStringLiteral("--environment"), QStringLiteral("studio"),
                                 QStringLiteral("--environment-intensity"), QStringLiteral("-1"),
                                 QStringLiteral("--environment-rotation"), QStringLiteral("45"),
                                 QStringLiteral("--environment-background"), QStringLiteral("blurred")} +
                     small);
        QVERIFY2(studio.code == 0 &&
                     studio.out.contains(QLatin1String("(the default rig, classic shading, studio "
                                                       "environment)")),
                 qPrintable(studio.show()));
        QCOMPARE(QImage(path(QStringLiteral("environment.png"))).size(), QSize(64, 48));
        // --environment none takes a rig's environment away.
        const QString preset =
            QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/presets/pbr-studio-environment.json");
        Run r = lightrig(QStringList{suzanne(), QStringLiteral("--rig"), preset} + small);
        QVERIFY2(r.code == 0 &&
                     r.out.contains(QStringLiteral("(%1, pbr shading, studio environment)").arg(preset)),
                 qPrintable(r.show()));
        r = lightrig(QStringList{suzanne(), QStringLiteral("--rig"), preset, QStringLiteral("--environment"),
                                 QStringLiteral("none")} +
                     small);
        QVERIFY2(r.code == 0 && r.out.contains(QStringLiteral("(%1, pbr shading)").arg(preset)),
                 qPrintable(r.show()));
    }

    // Issue 13: without --rig, a model's default rig follows core/defaultrig.h — its own lights, shaded
    // physically based exactly when its imported materials are (the test imports it to know).
    void defaultRigFollowsTheMaterials_data() {
        QTest::addColumn<QString>("model");
        QTest::newRow("scene.gltf") << QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf");
        QTest::newRow("helmet_8pt") << shared("bench/helmet_8pt.glb");
    }

    void defaultRigFollowsTheMaterials() {
        QFETCH(QString, model);
        if (!QFile::exists(model)) QSKIP("../shared/models is not here (third-party test models)");
        LR_REQUIRE_DISPLAY();
        lr::setImportWorkerExecutable(QStringLiteral(LIGHTRIG_EXECUTABLE));
        const lr::ModelLoadResult imported = lr::importModelIsolated(model);
        QVERIFY2(imported.ok(), qPrintable(imported.error));
        QVERIFY(!imported.model->lights.lights.empty());
        const QString expected =
            lr::toString(lr::defaultShadingFor(imported.model->hasPbrMaterials(), model));
        const Run r = lightrig({model, QStringLiteral("--size"), QStringLiteral("64x48"),
                                QStringLiteral("-o"), path(QStringLiteral("own-lights.png"))});
        QVERIFY2(r.code == 0 &&
                     r.out.contains(QStringLiteral("(the model's lights, %1 shading)").arg(expected)),
                 qPrintable(r.show() + QStringLiteral("\nexpected %1 shading").arg(expected)));
    }

    // Issue 38: render reports what each linked name matches, and warns of names that match nothing
    // (kept: the rig may be meant for another model). scene.gltf places its one mesh by two nodes.
    void reportsLinkMatches() {
        LR_REQUIRE_DISPLAY();
        lr::Rig rig = lr::pbrDefaultRig();
        rig.lights.resize(1);
        rig.lights[0].link.lit.include = {QStringLiteral("child"), QStringLiteral("Visor")};
        rig.lights[0].link.shadow.exclude = {QStringLiteral("square")};
        rig.lights[0].name = QStringLiteral("Rim");
        QVERIFY(lrtest::writeFile(path(QStringLiteral("linked.json")), lr::writeRigJson(rig)));
        const Run r =
            lightrig({QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"), QStringLiteral("--rig"),
                      path(QStringLiteral("linked.json")), QStringLiteral("--size"), QStringLiteral("64x48"),
                      QStringLiteral("-o"), path(QStringLiteral("linked.png"))});
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        QVERIFY2(r.err.contains(QStringLiteral("linking: Rim: link.include \"child\": 1 part (child)")),
                 qPrintable(r.show()));
        QVERIFY2(r.err.contains(
                     QStringLiteral("linking: Rim: link.shadow.exclude \"square\": 2 parts (child, mirror)")),
                 qPrintable(r.show()));
        QVERIFY2(r.err.contains(
                     QStringLiteral("warning: Rim: link.include: \"Visor\" matches no part of the model")),
                 qPrintable(r.show()));
    }

    // Issue 39: render names a shaping file that did not load, with its field, and says which lights the
    // raster draws unshaped; the path-traced tier shapes them and says nothing of it.
    void reportsShaping() {
        lr::Rig rig = lr::pbrDefaultRig();
        rig.lights.resize(2);
        rig.lights[0] = lr::makeLight(lr::LightType::Spot, QStringLiteral("Key"));
        rig.lights[0].ies = lr::IesSpec{};
        rig.lights[0].ies->file = QStringLiteral(LIGHTRIG_TEST_DATA "/ies/full.ies");
        rig.lights[1] = lr::makeLight(lr::LightType::Spot, QStringLiteral("Fill"));
        rig.lights[1].ies = lr::IesSpec{};
        rig.lights[1].ies->file = QStringLiteral("missing.ies"); // relative: beside the rig, where it is not
        QVERIFY(lrtest::writeFile(path(QStringLiteral("shaped.json")), lr::writeRigJson(rig)));
        const QStringList args{suzanne(),
                               QStringLiteral("--rig"),
                               path(QStringLiteral("shaped.json")),
                               QStringLiteral("--size"),
                               QStringLiteral("32x24"),
                               QStringLiteral("-o"),
                               path(QStringLiteral("shaped.png"))};
        const QString missing = QStringLiteral("warning: lights[1].ies.file: %1")
                                    .arg(QDir::cleanPath(path(QStringLiteral("missing.ies"))));
        const Run traced = lightrig(args + QStringList{QStringLiteral("--quality"), QStringLiteral("path"),
                                                       QStringLiteral("--samples"), QStringLiteral("1")});
        QVERIFY2(traced.code == 0, qPrintable(traced.show()));
        QVERIFY2(traced.err.contains(missing), qPrintable(traced.show()));
        QVERIFY2(!traced.err.contains(QStringLiteral("lights[0]")), qPrintable(traced.show()));
        LR_REQUIRE_DISPLAY();
        const Run r = lightrig(args); // the raster shapes the profile that loads, and says nothing of it
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        QVERIFY2(r.err.contains(missing), qPrintable(r.show()));
        QVERIFY2(!r.err.contains(QStringLiteral("lights[0]")), qPrintable(r.show()));
    }
};

QTEST_GUILESS_MAIN(TestRenderCliOptions)
#include "tst_renderclioptions.moc"
