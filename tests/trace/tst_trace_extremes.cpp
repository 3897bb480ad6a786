// The path tracer at the extremes (issue 36): grazing rays, a light on the surface, roughness 0 and 1,
// zero-area emitters, NaN and infinite texels, a 1e6-radiance environment give finite images; alpha MASK
// and BLEND let light through; emission is seen as it is; a classic-shading rig is refused, saying why.
#include "tracescenes.h"

#include <QTest>
#include <cmath>
#include <limits>

using namespace lr;
using namespace tracetest;

namespace {

Model floorQuad(const Material& material, double half = 2.0) {
    return quadsModel({{glm::dvec3(-half, 0, half), glm::dvec3(half, 0, half), glm::dvec3(half, 0, -half),
                        glm::dvec3(-half, 0, -half)}},
                      material);
}

// Renders and checks that every pixel is finite and no sample was dropped.
void expectFinite(const SceneDescription& scene, const ViewCamera& camera, int bounces = 8) {
    QString error;
    const auto traced = trace::TraceScene::build(scene, &error);
    QVERIFY2(traced, qPrintable(error));
    trace::TraceSettings settings;
    settings.bounces = bounces;
    trace::PathTracer tracer(traced, camera, QSize(16, 12), settings, 2);
    tracer.render(4);
    QVERIFY(allFinite(tracer.image()));
    QCOMPARE(tracer.nonFiniteSamples(), std::int64_t(0));
}

} // namespace

class TraceExtremes : public QObject {
    Q_OBJECT
  private slots:
    void grazingRaysAndALightOnTheSurface() {
        Rig rig = pbrRig(true);
        Light onSurface;
        onSurface.type = LightType::Point;
        onSurface.position = glm::dvec3(0.0);
        onSurface.intensity = 5.0;
        onSurface.falloff.model = FalloffModel::InverseSquare;
        rig.lights.push_back(onSurface);
        auto scene = describe(floorQuad(pbrMaterial(glm::vec3(0.8f), 0.0f, 0.5f)), rig,
                              uniformEnvironment(glm::vec3(1.0f)));
        expectFinite(*scene, lookAt({-3.0, 1e-6, 0.0}, {3.0, 1e-6, 0.0}, 30.0));
        expectFinite(*scene, lookAt({0.0, 3.0, 0.01}, glm::dvec3(0.0), 10.0));
    }

    void roughnessZeroAndOneUnderAHugeEnvironmentWithBadTexels() {
        auto env = std::make_shared<LoadedEnvironment>(*uniformEnvironment(glm::vec3(1e6f), 32));
        env->image.at(3, 3) = glm::vec3(std::numeric_limits<float>::quiet_NaN());
        env->image.at(4, 3) = glm::vec3(std::numeric_limits<float>::infinity());
        env->image.at(5, 3) = glm::vec3(-1.0f);
        for (float roughness : {0.0f, 1.0f})
            for (float metallic : {0.0f, 1.0f}) {
                Model m = floorQuad(pbrMaterial(glm::vec3(0.9f), metallic, roughness));
                merge(m, makeSphere(0.5, 32, 16, glm::dvec3(0.0, 0.5, 0.0)));
                m.materials.back() = pbrMaterial(glm::vec3(0.9f), metallic, roughness);
                auto scene = describe(m, pbrRig(true), env);
                expectFinite(*scene, lookAt({2.0, 1.5, 2.0}, glm::dvec3(0.0), 40.0));
            }
    }

    void zeroAreaEmitters() {
        Rig rig = pbrRig(false);
        Light rect;
        rect.type = LightType::Rect;
        rect.position = {0.0, 1.0, 0.0};
        rect.direction = {0.0, -1.0, 0.0};
        rect.intensity = 10.0;
        rect.area.width = 0.0;
        rect.area.height = 0.0;
        Light disk = rect;
        disk.type = LightType::Disk;
        disk.area.radius = 0.0;
        rig.lights = {rect, disk};
        Model m = floorQuad(pbrMaterial(glm::vec3(0.8f), 0.0f, 0.5f));
        // An emissive mesh of one zero-area triangle and one proper one.
        Model lamp = quadsModel({{glm::dvec3(-0.2, 0.8, 0.2), glm::dvec3(0.2, 0.8, 0.2),
                                  glm::dvec3(0.2, 0.8, -0.2), glm::dvec3(-0.2, 0.8, -0.2)}},
                                pbrMaterial(glm::vec3(0.0f), 0.0f, 1.0f));
        lamp.meshes.front().indices.insert(lamp.meshes.front().indices.begin(), {0, 0, 0});
        lamp.materials.front().emissive = glm::vec3(3.0f);
        merge(m, lamp);
        auto scene = describe(m, rig);
        expectFinite(*scene, lookAt({2.0, 1.5, 2.0}, glm::dvec3(0.0), 40.0));
    }

    // A camera ray that meets an emissive surface sees its emission (bounces 0: nothing else), through a
    // masked quad whose alpha is under its cutoff; a BLEND quad of alpha a passes 1 − a of it.
    void emissionAndAlpha() {
        Material glow = pbrMaterial(glm::vec3(0.0f), 0.0f, 1.0f);
        glow.emissive = glm::vec3(2.0f, 1.0f, 0.5f);
        Model m = floorQuad(glow);
        Material cover = pbrMaterial(glm::vec3(0.0f), 0.0f, 1.0f);
        cover.baseColor.a = 0.25f;
        cover.alphaMode = AlphaMode::Mask;
        Model sheet = quadsModel({{glm::dvec3(-3, 0.5, 3), glm::dvec3(3, 0.5, 3), glm::dvec3(3, 0.5, -3),
                                   glm::dvec3(-3, 0.5, -3)}},
                                 cover);
        const ViewCamera camera = lookAt({0.0, 3.0, 0.01}, glm::dvec3(0.0), 20.0);
        trace::TraceSettings settings;
        settings.bounces = 0;
        for (AlphaMode mode : {AlphaMode::Mask, AlphaMode::Blend}) {
            Model both = m;
            sheet.materials.front().alphaMode = mode;
            merge(both, sheet);
            auto scene = describe(both, pbrRig(false));
            QString error;
            const auto traced = trace::TraceScene::build(*scene, &error);
            QVERIFY2(traced, qPrintable(error));
            trace::PathTracer tracer(traced, camera, QSize(16, 16), settings, 2);
            tracer.render(64);
            const double expected = mode == AlphaMode::Mask ? 2.0 : 2.0 * 0.75;
            const double got = meanChannel(tracer.image(), 0);
            QVERIFY2(std::abs(got - expected) < 0.03 * expected, qPrintable(QString::number(got)));
        }
    }

    void classicShadingIsRefused() {
        Rig rig = pbrRig(false);
        rig.shading.model = ShadingModel::Classic;
        auto scene = describe(floorQuad(pbrMaterial(glm::vec3(0.8f), 0.0f, 0.5f)), rig);
        QString error;
        QVERIFY(!trace::TraceScene::build(*scene, &error));
        QVERIFY2(error.contains(QLatin1String("classic shading")), qPrintable(error));
        QVERIFY2(error.contains(QLatin1String("--shading pbr")), qPrintable(error));
    }
};

QTEST_GUILESS_MAIN(TraceExtremes)
#include "tst_trace_extremes.moc"
