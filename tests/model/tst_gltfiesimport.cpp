// Issue 39: EXT_lights_ies imported (model/gltflightextras.cpp, gltfiesprofile.cpp): a light exported with
// an IES profile comes back as a point light of the same position, nadir, rotation, multiplier and colour,
// naming a file with the profile's bytes (the IES cache for an embedded one, the file itself for a relative
// uri); a bufferView in a .gltf's file buffer and in a GLB's BIN chunk; and every bad profile (malformed,
// missing, invalid base64, outside the folder, too large) a warning naming the file and the JSON field,
// the light imported without its profile.
#include "core/ies.h"
#include "gltflightfixtures.h"
#include "model/upaxis.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QTest>

using namespace lr;
using lr::test::lightNamed;
using lr::test::setIn;
using lr::test::warningWith;

namespace {

QString iesData(const QString& name) {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/ies/") + name;
}

// A physically based rig: "Down", a spot with full.ies (rotation 30, level as given, multiplier 2), aimed
// obliquely, and "Key", a plain point light.
Rig rigWithProfile(IesLevel level) {
    Rig rig;
    rig.shading.model = ShadingModel::Pbr;
    Light spot = makeLight(LightType::Spot, QStringLiteral("Down"));
    spot.position = {1.0, 3.0, -2.0};
    spot.direction = glm::normalize(glm::dvec3(0.3, -1.0, 0.2));
    spot.intensity = 40.0;
    spot.color = {1.0, 0.5, 0.25};
    spot.temperature.reset();
    spot.falloff.model = FalloffModel::InverseSquare;
    spot.falloff.range = -1.0;
    spot.ies = IesSpec{QStringLiteral("full.ies"), iesData(QStringLiteral("full.ies")), 2.0, level, 30.0};
    Light key = makeLight(LightType::Point, QStringLiteral("Key"));
    key.falloff.model = FalloffModel::InverseSquare;
    key.falloff.range = -1.0;
    rig.lights = {key, spot};
    return rig;
}

bool near(double a, double b, double tol = 1e-9) {
    return std::abs(a - b) <= tol;
}

} // namespace

class TestGltfIesImport : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir, m_cache;
    QByteArray m_full;

    // Writes `root` as NAME.gltf in the test folder and imports it.
    std::shared_ptr<Model> load(const QString& name, const QJsonObject& root,
                                const ModelLoadOptions& o = {}) {
        const QString path = m_dir.filePath(name + QStringLiteral(".gltf"));
        if (!test::writeJson(path, root)) return nullptr;
        ModelLoadResult r = loadModel(path, o);
        if (!r.ok()) qWarning("%s", qPrintable(r.error));
        return r.model;
    }
    // The profile's uri set to `uri` (and the import), checking the light came without a profile and a
    // warning names the file, the field and `reason`.
    void expectNoProfile(const QString& name, const QString& uri, const QString& reason) {
        QJsonObject root = test::exportedScene(rigWithProfile(IesLevel::Profile));
        setIn(root, {"extensions", "EXT_lights_ies", "lights", "0", "uri"}, uri);
        const std::shared_ptr<Model> m = load(name, root);
        QVERIFY(m);
        const Light* down = lightNamed(*m, QStringLiteral("Down"));
        QVERIFY(down);
        QVERIFY(!down->ies);
        QVERIFY(down->type == LightType::Point);
        const QString w =
            warningWith(*m, {name + QStringLiteral(".gltf: extensions.EXT_lights_ies.lights[0].uri: "),
                             reason, QStringLiteral("imported without its profile")});
        QVERIFY2(!w.isEmpty(), qPrintable(m->warnings.join(QLatin1Char('\n'))));
    }

  private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid() && m_cache.isValid());
        qputenv("LIGHTRIG_IES_CACHE", m_cache.path().toUtf8());
        m_full = lrtest::readFile(iesData(QStringLiteral("full.ies")));
        QVERIFY(!m_full.isEmpty());
    }

    void roundTripsAnExportedProfile_data() {
        QTest::addColumn<int>("level");
        QTest::newRow("level profile") << int(IesLevel::Profile);
        QTest::newRow("level light") << int(IesLevel::Light);
    }
    void roundTripsAnExportedProfile() {
        QFETCH(int, level);
        const Rig rig = rigWithProfile(IesLevel(level));
        const std::shared_ptr<Model> m = load(QStringLiteral("roundtrip"), test::exportedScene(rig));
        QVERIFY(m);
        QVERIFY(lightNamed(*m, QStringLiteral("Key"))); // the punctual light, through Assimp
        const Light* down = lightNamed(*m, QStringLiteral("Down"));
        QVERIFY(down);
        QVERIFY(down->type == LightType::Point); // EXT_lights_ies lights are points
        QVERIFY2(down->ies, qPrintable(m->warnings.join(QLatin1Char('\n'))));
        const Light& src = rig.lights[1];
        QVERIFY(glm::length(down->position - src.position) < 1e-9);
        QVERIFY(glm::length(down->direction - src.direction) < 1e-9);
        QVERIFY2(near(down->ies->rotation, 30.0), qPrintable(QString::number(down->ies->rotation, 'g', 17)));
        QVERIFY(down->ies->level == IesLevel::Profile);
        QVERIFY(glm::length(down->color - src.color) < 1e-9);
        // Level "profile": the multiplier as it was; level "light": intensity × multiplier / peak, the same
        // candela.
        QString error;
        const auto profile = readIesFile(iesData(QStringLiteral("full.ies")), &error);
        QVERIFY2(profile, qPrintable(error));
        const double expected = IesLevel(level) == IesLevel::Profile ? 2.0 : 40.0 * 2.0 / profile->peak;
        QVERIFY2(near(down->ies->multiplier, expected), qPrintable(QString::number(down->ies->multiplier)));
        // The embedded profile: a cache file of the same bytes, named by their SHA-256.
        const QString hash =
            QString::fromLatin1(QCryptographicHash::hash(m_full, QCryptographicHash::Sha256).toHex());
        QCOMPARE(down->ies->file, QDir(m_cache.path()).filePath(hash + QStringLiteral(".ies")));
        QCOMPARE(lrtest::readFile(down->ies->file), m_full);
    }

    // The editor turns a model to another up axis (model/upaxis.h): the profile's axes turn with it.
    void turnsWithTheModelsUpAxis() {
        const std::shared_ptr<Model> m =
            load(QStringLiteral("upaxis"), test::exportedScene(rigWithProfile(IesLevel::Profile)));
        QVERIFY(m);
        const Model turned = rotateModelUp(*m, ModelUpAxis::ZUp);
        const glm::dmat3 r = upAxisRotation(ModelUpAxis::ZUp);
        const Light *before = lightNamed(*m, QStringLiteral("Down")),
                    *after = lightNamed(turned, QStringLiteral("Down"));
        QVERIFY(before && after && before->ies && after->ies);
        const AreaAxes a = areaAxes(before->direction, before->ies->rotation);
        const AreaAxes b = areaAxes(after->direction, after->ies->rotation);
        QVERIFY(glm::length(b.x - r * a.x) < 1e-9 && glm::length(b.y - r * a.y) < 1e-9);
        QVERIFY(!near(after->ies->rotation, before->ies->rotation)); // it did have to change here
    }

    void relativeUriNamesTheFileItself() {
        QVERIFY(QDir(m_dir.path()).mkpath(QStringLiteral("profiles")));
        const QString copy = m_dir.filePath(QStringLiteral("profiles/full copy.ies"));
        QVERIFY(lrtest::writeFile(copy, m_full));
        QJsonObject root = test::exportedScene(rigWithProfile(IesLevel::Profile));
        setIn(root, {"extensions", "EXT_lights_ies", "lights", "0", "uri"},
              QStringLiteral("profiles/full%20copy.ies"));
        const std::shared_ptr<Model> m = load(QStringLiteral("relative"), root);
        QVERIFY(m);
        const Light* down = lightNamed(*m, QStringLiteral("Down"));
        QVERIFY(down && down->ies);
        QCOMPARE(down->ies->file, QFileInfo(copy).absoluteFilePath());
    }

    void bufferViewInAFileBufferAndInAGlb() {
        QJsonObject root = test::exportedScene(rigWithProfile(IesLevel::Profile));
        QJsonArray buffers = root.value(QStringLiteral("buffers")).toArray();
        QJsonArray views = root.value(QStringLiteral("bufferViews")).toArray();
        QVERIFY(lrtest::writeFile(m_dir.filePath(QStringLiteral("profile.bin")), "pad!" + m_full));
        buffers.append(QJsonObject{{"uri", "profile.bin"}, {"byteLength", m_full.size() + 4}});
        views.append(
            QJsonObject{{"buffer", buffers.size() - 1}, {"byteOffset", 4}, {"byteLength", m_full.size()}});
        root.insert(QStringLiteral("buffers"), buffers);
        root.insert(QStringLiteral("bufferViews"), views);
        setIn(root, {"extensions", "EXT_lights_ies", "lights", "0"},
              QJsonObject{{"bufferView", views.size() - 1}, {"mimeType", "application/x-ies-lm-63"}});
        std::shared_ptr<Model> m = load(QStringLiteral("view"), root);
        QVERIFY(m);
        const Light* down = lightNamed(*m, QStringLiteral("Down"));
        QVERIFY2(down && down->ies, qPrintable(m->warnings.join(QLatin1Char('\n'))));
        QCOMPARE(lrtest::readFile(down->ies->file), m_full);

        // The same profile in a GLB's BIN chunk, after the scene's own data.
        QJsonObject glbRoot = test::exportedScene(rigWithProfile(IesLevel::Profile));
        QJsonArray glbViews = glbRoot.value(QStringLiteral("bufferViews")).toArray();
        qint64 offset = 0;
        glbViews.append(QJsonObject{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", m_full.size()}});
        glbRoot.insert(QStringLiteral("bufferViews"), glbViews);
        setIn(glbRoot, {"extensions", "EXT_lights_ies", "lights", "0"},
              QJsonObject{{"bufferView", glbViews.size() - 1}, {"mimeType", "application/x-ies-lm-63"}});
        test::asGlb(glbRoot, m_full, &offset); // learn where the profile lands, then point the view there
        setIn(glbRoot, {"bufferViews", QString::number(glbViews.size() - 1)},
              QJsonObject{{"buffer", 0}, {"byteOffset", offset}, {"byteLength", m_full.size()}});
        const QString glb = m_dir.filePath(QStringLiteral("view.glb"));
        QVERIFY(lrtest::writeFile(glb, test::asGlb(glbRoot, m_full, &offset)));
        ModelLoadResult r = loadModel(glb);
        QVERIFY2(r.ok(), qPrintable(r.error));
        down = lightNamed(*r.model, QStringLiteral("Down"));
        QVERIFY2(down && down->ies, qPrintable(r.model->warnings.join(QLatin1Char('\n'))));
        QCOMPARE(lrtest::readFile(down->ies->file), m_full);

        // A view beyond its buffer: a warning naming the field, no profile.
        setIn(glbRoot, {"bufferViews", QString::number(glbViews.size() - 1)},
              QJsonObject{{"buffer", 0}, {"byteOffset", offset + 8}, {"byteLength", m_full.size()}});
        QVERIFY(lrtest::writeFile(glb, test::asGlb(glbRoot, m_full, &offset)));
        r = loadModel(glb);
        QVERIFY2(r.ok(), qPrintable(r.error));
        down = lightNamed(*r.model, QStringLiteral("Down"));
        QVERIFY(down && !down->ies);
        QVERIFY(!warningWith(*r.model, {QStringLiteral("extensions.EXT_lights_ies.lights[0].bufferView"),
                                        QStringLiteral("beyond the BIN chunk")})
                     .isEmpty());
    }

    void malformedProfile() {
        const QByteArray bad = lrtest::readFile(iesData(QStringLiteral("malformed.ies")));
        QVERIFY(!bad.isEmpty());
        QString reason;
        QVERIFY(!readIesData(bad, QStringLiteral("embedded profile"), &reason));
        expectNoProfile(QStringLiteral("malformed"),
                        QStringLiteral("data:application/x-ies-lm-63;base64,") +
                            QString::fromLatin1(bad.toBase64()),
                        reason);
    }
    void missingFile() {
        expectNoProfile(QStringLiteral("missing"), QStringLiteral("nowhere.ies"),
                        QStringLiteral("no such file"));
    }
    void invalidBase64() {
        expectNoProfile(QStringLiteral("base64"),
                        QStringLiteral("data:application/x-ies-lm-63;base64,!!notbase64*"),
                        QStringLiteral("base64 does not decode"));
    }
    void outsideTheFolder() {
        expectNoProfile(QStringLiteral("outside"), QStringLiteral("../elsewhere.ies"),
                        QStringLiteral("outside the model's folder"));
    }
    void tooLargeADataUri() {
        // Over the import's data: URI limit the whole file is refused before Assimp (preflight), as for any
        // glTF data: URI; nothing crashes and the reason says so.
        QJsonObject root = test::exportedScene(rigWithProfile(IesLevel::Profile));
        setIn(root, {"extensions", "EXT_lights_ies", "lights", "0", "uri"},
              QStringLiteral("data:application/x-ies-lm-63;base64,") + QString(200000, QLatin1Char('A')));
        const QString path = m_dir.filePath(QStringLiteral("huge.gltf"));
        QVERIFY(test::writeJson(path, root));
        ModelLoadOptions o;
        o.maxDataUriBytes = 100000;
        const ModelLoadResult r = loadModel(path, o);
        QVERIFY(!r.ok());
        QVERIFY2(r.error.contains(QStringLiteral("100000")), qPrintable(r.error));
    }
};

QTEST_GUILESS_MAIN(TestGltfIesImport)
#include "tst_gltfiesimport.moc"
