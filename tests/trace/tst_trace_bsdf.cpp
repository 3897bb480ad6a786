// The path tracer's BSDF sampling (src/trace/bsdf.h): its directions and densities agree with its value,
// so that the estimate value / pdf is unbiased. For metals and dielectrics from mirror-like to rough and
// views from normal to grazing, the mean of value / pdf over sampled directions equals the reflectance
// ∫ f (n · l) dω found by quadrature, and the density integrates to at most 1 over the hemisphere (the rest
// is the share of samples that fall below the horizon and are lost).
#include "core/envintegrate.h"
#include "trace/bsdf.h"
#include "trace/sampler.h"

#include <QTest>

#include <cmath>
#include <numbers>

using lr::envintegrate::luminance;
using lr::trace::Bsdf;
using lr::trace::BsdfSample;
using lr::trace::Sampler;

namespace {

struct Integrals {
    double reflectance = 0.0; // ∫ luminance(eval) dω
    double density = 0.0;     // ∫ pdf dω
};

// Midpoint quadrature over the hemisphere in (cos θ, φ), finer where a sharp lobe needs it.
Integrals quadrature(const Bsdf& bsdf, int n) {
    Integrals out;
    const double dmu = 1.0 / n, dphi = 2.0 * std::numbers::pi / (2 * n);
    for (int i = 0; i < n; ++i) {
        const double mu = (i + 0.5) * dmu, s = std::sqrt(1.0 - mu * mu);
        for (int j = 0; j < 2 * n; ++j) {
            const double phi = (j + 0.5) * dphi;
            const glm::dvec3 l(s * std::cos(phi), s * std::sin(phi), mu);
            out.reflectance += luminance(bsdf.eval(l)) * dmu * dphi;
            out.density += bsdf.pdf(l) * dmu * dphi;
        }
    }
    return out;
}

} // namespace

class TraceBsdf : public QObject {
    Q_OBJECT
  private slots:
    void samplingIsUnbiased_data() {
        QTest::addColumn<double>("roughness");
        QTest::addColumn<double>("metallic");
        QTest::addColumn<double>("viewDegrees");
        for (double r : {0.25, 0.5, 1.0})
            for (double m : {0.0, 1.0})
                for (double v : {0.0, 45.0, 80.0})
                    QTest::addRow("roughness %.2f metallic %.0f view %.0f°", r, m, v) << r << m << v;
    }
    void samplingIsUnbiased() {
        QFETCH(double, roughness);
        QFETCH(double, metallic);
        QFETCH(double, viewDegrees);
        const double a = viewDegrees * std::numbers::pi / 180.0;
        const glm::dvec3 n(0.0, 0.0, 1.0), v(std::sin(a), 0.0, std::cos(a));
        const Bsdf bsdf(n, v, glm::dvec3(0.9, 0.6, 0.3), metallic, roughness);
        const Integrals truth = quadrature(bsdf, 800);
        QVERIFY2(truth.density <= 1.0 + 1e-3 && truth.density > 0.5,
                 qPrintable(QString::number(truth.density)));
        const int samples = 1 << 16;
        double sum = 0.0;
        for (int k = 0; k < samples; ++k) {
            Sampler s(1, std::uint32_t(k));
            const double lobe = s.next();
            const glm::dvec2 u = s.next2();
            const BsdfSample b = bsdf.sample(lobe, u.x, u.y);
            if (b.pdf > 0.0) {
                QVERIFY(std::abs(b.pdf - bsdf.pdf(b.direction)) <= 1e-9 * b.pdf);
                sum += luminance(b.value) / b.pdf;
            }
        }
        const double estimate = sum / samples;
        QVERIFY2(
            std::abs(estimate - truth.reflectance) < 0.01 * truth.reflectance + 1e-4,
            qPrintable(QStringLiteral("sampled %1, quadrature %2").arg(estimate).arg(truth.reflectance)));
    }
};

QTEST_GUILESS_MAIN(TraceBsdf)
#include "tst_trace_bsdf.moc"
