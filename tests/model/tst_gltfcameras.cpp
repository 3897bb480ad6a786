// Issue 41 item 5: a glTF's cameras are numbered by its `cameras` array, as three.js numbers them, not in
// the order Assimp's node walk meets them: tests/data/model/scene.gltf with a second camera whose node
// comes first in the scene (so Assimp meets camera 1 first), as .gltf and .glb, named and unnamed nodes.
#include "core/gltfrewrite.h"
#include "model/modelloader.h"
#include "support/files.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>
#include <QtEndian>

using namespace lr;

class TestGltfCameras : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

  private slots:
    void numberedAsTheCamerasArray_data() {
        QTest::addColumn<bool>("glb");
        QTest::addColumn<bool>("unnamed"); // camera 0's node has no name (Assimp calls it "nodes[5]")
        QTest::newRow("gltf") << false << false;
        QTest::newRow("glb") << true << false;
        QTest::newRow("gltf, camera 0 on an unnamed node") << false << true;
    }
    void numberedAsTheCamerasArray() {
        QFETCH(bool, glb);
        QFETCH(bool, unnamed);
        QVERIFY(m_dir.isValid());
        QJsonObject root =
            QJsonDocument::fromJson(lrtest::readFile(QStringLiteral(LIGHTRIG_TEST_DATA "/model/scene.gltf")))
                .object();
        QJsonArray cameras = root.value(QStringLiteral("cameras")).toArray();
        QCOMPARE(cameras.size(), 1);
        QJsonObject wide = cameras[0].toObject();
        QJsonObject perspective = wide.value(QStringLiteral("perspective")).toObject();
        perspective.insert(QStringLiteral("yfov"), 1.2);
        wide.insert(QStringLiteral("perspective"), perspective);
        cameras.append(wide);
        root.insert(QStringLiteral("cameras"), cameras);
        QJsonArray nodes = root.value(QStringLiteral("nodes")).toArray();
        QJsonObject camNode = nodes[5].toObject(); // camera 0 at (1, 2, 3)
        QCOMPARE(camNode.value(QStringLiteral("camera")).toInt(-1), 0);
        if (unnamed) camNode.remove(QStringLiteral("name"));
        nodes[5] = camNode;
        nodes.append(QJsonObject{{QStringLiteral("name"), QStringLiteral("firstNode")},
                                 {QStringLiteral("translation"), QJsonArray{7, 0, 0}},
                                 {QStringLiteral("camera"), 1}});
        root.insert(QStringLiteral("nodes"), nodes);
        QJsonArray scenes = root.value(QStringLiteral("scenes")).toArray();
        QJsonObject scene = scenes[0].toObject();
        QJsonArray sceneNodes = scene.value(QStringLiteral("nodes")).toArray();
        sceneNodes.prepend(6); // met first: Assimp's camera 0 was glTF camera 1
        scene.insert(QStringLiteral("nodes"), sceneNodes);
        scenes[0] = scene;
        root.insert(QStringLiteral("scenes"), scenes);
        QByteArray bin; // a GLB's buffer 0 is its BIN chunk: the data: URI's bytes move there
        if (glb) {
            QJsonArray buffers = root.value(QStringLiteral("buffers")).toArray();
            QJsonObject buffer = buffers[0].toObject();
            const QString uri = buffer.take(QStringLiteral("uri")).toString();
            const QByteArray data = QByteArray::fromBase64(uri.section(QLatin1Char(','), 1).toLatin1());
            buffers[0] = buffer;
            root.insert(QStringLiteral("buffers"), buffers);
            const QByteArray padded = data + QByteArray((4 - data.size() % 4) % 4, '\0');
            const quint32 length = qToLittleEndian(quint32(padded.size()));
            bin = QByteArray(reinterpret_cast<const char*>(&length), 4) + QByteArray("BIN\0", 4) + padded;
        }
        const QByteArray json = QJsonDocument(root).toJson(QJsonDocument::Compact);
        const QString file =
            m_dir.filePath(glb ? QStringLiteral("cameras.glb") : QStringLiteral("cameras.gltf"));
        QVERIFY(lrtest::writeFile(file, glb ? writeGlb(json, bin) : json));

        const ModelLoadResult r = loadModel(file);
        QVERIFY2(r.ok(), qPrintable(r.error));
        const std::vector<Camera>& got = r.model->cameras;
        QCOMPARE(got.size(), size_t(2));
        // Camera 0: camNode's, 0.6 rad; camera 1: firstNode's, 1.2 rad.
        QVERIFY2(std::abs(got[0].position.x - 1.0) < 1e-6 && std::abs(got[0].position.z - 3.0) < 1e-6,
                 qPrintable(got[0].name));
        QVERIFY(std::abs(got[0].yfovDegrees - 0.6 * 180.0 / M_PI) < 1e-3);
        QVERIFY2(std::abs(got[1].position.x - 7.0) < 1e-6, qPrintable(got[1].name));
        QVERIFY(std::abs(got[1].yfovDegrees - 1.2 * 180.0 / M_PI) < 1e-3);
    }
};

QTEST_GUILESS_MAIN(TestGltfCameras)
#include "tst_gltfcameras.moc"
