#include "rendertraced.h"

#include "renderestimate.h"

#include "scene/scenedescription.h"
#include "trace/pathtracer.h"
#include "trace/progressive.h"
#include "trace/tracescene.h"

#include <glm/glm.hpp>

#include <cmath>

namespace lr::cli {

std::optional<TracedImages::Result> TracedImages::render(const LoadedScene& scene, const Rig& rig,
                                                         const ViewCamera& camera, QSize size,
                                                         const RenderSettings& settings,
                                                         const std::function<void(const QString&)>& warn,
                                                         QString* error) {
    if (!m_scene || m_model != scene.model || m_environment != scene.environment || !(m_rig == rig)) {
        m_scene.reset();
        SceneDescription description;
        description.setModel(scene.model);
        description.setRig(rig);
        description.setEnvironment(scene.environment);
        m_scene = trace::TraceScene::build(description, error);
        if (!m_scene) return std::nullopt;
        m_model = scene.model, m_environment = scene.environment, m_rig = rig;
        for (const QString& w : m_scene->warnings())
            warn(w);
    }
    trace::TraceSettings ts;
    ts.bounces = m_options.bounces;
    ts.fireflyClamp = m_options.fireflyClamp;
    ts.seed = std::uint32_t(m_options.seed);
    ts.transparent = settings.transparentBackground;
    trace::PathTracer tracer(m_scene, camera, size, ts, m_options.threads);
    tracer.setLayers(m_options.layers);
    const trace::RenderOutcome outcome =
        trace::renderToTarget(tracer, {m_options.samples, m_options.timeLimit, m_options.noiseThreshold});
    if (tracer.nonFiniteSamples() > 0)
        warn(QStringLiteral("%1 samples were not finite and were left out of their pixels' means")
                 .arg(tracer.nonFiniteSamples()));
    Result r;
    r.image = tracer.display(settings.exposureEV, settings.toneMap);
    r.linear = tracer.image();
    if (m_options.layers) r.layers = tracer.layers();
    r.samples = outcome.samples;
    r.seconds = outcome.seconds;
    r.noise = outcome.noise;
    r.stoppedBy = QLatin1String(trace::stopReasonName(outcome.reason));
    const QString noise = std::isfinite(outcome.noise) ? QString::number(outcome.noise, 'g', 3)
                                                       : QStringLiteral("unknown (under 2 samples)");
    r.line = QStringLiteral("path traced, %1 samples per pixel, %2 bounces, %3 threads, %4 s (%5 samples/s), "
                            "noise %6, stopped by %7; %8 triangles")
                 .arg(outcome.samples)
                 .arg(m_options.bounces)
                 .arg(tracer.threads())
                 .arg(outcome.seconds, 0, 'f', 2)
                 .arg(double(size.width()) * size.height() * tracer.samplesDone() /
                          std::max(1e-9, outcome.seconds),
                      0, 'f', 0)
                 .arg(noise, QLatin1String(trace::stopReasonName(outcome.reason)))
                 .arg(m_scene->triangles());
    return r;
}

namespace {
// Per pixel: the radiance and alpha sums (4 doubles), the luminance mean and deviations (2 doubles), the
// sample count, the display image (RGBA8) and its encoding; and the traced scene's share, about.
constexpr std::int64_t kTracedBytesPerPixel = 4 * 8 + 2 * 8 + 4 + 4 + 4;
constexpr std::int64_t kTracedSceneBytes = std::int64_t(256) << 20;
// With layers of n groups, per pixel: the tracer's sums (trace::layerBytesPerPixel) and the RenderLayers
// it returns, float RGBA images: n groups, the beauty, albedo, normal and depth.
std::int64_t layerBytesPerPixel(int groups) {
    if (groups <= 0) return 0;
    return std::int64_t(trace::layerBytesPerPixel(std::size_t(groups))) +
           std::int64_t(groups + 4) * std::int64_t(sizeof(glm::vec4));
}
} // namespace

std::int64_t tracedImageBytes(QSize size, int layerGroups) {
    return std::int64_t(size.width()) * size.height() *
               (kTracedBytesPerPixel + layerBytesPerPixel(layerGroups)) +
           kTracedSceneBytes;
}

int tracedLayerGroups(const Rig& rig, bool hasEmissive) {
    return int(lightGroups(rig, {.hasEmissive = hasEmissive, .includeRims = false}).size());
}

bool checkTracedMemory(QSize size, bool unchecked, QString* error, int layerGroups) {
    QString what;
    const std::int64_t need = tracedImageBytes(size, layerGroups), available = availableMemory(&what);
    if (unchecked || available <= 0 || need <= available) return true;
    const auto gib = [](std::int64_t b) {
        return QStringLiteral("%1 GiB").arg(double(b) / double(1 << 30), 0, 'f', 1);
    };
    const QString layers =
        layerGroups > 0 ? QStringLiteral(" and the layers of %1 light groups").arg(layerGroups) : QString();
    *error =
        QStringLiteral("--size %1x%2 with --quality path%3 needs about %4 of memory (%5 bytes a pixel), more "
                       "than the %6 this process may use (%7): use a smaller --size, or "
                       "--no-memory-check to try anyway")
            .arg(size.width())
            .arg(size.height())
            .arg(layers, gib(need))
            .arg(kTracedBytesPerPixel + layerBytesPerPixel(layerGroups))
            .arg(gib(available), what);
    return false;
}

} // namespace lr::cli
