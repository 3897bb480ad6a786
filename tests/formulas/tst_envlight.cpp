// A light from the environment (core/envlight.h, issue 15 part 7): a synthetic equirectangular image with one
// bright disc at a known direction gives that direction (as where the light travels from), the exact Σ L·Ω
// of the disc's texels (lux; ÷ π under classic shading; × 2^EV), its colour, the rig's rotation applied, a
// dimmed spot that covers the disc, and "nothing bright here" for a uniform sky.
#include "core/envlight.h"
#include "core/rigjson.h"

#include <QTest>
#include <cmath>
#include <glm/geometric.hpp>

using namespace lr;
using environment::kPi;

namespace {
constexpr int kW = 256, kH = 128;
const glm::vec3 kSky(0.1f);
const glm::vec3 kDisc(10.0f, 5.0f, 2.5f);

double degreesBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)) * 180.0 / kPi;
}

// A uniform sky of kSky with texels whose centre is within `radius` degrees of `centre` set to kDisc; the
// disc's Σ L·Ω (per channel) in *sum.
EnvironmentImage discImage(const glm::dvec3& centre, double radius, glm::dvec3* sum) {
    EnvironmentImage img;
    img.width = kW;
    img.height = kH;
    img.texels.assign(size_t(kW) * kH, kSky);
    *sum = glm::dvec3(0.0);
    const double c = std::cos(radius * kPi / 180.0);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            if (glm::dot(environment::texelDirection(x, y, kW, kH), centre) >= c) {
                img.at(x, y) = kDisc;
                *sum += glm::dvec3(kDisc) * environment::texelSolidAngle(y, kW, kH);
            }
    return img;
}
// What dimming `spot` removes from `img`: Σ (L − L')·Ω per channel, and which texels it changed.
glm::dvec3 removedBy(const EnvironmentImage& img, const EnvironmentSpot& spot, std::vector<char>* dimmed) {
    EnvironmentImage after = img;
    environment::applySpots(&after, {spot});
    glm::dvec3 removed(0.0);
    dimmed->assign(img.texels.size(), 0);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const glm::dvec3 d = glm::dvec3(img.at(x, y)) - glm::dvec3(after.at(x, y));
            removed += d * environment::texelSolidAngle(y, img.width, img.height);
            (*dimmed)[size_t(y) * img.width + x] = after.at(x, y) != img.at(x, y);
        }
    return removed;
}
} // namespace

class TestEnvLight : public QObject {
    Q_OBJECT
  private slots:
    void discGivesItsDirectionColourAndLux_data() {
        QTest::addColumn<double>("azimuth");
        QTest::addColumn<double>("elevation");
        QTest::newRow("front, 35° up") << 20.0 << 35.0;
        QTest::newRow("across the seam (-X)") << -90.0 << 10.0;
        QTest::newRow("low, behind") << 170.0 << -20.0;
    }
    void discGivesItsDirectionColourAndLux() {
        QFETCH(double, azimuth);
        QFETCH(double, elevation);
        const glm::dvec3 d = environment::softboxDirection(azimuth, elevation);
        glm::dvec3 sum;
        const EnvironmentImage img = discImage(d, 4.0, &sum);
        QVERIFY(sum.x > 0.0);
        // Clicked 8° off the disc: the search finds it.
        const glm::dvec3 clicked = glm::normalize(d + glm::dvec3(0.0, 0.14, 0.0));
        QVERIFY(degreesBetween(clicked, d) > 6.0);
        const EnvironmentLight l = lightFromEnvironment(img, 0.0, 0.0, ShadingModel::Pbr, clicked);
        QVERIFY2(l.found, qPrintable(l.reason));
        QVERIFY2(degreesBetween(-l.direction, d) < 0.3,
                 qPrintable(QString::number(degreesBetween(-l.direction, d))));
        QVERIFY(std::abs(glm::length(l.direction) - 1.0) < 1e-12);
        QVERIFY2(std::abs(l.intensity - sum.x) <= 1e-9 * sum.x,
                 qPrintable(QStringLiteral("%1 lux, the disc's Σ L·Ω %2").arg(l.intensity).arg(sum.x)));
        QCOMPARE(l.color.x, 1.0);
        QVERIFY(std::abs(l.color.y - 0.5) < 1e-9 && std::abs(l.color.z - 0.25) < 1e-9);
        // The dimmed spot just holds the disc's texel centres (all within 4°), keyed above the sky.
        QVERIFY(degreesBetween(l.spot.direction, d) < 0.3);
        QVERIFY2(l.spot.angle >= 4.0 - 180.0 / kH && l.spot.angle <= 4.0 + 180.0 / kH,
                 qPrintable(QString::number(l.spot.angle)));
        QVERIFY(l.spot.threshold > environment::luminance(kSky));
        QCOMPARE(l.spot.factor, 0.0);
        EnvironmentImage dimmed = img;
        environment::applySpots(&dimmed, {l.spot});
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x)
                if (img.at(x, y) == kDisc) QCOMPARE(dimmed.at(x, y), glm::vec3(0.0f));
        const EnvironmentLight again = lightFromEnvironment(dimmed, 0.0, 0.0, ShadingModel::Pbr, clicked);
        QVERIFY(!again.found); // a dimmed spot leaves nothing bright there
    }

    void rotationIntensityAndShading() {
        const glm::dvec3 d = environment::softboxDirection(60.0, 20.0); // in the image's own frame
        glm::dvec3 sum;
        const EnvironmentImage img = discImage(d, 5.0, &sum);
        const glm::dvec3 world = environment::rotateAboutUp(d, 90.0); // where it is, turned by 90°
        const EnvironmentLight pbr = lightFromEnvironment(img, 90.0, 0.0, ShadingModel::Pbr, world);
        QVERIFY2(pbr.found, qPrintable(pbr.reason));
        QVERIFY(degreesBetween(-pbr.direction, world) < 0.3);
        QVERIFY(degreesBetween(pbr.spot.direction, d) < 0.3); // the spot is in the image's frame
        // Clicked where the unrotated disc would be: 90° from the turned one, nothing there.
        QVERIFY(!lightFromEnvironment(img, 90.0, 0.0, ShadingModel::Pbr, d).found);
        const EnvironmentLight classic = lightFromEnvironment(img, 90.0, 0.0, ShadingModel::Classic, world);
        QVERIFY(std::abs(classic.intensity - sum.x / kPi) <= 1e-9 * sum.x);
        const EnvironmentLight brighter = lightFromEnvironment(img, 90.0, 1.5, ShadingModel::Pbr, world);
        QVERIFY(std::abs(brighter.intensity - sum.x * std::exp2(1.5)) <= 1e-9 * sum.x);
        QCOMPARE(brighter.color, pbr.color);
    }

    void uniformSkyHasNothingBright() {
        EnvironmentImage img;
        img.width = kW;
        img.height = kH;
        img.texels.assign(size_t(kW) * kH, glm::vec3(0.7f, 0.8f, 0.9f));
        const EnvironmentLight l =
            lightFromEnvironment(img, 0.0, 0.0, ShadingModel::Pbr, glm::dvec3(0.3, 0.4, -1.0));
        QVERIFY(!l.found);
        QVERIFY2(l.reason.startsWith(QLatin1String("nothing bright here")), qPrintable(l.reason));
        // A black sky, no image, and no direction are refused the same way, with finite results.
        img.texels.assign(img.texels.size(), glm::vec3(0.0f));
        QVERIFY(!lightFromEnvironment(img, 0.0, 0.0, ShadingModel::Pbr, glm::dvec3(0, 1, 0)).found);
        QVERIFY(!lightFromEnvironment(EnvironmentImage{}, 0.0, 0.0, ShadingModel::Pbr, glm::dvec3(0, 1, 0))
                     .found);
        QVERIFY(!lightFromEnvironment(img, 0.0, 0.0, ShadingModel::Pbr, glm::dvec3(0.0)).found);
        QVERIFY(!lightFromEnvironment(img, 0.0, 0.0, ShadingModel::Pbr, glm::dvec3(NAN, 0, 0)).found);
    }

    void studioSoftboxIsFound() {
        // The procedural studio's softbox (core/environment.h renderStudio) is a bright spot like any other.
        Studio studio;
        Softbox box;
        box.azimuth = 45.0;
        box.elevation = 40.0;
        box.width = box.height = 20.0;
        box.color = glm::dvec3(1.0, 0.9, 0.8);
        box.intensity = 20.0;
        studio.softboxes = {box};
        const EnvironmentImage img = environment::renderStudio(studio, 512);
        const glm::dvec3 d = environment::softboxDirection(box.azimuth, box.elevation);
        const EnvironmentLight l = lightFromEnvironment(img, 0.0, 0.0, ShadingModel::Pbr, d);
        QVERIFY2(l.found, qPrintable(l.reason));
        QVERIFY2(degreesBetween(-l.direction, d) < 1.0,
                 qPrintable(QString::number(degreesBetween(-l.direction, d))));
        // Its radiance × its solid angle: a 20° × 20° gnomonic rectangle spans 4·asin(sin²10°) sr; the texels
        // inside it at 512 × 256 cover that to within a few per cent.
        const double a = 10.0 * kPi / 180.0;
        const double expected = 20.0 * 4.0 * std::asin(std::sin(a) * std::sin(a));
        QVERIFY2(std::abs(l.intensity - expected) < 0.05 * expected,
                 qPrintable(QStringLiteral("%1 lux, expected about %2").arg(l.intensity).arg(expected)));
        // Its colour, but for the sky in the antialiased edge texels the light takes with the softbox.
        QVERIFY2(std::abs(l.color.y - 0.9) < 0.01 && std::abs(l.color.z - 0.8) < 0.01,
                 qPrintable(QStringLiteral("%1, %2").arg(l.color.y).arg(l.color.z)));
    }

    void dimmedSpotIsExactlyTheSoftbox() {
        // Issue 41: "Dim the spot" on the procedural studio blacked out a disc far larger than the softbox,
        // sky included. The dimmed texels must be the softbox's own (nothing of the sky), and the energy
        // they lose must be the new light's: Σ ΔL·Ω = colour × lux at 0 EV under PBR.
        Studio studio;
        Softbox box;
        box.azimuth = 45.0;
        box.elevation = 35.0;
        box.width = 40.0;
        box.height = 30.0;
        box.color = glm::dvec3(1.0, 0.9, 0.8);
        box.intensity = 6.0;
        studio.softboxes = {box};
        const EnvironmentImage img = environment::renderStudio(studio, 512);
        Studio bare = studio;
        bare.softboxes.clear();
        const EnvironmentImage sky = environment::renderStudio(bare, 512);
        const EnvironmentLight l = lightFromEnvironment(
            img, 0.0, 0.0, ShadingModel::Pbr, environment::softboxDirection(box.azimuth, box.elevation));
        QVERIFY2(l.found, qPrintable(l.reason));
        std::vector<char> dimmed;
        const glm::dvec3 removed = removedBy(img, l.spot, &dimmed);
        const glm::dvec3 taken = l.color * l.intensity;
        for (int c = 0; c < 3; ++c)
            QVERIFY2(std::abs(removed[c] - taken[c]) <= 1e-6 * taken[c],
                     qPrintable(QStringLiteral("channel %1: dimming removes %2, the light takes %3")
                                    .arg(c)
                                    .arg(removed[c], 0, 'g', 9)
                                    .arg(taken[c], 0, 'g', 9)));
        const glm::vec3 full(box.color * box.intensity);
        int skyDimmed = 0, boxKept = 0, boxTexels = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const bool isDimmed = dimmed[size_t(y) * img.width + x];
                const bool touched = img.at(x, y) != sky.at(x, y); // the softbox covers some of it
                const bool inside = img.at(x, y) == full;          // the softbox covers all of it
                skyDimmed += isDimmed && !touched;
                boxKept += inside && !isDimmed;
                boxTexels += inside;
            }
        QVERIFY(boxTexels > 100);
        QVERIFY2(skyDimmed == 0, qPrintable(QStringLiteral("%1 sky texels dimmed").arg(skyDimmed)));
        QVERIFY2(boxKept == 0,
                 qPrintable(QStringLiteral("%1 of %2 softbox texels kept").arg(boxKept).arg(boxTexels)));
        // The same under classic shading (÷ π) and at another EV (× 2^EV): still what the spot removes.
        const EnvironmentLight classic = lightFromEnvironment(
            img, 0.0, 2.0, ShadingModel::Classic, environment::softboxDirection(box.azimuth, box.elevation));
        QVERIFY(classic.spot == l.spot);
        QVERIFY(std::abs(classic.intensity * kPi / 4.0 - l.intensity) <= 1e-9 * l.intensity);
    }

    void aSpotDimsOnlyWhatReachesItsThreshold() {
        EnvironmentImage img;
        img.width = 8;
        img.height = 4;
        img.texels.assign(32, glm::vec3(1.0f));
        img.at(3, 1) = glm::vec3(5.0f);
        EnvironmentSpot spot;
        spot.direction = environment::texelDirection(3, 1, 8, 4);
        spot.angle = 90.0;
        spot.threshold = 2.0; // the cone holds many texels; only the bright one is dimmed
        environment::applySpots(&img, {spot});
        QCOMPARE(img.at(3, 1), glm::vec3(0.0f));
        QCOMPARE(img.at(4, 1), glm::vec3(1.0f));
        // The rig file keeps it.
        Rig rig = defaultRig();
        rig.environment.source = EnvironmentSource::Studio;
        rig.environment.spots = {spot};
        const RigReadResult read = readRigJson(writeRigJson(rig), QStringLiteral("spot.json"));
        QVERIFY2(read.ok(), qPrintable(read.errors.join(QLatin1Char('\n'))));
        QCOMPARE(read.rig->environment.spots.size(), size_t(1));
        QCOMPARE(read.rig->environment.spots[0].threshold, 2.0);
    }
};

QTEST_GUILESS_MAIN(TestEnvLight)
#include "tst_envlight.moc"
