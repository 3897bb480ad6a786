// Model import of broken and hostile input: references leaving the model's folder, degenerate geometry,
// the data URI and header limits (with the sweep's reproducers in tests/data/model/hostile), coincident
// vertices, lights and cameras beyond the rig format's limits, and errors naming the file as given.
#include "core/rigjson.h"
#include "model/modelloader.h"
#include "modelchecks.h"
#include "modelimport.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <cmath>

using namespace lr;
using namespace lr::test;

class TestModelHostile : public QObject {
    Q_OBJECT
  private slots:
    void referencesOutsideTheFolderAreRefused();
    void degenerateGeometryIsDroppedWithWarnings();
    void dataUriLimit();
    void hostileHeadersAndPlyCommentsAreRefused();
    void coincidentVerticesSkipSmoothing();
    void modelLightsGetTheRigLimits();
    void unusableCameraIsIgnored();
    void errorsNameTheFile();
};

void TestModelHostile::referencesOutsideTheFolderAreRefused() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const QString root = tmp.path();
    QVERIFY(QDir(root).mkdir(QStringLiteral("model")));
    QImage outside(4, 4, QImage::Format_RGBA8888);
    outside.fill(Qt::yellow);
    QVERIFY(outside.save(root + QStringLiteral("/outside.png")));
    QVERIFY(outside.save(root + QStringLiteral("/model/local.png")));
    // Relative escape, absolute path, and a Windows path whose file name exists beside the model.
    QVERIFY(writeFile(root + QStringLiteral("/model/quad.mtl"),
                      "newmtl up\nmap_Kd ../outside.png\nnewmtl abs\nmap_Kd " + root.toUtf8() +
                          "/outside.png\nnewmtl win\nmap_Kd C:\\textures\\local.png\n"));
    QVERIFY(writeFile(root + QStringLiteral("/model/quad.obj"),
                      "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                      "vt 0 0\nusemtl up\nf 1/1 2/1 3/1\nusemtl abs\n"
                      "f 1/1 3/1 4/1\nusemtl win\nf 2/1 3/1 4/1\n"));
    // A glTF whose buffer lies outside: the import itself must fail, naming the file.
    const float triangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    QVERIFY(writeFile(root + QStringLiteral("/outside.bin"),
                      QByteArray(reinterpret_cast<const char*>(triangle), 36)));
    QVERIFY(writeFile(root + QStringLiteral("/model/buffer.gltf"),
                      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
                         "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],
                         "buffers":[{"uri":"../outside.bin","byteLength":36}],
                         "bufferViews":[{"buffer":0,"byteLength":36}],
                         "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",
                                       "min":[0,0,0],"max":[1,1,0]}]})"));

    const auto refused = mustLoad(root + QStringLiteral("/model/quad.obj"));
    QVERIFY(refused);
    QCOMPARE(refused->textures.size(), size_t(1)); // only the Windows path's stand-in beside the model
    QCOMPARE(QFileInfo(refused->textures.front().name).fileName(), QStringLiteral("local.png"));
    const QString warnings = refused->warnings.join(QLatin1Char('\n'));
    QVERIFY2(warnings.contains(QStringLiteral("../outside.png")) &&
                 warnings.contains(root + QStringLiteral("/outside.png")),
             qPrintable(warnings));
    QVERIFY2(warnings.count(QStringLiteral("outside the model's folder")) >= 3, qPrintable(warnings));
    // The two that permission would load are listed for the question; the Windows path is not.
    QStringList outsideRefs = refused->texturesOutsideFolder;
    outsideRefs.sort();
    QCOMPARE(outsideRefs,
             QStringList({QStringLiteral("../outside.png"), root + QStringLiteral("/outside.png")}));

    const ModelLoadResult buffer = loadModel(root + QStringLiteral("/model/buffer.gltf"));
    QVERIFY(!buffer.ok());
    QVERIFY2(buffer.error.startsWith(QStringLiteral("could not import %1/model/buffer.gltf: ").arg(root)),
             qPrintable(buffer.error));
    QVERIFY2(buffer.error.contains(QStringLiteral("outside the model's folder")), qPrintable(buffer.error));

    ModelLoadOptions allow;
    allow.allowTexturesOutsideFolder = true;
    const auto allowed = mustLoad(root + QStringLiteral("/model/quad.obj"), allow);
    QVERIFY(allowed);
    QCOMPARE(allowed->textures.size(), size_t(2)); // ../outside.png and the absolute path are one file
    QVERIFY(allowed->texturesOutsideFolder.isEmpty());
    const auto upMat = std::find_if(allowed->materials.begin(), allowed->materials.end(),
                                    [](const Material& mat) { return mat.name == QLatin1String("up"); });
    QVERIFY(upMat != allowed->materials.end() && upMat->baseColorTexture >= 0);
    QCOMPARE(allowed->textures[size_t(upMat->baseColorTexture)].image.pixel(0, 0), QColor(Qt::yellow).rgb());
    const auto viaBuffer = mustLoad(root + QStringLiteral("/model/buffer.gltf"), allow);
    QVERIFY(viaBuffer);
    QCOMPARE(viaBuffer->triangleCount(), size_t(1));
}

void TestModelHostile::degenerateGeometryIsDroppedWithWarnings() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const QString path = tmp.filePath(QStringLiteral("degenerate.obj"));
    QVERIFY(writeFile(path, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 1 1 0\nv 2 2 0\nv nan 0 0\nv 0 inf 0\n"
                            "vn 0 0 1\nvn 0 0 0\n"
                            "f 1//1 2//1 3//1\n"    // good
                            "f 2//1 4//1 5//1\n"    // two vertices at one place: no area
                            "f 1//1 4//1 6//1\n"    // collinear: no area
                            "f 1//1 2//1 7//1\n"    // NaN position
                            "f 1//1 8//1 3//1\n"    // infinite position
                            "f 2//2 4//2 3//2\n")); // good triangle with zero-length normals
    const ModelLoadResult r = loadModel(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    const Model& m = *r.model;
    QCOMPARE(test::modelProblems(m), QString());
    QCOMPARE(m.triangleCount(), size_t(2));
    QVERIFY(near(m.bounds.min, glm::dvec3(0.0), 0.0));
    QVERIFY(near(m.bounds.max, glm::dvec3(1.0, 1.0, 0.0), 0.0));
    const QString warnings = m.warnings.join(QLatin1Char('\n'));
    QVERIFY2(warnings.contains(QStringLiteral("degenerate.obj: 2 triangles with NaN or infinite")),
             qPrintable(warnings));
    QVERIFY2(warnings.contains(QStringLiteral("2 zero-area triangles dropped")), qPrintable(warnings));
    QVERIFY2(warnings.contains(QStringLiteral("normals recomputed")), qPrintable(warnings));
    for (const Mesh& mesh : m.meshes) {
        QCOMPARE(test::clockwiseTriangles(mesh), size_t(0));
        for (const Vertex& v : mesh.vertices)
            QVERIFY(glm::length(v.normal - glm::vec3(0, 0, 1)) < 1e-6f);
    }
    // Nothing usable at all: an error, not an empty model.
    const QString empty = tmp.filePath(QStringLiteral("allbad.obj"));
    QVERIFY(writeFile(empty, "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n"));
    const ModelLoadResult none = loadModel(empty);
    QVERIFY(!none.ok());
    QVERIFY2(none.error.startsWith(QStringLiteral("could not import %1: ").arg(empty)),
             qPrintable(none.error));
}

void TestModelHostile::dataUriLimit() {
    const QString path = dataFile(QStringLiteral("scene.gltf"));
    ModelLoadOptions tight;
    tight.maxDataUriBytes = 64; // the buffer's data URI is a few hundred bytes
    const ModelLoadResult r = loadModel(path, tight);
    QVERIFY(!r.ok());
    QVERIFY2(r.error.startsWith(QStringLiteral("could not import %1: a data URI of ").arg(path)),
             qPrintable(r.error));
    QVERIFY(loadModel(path).ok());
}

// A GLB header (magic, version 2, `length`) and the header of a JSON chunk of `chunk` bytes.
static QByteArray glb(quint32 length, quint32 chunk) {
    QByteArray b("glTF");
    for (const quint32 v : {2u, length, chunk, 0x4E4F534Au}) // "JSON"
        for (int k = 0; k < 4; ++k)
            b += char((v >> (8 * k)) & 0xFF);
    return b;
}

void TestModelHostile::hostileHeadersAndPlyCommentsAreRefused() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const QByteArray header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const struct {
        const char* name;
        QByteArray content;
        const char* reason;
    } cases[] = {
        // Assimp 5.2.5 misparses comment lines inside PLY data (and aborts on some, see tst_model_shared).
        {"comment.ply", header + "0 0 0\n1 0 0\n0 1 0\ncomment added by hand\n3 0 1 2\n",
         "not a row of numbers"},
        // Element counts the file cannot hold: Assimp would allocate for them before noticing.
        {"bomb.ply",
         "ply\nformat binary_little_endian 1.0\nelement vertex 1500000000\nproperty float x\n"
         "property float y\nproperty float z\nend_header\n",
         "the header declares 1500000000 elements"},
        {"bomb.off", "OFF\n353535235358 6 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "the header declares"},
        // An 80-byte GLB whose JSON chunk claims 4 GB: Assimp allocated 4.2 GB for it.
        {"huge-chunk.glb", glb(88, 0xFFFFFFF0u) + QByteArray(68, ' '),
         "GLB chunk 0 declares 4294967280 bytes, but only 68 follow"},
        // A header claiming more bytes than the file has (2.1 GB and 41 s in Assimp).
        {"long-header.glb", glb(30604, 2) + "{}" + QByteArray(62, ' '),
         "the GLB header declares 30604 bytes, but the file has 84"},
        {"short.glb", QByteArray("glTF\x02\0\0\0", 8), "shorter than a GLB header"},
        // A Collada index list with a character that is not part of a number: Assimp 5.2.5 loops forever
        // (a mutated duck.dae in scripts/sweep).
        {"loop.dae",
         "<?xml version=\"1.0\"?>\n<COLLADA>\n<library_geometries><geometry><mesh>\n<triangles count=\"1\">"
         "<p>0 1 2 178$</p></triangles></mesh></geometry></library_geometries></COLLADA>\n",
         "line 4: the <p> index list holds '$', which is not part of an integer"},
        // A PLY header that never ends: Assimp waited for end_header until the worker's time limit.
        {"trunc.ply", "ply\nformat ascii 1.0          \ne", "the PLY header has no end_header line"},
    };
    for (const auto& c : cases) {
        const QString path = tmp.filePath(QLatin1String(c.name));
        QVERIFY(writeFile(path, c.content));
        const ModelLoadResult r = loadModel(path);
        QVERIFY2(!r.ok(), c.name);
        QVERIFY2(r.error.startsWith(QStringLiteral("could not import %1: ").arg(path)), qPrintable(r.error));
        QVERIFY2(r.error.contains(QLatin1String(c.reason)), qPrintable(r.error));
    }
    // The sweep's reproducers themselves (tests/data/model/hostile).
    for (const auto& [file, reason] :
         {std::pair{"hostile/glb-huge-chunk.glb", "the GLB header declares 100 bytes, but the file has 80"},
          std::pair{"hostile/trunc-cube-32.ply", "the PLY header has no end_header line"}}) {
        const ModelLoadResult r = loadModel(dataFile(QLatin1String(file)));
        QVERIFY2(!r.ok() && r.error.contains(QLatin1String(reason)), qPrintable(r.error));
    }
    // A well-formed GLB (a JSON and a BIN chunk) passes the checks and loads.
    QByteArray json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"accessors":[{"bufferView":0,)"
        R"("componentType":5126,"count":3,"type":"VEC3","max":[1,1,0],"min":[0,0,0]}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36}]})";
    while (json.size() % 4)
        json += ' ';
    const float triangle[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    QByteArray bin(reinterpret_cast<const char*>(triangle), sizeof triangle);
    QByteArray good = glb(quint32(12 + 8 + json.size() + 8 + bin.size()), quint32(json.size())) + json;
    for (const quint32 v : {quint32(bin.size()), 0x004E4942u}) // "BIN\0"
        for (int k = 0; k < 4; ++k)
            good += char((v >> (8 * k)) & 0xFF);
    good += bin;
    const QString goodPath = tmp.filePath(QStringLiteral("good.glb"));
    QVERIFY(writeFile(goodPath, good));
    const ModelLoadResult loaded = loadModel(goodPath);
    QVERIFY2(loaded.ok(), qPrintable(loaded.error));
    // The same PLY without the comment loads.
    const QString clean = tmp.filePath(QStringLiteral("clean.ply"));
    QVERIFY(writeFile(clean, header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
    QVERIFY(loadModel(clean).ok());
}

// An OBJ of 30,000 copies of one triangle: Assimp's SpatialSort-based steps (smooth normals, tangents,
// joining vertices) are quadratic in coincident vertices (100,000 copies took over two minutes). The
// file loads without them, with flat normals and a warning saying why.
void TestModelHostile::coincidentVerticesSkipSmoothing() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    QByteArray obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 30'000; ++i)
        obj += "f 1 2 3\n";
    const QString path = tmp.filePath(QStringLiteral("copies.obj"));
    QVERIFY(writeFile(path, obj));
    const ModelLoadResult r = loadModel(path);
    QVERIFY2(r.ok(), qPrintable(r.error));
    size_t triangles = 0;
    for (const Mesh& m : r.model->meshes) {
        triangles += m.indices.size() / 3;
        for (const Vertex& v : m.vertices)
            QVERIFY(std::abs(v.normal.z - 1.0f) < 1e-6f); // the face's own normal
    }
    QCOMPARE(triangles, size_t(30'000));
    QVERIFY2(r.model->warnings.join(QLatin1Char('\n'))
                 .contains(QStringLiteral("share a position; normals are flat")),
             qPrintable(r.model->warnings.join(QLatin1Char('\n'))));
    // An ordinary file keeps smooth normals and no such warning.
    const auto suzanne = mustLoad(QStringLiteral(":/resources/models/suzanne/Suzanne.gltf"));
    QVERIFY(suzanne);
    QVERIFY(!suzanne->warnings.join(QLatin1Char('\n')).contains(QStringLiteral("share a position")));
}

// Lights in a model file used to skip the rig format's limits: gltf-light-neg.gltf (colour [-1, 2, 1e30],
// intensity -5, range 0) was imported and rendered, and the rig could not be saved. Now each value out
// of range is clamped with a warning naming the light, and the model's rig saves and reads back.
void TestModelHostile::modelLightsGetTheRigLimits() {
    const ModelLoadResult r = loadModel(dataFile(QStringLiteral("hostile/gltf-light-neg.gltf")));
    QVERIFY2(r.ok(), qPrintable(r.error));
    const QString warnings = r.model->warnings.join(QLatin1Char('\n'));
    QCOMPARE(r.model->lights.lights.size(), size_t(1));
    const Light& l = r.model->lights.lights[0];
    QVERIFY(l.intensity >= 0.0 && l.intensity <= kMaxRigIntensity);
    for (int i = 0; i < 3; ++i)
        QVERIFY(l.color[i] >= 0.0 && l.color[i] <= kMaxRigIntensity);
    QVERIFY2(warnings.contains(QStringLiteral("gltf-light-neg.gltf: light ")) &&
                 warnings.contains(QStringLiteral("negative or non-finite components; clamped to 0")),
             qPrintable(warnings));
    const RigReadResult back = readRigJson(writeRigJson(r.model->lights), QStringLiteral("model.json"));
    QVERIFY2(back.ok(), qPrintable(back.errors.join(QLatin1Char('\n'))));

    // Each limit on its own: intensity, a falloff range, a position past the format's ±1e12 (dropped).
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    QJsonObject gltf = readJson(dataFile(QStringLiteral("hostile/gltf-light-neg.gltf")));
    QJsonObject ext = gltf[QStringLiteral("extensions")].toObject();
    QJsonObject punctual = ext[QStringLiteral("KHR_lights_punctual")].toObject();
    punctual[QStringLiteral("lights")] = QJsonArray{
        QJsonObject{{QStringLiteral("type"), QStringLiteral("point")},
                    {QStringLiteral("intensity"), 1e9},
                    {QStringLiteral("range"), 1e15}},
        QJsonObject{{QStringLiteral("type"), QStringLiteral("point")}},
    };
    ext[QStringLiteral("KHR_lights_punctual")] = punctual;
    gltf[QStringLiteral("extensions")] = ext;
    QJsonArray nodes = gltf[QStringLiteral("nodes")].toArray();
    nodes.append(QJsonObject{
        {QStringLiteral("translation"), QJsonArray{0, 1e13, 0}},
        {QStringLiteral("extensions"),
         QJsonObject{{QStringLiteral("KHR_lights_punctual"), QJsonObject{{QStringLiteral("light"), 1}}}}}});
    gltf[QStringLiteral("nodes")] = nodes;
    QJsonArray scenes = gltf[QStringLiteral("scenes")].toArray();
    scenes[0] = QJsonObject{{QStringLiteral("nodes"), QJsonArray{0, 1, 2}}};
    gltf[QStringLiteral("scenes")] = scenes;
    const QString path = tmp.filePath(QStringLiteral("limits.gltf"));
    QVERIFY(writeFile(path, QJsonDocument(gltf).toJson()));
    const ModelLoadResult limits = loadModel(path);
    QVERIFY2(limits.ok(), qPrintable(limits.error));
    const QString said = limits.model->warnings.join(QLatin1Char('\n'));
    QCOMPARE(limits.model->lights.lights.size(), size_t(1)); // the one at y = 1e13 is dropped
    const Light& kept = limits.model->lights.lights[0];
    QCOMPARE(kept.intensity, kMaxRigIntensity);
    QCOMPARE(kept.falloff.range, kMaxRigLength);
    QVERIFY2(said.contains(QStringLiteral("intensity 1e+09 clamped to 1e+06")), qPrintable(said));
    QVERIFY2(said.contains(QStringLiteral("falloff value 1e+15 clamped to 1e+12")), qPrintable(said));
    QVERIFY2(said.contains(QStringLiteral("position beyond ±1e+12")) &&
                 said.contains(QStringLiteral("skipped")),
             qPrintable(said));
    QVERIFY(readRigJson(writeRigJson(limits.model->lights), QStringLiteral("m.json")).ok());
}

// gltf-camera-nan.gltf: yfov 1e39, znear 1e-45. The near plane leaves no depth precision (the model
// rendered as the background alone): the camera is ignored with a warning, and the model's views remain.
void TestModelHostile::unusableCameraIsIgnored() {
    const ModelLoadResult r = loadModel(dataFile(QStringLiteral("hostile/gltf-camera-nan.gltf")));
    QVERIFY2(r.ok(), qPrintable(r.error));
    QVERIFY(r.model->cameras.empty());
    QVERIFY2(r.model->warnings.join(QLatin1Char('\n'))
                 .contains(QStringLiteral("has an unusable near plane (1.4013e-45); ignored")),
             qPrintable(r.model->warnings.join(QLatin1Char('\n'))));
    // A camera with an ordinary near plane is kept (scene.gltf's).
    const ModelLoadResult scene = loadModel(dataFile(QStringLiteral("scene.gltf")));
    QVERIFY2(scene.ok() && !scene.model->cameras.empty(), qPrintable(scene.error));
}

// Errors name the path as given, not only its file name ("could not import empty.obj" was ambiguous in
// batch runs): absolute, relative and with "..", each as written.
void TestModelHostile::errorsNameTheFile() {
    QTemporaryDir tmp;
    QVERIFY(tmp.isValid());
    const ModelLoadResult missing = loadModel(tmp.filePath(QStringLiteral("nothing.obj")));
    QVERIFY(!missing.ok());
    QCOMPARE(
        missing.error,
        QStringLiteral("could not import %1: no such file").arg(tmp.filePath(QStringLiteral("nothing.obj"))));
    const QString relative =
        QDir::current().relativeFilePath(tmp.filePath(QStringLiteral("sub/../nothing.obj")));
    const ModelLoadResult relativeMissing = loadModel(relative);
    QCOMPARE(relativeMissing.error, QStringLiteral("could not import %1: no such file").arg(relative));
    const ModelLoadResult folder = loadModel(tmp.path());
    QVERIFY(!folder.ok());
    QCOMPARE(folder.error,
             QStringLiteral("could not import %1: not a regular file (a folder, FIFO, socket or device)")
                 .arg(tmp.path()));
    const QString junk = tmp.filePath(QStringLiteral("junk.fbx"));
    QByteArray bytes;
    for (int i = 0; i < 4096; ++i)
        bytes.append(char((i * 7919) % 251));
    QVERIFY(writeFile(junk, bytes));
    const ModelLoadResult garbage = loadModel(junk);
    QVERIFY(!garbage.ok());
    QVERIFY2(garbage.error.startsWith(QStringLiteral("could not import %1: ").arg(junk)),
             qPrintable(garbage.error));
}

QTEST_GUILESS_MAIN(TestModelHostile)
#include "tst_modelhostile.moc"
