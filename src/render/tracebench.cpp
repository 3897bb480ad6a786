#include "tracebench.h"

#include "imageerrors.h"
#include "scene/environmentloader.h"
#include "scene/scenedescription.h"
#include "trace/pathtracer.h"

#include <QElapsedTimer>
#include <QJsonObject>
#include <algorithm>
#include <cmath>

namespace lr {

namespace {

QJsonValue finiteOrNull(double v) {
    return std::isfinite(v) ? QJsonValue(v) : QJsonValue(QJsonValue::Null);
}

// 1, 2, 4, 8, … up to `samples`, and `samples` itself: doubling steps, so that the first step within
// 30 dB is found to a factor of two.
std::vector<int> ladder(int samples) {
    std::vector<int> out;
    for (int k = 1; k <= samples; k *= 2)
        out.push_back(k);
    if (out.empty() || out.back() != samples) out.push_back(std::max(1, samples));
    return out;
}

QString psnrText(double db) {
    return std::isfinite(db) ? QString::number(db, 'f', 1) : QStringLiteral("inf");
}

} // namespace

bool runPathBench(const std::vector<BenchScene>& scenes, const PathBenchOptions& options, BenchReport* report,
                  const BenchProgress& progress) {
    const BenchOptions& bo = report->options;
    const size_t runs = bo.tiers.size() + (bo.uberShader ? 1 : 0);
    for (size_t i = 0; i < scenes.size(); ++i) {
        const BenchScene& scene = scenes[i];
        PathBenchResult p;
        p.scene = scene.name;
        p.size = bo.size;
        p.bounces = options.bounces;
        if (progress && !progress(double(i) / double(scenes.size()), scene.name + QStringLiteral(" · path")))
            return false;
        QElapsedTimer clock;
        clock.start();
        SceneDescription description;
        description.setModel(scene.model);
        description.setRig(scene.rig);
        std::shared_ptr<const LoadedEnvironment> environment = scene.environment;
        if (!environment && scene.environmentLoad) { // waits for it (a path-only run never started it)
            const EnvironmentLoadResult loaded = scene.environmentLoad->result();
            if (!loaded.environment && !loaded.error.isEmpty()) {
                p.error = loaded.error;
                report->path.push_back(p);
                continue;
            }
            environment = loaded.environment;
        }
        description.setEnvironment(environment);
        const std::shared_ptr<const trace::TraceScene> traced =
            trace::TraceScene::build(description, &p.error);
        if (!traced) {
            report->path.push_back(p);
            continue;
        }
        p.buildMs = clock.nsecsElapsed() * 1e-6;
        p.triangles = traced->triangles();
        trace::TraceSettings settings;
        settings.bounces = options.bounces;
        // The converged image: other random numbers than the ladder's, so that its steps are not a
        // share of the very samples they are compared with.
        trace::TraceSettings convergedSettings = settings;
        convergedSettings.seed = settings.seed ^ 0x9e3779b9u;
        trace::PathTracer converged(traced, scene.camera, bo.size, convergedSettings, options.threads);
        clock.restart();
        converged.render(options.convergedSamples);
        p.convergedSeconds = clock.nsecsElapsed() * 1e-9;
        p.convergedSamples = converged.samplesDone();
        p.convergedNoise = converged.noiseEstimate();
        p.threads = converged.threads();
        const QImage truth = converged.display(bo.exposureEV, bo.toneMap);

        trace::PathTracer tracer(traced, scene.camera, bo.size, settings, options.threads);
        double seconds = 0.0;
        for (int k : ladder(options.samples)) {
            clock.restart();
            tracer.render(k - tracer.samplesDone());
            seconds += clock.nsecsElapsed() * 1e-9;
            PathBenchStep step;
            step.samples = tracer.samplesDone();
            step.seconds = seconds;
            step.noise = tracer.noiseEstimate();
            step.errors = imageErrors(tracer.display(bo.exposureEV, bo.toneMap), truth);
            if (p.secondsTo30Db < 0.0 && step.errors.psnrDb >= 30.0) p.secondsTo30Db = seconds;
            p.steps.push_back(step);
        }
        if (!p.steps.empty() && p.steps.back().samples > 0) {
            p.secondsPerSample = p.steps.back().seconds / p.steps.back().samples;
            p.samplesPerSecond = p.secondsPerSample > 0.0 ? 1.0 / p.secondsPerSample : 0.0;
        }
        for (size_t k = i * runs; k < std::min(report->results.size(), (i + 1) * runs); ++k) {
            BenchResult& r = report->results[k];
            if (r.scene != scene.name || r.image.isNull() || r.image.size() != truth.size()) continue;
            r.tracedErrors = imageErrors(r.image, truth, &r.covered);
            r.hasTracedErrors = true;
        }
        report->path.push_back(std::move(p));
    }
    return true;
}

QString pathBenchTable(const BenchReport& report) {
    if (report.path.empty()) return {};
    QString out = QStringLiteral("\nPath tier (CPU path tracer; PSNR and mean error in 8-bit levels against "
                                 "the converged image, every pixel):\n");
    for (const PathBenchResult& p : report.path) {
        if (!p.error.isEmpty()) {
            out += QStringLiteral("%1: not traced: %2\n").arg(p.scene, p.error);
            continue;
        }
        out +=
            QStringLiteral("%1: %2x%3, %4 threads, %5 bounces, %6 s/sample, %7 samples/s, within 30 dB "
                           "after %8; converged: %9 samples in %10 s (noise %11), scene built in %12 ms\n")
                .arg(p.scene)
                .arg(p.size.width())
                .arg(p.size.height())
                .arg(p.threads)
                .arg(p.bounces)
                .arg(p.secondsPerSample, 0, 'f', 3)
                .arg(p.samplesPerSecond, 0, 'f', 2)
                .arg(p.secondsTo30Db >= 0.0 ? QString::number(p.secondsTo30Db, 'f', 2) + QStringLiteral(" s")
                                            : QStringLiteral("never"))
                .arg(p.convergedSamples)
                .arg(p.convergedSeconds, 0, 'f', 1)
                .arg(p.convergedNoise, 0, 'g', 3)
                .arg(p.buildMs, 0, 'f', 0);
        out += QStringLiteral("  samples  seconds  noise     PSNR dB  mean err  max err\n");
        for (const PathBenchStep& s : p.steps)
            out +=
                QStringLiteral("  %1  %2  %3  %4  %5  %6\n")
                    .arg(s.samples, 7)
                    .arg(s.seconds, 7, 'f', 2)
                    .arg(std::isfinite(s.noise) ? QString::number(s.noise, 'f', 4) : QStringLiteral("–"), 8)
                    .arg(psnrText(s.errors.psnrDb), 7)
                    .arg(s.errors.meanLevels, 8, 'f', 3)
                    .arg(s.errors.maxLevels, 7);
    }
    return out;
}

QJsonArray pathBenchJson(const BenchReport& report) {
    QJsonArray out;
    for (const PathBenchResult& p : report.path) {
        QJsonArray steps;
        for (const PathBenchStep& s : p.steps)
            steps.append(QJsonObject{{QStringLiteral("samples"), s.samples},
                                     {QStringLiteral("seconds"), s.seconds},
                                     {QStringLiteral("noise"), finiteOrNull(s.noise)},
                                     {QStringLiteral("psnr_db"), finiteOrNull(s.errors.psnrDb)},
                                     {QStringLiteral("mean_error_levels"), s.errors.meanLevels},
                                     {QStringLiteral("max_error_levels"), s.errors.maxLevels}});
        QJsonObject o{{QStringLiteral("scene"), p.scene},
                      {QStringLiteral("width"), p.size.width()},
                      {QStringLiteral("height"), p.size.height()},
                      {QStringLiteral("threads"), p.threads},
                      {QStringLiteral("bounces"), p.bounces},
                      {QStringLiteral("triangles"), double(p.triangles)},
                      {QStringLiteral("build_ms"), p.buildMs},
                      {QStringLiteral("seconds_per_sample"), p.secondsPerSample},
                      {QStringLiteral("samples_per_second"), p.samplesPerSecond},
                      {QStringLiteral("seconds_to_30db"),
                       p.secondsTo30Db >= 0.0 ? QJsonValue(p.secondsTo30Db) : QJsonValue()},
                      {QStringLiteral("converged_samples"), p.convergedSamples},
                      {QStringLiteral("converged_seconds"), p.convergedSeconds},
                      {QStringLiteral("converged_noise"), finiteOrNull(p.convergedNoise)},
                      {QStringLiteral("steps"), steps}};
        if (!p.error.isEmpty()) o.insert(QStringLiteral("error"), p.error);
        out.append(o);
    }
    return out;
}

} // namespace lr
