// The path tracer's noise estimate (issue 36): the relative standard error of the pixel means falls as
// 1/√samples on a noisy scene, is exactly 0 where every sample is alike (a uniform sky), and is +infinity
// (never NaN) before a second sample.
#include "tracescenes.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace tracetest;

namespace {

std::shared_ptr<const trace::TraceScene> ballOnPlane() {
    Model plane =
        quadsModel({{glm::dvec3(-2, 0, 2), glm::dvec3(2, 0, 2), glm::dvec3(2, 0, -2), glm::dvec3(-2, 0, -2)}},
                   pbrMaterial(glm::vec3(0.8f), 0.0f, 0.5f));
    merge(plane, makeSphere(0.5, 32, 16, glm::dvec3(0.0, 0.5, 0.0)));
    auto scene = describe(plane, pbrRig(true), uniformEnvironment(glm::vec3(1.0f)));
    QString error;
    auto traced = trace::TraceScene::build(*scene, &error);
    if (!traced) qWarning().noquote() << error;
    return traced;
}

} // namespace

class TraceNoise : public QObject {
    Q_OBJECT
  private slots:
    void fallsAsOneOverRootSamples() {
        const auto traced = ballOnPlane();
        QVERIFY(traced);
        trace::PathTracer tracer(traced, lookAt({2.0, 2.0, 3.0}, glm::dvec3(0.0), 40.0), QSize(32, 24), {},
                                 2);
        QVERIFY(std::isinf(tracer.noiseEstimate()));
        tracer.render(1);
        QVERIFY(std::isinf(tracer.noiseEstimate())); // one sample: no variance yet
        tracer.render(3);
        double previous = tracer.noiseEstimate();
        QVERIFY2(std::isfinite(previous) && previous > 0.0, qPrintable(QString::number(previous)));
        for (int samples = 16; samples <= 64; samples *= 4) {
            tracer.render(samples - tracer.samplesDone());
            const double noise = tracer.noiseEstimate();
            const double ratio = previous / noise; // 4× the samples: half the noise
            qInfo().noquote() << QStringLiteral("%1 samples: noise %2, ratio to a quarter of them %3")
                                     .arg(samples)
                                     .arg(noise)
                                     .arg(ratio);
            QVERIFY2(ratio > 1.6 && ratio < 2.5, qPrintable(QString::number(ratio)));
            previous = noise;
        }
        tracer.restart();
        QVERIFY(std::isinf(tracer.noiseEstimate()));
    }

    // Looking up into a uniform sky, with the plane behind the camera: every sample is the sky's radiance.
    void zeroForANoiselessImage() {
        const auto traced = ballOnPlane();
        QVERIFY(traced);
        trace::PathTracer tracer(traced, lookAt({0.0, 3.0, 0.0}, {0.0, 10.0, 0.0}, 30.0, {0, 0, -1}),
                                 QSize(16, 16), {}, 2);
        tracer.render(8);
        QCOMPARE(tracer.noiseEstimate(), 0.0);
        QVERIFY(meanChannel(tracer.image(), 1) > 0.5);
    }
};

QTEST_GUILESS_MAIN(TraceNoise)
#include "tst_trace_noise.moc"
