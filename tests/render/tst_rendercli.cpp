// `lightrig render` as the user runs it (QProcess on the built executable): exit codes 0 (written),
// 1 (bad model, rig, camera or path: one line on stderr, nothing written), 2 (usage); PNG and JPEG by
// extension; and image baselines of real models (tests/data/render/baselines, compared per pixel;
// a missing baseline is written and the test fails so that it gets reviewed and committed).
#include "core/defaultrig.h"
#include "core/rigjson.h"
#include "glfixture.h"
#include "support/cli.h"
#include "support/files.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>
#include <sys/stat.h>
#include <tuple>
#include <unistd.h>

namespace {

using Run = lrtest::CliRun; // errorLines(): ours, without platform chatter such as XDG_RUNTIME_DIR notes

QString suzanne() {
    return QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/suzanne/Suzanne.gltf");
}
QString shared(const char* path) {
    return QStringLiteral(LIGHTRIG_SHARED_MODELS "/") + QLatin1String(path);
}

// Per pixel and channel |a - b|; fails when more than 0.5% of the pixels differ by more than 16 levels or
// the mean difference exceeds 1 level (rasterisers may differ on a few silhouette pixels).
QString compareImages(const QImage& got, const QImage& want) {
    if (got.size() != want.size())
        return QStringLiteral("size %1x%2, baseline %3x%4")
            .arg(got.width())
            .arg(got.height())
            .arg(want.width())
            .arg(want.height());
    const QImage a = got.convertToFormat(QImage::Format_RGBA8888),
                 b = want.convertToFormat(QImage::Format_RGBA8888);
    qint64 sum = 0, bad = 0;
    for (int y = 0; y < a.height(); ++y) {
        const uchar* p = a.constScanLine(y);
        const uchar* q = b.constScanLine(y);
        for (int x = 0; x < a.width(); ++x) {
            int worst = 0;
            for (int k = 0; k < 4; ++k) {
                const int d = std::abs(int(p[4 * x + k]) - int(q[4 * x + k]));
                worst = std::max(worst, d);
                sum += d;
            }
            if (worst > 16) ++bad;
        }
    }
    const double pixels = double(a.width()) * a.height();
    const double mean = sum / (pixels * 4);
    if (bad > pixels * 0.005 || mean > 1.0)
        return QStringLiteral("%1 pixels differ by more than 16 levels, mean difference %2")
            .arg(bad)
            .arg(mean);
    return {};
}

} // namespace

class TestRenderCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QProcessEnvironment m_env = QProcessEnvironment::systemEnvironment();

    Run lightrig(const QStringList& args, const QProcessEnvironment* env = nullptr) {
        return lrtest::runLightrig(QStringList{QStringLiteral("render")} + args, env ? env : &m_env);
    }
    QString path(const QString& name) const { return m_dir.filePath(name); }

    void checkBaseline(const QString& name, const QStringList& args) {
        const QString out = path(name + QStringLiteral(".png"));
        const Run r = lightrig(args + QStringList{QStringLiteral("-o"), out});
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        const QImage got(out);
        QVERIFY(!got.isNull());
        const QString baseline =
            QStringLiteral(LIGHTRIG_TEST_DATA "/render/baselines/") + name + QStringLiteral(".png");
        if (!QFile::exists(baseline)) {
            QFile::copy(out, baseline);
            QFAIL(
                qPrintable(QStringLiteral("no baseline: wrote %1; look at it and commit it").arg(baseline)));
        }
        const QString diff = compareImages(got, QImage(baseline));
        if (!diff.isEmpty()) {
            got.save(baseline + QStringLiteral(".actual.png"));
            QFAIL(qPrintable(QStringLiteral("%1 differs from its baseline: %2 (wrote %3.actual.png)")
                                 .arg(name, diff, baseline)));
        }
    }

  private slots:
    void initTestCase() {
        QVERIFY2(QFile::exists(QStringLiteral(LIGHTRIG_EXECUTABLE)), LIGHTRIG_EXECUTABLE);
        QVERIFY(m_dir.isValid());
        QDir(m_dir.path()).mkdir(QStringLiteral("xdg"));
        QFile::setPermissions(path(QStringLiteral("xdg")),
                              QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        m_env.insert(QStringLiteral("XDG_RUNTIME_DIR"), path(QStringLiteral("xdg")));
        QVERIFY(::mkfifo(QFile::encodeName(path(QStringLiteral("fifo.json"))).constData(), 0600) == 0);
    }

    void usageErrorsExit2_data() {
        QTest::addColumn<QStringList>("args");
        const QString m = suzanne(), o = QStringLiteral("/tmp/never-written.png");
        QTest::newRow("no model") << QStringList{QStringLiteral("-o"), o};
        QTest::newRow("empty model path") << QStringList{QString(), QStringLiteral("-o"), o}; // was exit 1
        QTest::newRow("no output") << QStringList{m};
        QTest::newRow("two models") << QStringList{m, m, QStringLiteral("-o"), o};
        QTest::newRow("unknown option") << QStringList{m, QStringLiteral("-o"), o, QStringLiteral("--shiny")};
        QTest::newRow("bad size") << QStringList{m, QStringLiteral("-o"), o, QStringLiteral("--size"),
                                                 QStringLiteral("12x")};
        QTest::newRow("zero size") << QStringList{m, QStringLiteral("-o"), o, QStringLiteral("--size"),
                                                  QStringLiteral("0x10")};
        QTest::newRow("camera and view") << QStringList{m,
                                                        QStringLiteral("-o"),
                                                        o,
                                                        QStringLiteral("--camera-index"),
                                                        QStringLiteral("0"),
                                                        QStringLiteral("--view"),
                                                        QStringLiteral("top")};
        QTest::newRow("bad view") << QStringList{m, QStringLiteral("-o"), o, QStringLiteral("--view"),
                                                 QStringLiteral("sideways")};
        QTest::newRow("bad camera index") << QStringList{
            m, QStringLiteral("-o"), o, QStringLiteral("--camera-index"), QStringLiteral("-1")};
        QTest::newRow("bad quality") << QStringList{m, QStringLiteral("-o"), o, QStringLiteral("--quality"),
                                                    QStringLiteral("best")};
        QTest::newRow("bad supersample")
            << QStringList{m, QStringLiteral("-o"), o, QStringLiteral("--supersample"), QStringLiteral("5")};
        QTest::newRow("bad exposure") << QStringList{m, QStringLiteral("-o"), o, QStringLiteral("--exposure"),
                                                     QStringLiteral("bright")};
        QTest::newRow("bad tonemap") << QStringList{m, QStringLiteral("-o"), o, QStringLiteral("--tonemap"),
                                                    QStringLiteral("filmic")};
        QTest::newRow("bad extension")
            << QStringList{m, QStringLiteral("-o"), QStringLiteral("/tmp/out.bmp")};
    }

    void usageErrorsExit2() {
        QFETCH(QStringList, args);
        const Run r = lightrig(args);
        QVERIFY2(r.code == 2, qPrintable(r.show()));
        QVERIFY(!QFile::exists(QStringLiteral("/tmp/never-written.png")));
    }

    // Issue 41: --help lists --msaa and its usage line the environment options; a side of 10 digits is
    // "larger than the limit", not a syntax error.
    void helpAndSizeMessages() {
        const Run help = lightrig({QStringLiteral("--help")});
        QCOMPARE(help.code, 0);
        const QString usage = help.lines().value(0);
        for (const char* option : {"[--msaa N]", "[--environment FILE|builtin:NAME|studio|none]",
                                   "[--environment-background visible|blurred|color]", "neutral|agx"})
            QVERIFY2(usage.contains(QLatin1String(option)), option);
        QVERIFY2(help.out.contains(QLatin1String("--msaa <N>")), qPrintable(help.out));
        const Run big = lightrig({suzanne(), QStringLiteral("-o"), QStringLiteral("/tmp/never-written.png"),
                                  QStringLiteral("--size"), QStringLiteral("1234567890x10")});
        QCOMPARE(big.code, 2);
        QVERIFY2(big.err.contains(QLatin1String("the width 1234567890 is larger than the limit 32768")),
                 qPrintable(big.show()));
    }

    // Issue 41: a rig of 1,000 errors says "(and 999 more errors)", not the 200 it lists.
    void everyRigErrorIsCounted() {
        LR_REQUIRE_DISPLAY();
        QByteArray lights;
        for (int i = 0; i < 1000; ++i)
            lights += QByteArray(i ? "," : "") + "{\"type\": \"laser\"}";
        QVERIFY(
            lrtest::writeFile(path(QStringLiteral("many.json")),
                              "{\"format\": \"lightrig\", \"version\": 1, \"lights\": [" + lights + "]}"));
        const Run r = lightrig({suzanne(), QStringLiteral("--rig"), path(QStringLiteral("many.json")),
                                QStringLiteral("-o"), path(QStringLiteral("never-many.png"))});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QLatin1String("(and 999 more errors)")), qPrintable(r.show()));
    }

    void failuresExit1AndWriteNothing_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        const QString out = path(QStringLiteral("kept.png"));
        const QString badRig = path(QStringLiteral("bad-rig.json"));
        QTest::newRow("missing model")
            << QStringList{path(QStringLiteral("nope.glb")), QStringLiteral("-o"), out}
            << QStringLiteral("nope.glb");
        QTest::newRow("not a model") << QStringList{badRig, QStringLiteral("-o"), out}
                                     << QStringLiteral("bad-rig.json");
        QTest::newRow("bad rig") << QStringList{suzanne(), QStringLiteral("--rig"), badRig,
                                                QStringLiteral("-o"), out}
                                 << QStringLiteral("bad-rig.json");
        QTest::newRow("missing rig") << QStringList{suzanne(), QStringLiteral("--rig"),
                                                    path(QStringLiteral("none.json")), QStringLiteral("-o"),
                                                    out}
                                     << QStringLiteral("none.json");
        QTest::newRow("rig is a FIFO")
            << QStringList{suzanne(), QStringLiteral("--rig"), path(QStringLiteral("fifo.json")),
                           QStringLiteral("-o"), out}
            << QStringLiteral("fifo.json: is not a regular file");
        QTest::newRow("camera out of range") << QStringList{suzanne(), QStringLiteral("--camera-index"),
                                                            QStringLiteral("3"), QStringLiteral("-o"), out}
                                             << QStringLiteral("camera");
        QTest::newRow("no such folder")
            << QStringList{suzanne(), QStringLiteral("-o"), path(QStringLiteral("no/such/dir/x.png"))}
            << QStringLiteral("does not exist");
    }

    void failuresExit1AndWriteNothing() {
        LR_REQUIRE_DISPLAY(); // without one, every render fails first with "needs an X display"
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        {
            QFile rig(path(QStringLiteral("bad-rig.json")));
            QVERIFY(rig.open(QIODevice::WriteOnly));
            rig.write("{\"format\": \"lightrig\", \"version\": 1, \"lights\": [{\"type\": \"laser\"}]}");
        }
        QFile kept(path(QStringLiteral("kept.png"))); // an earlier output stays as it was
        QVERIFY(kept.open(QIODevice::WriteOnly));
        kept.write("previous");
        kept.close();
        const Run r = lightrig(args);
        QVERIFY2(r.code == 1, qPrintable(r.show()));
        QVERIFY2(r.errorLines().size() == 1 && r.errorLines().first().contains(mentions),
                 qPrintable(r.show()));
        QVERIFY(kept.open(QIODevice::ReadOnly));
        QCOMPARE(kept.readAll(), QByteArray("previous"));
        QVERIFY(!QFile::exists(path(QStringLiteral("no/such/dir/x.png"))));
    }

    // Issue 18: models at extreme scales or seen through a broken camera rendered as the background alone,
    // with exit 0 and nothing said. Now: a framed image with a warning, or exit 1 with nothing written.
    void extremeModelsAreNeverAnEmptyImageInSilence_data() {
        QTest::addColumn<QString>("model");
        QTest::addColumn<QString>("warning");
        const QString hostile = QStringLiteral(LIGHTRIG_TEST_DATA "/model/hostile/");
        QTest::newRow("camera yfov 1e39, znear 1e-45") << hostile + QStringLiteral("gltf-camera-nan.gltf")
                                                       << QStringLiteral("has an unusable near plane");
        QTest::newRow("node scale 1e38")
            << hostile + QStringLiteral("gltf-node-huge-scale.gltf") << QString();
        QTest::newRow("coordinates 3e38") << hostile + QStringLiteral("ply-huge-coords.ply") << QString();
    }

    void extremeModelsAreNeverAnEmptyImageInSilence() {
        LR_REQUIRE_DISPLAY();
        QFETCH(QString, model);
        QFETCH(QString, warning);
        const QString out = path(QStringLiteral("extreme.png"));
        QFile::remove(out);
        const Run r =
            lightrig({model, QStringLiteral("-o"), out, QStringLiteral("--size"), QStringLiteral("64x48")});
        if (r.code == 1) { // nothing can be drawn, or nothing was drawable: said so, nothing written
            const bool undrawable = r.err.contains(QStringLiteral("nothing of ")) &&
                                    r.err.contains(QStringLiteral("can be drawn"));
            const bool dropped = r.err.contains(QStringLiteral("has no triangles")) &&
                                 r.err.contains(QStringLiteral("beyond ±1e+12"));
            QVERIFY2(undrawable || dropped, qPrintable(r.show()));
            QVERIFY(!QFile::exists(out));
            return;
        }
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        if (!warning.isEmpty()) QVERIFY2(r.err.contains(warning), qPrintable(r.show()));
        // The image shows the model: some pixel differs from the background of the corner.
        const QImage image(out);
        QVERIFY(!image.isNull());
        const QRgb background = image.pixel(0, 0);
        int covered = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                covered += image.pixel(x, y) != background;
        QVERIFY2(covered > 0, qPrintable(r.show()));
    }

    void withoutDisplayExplains() {
        QProcessEnvironment env = m_env;
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("WAYLAND_DISPLAY"));
        env.remove(QStringLiteral("QT_QPA_PLATFORM"));
        const Run r =
            lightrig({suzanne(), QStringLiteral("-o"), path(QStringLiteral("nodisplay.png"))}, &env);
        QVERIFY2(r.code == 1, qPrintable(r.show()));
        QVERIFY2(r.err.contains(QLatin1String("needs an X display; run it under xvfb-run -a")),
                 qPrintable(r.show()));
        QVERIFY(!QFile::exists(path(QStringLiteral("nodisplay.png"))));
    }

    // Issue 41: an output that is one of the inputs (the model, the rig) or another output (an image and
    // --summary) is refused before anything is written, whatever its spelling: "./", a symbolic link or a
    // hard link name the same file.
    void outputThatIsAnInputIsRefused_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QDir(m_dir.path()).mkpath(QStringLiteral("same"));
        const QString dir = path(QStringLiteral("same/"));
        const QString model = dir + QStringLiteral("Suzanne.gltf"), rig = dir + QStringLiteral("rig.json");
        const QString image = dir + QStringLiteral("image.png");
        const QString o = QStringLiteral("-o"), summary = QStringLiteral("--summary");
        QTest::newRow("summary is the rig")
            << QStringList{model, QStringLiteral("--rig"), rig, o, image, summary, rig}
            << QStringLiteral("the rig");
        QTest::newRow("summary is the model, spelled ./")
            << QStringList{model, o, image, summary, dir + QStringLiteral("./Suzanne.gltf")}
            << QStringLiteral("the model");
        QTest::newRow("summary is the image")
            << QStringList{model, o, image, summary, dir + QStringLiteral("../same/image.png")}
            << QStringLiteral("the image");
        QTest::newRow("image is a link to the rig")
            << QStringList{model, QStringLiteral("--rig"), rig, o, dir + QStringLiteral("rig-link.png")}
            << QStringLiteral("the rig");
        QTest::newRow("summary is a hard link to the model")
            << QStringList{model, o, image, summary, dir + QStringLiteral("model-hardlink.json")}
            << QStringLiteral("the model");
        QTest::newRow("image is the model's texture") // known once the model is imported
            << QStringList{model, o, dir + QStringLiteral("Suzanne_BaseColor.png")}
            << QStringLiteral("the model's texture");
    }
    void outputThatIsAnInputIsRefused() {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        if (mentions.contains(QLatin1String("texture"))) LR_REQUIRE_DISPLAY();
        const QString dir = path(QStringLiteral("same/"));
        const QString suzanneDir = QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/suzanne/");
        for (const QString& f : QDir(suzanneDir).entryList(QDir::Files))
            QVERIFY(lrtest::copyWritable(suzanneDir + f, dir + f));
        QVERIFY(lrtest::writeFile(dir + QStringLiteral("rig.json"), lr::writeRigJson(lr::pbrDefaultRig())));
        QVERIFY(lrtest::writeFile(dir + QStringLiteral("image.png"), "previous"));
        QFile::remove(dir + QStringLiteral("rig-link.png"));
        QFile::remove(dir + QStringLiteral("model-hardlink.json"));
        QVERIFY(QFile::link(dir + QStringLiteral("rig.json"), dir + QStringLiteral("rig-link.png")));
        QVERIFY(::link(QFile::encodeName(dir + QStringLiteral("Suzanne.gltf")).constData(),
                       QFile::encodeName(dir + QStringLiteral("model-hardlink.json")).constData()) == 0);
        const QByteArray model = lrtest::readFile(dir + QStringLiteral("Suzanne.gltf"));
        const QByteArray rig = lrtest::readFile(dir + QStringLiteral("rig.json"));
        const Run r = lightrig(args + QStringList{QStringLiteral("--size"), QStringLiteral("32x24")});
        QVERIFY2(r.code == 1, qPrintable(r.show()));
        QVERIFY2(r.errorLines().size() == 1 &&
                     r.errorLines().first().contains(QLatin1String("cannot write")) &&
                     r.errorLines().first().contains(mentions),
                 qPrintable(r.show()));
        QCOMPARE(lrtest::readFile(dir + QStringLiteral("Suzanne.gltf")), model);
        QCOMPARE(lrtest::readFile(dir + QStringLiteral("rig.json")), rig);
        QCOMPARE(lrtest::readFile(dir + QStringLiteral("image.png")), QByteArray("previous"));
        QCOMPARE(lrtest::readFile(dir + QStringLiteral("Suzanne_BaseColor.png")),
                 lrtest::readFile(
                     QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/models/suzanne/Suzanne_BaseColor.png")));
    }

    void writesPngAndJpeg() {
        LR_REQUIRE_DISPLAY();
        const Run png = lightrig({suzanne(), QStringLiteral("-o"), path(QStringLiteral("default.png"))});
        QVERIFY2(png.code == 0, qPrintable(png.show()));
        const QImage image(path(QStringLiteral("default.png")));
        QCOMPARE(image.size(), QSize(1280, 720)); // the default size
        QCOMPARE(QColor(image.pixel(0, 0)).alpha(), 255);

        const Run jpg = lightrig(
            {suzanne(), QStringLiteral("-o"), path(QStringLiteral("out.jpeg")), QStringLiteral("--size"),
             QStringLiteral("160x90"), QStringLiteral("--view"), QStringLiteral("front"),
             QStringLiteral("--tonemap"), QStringLiteral("aces"), QStringLiteral("--exposure"),
             QStringLiteral("1.5"), QStringLiteral("--supersample"), QStringLiteral("2")});
        QVERIFY2(jpg.code == 0, qPrintable(jpg.show()));
        QFile f(path(QStringLiteral("out.jpeg")));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QVERIFY(f.read(3) == QByteArray("\xFF\xD8\xFF")); // JPEG, by extension
        QCOMPARE(QImage(path(QStringLiteral("out.jpeg"))).size(), QSize(160, 90));

        const Run clear =
            lightrig({suzanne(), QStringLiteral("-o"), path(QStringLiteral("clear.png")),
                      QStringLiteral("--size"), QStringLiteral("160x90"), QStringLiteral("--transparent")});
        QVERIFY2(clear.code == 0, qPrintable(clear.show()));
        const QImage t(path(QStringLiteral("clear.png")));
        QCOMPARE(qAlpha(t.pixel(0, 0)), 0);
        QCOMPARE(qAlpha(t.pixel(80, 45)), 255);
    }

    void baselineSuzanne() {
        LR_REQUIRE_DISPLAY();
        checkBaseline(QStringLiteral("suzanne-default-rig"),
                      {suzanne(), QStringLiteral("--size"), QStringLiteral("320x240")});
        checkBaseline(QStringLiteral("suzanne-three-point-top-aces"),
                      {suzanne(), QStringLiteral("--rig"),
                       QStringLiteral(LIGHTRIG_SOURCE_DIR "/resources/presets/three-point.json"),
                       QStringLiteral("--view"), QStringLiteral("top"), QStringLiteral("--size"),
                       QStringLiteral("240x240"), QStringLiteral("--tonemap"), QStringLiteral("aces")});
    }

    void baselineSharedModels() {
        LR_REQUIRE_DISPLAY();
        if (!QFile::exists(shared("gltf/khronos/Duck/glTF-Binary/Duck.glb")))
            QSKIP("../shared/models is not here (third-party test models)");
        checkBaseline(QStringLiteral("duck-camera0"), {shared("gltf/khronos/Duck/glTF-Binary/Duck.glb"),
                                                       QStringLiteral("--size"), QStringLiteral("320x240")});
        checkBaseline(QStringLiteral("helmet-8pt"),
                      {shared("bench/helmet_8pt.glb"), QStringLiteral("--size"), QStringLiteral("320x180")});
        checkBaseline(QStringLiteral("box-textured-three-quarter"),
                      {shared("gltf/khronos/BoxTextured/glTF-Binary/BoxTextured.glb"),
                       QStringLiteral("--view"), QStringLiteral("three-quarter"), QStringLiteral("--size"),
                       QStringLiteral("200x200")});
    }
};

QTEST_GUILESS_MAIN(TestRenderCli)
#include "tst_rendercli.moc"
