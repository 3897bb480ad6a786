// `lightrig bench` run as the user runs it (QProcess on the built executable): usage errors exit 2, bad
// inputs exit 1 with a reason and write nothing, and a small run prints the table and writes a JSON file
// with the documented keys and a PNG chart. Timing values are checked for sanity only (no timed tests).
#include "support/cli.h"

#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

namespace {

using Run = lrtest::CliRun;
using lrtest::haveDisplay;

Run lightrig(const QStringList& args, int timeoutMs = 120000) {
    return lrtest::runLightrig(QStringList{QStringLiteral("bench")} + args, nullptr, timeoutMs);
}

QString show(const Run& r) {
    return r.show();
}

// The JSON object a run wrote to `path`, empty when it wrote none (a failed run's output is logged).
QJsonObject writtenJson(const Run& r, const QString& path) {
    if (r.code != 0) qWarning("%s", qPrintable(show(r)));
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QJsonDocument::fromJson(f.readAll()).object() : QJsonObject();
}

} // namespace

class TestBenchCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

  private slots:
    void initTestCase() {
        QVERIFY2(QFile::exists(QStringLiteral(LIGHTRIG_EXECUTABLE)), LIGHTRIG_EXECUTABLE);
        QVERIFY(m_dir.isValid());
    }

    void help() {
        const Run r = lightrig({QStringLiteral("--help")});
        QVERIFY2(r.code == 0, qPrintable(show(r)));
        for (const char* option : {"--lights",
                                   "--quality",
                                   "--json",
                                   "--chart",
                                   "--frames",
                                   "--msaa",
                                   "--rig",
                                   "--camera-index",
                                   "--view",
                                   "--size",
                                   "--exposure",
                                   "--tonemap",
                                   "--shading",
                                   "--ground",
                                   "--shadows",
                                   "--environment",
                                   "--environment-intensity",
                                   "--environment-rotation",
                                   "--environment-background",
                                   "--orbit",
                                   "--groups"})
            QVERIFY2(r.out.contains(QLatin1String(option)), option);
    }

    void usageErrors_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addRow("frames 0") << QStringList{"--frames", "0"};
        QTest::addRow("msaa 17") << QStringList{"--msaa", "17"};
        QTest::addRow("msaa word") << QStringList{"--msaa", "four"};
        QTest::addRow("bad tier") << QStringList{"--quality", "exact,bogus"};
        QTest::addRow("bad counts") << QStringList{"--lights", "8,x"};
        QTest::addRow("negative count") << QStringList{"--lights", "-1"};
        // Past what the renderer shades (65,535 lights): refused, not silently dropped (issue 18).
        QTest::addRow("too many lights") << QStringList{"--lights", "8,65536"};
        QTest::addRow("bad type") << QStringList{"--light-type", "laser"};
        QTest::addRow("rig and lights") << QStringList{"--rig", "r.json", "--lights", "8"};
        QTest::addRow("camera and view") << QStringList{"--camera-index", "0", "--view", "front"};
        QTest::addRow("bad size") << QStringList{"--size", "12"};
        QTest::addRow("bad approximation") << QStringList{"--approximations", "b1,b9"};
        QTest::addRow("unknown option") << QStringList{"--fastest"};
        QTest::addRow("bad shading") << QStringList{"--shading", "phong"}; // issue 13
        QTest::addRow("bad environment intensity")
            << QStringList{"--environment-intensity", "99"}; // issue 15
        QTest::addRow("bad environment background") << QStringList{"--environment-background", "grey"};
        QTest::addRow("orbit past a turn") << QStringList{"--orbit", "400"};
        QTest::addRow("orbit word") << QStringList{"--orbit", "left"};
        QTest::addRow("scale 0") << QStringList{"--scale", "0"}; // issue 40
        QTest::addRow("scale past 1") << QStringList{"--scale", "1.5"};
        QTest::addRow("scale word") << QStringList{"--scale", "half"};
        QTest::addRow("groups and json") << QStringList{"--groups", "--json", "out.json"}; // issue 37
    }

    void usageErrors() {
        QFETCH(QStringList, args);
        const Run r = lightrig(args);
        QVERIFY2(r.code == 2, qPrintable(show(r)));
        QVERIFY2(r.err.contains(QStringLiteral("Usage: lightrig bench")), qPrintable(show(r)));
        if (args.first() == QLatin1String("--shading"))
            QVERIFY2(r.err.contains(QStringLiteral("--shading must be \"classic\" or \"pbr\", got 'phong'")),
                     qPrintable(show(r)));
        if (args.first() == QLatin1String("--scale"))
            QVERIFY2(r.err.contains(
                         QStringLiteral("--scale must be a fraction in 0.125..1, got '%1'").arg(args[1])),
                     qPrintable(show(r)));
        if (args.first().startsWith(QLatin1String("--environment")))
            QVERIFY2(r.err.contains(args.first() + QStringLiteral(" must be ")), qPrintable(show(r)));
    }

    void badInputsWriteNothing() {
        const QString json = m_dir.filePath(QStringLiteral("never.json"));
        const Run missing =
            lightrig({m_dir.filePath(QStringLiteral("nope.glb")), QStringLiteral("--json"), json});
        QVERIFY2(missing.code == 1 && missing.err.contains(QStringLiteral("nope.glb")),
                 qPrintable(show(missing)));
        const Run noFolder =
            lightrig({QStringLiteral("--json"), m_dir.filePath(QStringLiteral("no/such/dir/out.json"))});
        QVERIFY2(noFolder.code == 1 && noFolder.err.contains(QStringLiteral("does not exist")),
                 qPrintable(show(noFolder)));
        // Issue 15: an environment that does not load fails the bench, naming the file.
        const Run sky =
            lightrig({QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"), QStringLiteral("--environment"),
                      m_dir.filePath(QStringLiteral("no-sky.exr")), QStringLiteral("--json"), json});
        if (haveDisplay())
            QVERIFY2(sky.code == 1 && sky.err.contains(QStringLiteral("no-sky.exr")), qPrintable(show(sky)));
        QVERIFY(!QFile::exists(json));
    }

    void smallSuite() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const QString json = m_dir.filePath(QStringLiteral("bench.json")),
                      chart = m_dir.filePath(QStringLiteral("chart.png")),
                      scaling = m_dir.filePath(QStringLiteral("scaling.png"));
        const Run r =
            lightrig({QStringLiteral("--lights"), QStringLiteral("1,4"), QStringLiteral("--light-type"),
                      QStringLiteral("point,spot"), QStringLiteral("--size"), QStringLiteral("64x48"),
                      QStringLiteral("--frames"), QStringLiteral("2"), QStringLiteral("--warmup"),
                      QStringLiteral("0"), QStringLiteral("--json"), json, QStringLiteral("--chart"), chart,
                      QStringLiteral("--scaling-chart"), scaling},
                     300000); // the über-shader (every light model, the area lights' LTC code too since
                              // issue 16) takes llvmpipe 7-9 s to compile per scene: 95 s idle in all
        QVERIFY2(r.code == 0, qPrintable(show(r)));
        QVERIFY2(r.out.contains(QStringLiteral("ms med")) && r.out.contains(QStringLiteral("über-shader")),
                 qPrintable(show(r)));
        QFile f(json);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QJsonParseError parseError;
        const QJsonDocument doc = QJsonDocument::fromJson(f.readAll(), &parseError);
        QVERIFY2(doc.isObject(), qPrintable(parseError.errorString()));
        const QJsonArray results = doc.object().value(QStringLiteral("results")).toArray();
        QCOMPARE(results.size(), 2 * 2 * 4); // types × counts × (exact, balanced, fast, über)
        QSet<QString> scenes, tiers;
        for (const QJsonValue& v : results) {
            const QJsonObject o = v.toObject();
            for (const char* key :
                 {"scene", "lights", "quality", "width", "height", "ms_median", "ms_min", "ms_max",
                  "first_frame_ms", "second_frame_ms", "max_error_levels", "mean_error_levels", "psnr_db",
                  "nonfinite_pixels", "gpu_ms_median", "variants", "lights_uploaded", "triangles"})
                QVERIFY2(o.contains(QLatin1String(key)), key);
            QCOMPARE(o.value(QStringLiteral("width")).toInt(), 64);
            QCOMPARE(o.value(QStringLiteral("height")).toInt(), 48);
            QVERIFY(o.value(QStringLiteral("ms_min")).toDouble() > 0.0);
            QVERIFY(o.value(QStringLiteral("second_frame_ms")).toDouble() > 0.0);
            QVERIFY(o.value(QStringLiteral("ms_min")).toDouble() <=
                    o.value(QStringLiteral("ms_max")).toDouble());
            QCOMPARE(o.value(QStringLiteral("nonfinite_pixels")).toInt(), 0);
            QVERIFY(!o.contains(QStringLiteral("environment_prefilter_ms"))); // no environment
            QVERIFY(o.value(QStringLiteral("lights")).toInt() == 1 ||
                    o.value(QStringLiteral("lights")).toInt() == 4);
            scenes.insert(o.value(QStringLiteral("scene")).toString());
            tiers.insert(o.value(QStringLiteral("quality")).toString());
        }
        QCOMPARE(scenes.size(), 4);
        QCOMPARE(tiers, (QSet<QString>{QStringLiteral("exact"), QStringLiteral("balanced"),
                                       QStringLiteral("fast")}));
        QCOMPARE(doc.object().value(QStringLiteral("uber_shader")).toArray().size(), 4);
        const QImage image(chart);
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(1000, 640));
        const QImage curve(scaling);
        QVERIFY(!curve.isNull());
        QCOMPARE(curve.size(), QSize(1000, 640));
        // A line per tier in the tier's colour (exact blue, fast green): the curve was drawn, not just axes.
        int blue = 0, green = 0;
        for (int y = 0; y < curve.height(); ++y)
            for (int x = 0; x < curve.width(); ++x) {
                const QRgb c = curve.pixel(x, y);
                blue += c == qRgb(40, 100, 200);
                green += c == qRgb(40, 160, 70);
            }
        QVERIFY2(blue > 50 && green > 50,
                 qPrintable(QStringLiteral("%1 blue, %2 green").arg(blue).arg(green)));
    }

    // Issue 13: --shading pbr benches the model's lights physically based (the fast tier, 2 frames).
    void modelShadedPhysicallyBased() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const Run r =
            lightrig({QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"), QStringLiteral("--shading"),
                      QStringLiteral("pbr"), QStringLiteral("--quality"), QStringLiteral("fast"),
                      QStringLiteral("--size"), QStringLiteral("48x32"), QStringLiteral("--frames"),
                      QStringLiteral("2"), QStringLiteral("--no-uber"), QStringLiteral("--no-errors")});
        QVERIFY2(r.code == 0, qPrintable(show(r)));
        QVERIFY(r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts).size() == 3);
    }

    // Issue 37: --groups times the beauty against the light-group split per tier and the reference, one
    // row each; a light more is a group (and a pass) more.
    void groupsCost() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const Run r = lightrig({"--groups", "--lights", "1,3", "--light-type", "point", "--size", "48x32",
                                "--frames", "1", "--warmup", "0"});
        QVERIFY2(r.code == 0, qPrintable(show(r)));
        const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 2 + 2 * 4); // heading, titles, 2 scenes × (exact, balanced, fast, reference)
        QVERIFY2(lines[0].contains("load average"), qPrintable(lines[0]));
        QMap<QString, int> groups;
        for (const QString& line : lines.mid(2)) {
            const QStringList cells =
                line.split(QRegularExpression(QStringLiteral("\\s{2,}")), Qt::SkipEmptyParts);
            QVERIFY2(cells.size() >= 10, qPrintable(line));
            const QString tier = cells[1].trimmed();
            const int n = cells[2].trimmed().toInt();
            if (line.contains("1 point"))
                groups[tier] = n;
            else
                QVERIFY2(n == groups.value(tier) + 2, qPrintable(line));
        }
        QCOMPARE(groups.size(), 4);
    }

    void modelWithItsRigAndOneTier() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const Run r = lightrig({QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"),
                                QStringLiteral("--quality"), QStringLiteral("fast"), QStringLiteral("--size"),
                                QStringLiteral("48x32"), QStringLiteral("--frames"), QStringLiteral("2"),
                                QStringLiteral("--no-uber"), QStringLiteral("--no-errors")});
        QVERIFY2(r.code == 0, qPrintable(show(r)));
        const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3); // heading, column titles, one result
        QVERIFY(lines[2].startsWith(QStringLiteral("scene ")) && lines[2].contains(QStringLiteral(" fast ")));
    }

    // A still camera keeps the deferred G-buffer (one material: the attribute G-buffer, deferred at any
    // light count) on every timed frame after the first draw; --orbit turns
    // the camera between frames, and nothing is kept (the figure three.js's re-rendered frame compares to).
    void orbitDrawsEveryFrame() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const QString json = m_dir.filePath(QStringLiteral("orbit.json"));
        const auto kept = [&](const QStringList& extra) {
            const Run r = lightrig(
                QStringList{QStringLiteral(LIGHTRIG_TEST_DATA "/model/shiny.obj"),
                            QStringLiteral("--quality"), QStringLiteral("exact"), QStringLiteral("--msaa"),
                            QStringLiteral("0"), QStringLiteral("--size"), QStringLiteral("48x32"),
                            QStringLiteral("--frames"), QStringLiteral("3"), QStringLiteral("--no-uber"),
                            QStringLiteral("--no-errors"), QStringLiteral("--json"), json} +
                extra);
            const QJsonObject doc = writtenJson(r, json);
            const QJsonObject result = doc.value(QStringLiteral("results")).toArray().at(0).toObject();
            return result.value(QStringLiteral("gbuffer_kept_frames")).toInt(-1) * 1000 +
                   int(doc.value(QStringLiteral("options"))
                           .toObject()
                           .value(QStringLiteral("orbit_degrees"))
                           .toDouble());
        };
        QCOMPARE(kept({}), 3000);                                              // 3 kept, orbit 0
        QCOMPARE(kept({QStringLiteral("--orbit"), QStringLiteral("15")}), 15); // none kept, orbit 15
    }

    // Issue 40: --scale draws every frame smaller and stretches it, as the editor's moving frames; the
    // error figures are of the stretched image, so they grow (exact alone is within a level of the
    // reference), and the JSON records the scale.
    void scaleMeasuresTheStretchedFrame() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const QString json = m_dir.filePath(QStringLiteral("scale.json"));
        const auto run = [&](const QStringList& extra, double* scale) {
            const Run r =
                lightrig(QStringList{QStringLiteral(LIGHTRIG_TEST_DATA "/model/shiny.obj"),
                                     QStringLiteral("--quality"), QStringLiteral("exact"),
                                     QStringLiteral("--msaa"), QStringLiteral("0"), QStringLiteral("--size"),
                                     QStringLiteral("96x64"), QStringLiteral("--frames"), QStringLiteral("2"),
                                     QStringLiteral("--no-uber"), QStringLiteral("--json"), json} +
                         extra);
            const QJsonObject doc = writtenJson(r, json);
            *scale = doc.value(QStringLiteral("options"))
                         .toObject()
                         .value(QStringLiteral("render_scale"))
                         .toDouble(-1);
            return doc.value(QStringLiteral("results"))
                .toArray()
                .at(0)
                .toObject()
                .value(QStringLiteral("max_error_levels"))
                .toInt(-1);
        };
        double scale = 0.0;
        const int full = run({}, &scale);
        QCOMPARE(scale, 1.0);
        QVERIFY2(full >= 0 && full <= 1, qPrintable(QString::number(full)));
        const int half = run({QStringLiteral("--scale"), QStringLiteral("0.5")}, &scale);
        QCOMPARE(scale, 0.5);
        QVERIFY2(half > 1, qPrintable(QString::number(half)));
    }

    // lightrig re-executes itself with malloc on transparent huge pages (core/hugepages.h): the bench,
    // started without the tunable, ran with it; a user's own value of it is kept.
    void runsWithHugePages() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const QString json = m_dir.filePath(QStringLiteral("tunables.json"));
        const auto tunables = [&](const QString& value) {
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.remove(QStringLiteral("GLIBC_TUNABLES"));
            if (!value.isEmpty()) env.insert(QStringLiteral("GLIBC_TUNABLES"), value);
            QFile::remove(json);
            const Run r = lrtest::runLightrig(
                {QStringLiteral("bench"), QStringLiteral(LIGHTRIG_TEST_DATA "/model/shiny.obj"),
                 QStringLiteral("--quality"), QStringLiteral("fast"), QStringLiteral("--size"),
                 QStringLiteral("16x16"), QStringLiteral("--frames"), QStringLiteral("1"),
                 QStringLiteral("--no-uber"), QStringLiteral("--no-errors"), QStringLiteral("--json"), json},
                &env);
            return writtenJson(r, json).value(QStringLiteral("glibc_tunables")).toString();
        };
        QCOMPARE(tunables({}), QStringLiteral("glibc.malloc.hugetlb=1"));
        QCOMPARE(tunables(QStringLiteral("glibc.malloc.arena_max=2")),
                 QStringLiteral("glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1"));
        QCOMPARE(tunables(QStringLiteral("glibc.malloc.hugetlb=0")),
                 QStringLiteral("glibc.malloc.hugetlb=0"));
    }

    // Issue 15: --environment studio: the bench says which environment it used and what loading it cost
    // before its table, and the JSON has that cost with each result (a first frame waits for it).
    void environmentIsNamed() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const QString json = m_dir.filePath(QStringLiteral("environment.json"));
        const Run r =
            lightrig({QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"), QStringLiteral("--environment"),
                      QStringLiteral("studio"), QStringLiteral("--quality"), QStringLiteral("fast"),
                      QStringLiteral("--size"), QStringLiteral("48x32"), QStringLiteral("--frames"),
                      QStringLiteral("2"), QStringLiteral("--no-uber"), QStringLiteral("--no-errors"),
                      QStringLiteral("--json"), json});
        QVERIFY2(r.code == 0, qPrintable(show(r)));
        const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 4); // the environment, heading, column titles, one result
        QVERIFY2(
            lines[0].startsWith(QStringLiteral("lightrig bench: studio environment (studio), decoded in ")) &&
                lines[0].contains(QStringLiteral(" s, prefiltered in ")),
            qPrintable(show(r)));
        QFile f(json);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject o = QJsonDocument::fromJson(f.readAll())
                                  .object()
                                  .value(QStringLiteral("results"))
                                  .toArray()[0]
                                  .toObject();
        // The procedural studio is rendered, not decoded: no decoding time, some prefiltering, done during
        // the scene's first run (after its upload), whose first draw thus includes it.
        QCOMPARE(o.value(QStringLiteral("environment_decode_ms")).toDouble(-1.0), 0.0);
        QVERIFY(o.value(QStringLiteral("environment_concurrent")).toBool(false));
        QVERIFY2(o.value(QStringLiteral("environment_prefilter_ms")).toDouble() > 0.0,
                 qPrintable(QJsonDocument(o).toJson()));
    }

    // Issue 14: procedural bench lights take --shadows and --ground like a loaded rig: with shadows on the
    // results carry the shadow measure (present only when some light casts), without they do not.
    void proceduralLightsCastWithShadowsOn() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        for (const bool on : {true, false}) {
            const QString json = m_dir.filePath(QStringLiteral("procedural-%1.json").arg(on));
            QStringList args{QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"),
                             QStringLiteral("--lights"),
                             QStringLiteral("2"),
                             QStringLiteral("--light-type"),
                             QStringLiteral("spot"),
                             QStringLiteral("--ground"),
                             QStringLiteral("visible"),
                             QStringLiteral("--quality"),
                             QStringLiteral("exact"),
                             QStringLiteral("--size"),
                             QStringLiteral("48x32"),
                             QStringLiteral("--frames"),
                             QStringLiteral("1"),
                             QStringLiteral("--warmup"),
                             QStringLiteral("0"),
                             QStringLiteral("--no-uber"),
                             QStringLiteral("--json"),
                             json};
            if (on) args << QStringLiteral("--shadows") << QStringLiteral("on");
            const Run r = lightrig(args);
            QVERIFY2(r.code == 0, qPrintable(show(r)));
            QFile f(json);
            QVERIFY(f.open(QIODevice::ReadOnly));
            const QJsonArray results =
                QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("results")).toArray();
            QCOMPARE(results.size(), 1);
            QCOMPARE(results[0].toObject().contains(QStringLiteral("shadow_differing_share")), on);
        }
    }

    // Issue 14: --drag moves the first light between timed frames and its map alone is rendered again,
    // once a frame; holding still or orbiting renders no map after the first frame (maps are cached).
    void dragRendersOneMapAFrame() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const QString json = m_dir.filePath(QStringLiteral("drag.json"));
        const auto maps = [&](const QStringList& extra) {
            QFile::remove(json);
            const Run r = lightrig(
                QStringList{QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"),
                            QStringLiteral("--lights"), QStringLiteral("2"), QStringLiteral("--light-type"),
                            QStringLiteral("spot"), QStringLiteral("--shadows"), QStringLiteral("on"),
                            QStringLiteral("--quality"), QStringLiteral("fast"), QStringLiteral("--size"),
                            QStringLiteral("48x32"), QStringLiteral("--frames"), QStringLiteral("4"),
                            QStringLiteral("--no-uber"), QStringLiteral("--no-errors"),
                            QStringLiteral("--json"), json} +
                extra);
            const QJsonObject doc = writtenJson(r, json);
            if (doc.value(QStringLiteral("options"))
                    .toObject()
                    .value(QStringLiteral("drag_light"))
                    .toBool() != extra.contains(QStringLiteral("--drag")))
                return -2;
            return doc.value(QStringLiteral("results"))
                .toArray()
                .at(0)
                .toObject()
                .value(QStringLiteral("shadow_maps_rendered"))
                .toInt(-1);
        };
        QCOMPARE(maps({QStringLiteral("--drag")}), 4); // 4 timed frames, one map each
        QCOMPARE(maps({}), 0);
        QCOMPARE(maps({QStringLiteral("--orbit"), QStringLiteral("15")}), 0);
    }

    // Issue 18: a valid rig with a range-power light 1e12 above an 8×8 plane, range 1e12, seen from above
    // at +60 EV: every GPU tier was black where the double reference was white (1 - d/range is rounding
    // noise of ~1e-16 in double and 0 in float, and 2^60 made the noise white). Both now give 0 in the last
    // 1e-6 of the range (core/lighting.h kRangeEdge), so every tier agrees with the reference.
    void farRangePowerLightAgreesWithTheReference() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const QString plane = m_dir.filePath(QStringLiteral("plane.obj"));
        QFile obj(plane);
        QVERIFY(obj.open(QIODevice::WriteOnly));
        obj.write("v -4 0 -4\nv 4 0 -4\nv 4 0 4\nv -4 0 4\nvn 0 1 0\nf 1//1 3//1 2//1\nf 1//1 4//1 3//1\n");
        obj.close();
        const QString json = m_dir.filePath(QStringLiteral("far.json"));
        const Run r =
            lightrig({plane, QStringLiteral("--rig"),
                      QStringLiteral(LIGHTRIG_TEST_DATA "/model/hostile/far-light-range-power-1e12.rig.json"),
                      QStringLiteral("--view"), QStringLiteral("top"), QStringLiteral("--exposure"),
                      QStringLiteral("60"), QStringLiteral("--tonemap"), QStringLiteral("aces"),
                      QStringLiteral("--size"), QStringLiteral("32x32"), QStringLiteral("--frames"),
                      QStringLiteral("1"), QStringLiteral("--warmup"), QStringLiteral("0"),
                      QStringLiteral("--no-uber"), QStringLiteral("--json"), json});
        QVERIFY2(r.code == 0, qPrintable(show(r)));
        QFile f(json);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonArray results =
            QJsonDocument::fromJson(f.readAll()).object().value(QStringLiteral("results")).toArray();
        QCOMPARE(results.size(), 3); // exact, balanced, fast
        for (const QJsonValue& v : results) {
            const QJsonObject o = v.toObject();
            QVERIFY2(o.value(QStringLiteral("max_error_levels")).isDouble() &&
                         o.value(QStringLiteral("max_error_levels")).toDouble() <= 1.0,
                     qPrintable(QJsonDocument(o).toJson()));
        }
    }
    // Issue 41: `bench --lights 65535` ran 7 minutes without finishing its first run and without a word on
    // how long it would take. Beyond the standard suite's scale it now probes one frame and says before the
    // first run what the whole bench will take and which options bound it.
    void manyLightsSayTheirEstimateFirst() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const Run r = lightrig({QStringLiteral(LIGHTRIG_TEST_DATA "/model/tetra.stl"),
                                QStringLiteral("--lights"), QStringLiteral("65535"), QStringLiteral("--size"),
                                QStringLiteral("32x18"), QStringLiteral("--frames"), QStringLiteral("1"),
                                QStringLiteral("--warmup"), QStringLiteral("0"), QStringLiteral("--quality"),
                                QStringLiteral("exact"), QStringLiteral("--no-uber")});
        QVERIFY2(r.code == 0, qPrintable(show(r)));
        const qsizetype estimate = r.err.indexOf(QStringLiteral("lightrig bench: estimated "));
        QVERIFY2(estimate >= 0, qPrintable(show(r)));
        QVERIFY2(estimate < r.err.indexOf(QStringLiteral("[1/1] tetra · 65535 point: exact")),
                 qPrintable(show(r)));
        QVERIFY2(r.err.contains(QStringLiteral("for 4 frames: one frame of tetra · 65535 point at 32x18")),
                 qPrintable(show(r)));
        QVERIFY2(r.err.contains(QStringLiteral("--size, --frames")), qPrintable(show(r)));
        // The standard suite's scale says nothing more than before.
        const Run small =
            lightrig({QStringLiteral(LIGHTRIG_TEST_DATA "/model/tetra.stl"), QStringLiteral("--lights"),
                      QStringLiteral("256"), QStringLiteral("--size"), QStringLiteral("32x18"),
                      QStringLiteral("--frames"), QStringLiteral("1"), QStringLiteral("--quality"),
                      QStringLiteral("fast"), QStringLiteral("--no-uber")});
        QVERIFY2(small.code == 0 && !small.err.contains(QStringLiteral("estimated")),
                 qPrintable(show(small)));
    }

    // 65,535 area lights: the reference integrates each by Monte Carlo at every pixel (hours even at 32x18).
    // Over the reference budget a scene gets no reference and no error figures, and the report says so.
    void referenceOverItsBudgetIsSkippedWithANote() {
        if (!haveDisplay()) QSKIP("needs an X display with OpenGL: run under xvfb-run -a");
        const QString json = m_dir.filePath(QStringLiteral("skipped.json"));
        const Run r =
            lightrig({QStringLiteral(LIGHTRIG_TEST_DATA "/model/tetra.stl"), QStringLiteral("--lights"),
                      QStringLiteral("65535"), QStringLiteral("--light-type"), QStringLiteral("rect"),
                      QStringLiteral("--size"), QStringLiteral("32x18"), QStringLiteral("--frames"),
                      QStringLiteral("1"), QStringLiteral("--warmup"), QStringLiteral("0"),
                      QStringLiteral("--quality"), QStringLiteral("exact"), QStringLiteral("--no-uber"),
                      QStringLiteral("--json"), json});
        QVERIFY2(r.code == 0, qPrintable(show(r)));
        QVERIFY2(
            r.out.contains(QStringLiteral("note: tetra · 65535 rect: no reference and no error figures")),
            qPrintable(show(r)));
        QVERIFY2(r.out.contains(QStringLiteral("--full-reference")), qPrintable(show(r)));
        const QJsonArray results = writtenJson(r, json).value(QStringLiteral("results")).toArray();
        QCOMPARE(results.size(), 1);
        QVERIFY(results[0].toObject().value(QStringLiteral("max_error_levels")).isNull());
    }
};

QTEST_GUILESS_MAIN(TestBenchCli)

#include "tst_benchcli.moc"
