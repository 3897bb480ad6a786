// Multi-layer OpenEXR (issue 37, light mixing; model/exrencode.h, exrdecode.h) in process: round trips in
// float and half (values, layer names, channel order, attributes), depth kept float under half, the
// encoder's refusals, layer names made from anything, the single-layer encodeExrRgba, and oiiotool reading
// the layers ("key.R") when it is installed.
#include "exrfixtures.h"
#include "model/exrio.h"

#include <Imath/half.h>
#include <ImfChannelList.h>
#include <ImfInputFile.h>

#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <algorithm>
#include <limits>
#include <map>

using namespace lr;
using namespace exrtest;

namespace {

// The file's own channel types, read with OpenEXR: "key.R" -> HALF.
std::map<QString, Imf::PixelType> channelTypes(const QByteArray& bytes) {
    exrio::MemoryIStream stream(bytes);
    Imf::InputFile file(stream, 1);
    std::map<QString, Imf::PixelType> types;
    for (auto it = file.header().channels().begin(); it != file.header().channels().end(); ++it)
        types[QString::fromUtf8(it.name())] = it.channel().type;
    return types;
}

float asHalf(float v) {
    return float(Imath::half(std::isfinite(v) ? std::clamp(v, -65504.0f, 65504.0f) : v));
}

bool isDepth(const ExrLayer& l) {
    return l.channels == QStringList{"Z"};
}

void expectRefused(int w, int h, const std::vector<ExrLayer>& layers,
                   const std::vector<std::pair<QString, QString>>& attributes, const QString& part) {
    QString error;
    const QByteArray bytes = encodeExrLayers(w, h, layers, attributes, ExrPixel::Half, &error);
    QVERIFY2(bytes.isEmpty(), qPrintable(part));
    QVERIFY2(error.contains(part), qPrintable(error + " lacks " + part));
}

} // namespace

class TestExrLayers : public QObject {
    Q_OBJECT
  private slots:
    void roundTrip_data() {
        QTest::addColumn<bool>("half");
        QTest::newRow("float") << false;
        QTest::newRow("half") << true;
    }
    // 19 × 70: rows in two strips of the writer and five ZIP blocks, the last ones partial.
    void roundTrip() {
        QFETCH(bool, half);
        const int w = 19, h = 70;
        const std::vector<ExrLayer> written = aovLayers(w, h);
        const QByteArray bytes = encodeOrFail(w, h, written, half ? ExrPixel::Half : ExrPixel::Float);
        QString error;
        const std::optional<ExrFile> file = decodeExrLayers(bytes, &error);
        QVERIFY2(file, qPrintable(error));
        QCOMPARE(file->width, w);
        QCOMPARE(file->height, h);
        QStringList names, sortedNames;
        for (const ExrLayer& l : file->layers)
            names << l.name;
        for (const ExrLayer& l : written)
            sortedNames << l.name;
        sortedNames.sort();
        QCOMPARE(names, sortedNames); // by name, the unnamed one first
        for (const ExrLayer& want : written) {
            const ExrLayer* got = file->layer(want.name);
            QVERIFY2(got, qPrintable(want.name));
            QCOMPARE(got->channels, want.channels); // R G B A, X Y Z: the order they were written in
            QCOMPARE(got->pixels.size(), want.pixels.size());
            for (size_t i = 0; i < want.pixels.size(); ++i) {
                const float expected = half && !isDepth(want) ? asHalf(want.pixels[i]) : want.pixels[i];
                if (got->pixels[i] != expected)
                    QFAIL(qPrintable(QStringLiteral("layer \"%1\" value %2: %3, expected %4")
                                         .arg(want.name)
                                         .arg(i)
                                         .arg(double(got->pixels[i]), 0, 'g', 9)
                                         .arg(double(expected), 0, 'g', 9)));
            }
        }
        auto attributes = aovAttributes();
        std::sort(attributes.begin(), attributes.end());
        QCOMPARE(file->attributes, attributes);
        QVERIFY(!file->layer("absent"));
    }
    // Depth keeps float when half is asked (a half holds at most 65504 and 3 digits); a normal's Z follows
    // its layer; finite colours beyond half's range clamp to ±65504, inf and NaN stay.
    void depthStaysFloatUnderHalf() {
        std::vector<ExrLayer> layers = aovLayers(4, 3);
        layers[1].pixels[0] = 70000.0f;
        layers[1].pixels[1] = -1e9f;
        layers[1].pixels[2] = std::numeric_limits<float>::infinity();
        layers[1].pixels[3] = std::numeric_limits<float>::quiet_NaN();
        const QByteArray bytes = encodeOrFail(4, 3, layers, ExrPixel::Half);
        const auto types = channelTypes(bytes);
        QCOMPARE(types.at("depth.Z"), Imf::FLOAT);
        QCOMPARE(types.at("normal.Z"), Imf::HALF);
        QCOMPARE(types.at("key.R"), Imf::HALF);
        QCOMPARE(types.at("A"), Imf::HALF);
        QString error;
        const std::optional<ExrFile> file = decodeExrLayers(bytes, &error);
        QVERIFY2(file, qPrintable(error));
        QCOMPARE(file->layer("depth")->pixels, layers.back().pixels);
        QCOMPARE(file->layer("depth")->pixels[1], 123456.78f);
        const std::vector<float>& key = file->layer("key")->pixels;
        QCOMPARE(key[0], 65504.0f);
        QCOMPARE(key[1], -65504.0f);
        QVERIFY(std::isinf(key[2]) && key[2] > 0);
        QVERIFY(std::isnan(key[3]));
        for (const auto& [name, type] : channelTypes(encodeOrFail(4, 3, layers, ExrPixel::Float)))
            QVERIFY2(type == Imf::FLOAT, qPrintable(name));
    }
    // The file sorts channels by name; they come back R, G, B, A, X, Y, Z, then by name, whatever the
    // order they were given in, each with its own values.
    void channelOrder() {
        const std::vector<ExrLayer> written{makeLayer("mixed", {"B", "extra", "R", "A", "G"}, 3, 2, 0),
                                            makeLayer("grey", {"A", "Y"}, 3, 2, 1)};
        QString error;
        const std::optional<ExrFile> file =
            decodeExrLayers(encodeOrFail(3, 2, written, ExrPixel::Float), &error);
        QVERIFY2(file, qPrintable(error));
        QCOMPARE(file->layer("mixed")->channels, (QStringList{"R", "G", "B", "A", "extra"}));
        QCOMPARE(file->layer("grey")->channels, (QStringList{"A", "Y"}));
        for (const ExrLayer& want : written) {
            const ExrLayer& got = *file->layer(want.name);
            const qsizetype n = want.channels.size();
            for (qsizetype c = 0; c < n; ++c) {
                const qsizetype at = got.channels.indexOf(want.channels[c]);
                for (size_t p = 0; p < 6; ++p)
                    QCOMPARE(got.pixels[p * size_t(n) + size_t(at)], want.pixels[p * size_t(n) + size_t(c)]);
            }
        }
    }
    void refusals() {
        const auto one = [](const QString& name, const QStringList& channels = {"R", "G", "B"}) {
            return makeLayer(name, channels, 2, 2, 0);
        };
        expectRefused(2, 2, {}, {}, "there is no image to write");
        expectRefused(0, 2, {one("key")}, {}, "there is no image to write");
        expectRefused(40000, 1, {one("key")}, {}, "larger than the limit of 32768 on a side");
        expectRefused(2, 2, {one("key"), one("key")}, {}, "two layers are called \"key\"");
        expectRefused(2, 2, {one(""), one("")}, {}, "two layers are unnamed");
        expectRefused(2, 2, {one("key light")}, {}, "layer \"key light\": \" \" is not allowed");
        expectRefused(2, 2, {one("key.fill")}, {}, "\".\" is not allowed");
        expectRefused(2, 2, {one("Schlüssel")}, {}, "\"ü\" is not allowed");
        expectRefused(2, 2, {one(QString(65, 'k'))}, {}, "longer than 64 characters");
        expectRefused(2, 2, {one("key", {})}, {}, "layer \"key\" has no channel");
        expectRefused(2, 2, {one("key", {"R", "R"})}, {}, "layer \"key\" has channel \"R\" twice");
        expectRefused(2, 2, {one("key", {"R", ""})}, {}, "a channel name is empty");
        expectRefused(2, 2, {one("key", {"R.G"})}, {}, "channel \"R.G\" has \".\"");
        ExrLayer shortLayer = one("key");
        shortLayer.pixels.pop_back();
        expectRefused(2, 2, {shortLayer}, {},
                      "layer \"key\" has 11 values for 2×2 pixels of 3 channels (12 expected)");
        QStringList many;
        for (int i = 0; i < 257; ++i)
            many << QStringLiteral("c%1").arg(i);
        expectRefused(2, 2, {one("wide", many)}, {}, "257 channels in all is more than the limit of 256");
        expectRefused(2, 2, {one("")}, {{"compression", "none"}},
                      "attribute \"compression\" is one OpenEXR defines");
        expectRefused(2, 2, {one("")}, {{"a", "1"}, {"a", "2"}}, "attribute \"a\" appears twice");
        expectRefused(2, 2, {one("")}, {{"", "1"}}, "an attribute name is empty");
        expectRefused(2, 2, {one("")}, {{QString(256, 'n'), "1"}}, "longer than 255 bytes");
        expectRefused(2, 2, {one("")}, {{"line\nbreak", "1"}}, "control character");
        // Names up to the limits are written (a 64-character layer's channels need OpenEXR's long names).
        QString error;
        QVERIFY2(!encodeExrLayers(2, 2, {one(QString(64, 'k'))}, {{QString(255, 'n'), "v"}}, ExrPixel::Half,
                                  &error)
                      .isEmpty(),
                 qPrintable(error));
    }
    void layerNames() {
        for (const QString& valid : QStringList{"key", "Key_light-2", "_", "0", QString(64, 'k')}) {
            QVERIFY2(exrLayerNameProblem(valid).isEmpty(), qPrintable(valid));
            QCOMPARE(exrLayerName(valid), valid);
        }
        QCOMPARE(exrLayerName("Key light (L)"), QStringLiteral("Key_light_L"));
        QCOMPARE(exrLayerName("Schlüssel"), QStringLiteral("Schlussel"));
        QCOMPARE(exrLayerName("  rim.left  "), QStringLiteral("rim_left"));
        QCOMPARE(exrLayerName("主光"), QStringLiteral("layer"));
        QCOMPARE(exrLayerName(""), QStringLiteral("layer"));
        for (const QString& any :
             QStringList{"a b", "über", "x.y.z", "\t", QString(200, QChar(0x00e9)), "-", "🙂 fill"}) {
            const QString name = exrLayerName(any);
            QVERIFY2(!name.isEmpty() && exrLayerNameProblem(name).isEmpty(), qPrintable(any + " -> " + name));
        }
        const QStringList in{"key",           "key", "Key light", "Key_light", "albedo", QString(64, 'k'),
                             QString(64, 'k')};
        const QStringList out = uniqueExrLayerNames(in, {"albedo", "depth"});
        QCOMPARE(out.size(), in.size());
        QCOMPARE(out[0], QStringLiteral("key"));
        QCOMPARE(out[1], QStringLiteral("key_2"));
        QCOMPARE(out[4], QStringLiteral("albedo_2"));
        QStringList seen{"albedo", "depth"};
        for (const QString& name : out) {
            QVERIFY2(exrLayerNameProblem(name).isEmpty() && !name.isEmpty(), qPrintable(name));
            QVERIFY2(!seen.contains(name), qPrintable(name + " twice"));
            seen << name;
        }
    }
    // The single-layer writer is the layered one: one unnamed float RGBA layer.
    void rgba() {
        const ExrLayer layer = makeLayer("", {"R", "G", "B", "A"}, 5, 3, 7);
        QString error;
        const QByteArray bytes =
            encodeExrRgba(5, 3, layer.pixels.data(), {{"lightrig/samples", "8"}}, &error);
        QVERIFY2(!bytes.isEmpty(), qPrintable(error));
        const std::optional<ExrFile> file = decodeExrLayers(bytes, &error);
        QVERIFY2(file, qPrintable(error));
        QCOMPARE(file->layers.size(), size_t(1));
        QCOMPARE(file->layers[0].name, QString());
        QCOMPARE(file->layers[0].channels, layer.channels);
        QCOMPARE(file->layers[0].pixels, layer.pixels);
        QCOMPARE(file->attributes, (std::vector<std::pair<QString, QString>>{{"lightrig/samples", "8"}}));
        QVERIFY(encodeExrRgba(5, 3, nullptr, {}, &error).isEmpty());
        QCOMPARE(error, QStringLiteral("there is no image to write"));
    }
    // oiiotool (Debian openimageio-tools; scripts/setup.sh installs it) reads the layers as "layer.channel",
    // depth as float and the rest as half.
    void oiiotoolReadsTheLayers() {
        const QString oiiotool = QStandardPaths::findExecutable("oiiotool");
        if (oiiotool.isEmpty())
            QSKIP("oiiotool is not installed (Debian: apt-get install openimageio-tools; scripts/setup.sh "
                  "installs it)");
        QTemporaryDir dir;
        const QString path = dir.filePath("aovs.exr");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        const std::vector<ExrLayer> layers = aovLayers(8, 4);
        qsizetype channels = 0;
        for (const ExrLayer& l : layers)
            channels += l.channels.size();
        f.write(encodeOrFail(8, 4, layers, ExrPixel::Half));
        f.close();
        QProcess p;
        p.start(oiiotool, {"--info", "-v", path});
        QVERIFY(p.waitForFinished(60'000));
        const QString out = QString::fromUtf8(p.readAllStandardOutput() + p.readAllStandardError());
        QVERIFY2(p.exitCode() == 0, qPrintable(out));
        QVERIFY2(out.contains(QStringLiteral("8 x    4, %1 channel").arg(channels)), qPrintable(out));
        for (const QString channel : {"R (half)", "A (half)", "key.R (half)", "rim_2.B (half)",
                                      "albedo.G (half)", "normal.Z (half)", "depth.Z (float)"})
            QVERIFY2(out.contains(channel), qPrintable(channel + " not in:\n" + out));
        QVERIFY2(out.contains("lightrig/toneMap: \"agx\""), qPrintable(out));
        QVERIFY2(out.contains("compression: \"zip\""), qPrintable(out));
    }
};

QTEST_GUILESS_MAIN(TestExrLayers)
#include "tst_exrlayers.moc"
