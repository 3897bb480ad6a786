// The path tracer's sampling of rect lights by solid angle (src/trace/lights.h, Ureña et al. 2013): the
// points lie on the rect, the density is 1 / the solid angle it subtends (the closed form on its axis), the
// irradiance estimated from a few hundred samples matches quadrature over the rect's area, areaLightPdf
// gives the density sampling used, and disks and tiny rects fall back to area sampling consistently.
#include "core/barndoors.h"
#include "trace/lights.h"
#include "trace/sampler.h"

#include <QTest>

#include <cmath>
#include <numbers>

using namespace lr;
using lr::trace::TraceLight;

namespace {

// A rect (or disk) in the plane z = 0 facing +z, centred at `centre`.
TraceLight areaLight(LightType type, glm::dvec3 centre, double halfWidth, double halfHeight) {
    TraceLight t;
    t.shade.type = type;
    t.shade.position = centre;
    t.shade.direction = glm::dvec3(0, 0, 1);
    t.shade.axisX = glm::dvec3(0, 1, 0); // axisX × axisY = -direction
    t.shade.axisY = glm::dvec3(1, 0, 0);
    t.shade.halfWidth = halfWidth;
    t.shade.halfHeight = halfHeight;
    t.area =
        type == LightType::Disk ? std::numbers::pi * halfWidth * halfWidth : 4.0 * halfWidth * halfHeight;
    return t;
}

// ∫ cos θ dω over the light seen from p with normal n, by midpoint quadrature over its area.
double irradianceByArea(const TraceLight& l, const glm::dvec3& p, const glm::dvec3& n, int steps) {
    double sum = 0.0;
    const double dx = 2.0 * l.shade.halfWidth / steps, dy = 2.0 * l.shade.halfHeight / steps;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const glm::dvec3 q = l.shade.position + (-l.shade.halfWidth + (i + 0.5) * dx) * l.shade.axisX +
                                 (-l.shade.halfHeight + (j + 0.5) * dy) * l.shade.axisY;
            const glm::dvec3 d = q - p;
            const double r2 = glm::dot(d, d), r = std::sqrt(r2);
            sum += std::max(0.0, glm::dot(d, n) / r) * std::abs(d.z / r) / r2 * dx * dy;
        }
    return sum;
}

double irradianceBySampling(const TraceLight& l, const glm::dvec3& p, const glm::dvec3& n, int samples) {
    double sum = 0.0;
    for (int k = 0; k < samples; ++k) {
        trace::Sampler s(3, std::uint32_t(k));
        const glm::dvec2 u = s.next2();
        const trace::AreaLightSample a = trace::sampleAreaLightFrom(l, p, u.x, u.y);
        if (!(a.pdf > 0.0)) continue;
        const glm::dvec3 w = glm::normalize(a.point - p);
        sum += std::max(0.0, glm::dot(w, n)) / a.pdf;
    }
    return sum / samples;
}

} // namespace

class TraceLights : public QObject {
    Q_OBJECT
  private slots:
    // On the axis of an a × b rect at distance d: Ω = 4 asin(a b / √((a² + 4 d²)(b² + 4 d²))).
    void densityIsOneOverTheSolidAngle() {
        for (double d : {0.05, 0.5, 3.0}) {
            const double a = 2.0, b = 0.6;
            const TraceLight l = areaLight(LightType::Rect, glm::dvec3(0.0), a / 2, b / 2);
            const glm::dvec3 p(0.0, 0.0, d);
            const double omega =
                4.0 * std::asin(a * b / std::sqrt((a * a + 4 * d * d) * (b * b + 4 * d * d)));
            for (int k = 0; k < 64; ++k) {
                trace::Sampler s(0, std::uint32_t(k));
                const glm::dvec2 u = s.next2();
                const trace::AreaLightSample q = trace::sampleAreaLightFrom(l, p, u.x, u.y);
                QVERIFY2(
                    std::abs(q.pdf * omega - 1.0) < 1e-9,
                    qPrintable(QStringLiteral("d %1: pdf %2, 1/Ω %3").arg(d).arg(q.pdf).arg(1.0 / omega)));
                // On the rect.
                QVERIFY(std::abs(q.point.z) < 1e-9);
                QVERIFY(std::abs(q.point.y) <= a / 2 + 1e-9 && std::abs(q.point.x) <= b / 2 + 1e-9);
                // What a BSDF ray towards that point is told.
                const glm::dvec3 dir = glm::normalize(q.point - p);
                QCOMPARE(trace::areaLightPdf(l, p, dir, glm::length(q.point - p)), q.pdf);
            }
        }
    }

    // The irradiance at points beside, near and far from the rect (tilted receivers too), from 256
    // stratified samples by solid angle, against quadrature over the rect's area.
    void irradianceMatchesQuadrature_data() {
        QTest::addColumn<glm::dvec3>("point");
        QTest::addColumn<glm::dvec3>("normal");
        QTest::newRow("near, centred") << glm::dvec3(0.0, 0.0, 0.05) << glm::dvec3(0, 0, -1);
        QTest::newRow("beside, tilted")
            << glm::dvec3(1.3, -0.4, 0.3) << glm::normalize(glm::dvec3(-1, 0.3, -1));
        QTest::newRow("far") << glm::dvec3(0.2, 0.1, 6.0) << glm::dvec3(0, 0, -1);
        QTest::newRow("from behind") << glm::dvec3(0.1, 0.2, -0.5) << glm::dvec3(0, 0, 1);
    }
    void irradianceMatchesQuadrature() {
        QFETCH(glm::dvec3, point);
        QFETCH(glm::dvec3, normal);
        const TraceLight l = areaLight(LightType::Rect, glm::dvec3(0.0), 1.0, 0.4);
        const double truth = irradianceByArea(l, point, normal, 1200);
        const double sampled = irradianceBySampling(l, point, normal, 256);
        QVERIFY2(std::abs(sampled - truth) <= 0.005 * truth + 1e-7,
                 qPrintable(QStringLiteral("sampled %1, quadrature %2").arg(sampled).arg(truth)));
    }

    // Barn doors (issue 39, core/barndoors.h): samples come from the window the point sees, the irradiance
    // they estimate matches quadrature over the whole rect with each cell cut by the segment test, the BSDF
    // ray's density agrees, and a ray towards a hidden point of the emitter misses it.
    void barnDoorsCutTheSamples() {
        TraceLight l = areaLight(LightType::Rect, glm::dvec3(0.0), 1.0, 0.4);
        const barndoors::FlapShape f = barndoors::flapShape({20.0, 0.8});
        l.shade.barnDepth = f.depth;
        l.shade.barnExtent = f.extent;
        int compared = 0;
        for (const glm::dvec3 p :
             {glm::dvec3(0.9, 0.3, 1.5), glm::dvec3(-1.4, 0.2, 2.0), glm::dvec3(0.1, 0.0, 3.0)}) {
            const glm::dvec3 n(0, 0, -1);
            double truth = 0.0;
            const int steps = 600;
            const double dx = 2.0 * l.shade.halfWidth / steps, dy = 2.0 * l.shade.halfHeight / steps;
            for (int i = 0; i < steps; ++i)
                for (int j = 0; j < steps; ++j) {
                    const glm::dvec3 q = (-l.shade.halfWidth + (i + 0.5) * dx) * l.shade.axisX +
                                         (-l.shade.halfHeight + (j + 0.5) * dy) * l.shade.axisY;
                    if (barndoors::segmentHitsFlaps(l.shade, q, p)) continue;
                    const glm::dvec3 d = q - p;
                    const double r2 = glm::dot(d, d), r = std::sqrt(r2);
                    truth += std::max(0.0, glm::dot(d, n) / r) * std::abs(d.z / r) / r2 * dx * dy;
                }
            const double sampled = irradianceBySampling(l, p, n, 256);
            QVERIFY2(std::abs(sampled - truth) <= 0.01 * truth + 1e-7,
                     qPrintable(QStringLiteral("sampled %1, quadrature %2").arg(sampled).arg(truth)));
            ++compared;
            for (int k = 0; k < 16; ++k) {
                trace::Sampler s(7, std::uint32_t(k));
                const glm::dvec2 u = s.next2();
                const trace::AreaLightSample a = trace::sampleAreaLightFrom(l, p, u.x, u.y);
                if (!(a.pdf > 0.0)) continue;
                QVERIFY(!barndoors::segmentHitsFlaps(l.shade, a.point, p));
                const double t = glm::length(a.point - p);
                double hitT = 0.0;
                QVERIFY(trace::hitAreaLight(l, p, (a.point - p) / t, &hitT));
                QVERIFY(std::abs(trace::areaLightPdf(l, p, (a.point - p) / t, t) - a.pdf) <= 1e-9 * a.pdf);
            }
        }
        QCOMPARE(compared, 3);
        // Far beside the beam the flaps hide all of the emitter: a ray towards it misses it.
        const glm::dvec3 p(2.5, 0.0, 0.9);
        const glm::dvec3 hidden(0.0, 0.9 * l.shade.halfWidth, 0.0); // axisX is +y here
        QVERIFY(barndoors::segmentHitsFlaps(l.shade, hidden, p));
        double t = 0.0;
        QVERIFY(!trace::hitAreaLight(l, p, glm::normalize(hidden - p), &t));
    }

    // A disk, and a rect under 1e-4 sr, are sampled by area: the density is the area's converted to
    // solid angle, and areaLightPdf says the same.
    void areaSamplingFallBack() {
        const TraceLight disk = areaLight(LightType::Disk, glm::dvec3(0.0), 0.5, 0.5);
        const TraceLight tiny = areaLight(LightType::Rect, glm::dvec3(0.0), 0.001, 0.001);
        for (const TraceLight* l : {&disk, &tiny}) {
            const glm::dvec3 p(0.3, 0.2, 1.0);
            trace::Sampler s(5, 1);
            const glm::dvec2 u = s.next2();
            const trace::AreaLightSample q = trace::sampleAreaLightFrom(*l, p, u.x, u.y);
            const glm::dvec3 d = q.point - p;
            const double t = glm::length(d), cosL = std::abs(d.z) / t;
            QVERIFY(std::abs(q.pdf - t * t / (l->area * cosL)) <= 1e-9 * q.pdf);
            QVERIFY(std::abs(trace::areaLightPdf(*l, p, d / t, t) - q.pdf) <= 1e-9 * q.pdf);
        }
        const glm::dvec3 p(0.1, 0.2, 0.8);
        QVERIFY(std::abs(irradianceBySampling(disk, p, glm::dvec3(0, 0, -1), 1024) /
                             [&] { // quadrature in polar coordinates
                                 double sum = 0.0;
                                 const int n = 600;
                                 for (int i = 0; i < n; ++i)
                                     for (int j = 0; j < n; ++j) {
                                         const double r = 0.5 * (i + 0.5) / n,
                                                      phi = 2.0 * std::numbers::pi * (j + 0.5) / n;
                                         const glm::dvec3 d =
                                             glm::dvec3(r * std::sin(phi), r * std::cos(phi), 0.0) - p;
                                         const double r2 = glm::dot(d, d);
                                         sum += (-d.z) * (-d.z) / (r2 * r2) * r * (0.5 / n) *
                                                (2.0 * std::numbers::pi / n);
                                     }
                                 return sum;
                             }() -
                         1.0) < 0.01);
    }
};

QTEST_GUILESS_MAIN(TraceLights)
#include "tst_trace_lights.moc"
