// The environment's shared math (src/core/environment.h, issue 15): the one equirectangular mapping and its
// documented axes and rotation, the texels' solid angles, the SH9 basis, the procedural studio (softboxes,
// sky gradient, horizon blend, floor) and the dimmed spots. Pure core: no GL.
#include "core/environment.h"

#include <QTest>
#include <cmath>
#include <glm/geometric.hpp>
#include <random>

using namespace lr;
using namespace lr::environment;

namespace {

QString str(const glm::dvec3& v) {
    return QStringLiteral("(%1, %2, %3)").arg(v.x, 0, 'g', 17).arg(v.y, 0, 'g', 17).arg(v.z, 0, 'g', 17);
}

bool near(const glm::dvec3& a, const glm::dvec3& b, double tolerance) {
    return glm::length(a - b) <= tolerance;
}

glm::dvec3 randomUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> n;
    glm::dvec3 v;
    do
        v = {n(rng), n(rng), n(rng)};
    while (glm::dot(v, v) < 1e-12);
    return glm::normalize(v);
}

double degrees(double radians) {
    return radians * 180.0 / kPi;
}

// The angle between two unit vectors in degrees (robust near 0 and 180).
double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return degrees(std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)));
}

EnvironmentImage uniform(int width, glm::vec3 value) {
    EnvironmentImage img;
    img.width = width;
    img.height = width / 2;
    img.texels.assign(size_t(img.width) * size_t(img.height), value);
    return img;
}

} // namespace

class TestEnvironment : public QObject {
    Q_OBJECT
  private slots:
    void mappingRoundTrips();
    void documentedAxes();
    void rotationIsCounterClockwiseFromAbove();
    void solidAnglesSumToTheSphere();
    void shBasisIsOrthonormal();
    void softboxDirectionAxes();
    void studioSoftboxTexelsCarryItsRadiance();
    void studioSkyHorizonAndFloor();
    void studioSize();
    void spotsDimInsideTheirAngle();
    void spotsVisitOnlyWhatTheyCover();
};

// equirectDirection(equirectUv(d, r), r) = d for random unit directions and rotations, and the other way
// round for image coordinates inside the image.
void TestEnvironment::mappingRoundTrips() {
    std::mt19937_64 rng(20261126);
    std::uniform_real_distribution<double> angle(-720.0, 720.0), unit01(0.0, 1.0);
    for (int i = 0; i < 20000; ++i) {
        const glm::dvec3 d = randomUnit(rng);
        const double r = i % 4 == 0 ? 0.0 : angle(rng);
        const glm::dvec2 uv = equirectUv(d, r);
        QVERIFY2(uv.x >= 0.0 && uv.x < 1.0 && uv.y >= 0.0 && uv.y <= 1.0, qPrintable(str(d)));
        const glm::dvec3 back = equirectDirection(uv.x, uv.y, r);
        QVERIFY2(near(back, d, 1e-12), qPrintable(str(d) + QStringLiteral(" -> ") + str(back)));

        const double u = unit01(rng), v = 1e-6 + (1.0 - 2e-6) * unit01(rng); // off the poles, where u is moot
        const glm::dvec3 dir = equirectDirection(u, v, r);
        QVERIFY(std::abs(glm::length(dir) - 1.0) < 1e-14);
        const glm::dvec2 again = equirectUv(dir, r);
        const double du = std::abs(again.x - u);
        QVERIFY2(std::min(du, 1.0 - du) < 1e-9 && std::abs(again.y - v) < 1e-9,
                 qPrintable(QStringLiteral("(%1, %2) -> (%3, %4)").arg(u).arg(v).arg(again.x).arg(again.y)));
    }
    // Directions that are not finite give a coordinate inside the image, never NaN.
    const glm::dvec2 nan = equirectUv(glm::dvec3(std::nan(""), 0.0, 0.0));
    QVERIFY(nan.x >= 0.0 && nan.x < 1.0 && nan.y >= 0.0 && nan.y <= 1.0);
}

// The header's conventions: the centre column looks along +X, u = 3/4 along +Z, u = 1/4 along -Z, u = 0
// along -X; row 0 is up (+Y), the last row down.
void TestEnvironment::documentedAxes() {
    const struct {
        double u, v;
        glm::dvec3 d;
    } axes[] = {{0.5, 0.5, {1, 0, 0}},  {0.75, 0.5, {0, 0, 1}}, {0.25, 0.5, {0, 0, -1}},
                {0.0, 0.5, {-1, 0, 0}}, {0.5, 0.0, {0, 1, 0}},  {0.5, 1.0, {0, -1, 0}}};
    for (const auto& a : axes) {
        QVERIFY2(near(equirectDirection(a.u, a.v), a.d, 1e-15), qPrintable(str(equirectDirection(a.u, a.v))));
        const glm::dvec2 uv = equirectUv(a.d);
        if (a.d.y == 0.0) QCOMPARE(uv.x, a.u);
        QCOMPARE(uv.y, a.v);
    }
    // 30° above the horizon, towards +Z: v = 1/2 - 30/180.
    const glm::dvec3 up30(0.0, 0.5, std::sqrt(0.75));
    QVERIFY(std::abs(equirectUv(up30).y - (0.5 - 30.0 / 180.0)) < 1e-15);
    // Texel centres: the middle texel of a 4×2 image's bottom-right quarter looks below the horizon
    // towards u = 7/8 (between +Z and -X).
    const glm::dvec3 t = texelDirection(3, 1, 4, 2);
    QVERIFY(t.y < 0.0 && t.z > 0.0 && t.x < 0.0);
    QVERIFY(near(t, equirectDirection(7.0 / 8.0, 3.0 / 4.0), 1e-15));
}

// rotation turns the environment counter-clockwise seen from above: what the image shows at +X (its centre
// column) comes from -Z after 90°, from -X after 180°; the image is looked up at R_y(-rotation) · d.
void TestEnvironment::rotationIsCounterClockwiseFromAbove() {
    QVERIFY(near(rotateAboutUp({1, 0, 0}, 90.0), {0, 0, -1}, 1e-15));
    QVERIFY(near(rotateAboutUp({0, 0, -1}, 90.0), {-1, 0, 0}, 1e-15));
    QVERIFY(near(rotateAboutUp({0, 1, 0}, 37.0), {0, 1, 0}, 0.0));
    // Counter-clockwise seen from +Y: the cross product of before and after points up.
    const glm::dvec3 a(0.6, 0.0, 0.8), b = rotateAboutUp(a, 10.0);
    QVERIFY(glm::cross(a, b).y > 0.0);
    QVERIFY(std::abs(angleBetween(a, b) - 10.0) < 1e-12);

    QVERIFY(near(equirectDirection(0.5, 0.5, 90.0), {0, 0, -1}, 1e-15));
    QVERIFY(std::abs(equirectUv({0, 0, -1}, 90.0).x - 0.5) < 1e-15);
    QVERIFY(std::abs(equirectUv({-1, 0, 0}, 180.0).x - 0.5) < 1e-15);
    // The image's column u is seen, turned by r degrees, where column u - r/360 (mod 1) was: at the same
    // height, and looking up that direction at rotation r finds u again.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit01(0.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        const double u = unit01(rng), v = 0.05 + 0.9 * unit01(rng), r = 360.0 * unit01(rng);
        const glm::dvec2 seen = equirectUv(equirectDirection(u, v, r)); // in the unrotated frame
        double expected = u - r / 360.0;
        expected -= std::floor(expected);
        const double du = std::abs(seen.x - expected);
        QVERIFY2(std::min(du, 1.0 - du) < 1e-9, qPrintable(QString::number(du)));
        QVERIFY(std::abs(seen.y - v) < 1e-12);
    }
    // Rotating a direction and looking it up at the same rotation is the identity.
    QVERIFY(near(rotateAboutUp(rotateAboutUp({0.3, 0.4, glm::sqrt(0.75)}, 123.0), -123.0),
                 {0.3, 0.4, glm::sqrt(0.75)}, 1e-15));
}

// Σ texelSolidAngle over the image = 4π, each row's angle = 2π/width · (sin φ0 − sin φ1) exactly, rows
// mirror about the horizon, and a row's solid angle is that of the latitude band divided by the width.
void TestEnvironment::solidAnglesSumToTheSphere() {
    for (const auto& [w, h] : {std::pair{4, 2}, std::pair{64, 32}, std::pair{1024, 512}, std::pair{7, 3}}) {
        double sum = 0.0;
        for (int y = 0; y < h; ++y) {
            const double omega = texelSolidAngle(y, w, h);
            QVERIFY(omega > 0.0);
            QVERIFY(std::abs(omega - texelSolidAngle(h - 1 - y, w, h)) < 1e-15);
            sum += omega * w;
        }
        QVERIFY2(std::abs(sum - 4.0 * kPi) < 1e-12, qPrintable(QString::number(sum - 4.0 * kPi)));
    }
    // The top row of a 2-row image is the upper hemisphere: 2π spread over its texels.
    QVERIFY(std::abs(texelSolidAngle(0, 8, 2) * 8 - 2.0 * kPi) < 1e-14);
    // Near the horizon a texel is about (2π/w)(π/h) (the cosine of its latitude is close to 1).
    const double mid = texelSolidAngle(256, 1024, 512);
    QVERIFY(std::abs(mid / ((2.0 * kPi / 1024) * (kPi / 512)) - 1.0) < 1e-5);
}

// ∫ Y_i Y_j dω = δ_ij, by quadrature over a 1024×512 grid of texels (their exact solid angles; the midpoint
// rule's error is about 3e-6 there); the constants are Ramamoorthi & Hanrahan's six-digit values, so the
// tolerance is 1e-5.
void TestEnvironment::shBasisIsOrthonormal() {
    const int w = 1024, h = 512;
    double gram[9][9] = {};
    for (int y = 0; y < h; ++y) {
        const double omega = texelSolidAngle(y, w, h);
        for (int x = 0; x < w; ++x) {
            const std::array<double, 9> b = shBasis9(texelDirection(x, y, w, h));
            for (int i = 0; i < 9; ++i)
                for (int j = 0; j < 9; ++j)
                    gram[i][j] += b[size_t(i)] * b[size_t(j)] * omega;
        }
    }
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j)
            QVERIFY2(std::abs(gram[i][j] - (i == j ? 1.0 : 0.0)) < 1e-5,
                     qPrintable(QStringLiteral("<Y%1, Y%2> = %3").arg(i).arg(j).arg(gram[i][j], 0, 'g', 10)));
    // The documented order: Y1-1 ∝ y, Y10 ∝ z, Y11 ∝ x, Y20 ∝ 3z² − 1.
    const std::array<double, 9> bx = shBasis9({1, 0, 0}), by = shBasis9({0, 1, 0}), bz = shBasis9({0, 0, 1});
    QVERIFY(by[1] > 0.48 && bx[1] == 0.0 && bz[1] == 0.0);
    QVERIFY(bz[2] > 0.48 && bx[2] == 0.0 && by[2] == 0.0);
    QVERIFY(bx[3] > 0.48 && by[3] == 0.0 && bz[3] == 0.0);
    QCOMPARE(bz[6], 0.315392 * 2.0);
}

// Azimuth 0 faces +Z, 90 faces +X; elevation 90 is straight up.
void TestEnvironment::softboxDirectionAxes() {
    QVERIFY(near(softboxDirection(0, 0), {0, 0, 1}, 1e-15));
    QVERIFY(near(softboxDirection(90, 0), {1, 0, 0}, 1e-15));
    QVERIFY(near(softboxDirection(-90, 0), {-1, 0, 0}, 1e-15));
    QVERIFY(near(softboxDirection(180, 0), {0, 0, -1}, 1e-15));
    QVERIFY(near(softboxDirection(0, 90), {0, 1, 0}, 1e-15));
    QVERIFY(near(softboxDirection(123, -90), {0, -1, 0}, 1e-15));
    const glm::dvec3 d = softboxDirection(30, 45);
    QVERIFY(std::abs(glm::length(d) - 1.0) < 1e-15);
    QVERIFY(std::abs(degrees(std::asin(d.y)) - 45.0) < 1e-12);
    QVERIFY(std::abs(degrees(std::atan2(d.x, d.z)) - 30.0) < 1e-12);
}

// A softbox facing +X, 40° wide and 30° high (gnomonic: |atan(d·right / d·c)| <= 20°, |atan(d·up / d·c)| <=
// 15°): every texel inside carries color × intensity exactly, every texel outside the sky or floor. Texels
// within a texel (0.8°) of an edge are not judged: they are antialiased, the softbox drawn over by the share
// of the texel it covers, so the radiance it adds sums to its solid angle × its radiance.
void TestEnvironment::studioSoftboxTexelsCarryItsRadiance() {
    Studio s;
    s.zenith = s.horizon = s.floor = glm::dvec3(0.0);
    s.softboxes = {
        Softbox{90.0, 0.0, 40.0, 30.0, {1.0, 0.5, 0.25}, 4.0},
        Softbox{0.0, -40.0, 20.0, 20.0, {0.0, 1.0, 0.0}, 2.0}}; // below the horizon, over the floor
    const EnvironmentImage img = renderStudio(s, 512);
    int inside = 0, inside2 = 0;
    double covered = 0.0; // Σ Ω × box 1's share of the texel (its red: 4 × the share; box 2 has no red)
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const glm::dvec3 d = texelDirection(x, y, img.width, img.height);
            const glm::vec3 L = img.at(x, y);
            covered += L.x / 4.0 * texelSolidAngle(y, img.width, img.height);
            // Box 1: centre +X, right −Z (horizontal), up +Y.
            double h = d.x > 0 ? degrees(std::atan(std::abs(d.z) / d.x)) : 180.0;
            double v = d.x > 0 ? degrees(std::atan(std::abs(d.y) / d.x)) : 180.0;
            if (h < 19.2 && v < 14.2) {
                QVERIFY2(L == glm::vec3(4.0f, 2.0f, 1.0f), qPrintable(str(d)));
                ++inside;
                continue;
            }
            const bool out1 = h > 20.8 || v > 15.8;
            // Box 2: centre c at azimuth 0, elevation −40; right +X, up = c × right.
            const glm::dvec3 c = softboxDirection(0.0, -40.0), right(1, 0, 0), up = glm::cross(c, right);
            const double z = glm::dot(d, c);
            h = z > 0 ? degrees(std::atan(std::abs(glm::dot(d, right)) / z)) : 180.0;
            v = z > 0 ? degrees(std::atan(std::abs(glm::dot(d, up)) / z)) : 180.0;
            if (h < 9.2 && v < 9.2) {
                QVERIFY2(L == glm::vec3(0.0f, 2.0f, 0.0f), qPrintable(str(d)));
                ++inside2;
            } else if (out1 && (h > 10.8 || v > 10.8)) {
                QVERIFY2(L == glm::vec3(0.0f), qPrintable(str(d)));
            }
        }
    // Its solid angle, 4·asin(sin 20° sin 15°) ≈ 0.3496 sr, to within 0.5% (the coverage's 4 × 4 samples).
    const double expected = 4.0 * std::asin(std::sin(kPi / 9.0) * std::sin(kPi / 12.0));
    QVERIFY2(std::abs(covered / expected - 1.0) < 0.005, qPrintable(QString::number(covered / expected)));
    QVERIFY(inside > 500);
    QVERIFY(inside2 > 100);
    // A softbox of intensity 0 is black; one of 170° covers most of its hemisphere.
    s.softboxes = {Softbox{0.0, 0.0, 170.0, 170.0, {1, 1, 1}, 0.0}};
    s.horizon = glm::dvec3(1.0);
    const EnvironmentImage dark = renderStudio(s, 64);
    QCOMPARE(dark.at(48, 16), glm::vec3(0.0f)); // u = 3/4: +Z, the box's centre
}

// Without softboxes: the sky blends from `horizon` at the horizon to `zenith` straight up linearly in
// elevation, the floor below is uniform, and the two meet across ±1° of elevation.
void TestEnvironment::studioSkyHorizonAndFloor() {
    Studio s;
    s.zenith = {0, 0, 1};
    s.horizon = {0, 1, 0};
    s.floor = {1, 0, 0};
    const EnvironmentImage img = renderStudio(s, 2048);
    double previousB = -1.0, previousR = 2.0;
    int blended = 0;
    for (int y = img.height - 1; y >= 0; --y) { // from the bottom up
        const double lat = degrees(std::asin(texelDirection(0, y, img.width, img.height).y));
        const glm::vec3 L = img.at(0, y);
        for (int x = 1; x < img.width; x += 97)
            QCOMPARE(img.at(x, y), L); // every row is uniform
        if (lat < -1.0) {
            QCOMPARE(L, glm::vec3(1, 0, 0));
        } else if (lat > 1.0) {
            QCOMPARE(L.r, 0.0f);
            QVERIFY(std::abs(L.g + L.b - 1.0f) < 1e-6f);
            QVERIFY(std::abs(L.b - lat / 90.0) < 1e-6); // linear in elevation
            QVERIFY(L.b > previousB);
            previousB = L.b;
        } else { // the blend: the floor's share falls from 1 to 0 across it
            QVERIFY2(L.r > 0.0f && L.r < 1.0f, qPrintable(QString::number(lat)));
            QVERIFY(L.r < previousR);
            QVERIFY(std::abs(L.r - (1.0 - lat) / 2.0) < 1e-6);
            previousR = L.r;
            ++blended;
        }
    }
    QVERIFY(blended >= 10); // 2° of 1024 rows of 180°: 11 rows
    // The top row is within a texel of the zenith colour.
    QVERIFY(img.at(0, 0).b > 0.99f && img.at(0, img.height - 1) == glm::vec3(1, 0, 0));
}

void TestEnvironment::studioSize() {
    const EnvironmentImage img = renderStudio(Studio{}, 64);
    QCOMPARE(img.width, 64);
    QCOMPARE(img.height, 32);
    QCOMPARE(img.texels.size(), size_t(64 * 32));
    QCOMPARE(renderStudio(Studio{}).width, kSpecularBaseWidth);
    for (const glm::vec3& t : img.texels)
        QVERIFY(std::isfinite(t.r) && t.r >= 0.0f);
}

// Every texel whose centre is within `angle` of the spot's direction is multiplied by `factor`; the others
// keep their radiance; overlapping spots multiply; a direction need not be unit length; a zero direction
// dims nothing.
void TestEnvironment::spotsDimInsideTheirAngle() {
    EnvironmentImage img = uniform(256, glm::vec3(2.0f));
    const glm::dvec3 a = glm::normalize(glm::dvec3(1, 1, 0)), b(0, 0, -1);
    applySpots(&img, {EnvironmentSpot{a * 5.0, 10.0, 0.25}, EnvironmentSpot{b, 30.0, 0.0},
                      EnvironmentSpot{{0, 0, 0}, 90.0, 0.0}, EnvironmentSpot{{0, -1, 0}, 20.0, 1.0}});
    int dimmed = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const glm::dvec3 d = texelDirection(x, y, img.width, img.height);
            const double ta = angleBetween(d, a), tb = angleBetween(d, b);
            const glm::vec3 L = img.at(x, y);
            if (std::abs(ta - 10.0) < 1e-9 || std::abs(tb - 30.0) < 1e-9) continue; // on an edge
            const float expected = (ta < 10.0 ? 0.5f : 2.0f) * (tb < 30.0 ? 0.0f : 1.0f);
            QVERIFY2(L == glm::vec3(expected), qPrintable(str(d)));
            dimmed += ta < 10.0;
        }
    QVERIFY(dimmed > 50);
    // Overlapping spots multiply.
    EnvironmentImage twice = uniform(64, glm::vec3(1.0f));
    applySpots(&twice, {EnvironmentSpot{{1, 0, 0}, 20.0, 0.5}, EnvironmentSpot{{1, 0, 0}, 20.0, 0.5}});
    QCOMPARE(twice.at(32, 16), glm::vec3(0.25f)); // the texel beside +X
    QCOMPARE(twice.at(0, 16), glm::vec3(1.0f));   // -X
    // Nothing to do: no crash.
    applySpots(nullptr, {EnvironmentSpot{}});
    EnvironmentImage empty;
    applySpots(&empty, {EnvironmentSpot{}});
}

// Issue 41: 64 dimmed spots cost 23 s to validate, each testing every texel. Now each tests only the rows
// and columns its cap can reach, with the same test: the image is bit for bit what testing every texel
// gives, and 64 small spots test far fewer texels than one image holds.
void TestEnvironment::spotsVisitOnlyWhatTheyCover() {
    EnvironmentImage img = uniform(1024, glm::vec3(1.0f));
    for (size_t i = 0; i < img.texels.size(); ++i)
        img.texels[i] = glm::vec3(float(i % 7 + 1), float(i % 5 + 1), 1.0f);
    std::vector<EnvironmentSpot> spots;
    for (int i = 0; i < 64; ++i) { // a spiral over the sphere, seam and poles included
        const double y = 1.0 - 2.0 * (i + 0.5) / 64.0, phi = i * 2.399963;
        const double r = std::sqrt(1.0 - y * y);
        spots.push_back({{r * std::cos(phi), y, r * std::sin(phi)}, 2.0 + i % 3, 0.5});
    }
    spots.push_back({{-1, 0, 0}, 4.0, 0.25});  // on the image's left/right seam
    spots.push_back({{0, 1, 0}, 6.0, 0.0});    // around the pole
    spots.push_back({{1, 0.2, 0}, 90.0, 0.9}); // a hemisphere
    EnvironmentImage expected = img;
    for (const EnvironmentSpot& s : spots) { // every texel, as applySpots did before
        const glm::dvec3 axis = s.direction / glm::length(s.direction);
        const double cosAngle = std::cos(std::clamp(s.angle, 0.0, 180.0) * (kPi / 180.0));
        for (int y = 0; y < expected.height; ++y)
            for (int x = 0; x < expected.width; ++x)
                if (glm::dot(texelDirection(x, y, expected.width, expected.height), axis) >= cosAngle)
                    expected.at(x, y) *= float(s.factor);
    }
    EnvironmentImage small = img;
    const std::vector<EnvironmentSpot> smallSpots(spots.begin(), spots.begin() + 64);
    const std::size_t visited = applySpots(&small, smallSpots);
    QVERIFY2(visited < small.texels.size() / 8, qPrintable(QString::number(visited)));
    QVERIFY(visited > 0);
    applySpots(&img, spots);
    QVERIFY(img.texels == expected.texels);
}

QTEST_GUILESS_MAIN(TestEnvironment)
#include "tst_environment.moc"
