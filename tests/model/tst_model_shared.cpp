// Model import on the third-party files of ../shared/models (skipped when that folder is absent):
// the bench helmets' KHR_lights_punctual lights and camera, and every file of the folder, valid or
// not, imported in a child process (model_import_probe) so that an importer crash cannot end the run.
#include "model/modelloader.h"
#include "modelchecks.h"

#include <QDirIterator>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QQuaternion>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QtEndian>
#include <cmath>
#include <numbers>

using namespace lr;

namespace {

const QString kShared = QStringLiteral(LIGHTRIG_SHARED_MODELS);

// The JSON chunk of a GLB file.
QJsonObject glbJson(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    const QByteArray bytes = f.readAll();
    if (bytes.size() < 20 || !bytes.startsWith("glTF")) return {};
    const quint32 length = qFromLittleEndian<quint32>(bytes.constData() + 12);
    return QJsonDocument::fromJson(bytes.mid(20, qsizetype(length))).object();
}

glm::dvec3 vec3Of(const QJsonValue& v, glm::dvec3 fallback) {
    const QJsonArray a = v.toArray();
    return a.size() == 3 ? glm::dvec3(a[0].toDouble(), a[1].toDouble(), a[2].toDouble()) : fallback;
}

glm::dvec3 rotateByNode(const QJsonObject& node, const glm::dvec3& v) {
    const QJsonArray q = node.value(QStringLiteral("rotation")).toArray();
    if (q.size() != 4) return v;
    const QQuaternion rot(float(q[3].toDouble()), float(q[0].toDouble()), float(q[1].toDouble()),
                          float(q[2].toDouble()));
    const QVector3D r = rot.normalized().rotatedVector(QVector3D(float(v.x), float(v.y), float(v.z)));
    return glm::dvec3(r.x(), r.y(), r.z());
}

// MANIFEST.tsv: path -> assimp_status ("OK" or "FAIL") as recorded when the folder was assembled.
QHash<QString, QString> manifestStatus() {
    QHash<QString, QString> out;
    QFile f(kShared + QStringLiteral("/MANIFEST.tsv"));
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) return out;
    const QStringList header = QString::fromUtf8(f.readLine()).trimmed().split(QLatin1Char('\t'));
    const qsizetype statusColumn = header.indexOf(QStringLiteral("assimp_status"));
    while (!f.atEnd()) {
        const QStringList cols = QString::fromUtf8(f.readLine()).trimmed().split(QLatin1Char('\t'));
        if (statusColumn > 0 && cols.size() > statusColumn) out.insert(cols[0], cols[statusColumn]);
    }
    return out;
}

} // namespace

class TestModelShared : public QObject {
    Q_OBJECT
  private slots:
    void init() {
        if (!QFileInfo(kShared).isDir())
            QSKIP("no third-party models at LIGHTRIG_SHARED_MODELS (../shared/models)");
    }
    void benchHelmetLightsAndCamera_data();
    void benchHelmetLightsAndCamera();
    void everyFileLoadsOrFailsNamingIt();
    void plyCommentsInDataAreRefusedNotCrashed();
    void damagedHelmetMetalRoughMaterial_data();
    void damagedHelmetMetalRoughMaterial();
    void fbxShininessIsConvertedNotAssimpsRoughness();
};

void TestModelShared::benchHelmetLightsAndCamera_data() {
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("points");
    QTest::addColumn<int>("spots");
    QTest::newRow("1pt") << "helmet_1pt.glb" << 1 << 0;
    QTest::newRow("8pt") << "helmet_8pt.glb" << 8 << 0;
    QTest::newRow("64pt") << "helmet_64pt.glb" << 64 << 0;
    QTest::newRow("8spot") << "helmet_8spot.glb" << 0 << 8;
}

void TestModelShared::benchHelmetLightsAndCamera() {
    QFETCH(QString, file);
    QFETCH(int, points);
    QFETCH(int, spots);
    const QString path = kShared + QStringLiteral("/bench/") + file;
    const QJsonObject json = glbJson(path);
    QVERIFY(!json.isEmpty());
    const QJsonArray nodes = json[QStringLiteral("nodes")].toArray();
    const QJsonArray lights =
        json[QStringLiteral("extensions")][QStringLiteral("KHR_lights_punctual")][QStringLiteral("lights")]
            .toArray();

    const ModelLoadResult r = loadModel(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    const Model& m = *r.model;
    QCOMPARE(test::modelProblems(m), QString());
    QCOMPARE(int(m.lights.lights.size()), lights.size());
    int gotPoints = 0, gotSpots = 0;
    for (const Light& l : m.lights.lights) {
        gotPoints += l.type == LightType::Point;
        gotSpots += l.type == LightType::Spot;
        QJsonObject node;
        for (const QJsonValue& n : nodes)
            if (n[QStringLiteral("name")].toString() == l.name) node = n.toObject();
        QVERIFY2(!node.isEmpty(), qPrintable(l.name));
        const QJsonObject jl = lights[node[QStringLiteral("extensions")]
                                          [QStringLiteral("KHR_lights_punctual")][QStringLiteral("light")]
                                              .toInt()]
                                   .toObject();
        QVERIFY(glm::length(l.position - vec3Of(node[QStringLiteral("translation")], {})) < 1e-6);
        const glm::dvec3 radiance =
            vec3Of(jl[QStringLiteral("color")], glm::dvec3(1.0)) * jl[QStringLiteral("intensity")].toDouble();
        QVERIFY(glm::length(l.color * l.intensity - radiance) < 1e-5 * std::max(1.0, glm::length(radiance)));
        QVERIFY(l.falloff.model == FalloffModel::InverseSquare);
        QCOMPARE(l.falloff.hasRange(), jl.contains(QStringLiteral("range")));
        if (l.type == LightType::Spot) {
            const QJsonObject spot = jl[QStringLiteral("spot")].toObject();
            const double toDeg = 180.0 / std::numbers::pi;
            // glTF's inner 0 comes in as the smallest inner angle the rig's smooth cone takes (1e-3°).
            const double inner = std::max(spot[QStringLiteral("innerConeAngle")].toDouble(0.0) * toDeg, 1e-3);
            QVERIFY(std::abs(l.cone.inner - inner) < 1e-4);
            QVERIFY(std::abs(l.cone.outer -
                             spot[QStringLiteral("outerConeAngle")].toDouble(std::numbers::pi / 4) * toDeg) <
                    1e-4);
            QVERIFY(glm::length(l.direction - rotateByNode(node, glm::dvec3(0, 0, -1))) < 1e-5);
        }
    }
    QCOMPARE(gotPoints, points);
    QCOMPARE(gotSpots, spots);

    QCOMPARE(m.cameras.size(), size_t(1));
    const Camera& cam = m.cameras.front();
    QJsonObject camNode;
    for (const QJsonValue& n : nodes)
        if (n.toObject().contains(QStringLiteral("camera"))) camNode = n.toObject();
    const QJsonObject persp = json[QStringLiteral("cameras")][camNode[QStringLiteral("camera")].toInt()]
                                  [QStringLiteral("perspective")]
                                      .toObject();
    QVERIFY(glm::length(cam.position - vec3Of(camNode[QStringLiteral("translation")], {})) < 1e-6);
    QVERIFY(glm::length(cam.forward - rotateByNode(camNode, glm::dvec3(0, 0, -1))) < 1e-6);
    QVERIFY(std::abs(cam.yfovDegrees - persp[QStringLiteral("yfov")].toDouble() * 180.0 / std::numbers::pi) <
            1e-4);
    QVERIFY(std::abs(cam.aspect - persp[QStringLiteral("aspectRatio")].toDouble()) < 1e-6);
}

// The sizes of a GLB's images by glTF texture index, decoded here from the binary chunk.
static std::vector<QSize> glbTextureSizes(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    const QByteArray bytes = f.readAll();
    if (bytes.size() < 20) return {};
    const quint32 jsonLength = qFromLittleEndian<quint32>(bytes.constData() + 12);
    const QJsonObject json = QJsonDocument::fromJson(bytes.mid(20, qsizetype(jsonLength))).object();
    const qsizetype binStart = 20 + qsizetype(jsonLength) + 8;
    std::vector<QSize> out;
    for (const QJsonValue& t : json[QStringLiteral("textures")].toArray()) {
        const QJsonObject image =
            json[QStringLiteral("images")][t[QStringLiteral("source")].toInt()].toObject();
        const QJsonObject view =
            json[QStringLiteral("bufferViews")][image[QStringLiteral("bufferView")].toInt()].toObject();
        const QByteArray data = bytes.mid(binStart + view[QStringLiteral("byteOffset")].toInt(0),
                                          view[QStringLiteral("byteLength")].toInt());
        out.push_back(QImage::fromData(data).size());
    }
    return out;
}

void TestModelShared::damagedHelmetMetalRoughMaterial_data() {
    QTest::addColumn<QString>("file");
    QTest::newRow("Khronos sample") << "gltf/khronos/DamagedHelmet/glTF-Binary/DamagedHelmet.glb";
    QTest::newRow("bench 8pt") << "bench/helmet_8pt.glb";
}

// DamagedHelmet: metallic and roughness factors 1 (glTF's defaults, the texture carries the values), a
// metallic-roughness, occlusion, emissive, normal and base colour texture; each decodes at the size of the
// image the file holds for that role.
void TestModelShared::damagedHelmetMetalRoughMaterial() {
    QFETCH(QString, file);
    const QString path = kShared + QLatin1Char('/') + file;
    if (!QFileInfo::exists(path)) QSKIP(qPrintable(QStringLiteral("%1 is absent").arg(path)));
    const QJsonObject json = glbJson(path);
    const std::vector<QSize> sizes = glbTextureSizes(path);
    const QJsonObject jm = json[QStringLiteral("materials")][0].toObject();
    const QJsonObject pbr = jm[QStringLiteral("pbrMetallicRoughness")].toObject();
    const ModelLoadResult r = loadModel(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    const Model& m = *r.model;
    QCOMPARE(test::modelProblems(m), QString());
    QVERIFY(m.hasPbrMaterials());
    const Material& mat = m.materials[size_t(m.meshes.front().material)];
    QCOMPARE(mat.name, jm[QStringLiteral("name")].toString());
    QVERIFY(mat.pbr);
    QCOMPARE(mat.metallic, float(pbr[QStringLiteral("metallicFactor")].toDouble(1.0)));
    QCOMPARE(mat.roughness, float(pbr[QStringLiteral("roughnessFactor")].toDouble(1.0)));
    QCOMPARE(mat.metallic, 1.0f);
    QCOMPARE(mat.roughness, 1.0f);
    QVERIFY(mat.alphaMode == AlphaMode::Opaque);
    QCOMPARE(mat.occlusionStrength, 1.0f);
    QCOMPARE(mat.normalScale, 1.0f);
    QCOMPARE(mat.emissive, glm::vec3(1.0f));
    const struct {
        const char* role;
        int texture;
        QJsonValue info;
    } roles[] = {
        {"base colour", mat.baseColorTexture, pbr[QStringLiteral("baseColorTexture")]},
        {"metallic-roughness", mat.metallicRoughnessTexture, pbr[QStringLiteral("metallicRoughnessTexture")]},
        {"occlusion", mat.occlusionTexture, jm[QStringLiteral("occlusionTexture")]},
        {"emissive", mat.emissiveTexture, jm[QStringLiteral("emissiveTexture")]},
        {"normal", mat.normalTexture, jm[QStringLiteral("normalTexture")]}};
    for (const auto& role : roles) {
        QVERIFY2(role.texture >= 0, role.role);
        const int source = role.info[QStringLiteral("index")].toInt(-1);
        QVERIFY2(source >= 0 && size_t(source) < sizes.size(), role.role);
        QVERIFY2(!sizes[size_t(source)].isEmpty(), role.role);
        QCOMPARE(m.textures[size_t(role.texture)].image.size(), sizes[size_t(source)]);
        QCOMPARE(m.textures[size_t(role.texture)].image.format(), QImage::Format_RGBA8888);
    }
    // Five roles, five distinct images.
    QSet<int> distinct;
    for (const auto& role : roles)
        distinct.insert(role.texture);
    QCOMPARE(distinct.size(), 5);
    for (const QString& w : m.warnings)
        QVERIFY2(!w.contains(QLatin1String("material")) && !w.contains(QLatin1String("texture")),
                 qPrintable(w));
}

// Assimp's FBX importer adds a roughness derived from the shininess exponent (1 - sqrt(n) / 10); LightRig
// converts the exponent itself (docs/lighting-models.md) and marks the material as converted.
void TestModelShared::fbxShininessIsConvertedNotAssimpsRoughness() {
    const QString path = kShared + QStringLiteral("/fbx/assimp-tests/phong_cube.fbx");
    if (!QFileInfo::exists(path)) QSKIP(qPrintable(QStringLiteral("%1 is absent").arg(path)));
    const ModelLoadResult r = loadModel(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    const Material& mat = r.model->materials[size_t(r.model->meshes.front().material)];
    QVERIFY(mat.shininess > 0.0f);
    QVERIFY(!mat.pbr);
    QCOMPARE(mat.metallic, 0.0f);
    const double alpha = std::sqrt(2.0 / (double(mat.shininess) + 2.0));
    QVERIFY2(std::abs(double(mat.roughness) - std::sqrt(alpha)) < 1e-6,
             qPrintable(QString::number(mat.roughness)));
    QVERIFY(std::abs(mat.roughness - (1.0f - std::sqrt(mat.shininess) / 10.0f)) >
            0.01f); // 0.639 vs 0.684 at n = 10
    QVERIFY(!r.model->hasPbrMaterials());
}

void TestModelShared::everyFileLoadsOrFailsNamingIt() {
    const QHash<QString, QString> manifest = manifestStatus();
    QVERIFY2(!manifest.isEmpty(), "MANIFEST.tsv missing or unreadable");
    QStringList files;
    for (QDirIterator it(kShared, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories); it.hasNext();)
        files << it.next();
    files.sort();
    QVERIFY(files.size() >= manifest.size());

    QStringList failures;
    int loaded = 0, refused = 0;
    for (const QString& file : files) {
        const QString relative = QDir(kShared).relativeFilePath(file);
        QProcess probe;
        probe.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        probe.start(QStringLiteral(LIGHTRIG_MODEL_PROBE), {file});
        if (!probe.waitForFinished(60000)) {
            probe.kill();
            probe.waitForFinished();
            failures << relative + QStringLiteral(": import did not finish within 60 s");
            continue;
        }
        const QString out = QString::fromUtf8(probe.readAllStandardOutput()).trimmed();
        if (probe.exitStatus() != QProcess::NormalExit) {
            failures << relative + QStringLiteral(": the importer crashed");
            continue;
        }
        if (probe.exitCode() != 0 || out.count(QLatin1Char('\n')) != 0) {
            failures << relative + QStringLiteral(": exit %1: %2").arg(probe.exitCode()).arg(out);
            continue;
        }
        const QString expected = manifest.value(relative);
        if (out.startsWith(QStringLiteral("OK "))) {
            ++loaded;
            qInfo("%s", qPrintable(out.mid(3).replace(kShared + QLatin1Char('/'), QString())));
            if (expected == QLatin1String("FAIL"))
                failures << relative + QStringLiteral(": loaded, MANIFEST says FAIL");
        } else if (out.startsWith(QStringLiteral("ERROR could not import ") + file + QStringLiteral(": "))) {
            ++refused;
            if (expected == QLatin1String("OK")) failures << relative + QStringLiteral(": ") + out;
            if (!expected.isEmpty()) qInfo("%s", qPrintable(out));
        } else {
            failures << relative + QStringLiteral(": unexpected output: ") + out;
        }
    }
    qInfo("%d files: %d loaded, %d refused with a message", int(files.size()), loaded, refused);
    QVERIFY2(failures.isEmpty(), qPrintable(failures.join(QLatin1Char('\n'))));
}

// Assimp 5.2.5 (Debian, assertions on) aborts in TriangulateProcess on Wuson.ply with a comment line
// inserted among the faces; the loader must refuse such files before Assimp sees them.
void TestModelShared::plyCommentsInDataAreRefusedNotCrashed() {
    QFile source(kShared + QStringLiteral("/ply/assimp-tests/Wuson.ply"));
    QVERIFY(source.open(QIODevice::ReadOnly));
    const QByteArray original = source.readAll();
    const qsizetype dataStart = original.indexOf("end_header\n") + 11;
    QVERIFY(dataStart > 11);
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    QStringList paths;
    for (const double where : {0.0, 0.5, 0.999}) {
        qsizetype at = dataStart + qsizetype(where * double(original.size() - dataStart));
        at = original.indexOf('\n', at) + 1;
        QByteArray edited = original;
        edited.insert(at, "comment edited by hand\n");
        const QString path = tmp.filePath(QStringLiteral("wuson_%1.ply").arg(paths.size()));
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly) && out.write(edited) == edited.size());
        paths << path;
    }
    QProcess probe;
    probe.start(QStringLiteral(LIGHTRIG_MODEL_PROBE), paths);
    QVERIFY(probe.waitForFinished(60000));
    QCOMPARE(probe.exitStatus(), QProcess::NormalExit);
    QCOMPARE(probe.exitCode(), 0);
    const QStringList lines =
        QString::fromUtf8(probe.readAllStandardOutput()).trimmed().split(QLatin1Char('\n'));
    QCOMPARE(lines.size(), paths.size());
    for (qsizetype i = 0; i < lines.size(); ++i) {
        const QString expected = QStringLiteral("ERROR could not import %1: ").arg(paths[i]);
        QVERIFY2(lines[i].startsWith(expected) && lines[i].contains(QStringLiteral("comment")),
                 qPrintable(lines[i]));
    }
}

QTEST_GUILESS_MAIN(TestModelShared)
#include "tst_model_shared.moc"
