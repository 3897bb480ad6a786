// The binary Model codec (model/modelcodec.h) the import worker replies with: every field survives the
// round trip, and corrupted, truncated or hostile bytes give an error (never a crash, an out-of-bounds
// read or a model that breaks decodeModel's guarantees). Run it under -DLIGHTRIG_SANITIZE=address,undefined
// to have the sanitizers watch the mutation loop.
#include "model/modelcodec.h"
#include "modelcompare.h"
#include "workerfixtures.h"

#include <QColorSpace>
#include <QRandomGenerator>
#include <QTest>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>

using namespace lr;

namespace {

// Rewrites the header's body size to match the bytes, so a mutation reaches the body parser.
void fixBodySize(QByteArray& bytes) {
    if (bytes.size() < kModelCodecHeaderSize) return;
    const quint64 body = quint64(bytes.size() - kModelCodecHeaderSize);
    std::memcpy(bytes.data() + 24, &body, sizeof body);
}

QString decodeError(const QByteArray& bytes) {
    QString error;
    const std::shared_ptr<Model> m = decodeModel(bytes, &error);
    if (m) return QStringLiteral("<accepted>");
    return error;
}

Model oneTriangle() {
    Model m;
    m.materials.resize(1);
    Mesh mesh;
    mesh.vertices.resize(3);
    mesh.indices = {0, 1, 2};
    m.meshes.push_back(mesh);
    return m;
}

} // namespace

class TestModelCodec : public QObject {
    Q_OBJECT
  private slots:
    void roundTripsEveryField();
    void roundTripsEachMaterialField();
    void roundTripsEmptyAndBuiltInModels();
    void roundTripsManyEmptyParts();
    void streamsTheSameBytes();
    void lendsTexturePixels();
    void rejectsNonZeroPadding();
    void rejectsBadHeaders();
    void rejectsEveryTruncation();
    void rejectsInconsistentModels_data();
    void rejectsInconsistentModels();
    void rejectsHugeCounts();
    void survivesMutations();
};

void TestModelCodec::roundTripsEveryField() {
    const Model original = test::fullModel();
    QString error;
    const std::shared_ptr<Model> decoded = decodeModel(encodeModel(original), &error);
    QVERIFY2(decoded, qPrintable(error));
    const QString difference = test::modelDifference(original, *decoded);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
    // The comparison itself must notice a change (or the test above proves nothing).
    Model changed = original;
    changed.lights.lights[3].cone.exponent += 1.0;
    QVERIFY(!test::modelDifference(original, changed).isEmpty());
    changed = original;
    changed.lights.lights[4].area.roll += 1.0; // issue 16: the area shape crosses the worker too
    QVERIFY(!test::modelDifference(original, changed).isEmpty());
    changed = original;
    changed.lights.lights[1].ies->rotation += 1.0; // issue 39: shaping and linking cross the worker too
    QVERIFY(!test::modelDifference(original, changed).isEmpty());
    changed = original;
    changed.lights.lights[2].link.lit.include.removeLast();
    QVERIFY(!test::modelDifference(original, changed).isEmpty());
    QVERIFY(decoded->lights.lights[1].ies && decoded->lights.lights[1].ies->level == IesLevel::Profile);
    QVERIFY(decoded->lights.lights[2].gobo && decoded->lights.lights[3].barnDoors);
    changed = original;
    changed.meshes[1].vertices[2].tangent.w = -changed.meshes[1].vertices[2].tangent.w;
    QVERIFY(!test::modelDifference(original, changed).isEmpty());
    // Textures arrive as RGBA8888 whatever they were.
    QCOMPARE(decoded->textures[1].image.format(), QImage::Format_RGBA8888);
    QVERIFY(decoded->textures[2].image.isNull());
    QCOMPARE(decoded->textures[0].image.colorSpace(), QColorSpace(QColorSpace::SRgb));
    QVERIFY(!decoded->textures[1].image.colorSpace().isValid());
    QVERIFY(decoded->lights.lights[0].temperature.has_value());
    QVERIFY(!decoded->lights.lights[1].temperature.has_value());
    QVERIFY(decoded->lights.lights[1].ambient.has_value());
}

// Each Material field on its own, away from its default: a field the codec forgets comes back as its default
// and the materials differ (Material's operator== compares every field).
void TestModelCodec::roundTripsEachMaterialField() {
    const std::vector<std::pair<const char*, std::function<void(Material&)>>> changes = {
        {"name", [](Material& m) { m.name = QStringLiteral("m"); }},
        {"baseColor",
         [](Material& m) {
             m.baseColor = {0.1f, 0.2f, 0.3f, 0.4f};
         }},
        {"baseColorTexture", [](Material& m) { m.baseColorTexture = 0; }},
        {"normalTexture", [](Material& m) { m.normalTexture = 0; }},
        {"emissiveTexture", [](Material& m) { m.emissiveTexture = 0; }},
        {"emissive",
         [](Material& m) {
             m.emissive = {4.0f, 2.0f, 1.0f};
         }},
        {"specular",
         [](Material& m) {
             m.specular = {0.5f, 0.5f, 0.25f};
         }},
        {"shininess", [](Material& m) { m.shininess = 12.0f; }},
        {"doubleSided", [](Material& m) { m.doubleSided = true; }},
        {"pbr", [](Material& m) { m.pbr = true; }},
        {"metallic", [](Material& m) { m.metallic = 0.5f; }},
        {"roughness", [](Material& m) { m.roughness = 0.25f; }},
        {"metallicRoughnessTexture", [](Material& m) { m.metallicRoughnessTexture = 0; }},
        {"occlusionTexture", [](Material& m) { m.occlusionTexture = 0; }},
        {"occlusionStrength", [](Material& m) { m.occlusionStrength = 0.5f; }},
        {"normalScale", [](Material& m) { m.normalScale = 2.0f; }},
        {"alphaMode", [](Material& m) { m.alphaMode = AlphaMode::Blend; }},
        {"alphaCutoff", [](Material& m) { m.alphaCutoff = 0.75f; }},
        {"baseColorTransform",
         [](Material& m) {
             m.baseColorTransform.offset = {0.5f, 0.25f};
         }},
        {"normalTransform", [](Material& m) { m.normalTransform.rotation = 1.0f; }},
        {"emissiveTransform",
         [](Material& m) {
             m.emissiveTransform.scale = {2.0f, 3.0f};
         }},
        {"metallicRoughnessTransform", [](Material& m) { m.metallicRoughnessTransform.offset.y = -1.0f; }},
        {"occlusionTransform", [](Material& m) { m.occlusionTransform.scale.x = 0.5f; }},
        {"baseColorSampling", [](Material& m) { m.baseColorSampling.wrapS = TextureWrap::ClampToEdge; }},
        {"normalSampling", [](Material& m) { m.normalSampling.wrapT = TextureWrap::MirroredRepeat; }},
        {"emissiveSampling", [](Material& m) { m.emissiveSampling.nearestMagnification = true; }},
        {"metallicRoughnessSampling",
         [](Material& m) { m.metallicRoughnessSampling.wrapT = TextureWrap::ClampToEdge; }},
        {"occlusionSampling", [](Material& m) { m.occlusionSampling.wrapS = TextureWrap::MirroredRepeat; }},
        {"extensions",
         [](Material& m) {
             m.extensions = {
                 {QStringLiteral("KHR_materials_clearcoat"), QStringLiteral("{\"clearcoatFactor\":1}")},
                 {QStringLiteral("KHR_materials_ior"), QStringLiteral("{\"ior\":1.5}")}};
         }},
    };
    for (const auto& [field, change] : changes) {
        Model m = oneTriangle();
        m.textures.push_back({QStringLiteral("t.png"), test::patternImage(2, 2, QImage::Format_RGBA8888, 5)});
        change(m.materials[0]);
        QVERIFY2(!(m.materials[0] == Material()), field);
        QString error;
        const std::shared_ptr<Model> decoded = decodeModel(encodeModel(m), &error);
        QVERIFY2(decoded, qPrintable(QStringLiteral("%1: %2").arg(QLatin1String(field), error)));
        QVERIFY2(decoded->materials[0] == m.materials[0], field);
    }
    // Every field of Material is listed above: its size changes when a field is added (then list it).
    static_assert(sizeof(Material) == sizeof(QString) + 92 + 5 * sizeof(TextureTransform) +
                                          5 * sizeof(TextureSampling) + 4 /* alignment */ +
                                          sizeof(std::vector<MaterialExtension>),
                  "a Material field was added: add it to the codec and to this test");
}

void TestModelCodec::roundTripsEmptyAndBuiltInModels() {
    for (const Model& m : {Model(), makeSphere(2.0, 24, 12, {1e7, 0.0, -3.0}), makePlane(5.0)}) {
        QString error;
        const std::shared_ptr<Model> decoded = decodeModel(encodeModel(m), &error);
        QVERIFY2(decoded, qPrintable(error));
        const QString difference = test::modelDifference(m, *decoded);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
    }
}

// Counts are checked against the fewest bytes an element can take: that bound must not be too high.
void TestModelCodec::roundTripsManyEmptyParts() {
    Model m;
    m.meshes.resize(1000);
    m.materials.resize(1000);
    m.textures.resize(1000);
    m.cameras.resize(1000);
    m.lights.lights.resize(1000);
    m.warnings = QStringList(1000, QString());
    m.texturesOutsideFolder = QStringList(1000, QString());
    QString error;
    const std::shared_ptr<Model> decoded = decodeModel(encodeModel(m), &error);
    QVERIFY2(decoded, qPrintable(error));
    const QString difference = test::modelDifference(m, *decoded);
    QVERIFY2(difference.isEmpty(), qPrintable(difference));
}

void TestModelCodec::streamsTheSameBytes() {
    Model m = test::fullModel();
    m.textures[0].image =
        test::patternImage(300, 200, QImage::Format_RGBA8888, 3); // large enough to bypass the buffer
    const QByteArray whole = encodeModel(m);
    QCOMPARE(qsizetype(encodedModelSize(m)), whole.size());
    QByteArray streamed;
    int pieces = 0;
    QVERIFY(writeModel(m, [&](const char* data, std::size_t size) {
        streamed.append(data, qsizetype(size));
        ++pieces;
        return true;
    }));
    QCOMPARE(streamed, whole);
    QVERIFY(pieces > 1);
    // A sink that refuses stops the stream.
    int calls = 0;
    QVERIFY(!writeModel(m, [&](const char*, std::size_t) { return ++calls < 2; }));
    QCOMPARE(calls, 2);
}

namespace {
int g_released = 0;
void countRelease(void*) {
    ++g_released;
}
} // namespace

// With an ImageLender, texture images refer to the (page-aligned) input instead of copying it.
void TestModelCodec::lendsTexturePixels() {
    const Model original = test::fullModel();
    const QByteArray encoded = encodeModel(original);
    const std::size_t size = (std::size_t(encoded.size()) + 4095) / 4096 * 4096;
    std::unique_ptr<char, decltype(&std::free)> aligned(static_cast<char*>(std::aligned_alloc(4096, size)),
                                                        &std::free);
    QVERIFY(aligned);
    std::memcpy(aligned.get(), encoded.constData(), std::size_t(encoded.size()));
    const char* begin = aligned.get();
    int lent = 0;
    const ImageLender lend = [&](const char* pixels, std::size_t bytes, QImageCleanupFunction* cleanup,
                                 void** info) {
        if ((pixels - begin) % qsizetype(kModelCodecPixelAlignment) != 0 ||
            pixels + bytes > begin + encoded.size())
            return false;
        ++lent;
        *cleanup = countRelease;
        *info = nullptr;
        return true;
    };
    g_released = 0;
    {
        QString error;
        std::shared_ptr<Model> decoded = decodeModel(QByteArrayView(begin, encoded.size()), &error, {}, lend);
        QVERIFY2(decoded, qPrintable(error));
        QCOMPARE(lent, 2); // the two non-null textures
        const QString difference = test::modelDifference(original, *decoded);
        QVERIFY2(difference.isEmpty(), qPrintable(difference));
        for (int t : {0, 1}) {
            const auto* bits = reinterpret_cast<const char*>(decoded->textures[size_t(t)].image.constBits());
            QVERIFY(bits >= begin && bits < begin + encoded.size());
        }
        const QImage kept = decoded->textures[0].image; // a copy shares the lent pixels
        decoded.reset();
        QCOMPARE(g_released, 1);
    }
    QCOMPARE(g_released, 2);
}

void TestModelCodec::rejectsNonZeroPadding() {
    Model m = oneTriangle();
    m.textures.push_back({QStringLiteral("t.png"), test::patternImage(2, 2, QImage::Format_RGBA8888, 5)});
    QByteArray bytes = encodeModel(m);
    QVERIFY(bytes.size() > qsizetype(kModelCodecPixelAlignment)); // pixels start at 4096, zeros before
    QCOMPARE(bytes.at(qsizetype(kModelCodecPixelAlignment) - 1), '\0');
    bytes[qsizetype(kModelCodecPixelAlignment) - 1] = 1;
    const QString error = decodeError(bytes);
    QVERIFY2(error.contains(QLatin1String("texture 0: padding is not zero")), qPrintable(error));
}

void TestModelCodec::rejectsBadHeaders() {
    const QByteArray good = encodeModel(test::fullModel());
    QCOMPARE(decodeError(good), QStringLiteral("<accepted>"));
    QVERIFY(decodeError(QByteArray()).contains(QLatin1String("truncated header")));
    QByteArray bad = good;
    bad[0] = 'X';
    QVERIFY(decodeError(bad).contains(QLatin1String("not a LightRig model")));
    bad = good;
    bad[8] = char(kModelCodecVersion + 1);
    QVERIFY(decodeError(bad).contains(QLatin1String("version")));
    bad = good;
    std::swap(bad[12], bad[15]);
    QVERIFY(decodeError(bad).contains(QLatin1String("byte order")));
    bad = good;
    bad[16] = char(bad[16] + 4);
    QVERIFY(decodeError(bad).contains(QLatin1String("vertex size")));
    bad = good + QByteArray(3, '\0');
    QVERIFY(decodeError(bad).contains(QLatin1String("header says")));
    fixBodySize(bad);
    QVERIFY(decodeError(bad).contains(QLatin1String("unexpected bytes")));
}

void TestModelCodec::rejectsEveryTruncation() {
    const QByteArray good = encodeModel(test::fullModel());
    for (qsizetype n = 0; n < good.size(); ++n) {
        QByteArray cut = good.left(n);
        const QString plain = decodeError(cut);
        fixBodySize(cut);
        const QString fixed = decodeError(cut);
        if (plain == QLatin1String("<accepted>") || fixed == QLatin1String("<accepted>") || plain.isEmpty() ||
            fixed.isEmpty())
            QFAIL(qPrintable(QStringLiteral("prefix of %1 bytes: %2 / %3").arg(n).arg(plain, fixed)));
    }
}

void TestModelCodec::rejectsInconsistentModels_data() {
    QTest::addColumn<int>("kind");
    QTest::addColumn<QString>("expected");
    QTest::newRow("index out of range") << 0 << QStringLiteral("index 3 out of range (3 vertices)");
    QTest::newRow("partial triangle") << 1 << QStringLiteral("not whole triangles");
    QTest::newRow("NaN position") << 2 << QStringLiteral("vertex 1 is not finite");
    QTest::newRow("Inf colour") << 3 << QStringLiteral("vertex 2 is not finite");
    QTest::newRow("material out of range") << 4 << QStringLiteral("material 1 out of range (1 materials)");
    QTest::newRow("texture out of range") << 5 << QStringLiteral("texture 0 out of range or empty");
    QTest::newRow("null texture referenced") << 6 << QStringLiteral("texture 0 out of range or empty");
    QTest::newRow("NaN light") << 7 << QStringLiteral("light 0 intensity is not finite");
    QTest::newRow("Inf camera") << 8 << QStringLiteral("camera 0 znear is not finite");
    QTest::newRow("negative material") << 9 << QStringLiteral("material -1 out of range");
    QTest::newRow("metal-rough texture out of range")
        << 10 << QStringLiteral("material 0: texture 0 out of range or empty");
    QTest::newRow("occlusion texture out of range")
        << 11 << QStringLiteral("material 0: texture 5 out of range or empty");
    QTest::newRow("roughness above 1") << 12 << QStringLiteral("material 0 roughness 1.5 is outside [0, 1]");
    QTest::newRow("NaN alpha cutoff") << 13 << QStringLiteral("material 0 alpha cutoff is not finite");
    QTest::newRow("Inf texture rotation")
        << 14 << QStringLiteral("material 0 texture rotation is not finite");
    QTest::newRow("alpha mode out of range")
        << 15 << QStringLiteral("material 0 alpha mode out of range (7)");
    QTest::newRow("negative metallic") << 16 << QStringLiteral("material 0 metallic -0.25 is outside [0, 1]");
    QTest::newRow("shading model out of range") << 17 << QStringLiteral("rig shading model out of range (2)");
    QTest::newRow("texture wrap out of range")
        << 18 << QStringLiteral("material 0 texture wrap T out of range (3)");
    QTest::newRow("too many extensions")
        << 19 << QStringLiteral("material 0 lists 33 extensions (at most 32)");
}

void TestModelCodec::rejectsInconsistentModels() {
    QFETCH(int, kind);
    QFETCH(QString, expected);
    Model m = oneTriangle();
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    switch (kind) {
    case 0:
        m.meshes[0].indices = {0, 1, 3};
        break;
    case 1:
        m.meshes[0].indices = {0, 1, 2, 0};
        break;
    case 2:
        m.meshes[0].vertices[1].position.y = nan;
        break;
    case 3:
        m.meshes[0].vertices[2].color.a = -inf;
        break;
    case 4:
        m.meshes[0].material = 1;
        break;
    case 5:
        m.materials[0].normalTexture = 0;
        break;
    case 6:
        m.textures.push_back({QStringLiteral("x.png"), QImage()});
        m.materials[0].baseColorTexture = 0;
        break;
    case 7:
        m.lights.lights.push_back(makeLight(LightType::Point, QStringLiteral("p")));
        m.lights.lights[0].intensity = double(nan);
        break;
    case 8:
        m.cameras.resize(1);
        m.cameras[0].znear = double(inf);
        break;
    case 9:
        m.meshes[0].material = -1;
        break;
    case 10:
        m.materials[0].metallicRoughnessTexture = 0;
        break;
    case 11:
        m.materials[0].occlusionTexture = 5;
        break;
    case 12:
        m.materials[0].roughness = 1.5f;
        break;
    case 13:
        m.materials[0].alphaCutoff = nan;
        break;
    case 14:
        m.materials[0].occlusionTransform.rotation = inf;
        break;
    case 15:
        m.materials[0].alphaMode = AlphaMode(7);
        break;
    case 16:
        m.materials[0].metallic = -0.25f;
        break;
    case 17:
        m.lights.shading.model = ShadingModel(2);
        break;
    case 18:
        m.materials[0].emissiveSampling.wrapT = TextureWrap(3);
        break;
    case 19:
        m.materials[0].extensions.resize(kMaxMaterialExtensions + 1);
        break;
    }
    const QString error = decodeError(encodeModel(m));
    QVERIFY2(error.contains(expected), qPrintable(error));
}

void TestModelCodec::rejectsHugeCounts() {
    // The mesh count sits after the header, the path string and the origin.
    const Model m = oneTriangle();
    const QByteArray good = encodeModel(m);
    const qsizetype meshCountAt = kModelCodecHeaderSize + 4 + m.path.toUtf8().size() + 24;
    for (quint64 count : {quint64(1) << 62, quint64(1) << 32, quint64(1000000), ~quint64(0)}) {
        QByteArray bad = good;
        std::memcpy(bad.data() + meshCountAt, &count, sizeof count);
        const QString error = decodeError(bad);
        QVERIFY2(error.contains(QLatin1String("meshes count")), qPrintable(error));
    }
    // Vertex count of mesh 0: after the mesh count and the (empty) mesh and node names.
    for (quint64 count : {quint64(1) << 58, quint64(4)}) {
        QByteArray bad = good;
        std::memcpy(bad.data() + meshCountAt + 8 + 4 + 4, &count, sizeof count);
        const QString error = decodeError(bad);
        QVERIFY2(error.contains(QLatin1String("mesh 0 vertices")) ||
                     error.contains(QLatin1String("truncated")),
                 qPrintable(error));
    }
}

void TestModelCodec::survivesMutations() {
    const QByteArray good = encodeModel(test::fullModel());
    QRandomGenerator rng(20240611u);
    int accepted = 0, rejected = 0;
    const quint64 interesting[] = {0,
                                   1,
                                   2,
                                   3,
                                   0x7f,
                                   0xff,
                                   0xffff,
                                   0x7fffffff,
                                   0x80000000,
                                   0xffffffff,
                                   quint64(1) << 32,
                                   quint64(1) << 62,
                                   ~quint64(0),
                                   0x7ff8000000000000ull,
                                   0x7f800000ull};
    constexpr int kMutations = 6000;
    for (int i = 0; i < kMutations; ++i) {
        QByteArray bytes = good;
        const int edits = 1 + int(rng.bounded(4));
        for (int e = 0; e < edits; ++e) {
            const auto at = qsizetype(rng.bounded(quint32(bytes.size())));
            switch (rng.bounded(6)) {
            case 0:
                bytes[at] = char(bytes[at] ^ char(1 << rng.bounded(8)));
                break;
            case 1:
                bytes[at] = char(rng.bounded(256));
                break;
            case 2: {
                const quint64 v = interesting[rng.bounded(quint32(std::size(interesting)))];
                const qsizetype width = qsizetype(1) << rng.bounded(4); // 1, 2, 4 or 8 bytes
                if (at + width <= bytes.size()) std::memcpy(bytes.data() + at, &v, size_t(width));
                break;
            }
            case 3:
                bytes.truncate(at);
                break;
            case 4:
                bytes.insert(at, QByteArray(1 + int(rng.bounded(16)), char(rng.bounded(256))));
                break;
            case 5:
                bytes.remove(at, 1 + qsizetype(rng.bounded(16)));
                break;
            }
            if (bytes.isEmpty()) break;
        }
        if (rng.bounded(10) < 8) fixBodySize(bytes);
        QString error;
        const std::shared_ptr<Model> m = decodeModel(bytes, &error);
        if (m) {
            ++accepted;
            const QString unsafe = test::decodedModelUnsafe(*m);
            QVERIFY2(unsafe.isEmpty(),
                     qPrintable(QStringLiteral("mutation %1 accepted: %2").arg(i).arg(unsafe)));
        } else {
            ++rejected;
            QVERIFY2(!error.isEmpty(),
                     qPrintable(QStringLiteral("mutation %1 rejected without a message").arg(i)));
        }
    }
    qInfo("%d mutations: %d rejected with a message, %d accepted (a harmless change, e.g. in a colour)",
          kMutations, rejected, accepted);
    QVERIFY(rejected > kMutations / 2);
}

QTEST_GUILESS_MAIN(TestModelCodec)
#include "tst_modelcodec.moc"
