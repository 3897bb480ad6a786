// Issue 39: an IES profile in the path-traced tier. A point light with a known profile over a plane, one
// bounce: every pixel equals core's direct light with the profile (tested against the closed form in
// tests/formulas/tst_iesshade.cpp); the profile visibly shapes the image; a profile that does not load
// leaves the light unshaped with a warning.
#include "tracescenes.h"

#include "core/shade.h"

#include <QTest>
#include <cmath>

using namespace lr;
using namespace tracetest;

namespace {

QString data(const QString& name) {
    return QStringLiteral(LIGHTRIG_TEST_DATA "/ies/") + name;
}

Rig downlightRig(const QString& file) {
    Rig rig = pbrRig(false);
    Light l;
    l.type = LightType::Point;
    l.position = {0.2, 1.5, -0.1};
    l.direction = {0.0, -1.0, 0.0};
    l.intensity = 5.0;
    l.falloff.model = FalloffModel::InverseSquare;
    l.falloff.range = -1.0;
    l.ies = IesSpec{file, {}, 1.0, IesLevel::Light, 30.0};
    rig.lights = {l};
    return rig;
}

struct Traced {
    FloatImage image;
    double worst = 0.0, meanRelative = 0.0;
    int covered = 0;
};

Traced traceAndCompare(const Rig& rig, QStringList* warnings = nullptr) {
    const Model plane =
        quadsModel({{glm::dvec3(-3, 0, 3), glm::dvec3(3, 0, 3), glm::dvec3(3, 0, -3), glm::dvec3(-3, 0, -3)}},
                   pbrMaterial(glm::vec3(0.8f), 0.0f, 0.9f));
    auto scene = describe(plane, rig);
    QString error;
    const auto traced = trace::TraceScene::build(*scene, &error);
    Traced out;
    if (!traced) return out;
    if (warnings) *warnings = traced->warnings();
    const ViewCamera camera = lookAt({0.0, 4.0, 2.5}, glm::dvec3(0.0), 60.0);
    const QSize size(32, 32);
    trace::TraceSettings settings;
    settings.bounces = 1;
    settings.jitter = false;
    trace::PathTracer tracer(traced, camera, size, settings, 2);
    tracer.render(1);
    out.image = tracer.image();
    const trace::CameraRays rays(camera, size);
    const glm::dmat4 view = camera.view();
    const auto lights = scene->lights(view); // with the profile (SceneDescription applies it)
    const auto st = scene->shadeSettings();
    for (int y = 0; y < size.height(); ++y)
        for (int x = 0; x < size.width(); ++x) {
            const auto s = tracetest::viewSurfaceAt(*traced, rays, view, x, y);
            if (!s) continue;
            const glm::dvec3 expected = lighting::shadeSurface<double>(*s, lights, st);
            const double e = glm::length(glm::dvec3(out.image.at(x, y)) - expected) /
                             std::max(1e-3, glm::length(expected));
            out.worst = std::max(out.worst, e);
            out.meanRelative += e;
            ++out.covered;
        }
    out.meanRelative /= std::max(1, out.covered);
    return out;
}

} // namespace

class TraceIes : public QObject {
    Q_OBJECT
  private slots:
    void planeEqualsCoresDirectLight() {
        const Traced t = traceAndCompare(downlightRig(data(QStringLiteral("full.ies"))));
        QVERIFY(t.covered > 500);
        qInfo("traced against core over %d pixels: worst relative error %.2e, mean %.2e", t.covered, t.worst,
              t.meanRelative);
        QVERIFY2(t.worst < 1e-3, qPrintable(QStringLiteral("worst relative error %1").arg(t.worst)));
        // The profile shapes the image: the plain light differs (full.ies varies 3:1 around the axis).
        Rig plain = downlightRig(data(QStringLiteral("full.ies")));
        plain.lights[0].ies.reset();
        const Traced p = traceAndCompare(plain);
        double differ = 0.0;
        const double scale = meanChannel(p.image, 1) / std::max(1e-12, meanChannel(t.image, 1));
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x)
                differ = std::max(differ, std::abs(double(t.image.at(x, y).y) * scale - p.image.at(x, y).y) /
                                              std::max(1e-6, double(p.image.at(x, y).y)));
        QVERIFY2(differ > 0.2, qPrintable(QString::number(differ)));
    }

    void aProfileThatDoesNotLoadIsWarnedAbout() {
        QStringList warnings;
        const Traced t = traceAndCompare(downlightRig(data(QStringLiteral("truncated.ies"))), &warnings);
        QVERIFY(t.covered > 500);
        QVERIFY(t.worst < 1e-3); // unshaped, as core shades it without the profile
        QVERIFY2(warnings.join('\n').contains(QStringLiteral("lights[0].ies.file: ")),
                 qPrintable(warnings.join('\n')));
        QVERIFY(warnings.join('\n').contains(QStringLiteral("truncated.ies:9: ")));
    }
};

QTEST_GUILESS_MAIN(TraceIes)
#include "tst_trace_ies.moc"
