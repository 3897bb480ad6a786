// Issue 37: `lightrig mix` re-balances the light groups of a multi-layer EXR (scene/renderlayersexr.h) with
// mix files: the mixed image equals mixGroupImages of the file's layers, several mixes write one image
// each, bad mix files and images fail naming the file and the field and write nothing. No display needed.
#include "support/cli.h"
#include "support/files.h"

#include "core/lightmix.h"
#include "model/exrdecode.h"
#include "scene/renderlayersexr.h"

#include <QDir>
#include <QImage>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

using namespace lr;
using namespace lrtest;

namespace {

FloatImage ramp(int w, int h, glm::vec3 colour, float phase) {
    FloatImage img;
    img.width = w;
    img.height = h;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            img.pixels.push_back(glm::vec4(
                colour * (0.25f + 0.5f * std::fabs(std::sin(phase + 0.3f * float(x + 2 * y)))), 1.0f));
    return img;
}

RenderLayers threeGroups() {
    RenderLayers l;
    l.groups = {{QStringLiteral("Key light"), LightGroupKind::Lights, {0}},
                {QStringLiteral("rim"), LightGroupKind::Lights, {1}},
                {QStringLiteral("environment"), LightGroupKind::Environment, {}}};
    l.groupImages = {ramp(8, 6, {1.0f, 0.8f, 0.6f}, 0.0f), ramp(8, 6, {0.2f, 0.3f, 1.0f}, 1.0f),
                     ramp(8, 6, {0.1f, 0.1f, 0.1f}, 2.0f)};
    l.beauty = mixGroupImages(l, LightMix{});
    return l;
}

const QByteArray kMix = R"({"format": "lightrig-mix", "version": 1, "groups": {
    "Key light": {"enabled": true, "ev": 1, "tint": [1, 0.5, 0.25]}, "rim": {"enabled": false}}})";

} // namespace

class TestMixCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_aovs;
    QString path(const QString& name) const { return m_dir.filePath(name); }

  private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        QString error;
        const QByteArray bytes = encodeRenderLayersExr(
            threeGroups(), {{QStringLiteral("lightrig/exposureEV"), QStringLiteral("0")}}, ExrPixel::Float,
            &error);
        QVERIFY2(!bytes.isEmpty(), qPrintable(error));
        m_aovs = path(QStringLiteral("aovs.exr"));
        QVERIFY(writeFile(m_aovs, bytes));
        QVERIFY(writeFile(path(QStringLiteral("warm.json")), kMix));
    }

    void layersRoundTripThroughTheFile() {
        QString error;
        const std::optional<ExrFile> file = decodeExrLayersFile(m_aovs, &error);
        QVERIFY2(file, qPrintable(error));
        const std::optional<RenderLayers> back = renderLayersFromExr(*file, &error);
        QVERIFY2(back, qPrintable(error));
        const RenderLayers l = threeGroups();
        QCOMPARE(groupNames(back->groups), groupNames(l.groups));
        QCOMPARE(back->groups[2].kind, LightGroupKind::Environment);
        for (size_t g = 0; g < l.groupImages.size(); ++g)
            QCOMPARE(back->groupImages[g].pixels, l.groupImages[g].pixels);
    }

    void mixesOneImage() {
        const QString out = path(QStringLiteral("warm.exr"));
        const CliRun r = runLightrig({QStringLiteral("mix"), m_aovs, QStringLiteral("--mix"),
                                      path(QStringLiteral("warm.json")), QStringLiteral("-o"), out},
                                     nullptr);
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        QString error;
        const std::optional<ExrFile> file = decodeExrLayersFile(out, &error);
        QVERIFY2(file, qPrintable(error));
        const ExrLayer* rgba = file->layer(QString());
        QVERIFY(rgba);
        const LightMix mix = *readLightMix(kMix, QStringLiteral("warm.json")).mix;
        const FloatImage expected = mixGroupImages(threeGroups(), mix);
        const qsizetype n = rgba->channels.size();
        QCOMPARE(rgba->channels.first(), QStringLiteral("R"));
        for (size_t i = 0; i < expected.pixels.size(); ++i)
            for (int c = 0; c < 3; ++c)
                QCOMPARE(rgba->pixels[i * size_t(n) + size_t(c)], expected.pixels[i][c]);
        // The mix changed the image: the key doubled and tinted, the rim gone.
        QVERIFY(std::abs(expected.pixels[0].x - threeGroups().beauty.pixels[0].x) > 1e-3f);
    }

    void severalMixesWriteOneImageEach() {
        QVERIFY(writeFile(path(QStringLiteral("cool.json")),
                          R"({"format": "lightrig-mix", "version": 1, "groups": {"rim": {"ev": 2}}})"));
        const QString folder = path(QStringLiteral("looks"));
        QVERIFY(QDir().mkpath(folder));
        const CliRun r = runLightrig({QStringLiteral("mix"), m_aovs, QStringLiteral("--mix"),
                                      path(QStringLiteral("warm.json")), QStringLiteral("--mix"),
                                      path(QStringLiteral("cool.json")), QStringLiteral("-o"), folder});
        QVERIFY2(r.code == 0, qPrintable(r.show()));
        const QImage warm(QDir(folder).filePath(QStringLiteral("warm.png"))),
            cool(QDir(folder).filePath(QStringLiteral("cool.png")));
        QCOMPARE(warm.size(), QSize(8, 6));
        QCOMPARE(cool.size(), QSize(8, 6));
        QVERIFY(warm != cool);
    }

    void badInputFailsNamingFileAndFieldAndWritesNothing_data() {
        QTest::addColumn<QByteArray>("mix");
        QTest::addColumn<QString>("error");
        QTest::newRow("ev")
            << QByteArray(R"({"format": "lightrig-mix", "version": 1, "groups": {"rim": {"ev": "up"}}})")
            << "bad.json: groups.rim.ev: must be";
        QTest::newRow("unknown group")
            << QByteArray(R"({"format": "lightrig-mix", "version": 1, "groups": {"fill": {}}})")
            << "bad.json: groups.fill: no such light group in the image; it has Key light, rim, environment";
        QTest::newRow("not json") << QByteArray("{") << "bad.json:";
    }
    void badInputFailsNamingFileAndFieldAndWritesNothing() {
        QFETCH(QByteArray, mix);
        QFETCH(QString, error);
        QVERIFY(writeFile(path(QStringLiteral("bad.json")), mix));
        const QString out = path(QStringLiteral("never.png"));
        const CliRun r = runLightrig({QStringLiteral("mix"), m_aovs, QStringLiteral("--mix"),
                                      path(QStringLiteral("bad.json")), QStringLiteral("-o"), out});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(error), qPrintable(r.show()));
        QVERIFY(!QFile::exists(out));
    }

    void notAnExrFails() {
        QVERIFY(writeFile(path(QStringLiteral("fake.exr")), "not an exr at all"));
        const CliRun r = runLightrig({QStringLiteral("mix"), path(QStringLiteral("fake.exr")),
                                      QStringLiteral("--mix"), path(QStringLiteral("warm.json")),
                                      QStringLiteral("-o"), path(QStringLiteral("x.png"))});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("fake.exr")), qPrintable(r.show()));
    }

    void usageErrors() {
        QCOMPARE(
            runLightrig({QStringLiteral("mix"), m_aovs, QStringLiteral("-o"), path(QStringLiteral("x.png"))})
                .code,
            2);
        QCOMPARE(runLightrig({QStringLiteral("mix"), m_aovs, QStringLiteral("--mix"),
                              path(QStringLiteral("warm.json")), QStringLiteral("-o"),
                              path(QStringLiteral("x.tiff"))})
                     .code,
                 2);
        QCOMPARE(runLightrig({QStringLiteral("mix"), m_aovs, QStringLiteral("--mix"),
                              path(QStringLiteral("warm.json")), QStringLiteral("--mix"),
                              path(QStringLiteral("warm.json")), QStringLiteral("-o"), m_dir.path()})
                     .code,
                 2); // two looks of one name
    }
};

QTEST_GUILESS_MAIN(TestMixCli)
#include "tst_mixcli.moc"
