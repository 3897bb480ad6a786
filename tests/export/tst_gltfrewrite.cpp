// The glTF rewrite (core/gltfrewrite.h): what it adds and changes, that everything else stays byte for byte
// (the BIN chunk, the materials' and animations' JSON text), and that malformed input is an error.
#include "core/gltfrewrite.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTest>

using namespace lr;

namespace {

// Odd but valid formatting (spaces, key order, 1.0, an escaped string) that a re-serialiser would change.
const QByteArray kMaterials =
    R"([ {"pbrMetallicRoughness" : {"roughnessFactor":0.10, "baseColorFactor":[1.0,0.5, 0.25,1]}, "name":"M\u00e9tal"} ])";
const QByteArray kAnimations = R"([{"channels":[{"sampler":0,"target":{"node":0,"path":"rotation"}}],)"
                               R"("samplers":[{"input":0,"output":1, "interpolation":"STEP"}]}])";
const QByteArray kJson =
    R"({"asset":{"version":"2.0","generator":"hand"},"scene":0,"scenes":[{"nodes":[0,1]}],)"
    R"("nodes":[{"name":"lamp","extensions":{"KHR_lights_punctual":{"light":0},"EXT_x":{"a":1}}},)"
    R"({"camera":0,"translation":[0,0,3]}],"cameras":[{"type":"perspective","perspective":{"yfov":1,"znear":0.1}}],)"
    R"("materials":)" +
    kMaterials + R"(,"animations":)" + kAnimations +
    R"(,"buffers":[{"byteLength":5}],"extensionsUsed":["EXT_x","KHR_lights_punctual"],)"
    R"("extensions":{"KHR_lights_punctual":{"lights":[{"type":"point"}]}},"extras":{"mine":[1, 2]}})";

QByteArray bin() {
    return QByteArray("\x01\x02\x03\x04\x05\x00\x00\x00", 8); // 5 bytes of data, padded
}

QByteArray binChunk() {
    QByteArray c("\x08\x00\x00\x00\x42\x49\x4E\x00", 8);
    return c + bin();
}

GltfAdditions twoLightsAndCamera() {
    GltfAdditions a;
    GltfLight p;
    p.name = QStringLiteral("Key");
    p.type = QStringLiteral("point");
    p.intensity = 10;
    p.translation = {1, 2, 3};
    GltfLight d = p;
    d.type = QStringLiteral("directional");
    a.lights = {p, d};
    a.camera = makeGltfCamera(QStringLiteral("view"), {0, 0, 5}, {0, 0, -1}, {0, 1, 0}, 40, 0.1, 50);
    a.note = {{QStringLiteral("generator"), QStringLiteral("LightRig")}};
    return a;
}

QJsonObject parse(const QByteArray& json) {
    QJsonParseError e;
    const QJsonDocument d = QJsonDocument::fromJson(json, &e);
    if (e.error != QJsonParseError::NoError) qWarning() << e.errorString() << json;
    return d.object();
}

} // namespace

class TestGltfRewrite : public QObject {
    Q_OBJECT
  private slots:
    void glbKeepsBinAndUnrelatedJsonByteForByte() {
        const QByteArray glb = writeGlb(kJson, binChunk());
        QString error;
        const auto in = parseGlb(glb, &error);
        QVERIFY2(in, qPrintable(error));
        QVERIFY(in->hasBin);
        QCOMPARE(in->bin, bin());
        const GltfRewriteResult r = rewriteGltfJson(in->json, twoLightsAndCamera());
        QVERIFY2(r.ok(), qPrintable(r.error));
        const QByteArray out = writeGlb(r.json, in->rest);
        QCOMPARE(out.size() % 4, 0);
        const auto back = parseGlb(out, &error);
        QVERIFY2(back, qPrintable(error));
        QCOMPARE(back->rest, binChunk()); // the BIN chunk, byte for byte
        QVERIFY(r.json.contains("\"materials\":" + kMaterials));
        QVERIFY(r.json.contains("\"animations\":" + kAnimations));
        QVERIFY(r.json.contains(R"("EXT_x":{"a":1})"));
        QVERIFY(r.json.contains(R"("mine":[1, 2])"));
    }

    void addsLightsNodesCameraAndNote() {
        const GltfRewriteResult r = rewriteGltfJson(kJson, twoLightsAndCamera());
        QVERIFY2(r.ok(), qPrintable(r.error));
        const QJsonObject root = parse(r.json);
        const QJsonArray lights = root[QStringLiteral("extensions")][QStringLiteral("KHR_lights_punctual")]
                                      [QStringLiteral("lights")]
                                          .toArray();
        QCOMPARE(lights.size(), 2); // the file's light replaced
        const QJsonArray nodes = root[QStringLiteral("nodes")].toArray();
        QCOMPARE(nodes.size(), 5);
        // The lamp lost the file's light but kept its other extension; the camera node points one further.
        QVERIFY(!nodes[0][QStringLiteral("extensions")].toObject().contains(
            QStringLiteral("KHR_lights_punctual")));
        QVERIFY(nodes[0][QStringLiteral("extensions")].toObject().contains(QStringLiteral("EXT_x")));
        QCOMPARE(nodes[1][QStringLiteral("camera")].toInt(), 1);
        QCOMPARE(nodes[2][QStringLiteral("extensions")][QStringLiteral("KHR_lights_punctual")]
                      [QStringLiteral("light")]
                          .toInt(),
                 0);
        QCOMPARE(nodes[3][QStringLiteral("extensions")][QStringLiteral("KHR_lights_punctual")]
                      [QStringLiteral("light")]
                          .toInt(),
                 1);
        QCOMPARE(nodes[4][QStringLiteral("camera")].toInt(), 0);
        QCOMPARE(root[QStringLiteral("scenes")][0][QStringLiteral("nodes")].toArray(),
                 (QJsonArray{0, 1, 2, 3, 4}));
        QCOMPARE(root[QStringLiteral("cameras")].toArray().size(), 2);
        QCOMPARE(root[QStringLiteral("cameras")][0][QStringLiteral("name")].toString(),
                 QStringLiteral("view"));
        QCOMPARE(root[QStringLiteral("extensionsUsed")].toArray(),
                 (QJsonArray{QStringLiteral("EXT_x"), QStringLiteral("KHR_lights_punctual")}));
        QCOMPARE(root[QStringLiteral("extras")][QStringLiteral("lightrig")][QStringLiteral("generator")]
                     .toString(),
                 QStringLiteral("LightRig"));
        QCOMPARE(root[QStringLiteral("extras")][QStringLiteral("mine")].toArray().size(), 2);
        QVERIFY(r.notes.join(QLatin1Char(' ')).contains(QStringLiteral("1 light(s) replaced")));
    }

    void noLightsLeavesNoExtension() {
        GltfAdditions none;
        const GltfRewriteResult r = rewriteGltfJson(kJson, none);
        QVERIFY2(r.ok(), qPrintable(r.error));
        const QJsonObject root = parse(r.json);
        QVERIFY(!root.contains(QStringLiteral("extensions")));
        QCOMPARE(root[QStringLiteral("extensionsUsed")].toArray(), QJsonArray{QStringLiteral("EXT_x")});
        QCOMPARE(root[QStringLiteral("cameras")].toArray().size(), 1);
        QCOMPARE(root[QStringLiteral("nodes")][1][QStringLiteral("camera")].toInt(), 0);
    }

    void realGltfKeepsItsParts() {
        QFile f(QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf"));
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray src = f.readAll();
        const GltfRewriteResult r = rewriteGltfJson(src, twoLightsAndCamera());
        QVERIFY2(r.ok(), qPrintable(r.error));
        const QJsonObject before = parse(src), after = parse(r.json);
        for (const char* key :
             {"meshes", "accessors", "bufferViews", "buffers", "materials", "textures", "images"})
            QCOMPARE(after.value(QLatin1String(key)), before.value(QLatin1String(key)));
        QCOMPARE(after[QStringLiteral("nodes")].toArray().size(),
                 before[QStringLiteral("nodes")].toArray().size() + 3);
    }

    void glbToGltfEmbedsTheBinAsDataUri() {
        GltfAdditions a = twoLightsAndCamera();
        a.embedBinAsUri = bin();
        const GltfRewriteResult r = rewriteGltfJson(kJson, a);
        QVERIFY2(r.ok(), qPrintable(r.error));
        const QString uri = parse(r.json)[QStringLiteral("buffers")][0][QStringLiteral("uri")].toString();
        QVERIFY(uri.startsWith(QStringLiteral("data:application/octet-stream;base64,")));
        QCOMPARE(QByteArray::fromBase64(uri.section(QLatin1Char(','), 1).toLatin1()),
                 bin().left(5)); // byteLength
    }

    void fileUrisAreRebasedToTheOutputFolder() {
        QCOMPARE(rebaseUri(QStringLiteral("Suzanne.bin"), QStringLiteral("/a/m"), QStringLiteral("/a/out")),
                 QStringLiteral("../m/Suzanne.bin"));
        QCOMPARE(rebaseUri(QStringLiteral("tex/my%20map.png"), QStringLiteral("/a/m"), QStringLiteral("/b")),
                 QStringLiteral("../a/m/tex/my%20map.png"));
        for (const char* kept : {"data:image/png;base64,AAAA", "https://example.com/a.png", "/abs/a.png"})
            QCOMPARE(rebaseUri(QLatin1String(kept), QStringLiteral("/a/m"), QStringLiteral("/b")),
                     QLatin1String(kept));
        const QByteArray json =
            R"({"asset":{"version":"2.0"},"buffers":[{"uri":"a.bin","byteLength":4}],)"
            R"("images":[{"uri":"data:image/png;base64,AAAA"},{"uri":"t.png", "name":"t"}]})";
        GltfAdditions a = twoLightsAndCamera();
        a.sourceFolder = QStringLiteral("/a/m");
        a.outputFolder = QStringLiteral("/a/out");
        const GltfRewriteResult r = rewriteGltfJson(json, a);
        QVERIFY2(r.ok(), qPrintable(r.error));
        const QJsonObject root = parse(r.json);
        QCOMPARE(root[QStringLiteral("buffers")][0][QStringLiteral("uri")].toString(),
                 QStringLiteral("../m/a.bin"));
        QVERIFY(r.json.contains(R"({"uri":"data:image/png;base64,AAAA"})")); // untouched, byte for byte
        QCOMPARE(root[QStringLiteral("images")][1][QStringLiteral("uri")].toString(),
                 QStringLiteral("../m/t.png"));
        QCOMPARE(root[QStringLiteral("images")][1][QStringLiteral("name")].toString(), QStringLiteral("t"));
        a.outputFolder = a.sourceFolder; // beside the source: nothing to rebase
        QVERIFY(rewriteGltfJson(json, a).json.contains(R"([{"uri":"a.bin","byteLength":4}])"));
    }

    void lightsOnlyHasNoMeshes() {
        const QJsonObject root = parse(lightsOnlyGltfJson(twoLightsAndCamera()));
        QCOMPARE(root[QStringLiteral("asset")][QStringLiteral("version")].toString(), QStringLiteral("2.0"));
        QCOMPARE(root[QStringLiteral("nodes")].toArray().size(), 2);
        QVERIFY(!root.contains(QStringLiteral("meshes")) && !root.contains(QStringLiteral("cameras")));
        QCOMPARE(root[QStringLiteral("scenes")][0][QStringLiteral("nodes")].toArray(), (QJsonArray{0, 1}));
        QCOMPARE(root[QStringLiteral("extensions")][QStringLiteral("KHR_lights_punctual")]
                     [QStringLiteral("lights")]
                         .toArray()
                         .size(),
                 2);
    }

    void malformedGlbIsRefused_data() {
        QTest::addColumn<QByteArray>("data");
        QTest::addColumn<QString>("reason");
        const QByteArray good = writeGlb(kJson, binChunk());
        QTest::newRow("short") << good.left(10) << QStringLiteral("too short");
        QByteArray magic = good;
        magic[0] = 'x';
        QTest::newRow("magic") << magic << QStringLiteral("magic");
        QTest::newRow("truncated") << good.left(good.size() - 4) << QStringLiteral("header claims");
        QByteArray version = good;
        version[4] = 1;
        QTest::newRow("version") << version << QStringLiteral("version 1");
        QByteArray chunk = good;
        chunk[14] = 0x7f; // the JSON chunk claims ~8 MB more than the file has
        QTest::newRow("json chunk") << chunk << QStringLiteral("JSON chunk claims");
        QByteArray binLength = good;
        binLength[good.size() - 16] = 0x40;
        QTest::newRow("bin chunk") << binLength << QStringLiteral("claims 64 bytes");
        QFile hostile(QStringLiteral(LIGHTRIG_TEST_DATA "/model/hostile/glb-huge-chunk.glb"));
        QVERIFY(hostile.open(QIODevice::ReadOnly));
        QTest::newRow("hostile") << hostile.readAll() << QStringLiteral("claims");
    }
    void malformedGlbIsRefused() {
        QFETCH(QByteArray, data);
        QFETCH(QString, reason);
        QString error;
        QVERIFY(!parseGlb(data, &error));
        QVERIFY2(error.contains(reason), qPrintable(error));
    }

    void malformedJsonIsRefused_data() {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("reason");
        QTest::newRow("syntax") << QByteArray(R"({"asset":{"version":"2.0"},)")
                                << QStringLiteral("not valid JSON");
        QTest::newRow("duplicate") << QByteArray(R"({"asset":{"version":"2.0"},"nodes":[],"nodes":[]})")
                                   << QStringLiteral("not valid JSON");
        QTest::newRow("array") << QByteArray("[]") << QStringLiteral("not an object");
        QTest::newRow("version") << QByteArray(R"({"asset":{"version":"1.0"}})")
                                 << QStringLiteral("asset.version");
        QTest::newRow("nodes") << QByteArray(R"({"asset":{"version":"2.0"},"nodes":{}})")
                               << QStringLiteral("nodes: must be an array");
        QTest::newRow("node") << QByteArray(R"({"asset":{"version":"2.0"},"nodes":[{},3]})")
                              << QStringLiteral("nodes[1]: must be an object");
        QTest::newRow("scene") << QByteArray(R"({"asset":{"version":"2.0"},"scene":2,"scenes":[{}]})")
                               << QStringLiteral("scene:");
        QTest::newRow("scene nodes") << QByteArray(R"({"asset":{"version":"2.0"},"scenes":[{"nodes":7}]})")
                                     << QStringLiteral("scenes[0].nodes");
    }
    void malformedJsonIsRefused() {
        QFETCH(QByteArray, json);
        QFETCH(QString, reason);
        const GltfRewriteResult r = rewriteGltfJson(json, twoLightsAndCamera());
        QVERIFY(!r.ok());
        QVERIFY(r.json.isEmpty());
        QVERIFY2(r.error.contains(reason), qPrintable(r.error));
    }
};

QTEST_APPLESS_MAIN(TestGltfRewrite)
#include "tst_gltfrewrite.moc"
