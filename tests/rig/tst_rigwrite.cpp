// Writing rig files: write -> read gives the same rig for random valid rigs, the canonical form is stable
// (byte-identical after load -> save), only used fields are written, and saving is atomic.
#include "rigtest.h"

#include "core/rigjson_json.h"

#include <QRandomGenerator>
#include <QTemporaryDir>
#include <csignal>
#include <glm/geometric.hpp>
#include <sys/resource.h>
#include <unistd.h>

using namespace lr;
using namespace lr::test;

namespace {

// Random valid rigs: values spread over the allowed ranges (ordinary, round, huge, tiny, subnormal),
// names with escapes and non-ASCII text, every type and model; unused fields left at their defaults.
class RigGenerator {
  public:
    explicit RigGenerator(quint32 seed) : m_rng(seed) {}

    Rig rig() {
        Rig r;
        r.name = name();
        r.space = pick<RigSpace>();
        r.ambient = color();
        // Under physically based shading the classic keys are neither written nor read: they stay default.
        r.shading.model = pick<ShadingModel>();
        if (r.shading.model == ShadingModel::Classic) {
            r.shading.specular = pick<SpecularModel>();
            r.shading.viewer = pick<ViewerModel>();
            r.shading.shininess = positive(kMaxRigExponent);
        }
        if (chance(0.4)) r.ground = {pick<GroundMode>(), {albedo(), albedo(), albedo()}};
        if (chance(0.4)) r.environment = environment();
        const int n = int(m_rng.bounded(8)); // fewer than kMaxShadowCasters, whatever casts
        for (int i = 0; i < n; ++i)
            r.lights.push_back(light());
        return r;
    }

  private:
    // Any valid environment: rotations already in [0, 360) (the canonical form normalises them).
    Environment environment() {
        Environment e;
        e.source = pick<EnvironmentSource>();
        if (e.source == EnvironmentSource::Image || chance(0.3))
            e.file = chance(0.3) ? QStringLiteral("builtin:studio") : QStringLiteral("hdr/") + name() + 'x';
        e.intensity = (chance(0.5) ? -1.0 : 1.0) * std::min(kMaxEnvironmentEV, value(kMaxEnvironmentEV));
        e.rotation = std::min(value(360.0), 359.5);
        e.background = pick<EnvironmentBackground>();
        e.blur = std::min(1.0, value(1.0));
        e.diffuse = pick<DiffuseModel>();
        if (e.source == EnvironmentSource::Studio || chance(0.2)) {
            e.studio.zenith = color();
            e.studio.floor = color();
            const int n = int(m_rng.bounded(kMaxEnvironmentSoftboxes + 1));
            for (int i = 0; i < n; ++i) {
                Softbox b;
                b.azimuth = signedLength();
                b.elevation = (chance(0.5) ? -1.0 : 1.0) * std::min(90.0, value(90.0));
                b.width = std::min(kMaxSoftboxAngle, positive(kMaxSoftboxAngle));
                b.height = std::min(kMaxSoftboxAngle, positive(kMaxSoftboxAngle));
                b.color = color();
                b.intensity = value(kMaxRigIntensity);
                e.studio.softboxes.push_back(b);
            }
        }
        const int spots = chance(0.5) ? int(m_rng.bounded(kMaxEnvironmentSpots + 1)) : 0;
        for (int i = 0; i < spots; ++i)
            e.spots.push_back({unit(), std::min(90.0, positive(90.0)), std::min(1.0, value(1.0))});
        return e;
    }

    template <typename E> E pick() { return E(m_rng.bounded(enumCount<E>())); }
    bool chance(double p) { return m_rng.generateDouble() < p; }

    // In [0, max]: mostly ordinary, sometimes 0, max, a round number, tiny or subnormal.
    double value(double max) {
        switch (m_rng.bounded(8)) {
        case 0:
            return 0.0;
        case 1:
            return max;
        case 2:
            return double(m_rng.bounded(100)) / 10.0;
        case 3:
            return std::ldexp(m_rng.generateDouble(), -int(m_rng.bounded(1060))); // down to subnormals
        case 4:
            return max * m_rng.generateDouble();
        default:
            return std::min(max, std::exp(m_rng.generateDouble() * 10.0 - 5.0));
        }
    }
    double positive(double max) {
        const double v = value(max);
        return v > 0.0 ? v : 0.5;
    }
    double signedLength() { return (chance(0.5) ? -1.0 : 1.0) * value(kMaxRigLength); }
    double albedo() { return std::min(1.0, value(1.0)); } // value() may round past its max
    glm::dvec3 color() { return {value(kMaxRigIntensity), value(2.0), value(1.0)}; }
    glm::dvec3 unit() {
        glm::dvec3 v;
        do
            v = {m_rng.generateDouble() * 2 - 1, m_rng.generateDouble() * 2 - 1,
                 m_rng.generateDouble() * 2 - 1};
        while (glm::dot(v, v) < 1e-6);
        return glm::normalize(v);
    }
    QString name() {
        static const char16_t pieces[][4] = {u"a",      u"Key", u" ",      u"\"",     u"\\",
                                             u"\n",     u"\t",  u"\u00e9", u"\u6f22", u"\U0001F4A1",
                                             u"\u0001", u"/",   u"\u007f", u"\u2028"};
        QString s;
        const int n = int(m_rng.bounded(12));
        for (int i = 0; i < n; ++i)
            s += QString::fromUtf16(pieces[m_rng.bounded(int(std::size(pieces)))]);
        return s;
    }

    Light light() {
        Light l;
        l.type = pick<LightType>();
        l.name = name();
        l.enabled = chance(0.8);
        l.color = color();
        if (chance(0.3)) l.temperature = 1000.0 + value(39000.0);
        l.intensity = value(kMaxRigIntensity);
        if (l.usesPosition()) l.position = {signedLength(), signedLength(), signedLength()};
        if (l.usesDirection()) l.direction = unit();
        if (l.usesFalloff()) {
            Falloff& f = l.falloff;
            f.model = pick<FalloffModel>();
            switch (f.model) {
            case FalloffModel::None:
                break;
            case FalloffModel::RangePower:
                f.range = positive(kMaxRigLength), f.exponent = positive(kMaxRigExponent);
                break;
            case FalloffModel::InversePolynomial:
                f.constant = value(kMaxRigLength), f.linear = value(kMaxRigLength),
                f.quadratic = value(kMaxRigLength);
                if (f.constant == 0.0 && f.linear == 0.0 && f.quadratic == 0.0) f.quadratic = 1.0;
                if (chance(0.5)) f.range = positive(kMaxRigLength);
                break;
            case FalloffModel::RangeQuadratic:
                f.range = positive(kMaxRigLength);
                break;
            case FalloffModel::InverseSquare:
                if (chance(0.5)) f.range = positive(kMaxRigLength);
                break;
            }
        }
        if (l.usesCone()) {
            Cone& c = l.cone;
            c.model = pick<ConeModel>();
            c.outer = positive(90.0);
            if (c.model == ConeModel::Smooth) c.inner = std::min(c.outer, positive(90.0));
            if (c.model != ConeModel::Hard) c.exponent = positive(kMaxRigExponent);
        }
        if (l.usesSurfaceModels()) {
            l.diffuse = pick<DiffuseModel>();
            if (chance(0.3)) {
                l.specularIsColor = true;
                l.specular = color();
            } else if (chance(0.5)) {
                l.specular = glm::dvec3(value(kMaxRigIntensity));
            }
            if (chance(0.3)) l.ambient = color();
        }
        if (l.type == LightType::Rim) l.rimExponent = positive(kMaxRigExponent);
        if (l.isArea()) {
            AreaShape& a = l.area;
            if (traitsOf(l.type).usesRectSize) {
                a.width = value(kMaxRigLength);
                a.height = value(kMaxRigLength);
            } else {
                a.radius = value(kMaxRigLength);
            }
            a.roll = std::min(180.0, value(360.0) - 180.0);
            a.twoSided = chance(0.5);
        }
        if (l.castsShadows() && chance(0.5)) {
            Shadow& s = l.shadow;
            s.enabled = chance(0.7);
            s.resolution = kMinShadowResolution << m_rng.bounded(5); // 256 ... 4096
            s.bias = std::min(kMaxShadowBias, value(kMaxShadowBias));
            s.normalOffset = std::min(kMaxShadowBias, value(kMaxShadowBias));
            if (l.isArea())
                ; // an area light's softness is its "area": its shadow has no size
            else if (l.usesPosition())
                s.size = value(kMaxRigLength);
            else
                s.angle = std::min(kMaxShadowAngle, value(kMaxShadowAngle));
        }
        return l;
    }

    QRandomGenerator m_rng;
};

void writeFile(const QString& path, const QByteArray& data) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    QCOMPARE(f.write(data), data.size());
}

} // namespace

class TestRigWrite : public QObject {
    Q_OBJECT
  private slots:
    void randomRigsRoundTrip();
    void loadSaveIsByteIdentical_data();
    void loadSaveIsByteIdentical();
    void numbersAreShortestAndExact();
    void onlyUsedFieldsAreWritten();
    void areaIsWrittenInFull();
    void shadowAndGroundOnlyWhenSet();
    void environmentOnlyWhenSet();
    void environmentRotationIsNormalised();
    void filesWithoutEnvironmentKeepTheirBytes_data();
    void filesWithoutEnvironmentKeepTheirBytes();
    void saveAndReload();
    void saveRefusesInvalidRig();
    void nonFiniteValuesAreNotSaved();
    void failedSaveKeepsOldFile();
    void readOnlyDirectoryKeepsOldFile();
    void missingDirectory();
};

void TestRigWrite::randomRigsRoundTrip() {
    RigGenerator gen(20261122);
    for (int i = 0; i < 500; ++i) {
        const Rig rig = gen.rig();
        const QByteArray text = writeRigJson(rig);
        const RigReadResult r = readRigJson(text, QStringLiteral("random.json"));
        QVERIFY2(r.ok(), qPrintable(describe(r) + QStringLiteral("\n") + QString::fromUtf8(text)));
        QVERIFY2(r.warnings.isEmpty(), qPrintable(describe(r)));
        QVERIFY2(*r.rig == rig,
                 qPrintable(QStringLiteral("rig %1 changed:\n").arg(i) + QString::fromUtf8(text)));
        QCOMPARE(writeRigJson(*r.rig), text);
    }
}

void TestRigWrite::loadSaveIsByteIdentical_data() {
    QTest::addColumn<QString>("file");
    for (const char* f :
         {"good/issue-example.json", "good/minimal.json", "good/all-fields.json", "good/utf8-bom.json",
          "good/shadows.json", "good/environment.json", "good/area.json"})
        QTest::newRow(f) << dataPath(QString::fromLatin1(f));
}

// Any valid file: load -> save -> load gives the same rig, and a second save the same bytes.
void TestRigWrite::loadSaveIsByteIdentical() {
    QFETCH(QString, file);
    const RigReadResult first = readRigFile(file);
    LR_VERIFY_OK(first);
    const QByteArray saved = writeRigJson(*first.rig);
    const RigReadResult second = readRigJson(saved, QStringLiteral("saved.json"));
    LR_VERIFY_OK(second);
    QVERIFY(*second.rig == *first.rig);
    QCOMPARE(writeRigJson(*second.rig), saved);
    QVERIFY(saved.endsWith("}\n"));
    QVERIFY(!saved.startsWith("\xEF\xBB\xBF"));
}

void TestRigWrite::numbersAreShortestAndExact() {
    Rig rig;
    Light l = makeLight(LightType::Point, QStringLiteral("n"));
    l.falloff = {FalloffModel::RangePower, 8.0, 2.0};
    l.intensity = 4.0;
    l.position = {0.1, 1.0 / 3.0, -0.0};
    l.color = {1e-7, 123456789.125 / 1e3, 100000.0};
    rig.lights = {l};
    const QByteArray text = writeRigJson(rig);
    // Integers without ".0", the shortest decimal that reads back exactly, -0 as 0.
    QVERIFY2(text.contains("\"intensity\": 4,"), text.constData());
    QVERIFY2(text.contains("\"position\": [0.1, 0.3333333333333333, 0]"), text.constData());
    QVERIFY2(text.contains("\"color\": [1e-7, 123456.789125, 100000]"), text.constData());
    QVERIFY2(text.contains("\"falloff\": {\"model\": \"range-power\", \"range\": 8, \"exponent\": 2}"),
             text.constData());
    const RigReadResult r = readRigJson(text, QStringLiteral("n.json"));
    LR_VERIFY_OK(r);
    QCOMPARE(r.rig->lights[0].position.y, 1.0 / 3.0);
    QCOMPARE(r.rig->lights[0].color, l.color);
}

void TestRigWrite::onlyUsedFieldsAreWritten() {
    // A point light whose (editor) state still holds spot fields, a rim light with surface settings.
    Light point = makeLight(LightType::Point, QStringLiteral("p"));
    point.cone = {ConeModel::Hard, 5.0, 10.0, 3.0};
    point.direction = {1, 0, 0};
    point.rimExponent = 7.0;
    point.area = {9.0, 9.0, 9.0, 9.0, true}; // an area light's values on a point light: not written
    Light rim = makeLight(LightType::Rim, QStringLiteral("r"));
    rim.position = {1, 2, 3};
    rim.diffuse = DiffuseModel::HalfLambert;
    rim.specular = glm::dvec3(0.5);
    rim.ambient = glm::dvec3(0.2);
    rim.falloff = {FalloffModel::RangePower, 3.0, 2.0};
    Rig rig;
    rig.lights = {point, rim};
    const QByteArray text = writeRigJson(rig);
    for (const char* key : {"\"cone\"", "\"direction\": [1, 0, 0]", "\"diffuse\"", "\"specular\": 0.5",
                            "\"ambient\": [0.2", "\"position\": [1, 2, 3]", "7", "area", "9"})
        QVERIFY2(!text.contains(key),
                 qPrintable(QStringLiteral("%1 in\n%2").arg(QLatin1String(key), QString::fromUtf8(text))));
    const RigReadResult r = readRigJson(text, QStringLiteral("u.json"));
    LR_VERIFY_OK(r);
    LR_COMPARE(r.rig->lights[0].falloff, point.falloff);
    QCOMPARE(r.rig->lights[1].direction, rim.direction);
}

// Issue 16: an area light always has "area", in full with the keys of its shape; its shadow never has a size
// or an angle (its softness is its own area), and the file is version 2 only when it has an area light.
void TestRigWrite::areaIsWrittenInFull() {
    Light rect = makeLight(LightType::Rect, QStringLiteral("r"));
    rect.area = {2.0, 0.5, 7.0, -45.0, true};
    rect.shadow.enabled = true;
    rect.shadow.size = 3.0;  // an editor's leftover: an area light's shadow has no size
    rect.shadow.angle = 4.0; // nor an angle
    Light disk = makeLight(LightType::Disk, QStringLiteral("d"));
    disk.area = {5.0, 6.0, 0.25, 0.0, false};
    Rig rig;
    rig.lights = {rect, disk};
    const QByteArray text = writeRigJson(rig);
    for (const char* line :
         {"\"version\": 2,", "\"area\": {\"width\": 2, \"height\": 0.5, \"roll\": -45, \"twoSided\": true}",
          "\"shadow\": {\"enabled\": true, \"resolution\": 1024, \"bias\": 1, \"normalOffset\": 1}",
          "\"area\": {\"radius\": 0.25, \"roll\": 0, \"twoSided\": false}"})
        QVERIFY2(
            text.contains(line),
            qPrintable(QStringLiteral("%1 not in\n%2").arg(QLatin1String(line), QString::fromUtf8(text))));
    const RigReadResult r = readRigJson(text, QStringLiteral("a.json"));
    LR_VERIFY_OK(r);
    LR_COMPARE(r.rig->lights[0].area, (AreaShape{2.0, 0.5, 0.5, -45.0, true})); // a rect has no radius
    QCOMPARE(r.rig->lights[1].area.radius, 0.25);
    // Its area's order in a light: after direction, before shadow.
    QVERIFY(text.indexOf("\"direction\"") < text.indexOf("\"area\"") &&
            text.indexOf("\"area\"") < text.indexOf("\"shadow\""));
    // Without area lights the same rig is version 1.
    rig.lights = {makeLight(LightType::Spot, QStringLiteral("s"))};
    QVERIFY(writeRigJson(rig).contains("\"version\": 1,"));
}

// Issue 14: "shadow" and "ground" are written only when they differ from the defaults (so files from before
// shadows keep their bytes), then in full on one line; a shadow only where the type casts one, with the
// softness key of its type.
void TestRigWrite::shadowAndGroundOnlyWhenSet() {
    Light spot = makeLight(LightType::Spot, QStringLiteral("s"));
    Light sun = makeLight(LightType::Directional, QStringLiteral("d"));
    Light rim = makeLight(LightType::Rim, QStringLiteral("r"));
    Rig rig;
    rig.lights = {spot, sun, rim};
    QByteArray text = writeRigJson(rig);
    QVERIFY2(!text.contains("shadow") && !text.contains("ground"), text.constData());

    rig.lights[0].shadow.enabled = true;
    rig.lights[0].shadow.size = 0.25;
    rig.lights[1].shadow.angle = 0.53;   // the shadow off, one value set: kept
    rig.lights[1].shadow.size = 3.0;     // not a directional light's: neither written nor compared
    rig.lights[2].shadow.enabled = true; // a rim light casts none: not written
    rig.ground = {GroundMode::Catcher, glm::dvec3(0.5)};
    text = writeRigJson(rig);
    QVERIFY2(text.contains("      \"shadow\": {\"enabled\": true, \"resolution\": 1024, \"bias\": 1, "
                           "\"normalOffset\": 1, \"size\": 0.25}\n    },"),
             text.constData());
    QVERIFY2(text.contains("      \"shadow\": {\"enabled\": false, \"resolution\": 1024, \"bias\": 1, "
                           "\"normalOffset\": 1, \"angle\": 0.53}\n    },"),
             text.constData());
    QCOMPARE(text.count("\"shadow\""), 2);
    QVERIFY2(text.contains("  \"shading\": {\"specular\": \"phong\", \"viewer\": \"local\", \"shininess\": "
                           "32},\n  \"ground\": {\"mode\": \"catcher\", \"color\": [0.5, 0.5, 0.5]},\n  "
                           "\"lights\": ["),
             text.constData());
    const RigReadResult r = readRigJson(text, QStringLiteral("s.json"));
    LR_VERIFY_OK(r);
    QVERIFY(r.rig->lights[0].shadow == rig.lights[0].shadow);
    QCOMPARE(r.rig->lights[1].shadow.angle, 0.53);
    QCOMPARE(r.rig->lights[1].shadow.size, 0.0);
    QVERIFY(!r.rig->lights[2].shadow.enabled);
    QVERIFY(r.rig->ground == rig.ground);
    QCOMPARE(writeRigJson(*r.rig), text);

    // Only the colour differs: the ground is written (mode off), and reads back the same.
    Rig grey;
    grey.ground.color = glm::dvec3(0.25, 0.5, 1.0);
    text = writeRigJson(grey);
    QVERIFY2(text.contains("\"ground\": {\"mode\": \"off\", \"color\": [0.25, 0.5, 1]}"), text.constData());
    QVERIFY(readRigJson(text, QStringLiteral("g.json")).rig->ground == grey.ground);
}

// Issue 15: "environment" is written only when it is not the default (so every file from before keeps its
// bytes), after "ground"; then every scalar, the file when there is one, the studio when it is the source
// (or was edited), the spots when there are some.
void TestRigWrite::environmentOnlyWhenSet() {
    Rig rig;
    rig.lights = {makeLight(LightType::Directional, QStringLiteral("d"))};
    QVERIFY2(!writeRigJson(rig).contains("environment"), writeRigJson(rig).constData());

    rig.environment.source = EnvironmentSource::Image;
    rig.environment.file = QStringLiteral("builtin:studio");
    rig.environment.intensity = 1.5;
    QByteArray text = writeRigJson(rig);
    QVERIFY2(
        text.contains("  \"shading\": {\"specular\": \"phong\", \"viewer\": \"local\", \"shininess\": "
                      "32},\n  \"environment\": {\n    \"source\": \"image\",\n    \"file\": "
                      "\"builtin:studio\",\n    \"intensity\": 1.5,\n    \"rotation\": 0,\n    "
                      "\"background\": \"visible\",\n    \"blur\": 0.3,\n    \"diffuse\": \"lambert\"\n  "
                      "},\n  \"lights\": ["),
        text.constData());
    RigReadResult r = readRigJson(text, QStringLiteral("e.json"));
    LR_VERIFY_OK(r);
    QVERIFY(r.rig->environment == rig.environment);

    // The procedural studio: written in full, softboxes and spots one per line.
    rig.environment.source = EnvironmentSource::Studio;
    rig.environment.studio.softboxes = {Softbox{}, Softbox{-30, 10, 20, 90, {1, 0.5, 0.25}, 0}};
    rig.environment.spots = {EnvironmentSpot{{1, 0, 0}, 10, 0.5}};
    text = writeRigJson(rig);
    QVERIFY2(
        text.contains("    \"studio\": {\n      \"zenith\": [0.35, 0.35, 0.35],\n      \"horizon\": "
                      "[0.6, 0.6, 0.6],\n      \"floor\": [0.12, 0.12, 0.12],\n      \"softboxes\": [\n"
                      "        {\"azimuth\": 0, \"elevation\": 30, \"width\": 40, \"height\": 30, "
                      "\"color\": [1, 1, 1], \"intensity\": 4},\n        {\"azimuth\": -30, "
                      "\"elevation\": 10, \"width\": 20, \"height\": 90, \"color\": [1, 0.5, 0.25], "
                      "\"intensity\": 0}\n      ]\n    },\n    \"spots\": [\n      {\"direction\": [1, 0, "
                      "0], \"angle\": 10, \"factor\": 0.5}\n    ]\n  },\n"),
        text.constData());
    r = readRigJson(text, QStringLiteral("e.json"));
    LR_VERIFY_OK(r);
    QVERIFY(r.rig->environment == rig.environment);
    QCOMPARE(writeRigJson(*r.rig), text);

    // Switched off, the settings are kept for later (like a shadow that is off); a default studio of an
    // image environment is not written.
    Rig off;
    off.environment.rotation = 90.0;
    text = writeRigJson(off);
    QVERIFY2(text.contains("\"source\": \"none\",\n    \"intensity\": 0,\n    \"rotation\": 90,"),
             text.constData());
    QVERIFY2(!text.contains("studio") && !text.contains("spots") && !text.contains("file"), text.constData());
    r = readRigJson(text, QStringLiteral("e.json"));
    LR_VERIFY_OK(r);
    QVERIFY(r.rig->environment == off.environment);
}

// Rotations are any finite number of degrees, read and written in [0, 360).
void TestRigWrite::environmentRotationIsNormalised() {
    for (const auto& [given, written] :
         {std::pair{-90.0, 270.0}, std::pair{720.0, 0.0}, std::pair{359.5, 359.5}, std::pair{-1e-20, 0.0},
          std::pair{1e300, std::fmod(1e300, 360.0)}, std::pair{-0.0, 0.0}}) {
        QCOMPARE(normalizedEnvironmentRotation(given), written);
        Rig rig;
        rig.environment.source = EnvironmentSource::Studio;
        rig.environment.rotation = given;
        const QByteArray text = writeRigJson(rig);
        QVERIFY2(text.contains("\"rotation\": " + json::formatNumber(written) + ','), text.constData());
        const QByteArray file = rigJson({}, R"("environment": {"source": "studio", "rotation": )" +
                                                json::formatNumber(given) + "},");
        const RigReadResult r = readRigJson(file, QStringLiteral("r.json"));
        LR_VERIFY_OK(r);
        QCOMPARE(r.rig->environment.rotation, written);
        QVERIFY(!std::signbit(r.rig->environment.rotation));
    }
}

// Files from before environments (every canonical file of the test data and every preset without one) load
// and save to exactly their bytes: no "environment" appears.
void TestRigWrite::filesWithoutEnvironmentKeepTheirBytes_data() {
    QTest::addColumn<QString>("file");
    QTest::newRow("good/shadows.json") << dataPath(QStringLiteral("good/shadows.json")); // canonical
    for (const QString& preset : builtinPresetNames())
        if (!readAll(builtinPresetPath(preset)).contains("\"environment\""))
            QTest::newRow(qPrintable(preset)) << builtinPresetPath(preset);
}

void TestRigWrite::filesWithoutEnvironmentKeepTheirBytes() {
    QFETCH(QString, file);
    const QByteArray bytes = readAll(file);
    const RigReadResult r = readRigJson(bytes, file);
    LR_VERIFY_OK(r);
    LR_COMPARE(r.rig->environment, Environment{});
    QCOMPARE(writeRigJson(*r.rig), bytes);
}

void TestRigWrite::saveAndReload() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("rig.json"));
    RigGenerator gen(7);
    Rig rig = gen.rig();
    QString error;
    QVERIFY2(saveRigFile(rig, path, &error), qPrintable(error));
    QVERIFY(error.isEmpty());
    const RigReadResult r = readRigFile(path);
    LR_VERIFY_OK(r);
    QVERIFY(*r.rig == rig);
    QCOMPARE(readAll(path), writeRigJson(rig));
    QVERIFY(saveRigFile(rig, path, nullptr)); // overwriting, no error string wanted
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{QStringLiteral("rig.json")});
}

void TestRigWrite::saveRefusesInvalidRig() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rig.json"));
    writeFile(path, "old contents");
    Rig rig;
    Light l = makeLight(LightType::Point, QStringLiteral("bad"));
    l.falloff = {FalloffModel::RangePower, -1.0, 2.0}; // no range: invalid for range-power
    rig.lights = {l};
    QString error;
    QVERIFY(!saveRigFile(rig, path, &error));
    QVERIFY2(error.startsWith(
                 path + QStringLiteral(": not saved: the rig is invalid: lights[0].falloff.range: must be")),
             qPrintable(error));
    QCOMPARE(readAll(path), QByteArray("old contents"));
}

// A write that fails half-way (here: the file size limit, which stops root too) leaves the old file.
void TestRigWrite::nonFiniteValuesAreNotSaved() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rig.json"));
    writeFile(path, "old contents");
    for (const double bad :
         {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        Rig rig;
        rig.lights = {makeLight(LightType::Directional, QStringLiteral("d"))};
        rig.lights[0].intensity = bad;
        QString error;
        QVERIFY(!saveRigFile(rig, path, &error));
        QVERIFY2(error.contains(QStringLiteral("lights[0].intensity: must be a finite number")),
                 qPrintable(error));
        QCOMPARE(readAll(path), QByteArray("old contents"));
    }
}

void TestRigWrite::failedSaveKeepsOldFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rig.json"));
    writeFile(path, "old contents");
    RigGenerator gen(11);
    Rig rig = gen.rig();
    while (rig.lights.size() < 4)
        rig.lights.push_back(makeLight(LightType::Spot, QStringLiteral("spot")));

    rlimit old{};
    QCOMPARE(getrlimit(RLIMIT_FSIZE, &old), 0);
    const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN); // write() fails with EFBIG instead
    rlimit small = old;
    small.rlim_cur = 100;
    QCOMPARE(setrlimit(RLIMIT_FSIZE, &small), 0);
    QString error;
    const bool saved = saveRigFile(rig, path, &error);
    setrlimit(RLIMIT_FSIZE, &old);
    std::signal(SIGXFSZ, oldHandler);

    QVERIFY(!saved);
    QVERIFY2(error.startsWith(path + QStringLiteral(": not saved: ")), qPrintable(error));
    QCOMPARE(readAll(path), QByteArray("old contents"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{QStringLiteral("rig.json")});
}

void TestRigWrite::readOnlyDirectoryKeepsOldFile() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("rig.json"));
    writeFile(path, "old contents");
    QFile::setPermissions(path, QFile::ReadOwner | QFile::WriteOwner);
    QVERIFY(QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner));
    const bool privileged = ::access(qPrintable(dir.path()), W_OK) == 0; // root ignores the mode
    QString error;
    const bool saved = saveRigFile(Rig{}, path, &error);
    QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    if (privileged)
        QSKIP(
            "running with privileges that ignore directory permissions (failedSaveKeepsOldFile covers this)");
    QVERIFY(!saved);
    QVERIFY2(error.startsWith(path + QStringLiteral(": not saved: ")), qPrintable(error));
    QCOMPARE(readAll(path), QByteArray("old contents"));
}

void TestRigWrite::missingDirectory() {
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("no/such/dir/rig.json"));
    QString error;
    QVERIFY(!saveRigFile(Rig{}, path, &error));
    QVERIFY2(error.startsWith(path + QStringLiteral(": not saved: ")), qPrintable(error));
    QVERIFY(!QFile::exists(path));
}

QTEST_GUILESS_MAIN(TestRigWrite)
#include "tst_rigwrite.moc"
