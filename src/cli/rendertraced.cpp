#include "rendertraced.h"

#include "cli.h"
#include "outputfiles.h"

#include "scene/scenedescription.h"
#include "trace/pathtracer.h"
#include "trace/progressive.h"

#include <QElapsedTimer>
#include <QTextStream>
#include <cmath>

namespace lr::cli {

int runRenderTraced(const RenderRequest& request, const RenderItem& item, const TracedRenderOptions& traced) {
    QTextStream err(stderr), out(stdout);
    const QString name = QStringLiteral("lightrig render");
    const QString modelPath = request.models.value(item.model);
    QString message;
    if (!checkOutputPath(item.file, &message)) {
        err << name << ": " << message << '\n';
        return Failed;
    }
    QElapsedTimer clock;
    clock.start();
    SceneOptions options = request.options;
    if (item.rig >= 0) options.rigPath = request.rigs.value(item.rig);
    LoadedScene loaded;
    if (!loadScene(modelPath, options, &loaded, &message, EnvironmentLoading::Now)) {
        err << name << ": " << message << '\n';
        return Failed;
    }
    for (const QString& w : loaded.model->warnings)
        err << name << ": warning: " << w << '\n';
    const double loadSeconds = clock.nsecsElapsed() * 1e-9;
    SceneDescription description;
    description.setModel(loaded.model);
    description.setRig(loaded.rig);
    description.setEnvironment(loaded.environment);
    const std::shared_ptr<const trace::TraceScene> scene = trace::TraceScene::build(description, &message);
    if (!scene) {
        err << name << ": " << modelPath << ": " << message << '\n';
        return Failed;
    }
    for (const QString& w : scene->warnings())
        err << name << ": warning: " << w << '\n';
    trace::TraceSettings settings;
    settings.bounces = traced.bounces;
    settings.fireflyClamp = traced.fireflyClamp;
    settings.seed = std::uint32_t(traced.seed);
    settings.transparent = request.transparent;
    trace::PathTracer tracer(scene, loaded.camera, request.options.size, settings, traced.threads);
    const trace::RenderOutcome outcome =
        trace::renderToTarget(tracer, {traced.samples, traced.timeLimit, traced.noiseThreshold});
    const double traceSeconds = outcome.seconds;
    if (tracer.nonFiniteSamples() > 0)
        err << name << ": warning: " << tracer.nonFiniteSamples()
            << " samples were not finite and were left out of their pixels' means\n";
    const QImage image = tracer.display(request.options.exposureEV, request.options.toneMap);
    if (request.transparent && request.format == "jpeg")
        err << name << ": warning: JPEG has no alpha channel; the transparent background is written black\n";
    if (!writeOutputImage(image, item.file, request.format, &message)) {
        err << name << ": " << message << '\n';
        return Failed;
    }
    const QString noise = std::isfinite(outcome.noise) ? QString::number(outcome.noise, 'g', 3)
                                                       : QStringLiteral("unknown (under 2 samples)");
    out << QStringLiteral("wrote %1 (%2x%3): path traced, %4 samples per pixel, %5 bounces, %6 threads, %7 s "
                          "(%8 samples/s), noise %13, stopped by %14; %9 triangles, %10, %11, load %12 s\n")
               .arg(item.file)
               .arg(image.width())
               .arg(image.height())
               .arg(outcome.samples)
               .arg(traced.bounces)
               .arg(tracer.threads())
               .arg(traceSeconds, 0, 'f', 2)
               .arg(double(image.width()) * image.height() * tracer.samplesDone() /
                        std::max(1e-9, traceSeconds),
                    0, 'f', 0)
               .arg(scene->triangles())
               .arg(loaded.rigSource, loaded.cameraSource)
               .arg(loadSeconds, 0, 'f', 2)
               .arg(noise, QLatin1String(trace::stopReasonName(outcome.reason)));
    return Ok;
}

} // namespace lr::cli
