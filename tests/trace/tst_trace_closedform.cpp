// The path tracer against scenes with closed forms (issue 36): a white furnace, an integrating sphere, the
// environment's occlusion of a plane by a ball, and one bounce equal to core's direct light. The expected
// values come from core's glTF BRDF integrated here by quadrature, never from the tracer itself.
#include "tracescenes.h"

#include "core/prepare.h"
#include "core/shade.h"

#include <QTest>
#include <cmath>
#include <numbers>

using namespace lr;
using namespace tracetest;

namespace {

constexpr double kPi = std::numbers::pi;

// f(ωi, ωo)·cos θi of core's BRDF (grey material, channel x), in the frame whose normal is +Z.
double brdfCos(const glm::dvec3& wi, const glm::dvec3& wo, double base, double metallic, double roughness) {
    const glm::dvec3 n(0, 0, 1), b(base);
    const auto f =
        lighting::pbrLobes(n, wi, wo, lighting::pbrDiffuseColor(b, metallic), lighting::pbrF0(b, metallic),
                           lighting::pbrAlpha(roughness), lighting::diffuseLambert(wi.z));
    return f.diffuse.x + f.specular.x;
}

glm::dvec3 fromAngles(double mu, double phi) {
    const double s = std::sqrt(std::max(0.0, 1.0 - mu * mu));
    return {s * std::cos(phi), s * std::sin(phi), mu};
}

} // namespace

class TraceClosedForm : public QObject {
    Q_OBJECT
  private slots:
    // An albedo-1 concave object (an open box of white mirror metal: F = 1) in a uniform environment shows
    // the environment's radiance everywhere: energy is conserved through Russian roulette. With one bounce
    // the paths that need more are missing, so it must be darker.
    void whiteFurnace() {
        const glm::vec3 sky(0.5f);
        const Model box = openBox(pbrMaterial(glm::vec3(1.0f), 1.0f, 0.0f));
        auto scene = describe(box, pbrRig(true), uniformEnvironment(sky));
        QString error;
        const auto traced = trace::TraceScene::build(*scene, &error);
        QVERIFY2(traced, qPrintable(error));
        const ViewCamera camera = lookAt({0.3, 3.0, 0.2}, {0.0, -1.0, 0.0}, 40.0, {0, 0, -1});
        trace::TraceSettings settings;
        settings.bounces = 256;
        trace::PathTracer full(traced, camera, QSize(24, 24), settings, 2);
        full.render(16);
        const double mean = meanChannel(full.image(), 1);
        QVERIFY2(std::abs(mean - sky.y) < 0.01 * sky.y, qPrintable(QString::number(mean)));
        settings.bounces = 1;
        trace::PathTracer one(traced, camera, QSize(24, 24), settings, 2);
        one.render(16);
        const double direct = meanChannel(one.image(), 1);
        qInfo().noquote() << QStringLiteral("furnace: all bounces %1, one bounce %2, sky %3")
                                 .arg(mean)
                                 .arg(direct)
                                 .arg(sky.y);
        QVERIFY2(direct < 0.97 * sky.y, qPrintable(QString::number(direct)));
    }

    // Inside a sphere of albedo 0.5 (dielectric, roughness 1) lit by a point light at its centre, every
    // wall point is alike; its radiance field L(θ) solves L = T + K L (T the direct light, K core's BRDF
    // over the hemisphere), solved here by quadrature. For a Lambertian wall it is T / (1 − a): twice the
    // direct light, the 0.5 against 0.246.
    void integratingSphere() {
        const double a = 0.5, roughness = 1.0;
        Model sphere = makeSphere(1.0, 192, 96);
        sphere.materials.front() = pbrMaterial(glm::vec3(float(a)), 0.0f, float(roughness));
        Rig rig = pbrRig(false);
        Light light;
        light.type = LightType::Point;
        light.position = glm::dvec3(0.0);
        light.intensity = 1.0;
        light.falloff.model = FalloffModel::InverseSquare;
        rig.lights.push_back(light);
        auto scene = describe(sphere, rig);
        QString error;
        const auto traced = trace::TraceScene::build(*scene, &error);
        QVERIFY2(traced, qPrintable(error));
        // The quadrature: M bins of μ = cos θ, P steps of φ.
        const int M = 48, P = 96;
        const double dMu = 1.0 / M, dPhi = 2.0 * kPi / P;
        const auto kernelRow = [&](double muO) {
            std::vector<double> row(size_t(M), 0.0);
            const glm::dvec3 wo = fromAngles(muO, 0.0);
            for (int i = 0; i < M; ++i)
                for (int p = 0; p < P; ++p)
                    row[size_t(i)] +=
                        brdfCos(fromAngles((i + 0.5) * dMu, (p + 0.5) * dPhi), wo, a, 0.0, roughness) * dMu *
                        dPhi;
            return row;
        };
        const auto direct = [&](double muO) {
            return brdfCos(glm::dvec3(0, 0, 1), fromAngles(muO, 0.0), a, 0.0, roughness); // E = 1 lux
        };
        std::vector<std::vector<double>> K;
        std::vector<double> T, L(size_t(M), 0.0);
        for (int o = 0; o < M; ++o) {
            K.push_back(kernelRow((o + 0.5) * dMu));
            T.push_back(direct((o + 0.5) * dMu));
        }
        for (int iteration = 0; iteration < 400; ++iteration) {
            std::vector<double> next = T;
            for (int o = 0; o < M; ++o)
                for (int i = 0; i < M; ++i)
                    next[size_t(o)] += K[size_t(o)][size_t(i)] * L[size_t(i)];
            L = next;
        }
        const std::vector<double> K1 = kernelRow(1.0);
        double expected = direct(1.0);
        for (int i = 0; i < M; ++i)
            expected += K1[size_t(i)] * L[size_t(i)];
        const double expectedDirect = direct(1.0);

        const ViewCamera camera = lookAt(glm::dvec3(0.0), {0.0, 0.0, 1.0}, 4.0);
        trace::TraceSettings settings;
        settings.bounces = 1;
        trace::PathTracer one(traced, camera, QSize(8, 8), settings, 2);
        one.render(4);
        const double tracedDirect = meanChannel(one.image(), 0);
        settings.bounces = 512;
        trace::PathTracer all(traced, camera, QSize(8, 8), settings, 2);
        all.render(256);
        const double tracedAll = meanChannel(all.image(), 0);
        const QString figures = QStringLiteral("direct %1 (expected %2), all bounces %3 (expected %4)")
                                    .arg(tracedDirect)
                                    .arg(expectedDirect)
                                    .arg(tracedAll)
                                    .arg(expected);
        qInfo().noquote() << figures;
        QVERIFY2(std::abs(tracedDirect - expectedDirect) < 0.01 * expectedDirect, qPrintable(figures));
        QVERIFY2(std::abs(tracedAll - expected) < 0.03 * expected, qPrintable(figures));
        QVERIFY2(tracedAll / tracedDirect > 1.8 && tracedAll / tracedDirect < 2.3, qPrintable(figures));
    }

    // A plane under a black ball (radius R, resting on it) in a uniform sky, one radius from the contact:
    // the ball hides (R/D)³ of the cosine-weighted sky (D = √2 R), so a Lambertian plane keeps 1 − 0.354
    // = 65 %. The expectation integrates core's BRDF over the hemisphere with the ball's visibility.
    void environmentOcclusion() {
        const double R = 1.0;
        Model plane = quadsModel({{glm::dvec3(-20, 0, 20), glm::dvec3(20, 0, 20), glm::dvec3(20, 0, -20),
                                   glm::dvec3(-20, 0, -20)}},
                                 pbrMaterial(glm::vec3(0.8f), 0.0f, 1.0f));
        Model ball = makeSphere(R, 256, 128, glm::dvec3(0.0, R, 0.0));
        ball.materials.front() = pbrMaterial(glm::vec3(0.0f), 0.0f, 1.0f);
        merge(plane, ball);
        auto scene = describe(plane, pbrRig(true), uniformEnvironment(glm::vec3(1.0f)));
        QString error;
        const auto traced = trace::TraceScene::build(*scene, &error);
        QVERIFY2(traced, qPrintable(error));
        const glm::dvec3 P(R, 0.0, 0.0), eye(3.0 * R, 2.0 * R, 0.0);
        const glm::dvec3 V = glm::normalize(eye - P);
        // Quadrature in the plane's frame (normal +Y): rotate (x, y, z) -> (x, z, y).
        const auto toWorld = [](const glm::dvec3& w) { return glm::dvec3(w.x, w.z, w.y); };
        const glm::dvec3 vLocal(V.x, V.z, V.y);
        const glm::dvec3 C(0.0, R, 0.0);
        double visible = 0.0, open = 0.0;
        const int M = 400, Q = 800;
        for (int i = 0; i < M; ++i)
            for (int q = 0; q < Q; ++q) {
                const glm::dvec3 w = fromAngles((i + 0.5) / M, (q + 0.5) * 2.0 * kPi / Q);
                const double f = brdfCos(w, vLocal, 0.8, 0.0, 1.0) * (1.0 / M) * (2.0 * kPi / Q);
                open += f;
                const glm::dvec3 d = toWorld(w), oc = P - C;
                const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - R * R;
                const bool hidden = b * b - c > 0.0 && -b - std::sqrt(b * b - c) > 0.0;
                visible += hidden ? 0.0 : f;
            }
        const double lambert = 1.0 - std::pow(R / std::sqrt(2.0) / R, 3.0);
        const ViewCamera camera = lookAt(eye, P, 0.4);
        trace::TraceSettings settings;
        settings.bounces = 1; // the ball's own reflection is not the occlusion asked about
        trace::PathTracer tracer(traced, camera, QSize(8, 8), settings, 2);
        tracer.render(256);
        const double got = meanChannel(tracer.image(), 0);
        const QString figures = QStringLiteral("traced %1, expected %2 (open sky %3: %4 %, Lambert's %5 %)")
                                    .arg(got)
                                    .arg(visible)
                                    .arg(open)
                                    .arg(100.0 * visible / open)
                                    .arg(100.0 * lambert);
        qInfo().noquote() << figures;
        QVERIFY2(std::abs(got - visible) < 0.025 * visible, qPrintable(figures));
        QVERIFY2(std::abs(visible / open - lambert) < 0.05, qPrintable(figures));
    }

    // One bounce without an environment is the direct light core's shadeSurface gives at the same surface
    // point (the double reference's formula), for point, spot and directional lights: no noise then.
    void oneBounceIsDirectLight() {
        Model sphere = makeSphere(1.0, 64, 32);
        sphere.materials.front() = pbrMaterial(glm::vec3(0.7f, 0.5f, 0.3f), 0.3f, 0.4f);
        Rig rig = pbrRig(false);
        Light point;
        point.type = LightType::Point;
        point.position = {1.5, 2.0, 4.0};
        point.intensity = 12.0;
        point.falloff.model = FalloffModel::InverseSquare;
        point.falloff.range = 30.0;
        Light spot = point;
        spot.type = LightType::Spot;
        spot.position = {-2.0, 1.0, 4.0};
        spot.direction = glm::normalize(-spot.position);
        spot.cone.inner = 10.0, spot.cone.outer = 25.0, spot.cone.exponent = 2.0;
        Light sun;
        sun.type = LightType::Directional;
        sun.direction = glm::normalize(glm::dvec3(-0.3, -0.5, -1.0));
        sun.intensity = 2.0;
        rig.lights = {point, spot, sun};
        auto scene = describe(sphere, rig);
        QString error;
        const auto traced = trace::TraceScene::build(*scene, &error);
        QVERIFY2(traced, qPrintable(error));
        const ViewCamera camera = lookAt({0.0, 0.0, 5.0}, glm::dvec3(0.0), 30.0);
        const QSize size(24, 24);
        trace::TraceSettings settings;
        settings.bounces = 1;
        settings.jitter = false;
        trace::PathTracer tracer(traced, camera, size, settings, 2);
        tracer.render(1);
        const FloatImage image = tracer.image();
        const trace::CameraRays rays(camera, size);
        const glm::dmat4 view = camera.view();
        const auto lights = scene->lights(view);
        const auto st = scene->shadeSettings();
        int covered = 0, matching = 0;
        double relative = 0.0;
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x) {
                const auto s = tracetest::viewSurfaceAt(*traced, rays, view, x, y);
                if (!s) continue;
                const glm::dvec3 expected = lighting::shadeSurface<double>(*s, lights, st);
                const glm::dvec3 got(image.at(x, y));
                ++covered;
                const double e = glm::length(got - expected) / std::max(1e-3, glm::length(expected));
                relative += e;
                matching += e < 1e-3 ? 1 : 0;
            }
        QVERIFY(covered > 200);
        // Where the interpolated normal sees a light the faceted sphere hides (the shadow terminator),
        // the traced shadow ray is blocked: a few pixels.
        QVERIFY2(matching >= covered * 97 / 100,
                 qPrintable(QStringLiteral("%1 of %2").arg(matching).arg(covered)));
        QVERIFY2(relative / covered < 5e-3, qPrintable(QString::number(relative / covered)));
    }

    // The image does not depend on the thread count, and cancel() stops a pass.
    void deterministicAndCancellable() {
        Model plane = quadsModel(
            {{glm::dvec3(-2, 0, 2), glm::dvec3(2, 0, 2), glm::dvec3(2, 0, -2), glm::dvec3(-2, 0, -2)}},
            pbrMaterial(glm::vec3(0.8f), 0.0f, 0.5f));
        merge(plane, makeSphere(0.5, 32, 16, glm::dvec3(0.0, 0.5, 0.0)));
        auto scene = describe(plane, pbrRig(true), uniformEnvironment(glm::vec3(1.0f)));
        QString error;
        const auto traced = trace::TraceScene::build(*scene, &error);
        QVERIFY2(traced, qPrintable(error));
        const ViewCamera camera = lookAt({2.0, 2.0, 3.0}, glm::dvec3(0.0), 40.0);
        trace::PathTracer one(traced, camera, QSize(40, 30), {}, 1),
            three(traced, camera, QSize(40, 30), {}, 3);
        one.render(2);
        three.render(1);
        three.render(1);
        QCOMPARE(one.samplesDone(), 2);
        QCOMPARE(three.samplesDone(), 2);
        const FloatImage a = one.image(), b = three.image();
        QVERIFY(a.pixels == b.pixels);
        three.cancel();
        QVERIFY(!three.render(4));
        QCOMPARE(three.samplesDone(), 2);
        three.restart();
        QCOMPARE(three.samplesDone(), 0);
        QVERIFY(three.render(1));
        QCOMPARE(three.samplesDone(), 1);
    }
};

QTEST_GUILESS_MAIN(TraceClosedForm)
#include "tst_trace_closedform.moc"
