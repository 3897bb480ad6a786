// The path tracer's sampler (src/trace/sampler.h): Owen-scrambled, per-dimension shuffled Sobol points.
// What the image's quality and correctness rest on: every draw is uniform, the samples of one pixel are
// stratified (one per stratum, in one dimension and in the 2-D pairs), dimensions and pixels are
// independent, and the draws are a pure function of (pixel, sample, seed, dimension).
#include "trace/sampler.h"

#include <QTest>

#include <cmath>
#include <vector>

using lr::trace::Sampler;

namespace {

// The first-dimension pair of samples 0..n-1 of a pixel, after `skip` draws.
std::vector<glm::dvec2> pairs(std::uint32_t pixel, int n, int skip = 0, std::uint32_t seed = 0) {
    std::vector<glm::dvec2> out;
    for (int k = 0; k < n; ++k) {
        Sampler s(pixel, std::uint32_t(k), seed);
        for (int i = 0; i < skip; ++i)
            s.next();
        out.push_back(s.next2());
    }
    return out;
}

} // namespace

class TraceSampler : public QObject {
    Q_OBJECT
  private slots:
    // 256 samples of one pixel: one in each of 256 equal intervals of x, of y, and in each box of every
    // elementary grid of area 1/256 (1×256, 2×128, … 256×1): a (0, 8, 2)-net, in every dimension pair.
    void samplesOfAPixelAreStratified() {
        for (int skip : {0, 1, 5, 40})
            for (std::uint32_t pixel : {0u, 7u, 123456u}) {
                const std::vector<glm::dvec2> p = pairs(pixel, 256, skip);
                for (int bx = 0; bx <= 8; ++bx) {
                    const int nx = 1 << bx, ny = 256 / nx;
                    std::vector<int> count(256, 0);
                    for (const glm::dvec2& q : p) {
                        QVERIFY(q.x >= 0.0 && q.x < 1.0 && q.y >= 0.0 && q.y < 1.0);
                        ++count[size_t(int(q.x * nx) * ny + int(q.y * ny))];
                    }
                    for (int c : count)
                        QVERIFY2(c == 1,
                                 qPrintable(QStringLiteral("pixel %1, skip %2, grid %3x%4: a box holds %5")
                                                .arg(pixel)
                                                .arg(skip)
                                                .arg(nx)
                                                .arg(ny)
                                                .arg(c)));
                }
            }
    }

    // Over many pixels and samples each dimension is uniform (mean 1/2, variance 1/12) and two dimensions
    // of one sample, or the same dimension of two pixels, are uncorrelated.
    void dimensionsAndPixelsAreIndependent() {
        const int pixels = 512, samples = 16;
        double sum[3] = {}, sq[3] = {}, cross01 = 0.0, crossPixels = 0.0;
        int n = 0;
        for (int p = 0; p < pixels; ++p)
            for (int k = 0; k < samples; ++k) {
                Sampler a{std::uint32_t(p), std::uint32_t(k)}, b{std::uint32_t(p + pixels), std::uint32_t(k)};
                const double u0 = a.next(), u1 = a.next();
                a.startBounce(3);
                const double u2 = a.next(), v0 = b.next();
                const double u[3] = {u0, u1, u2};
                for (int d = 0; d < 3; ++d)
                    sum[d] += u[d], sq[d] += u[d] * u[d];
                cross01 += (u0 - 0.5) * (u1 - 0.5);
                crossPixels += (u0 - 0.5) * (v0 - 0.5);
                ++n;
            }
        for (int d = 0; d < 3; ++d) {
            const double mean = sum[d] / n, variance = sq[d] / n - mean * mean;
            QVERIFY2(std::abs(mean - 0.5) < 0.01, qPrintable(QString::number(mean)));
            QVERIFY2(std::abs(variance - 1.0 / 12.0) < 0.005, qPrintable(QString::number(variance)));
        }
        // Correlation coefficients; independent draws give about ±1/√8192 = ±0.011.
        QVERIFY2(std::abs(cross01 / n * 12.0) < 0.05, qPrintable(QString::number(cross01 / n * 12.0)));
        QVERIFY2(std::abs(crossPixels / n * 12.0) < 0.05,
                 qPrintable(QString::number(crossPixels / n * 12.0)));
    }

    // The same (pixel, sample, seed) draws the same numbers; another seed or sample other numbers.
    void drawsArePure() {
        Sampler a(42, 9, 3), b(42, 9, 3), c(42, 9, 4), d(42, 10, 3);
        for (int i = 0; i < 20; ++i) {
            const double x = a.next();
            QCOMPARE(b.next(), x);
            QVERIFY(c.next() != x);
            QVERIFY(d.next() != x);
        }
    }
};

QTEST_GUILESS_MAIN(TraceSampler)
#include "tst_trace_sampler.moc"
