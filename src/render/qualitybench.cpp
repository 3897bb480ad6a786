#include "qualitybench.h"

#include "benchestimate.h"
#include "core/statistics.h"
#include "offscreen.h"
#include "reference.h"
#include "scene/environmentloader.h"
#include "turntable.h"

#include <QElapsedTimer>
#include <QFile>
#include <QFuture>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QThread>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>

namespace lr {

namespace {

RenderSettings tierSettings(const BenchOptions& o, Quality q, bool uber) {
    RenderSettings s;
    s.exposureEV = o.exposureEV;
    s.toneMap = o.toneMap;
    s.quality = q;
    s.msaaSamples = o.msaaSamples >= 0 ? o.msaaSamples : tierMsaaSamples(q);
    s.forceAllFeatures = uber;
    s.approximations = o.approximations;
    s.interactive = o.interactive;
    s.renderScale = o.renderScale;
    return s;
}

struct Progress {
    const BenchProgress& fn;
    double total = 1.0, done = 0.0;
    bool cancelled = false;
    bool report(double extra, const QString& what) {
        if (fn && !cancelled && !fn(std::clamp((done + extra) / total, 0.0, 1.0), what)) cancelled = true;
        return !cancelled;
    }
};

// Gives the renderer the scene's environment: the loaded one, or its load (started here when first needed).
void giveEnvironment(Renderer& renderer, const BenchScene& scene) {
    if (scene.environmentLoad)
        renderer.setEnvironment(scene.environmentLoad->start());
    else
        renderer.setEnvironment(scene.environment);
}

// The scene's environment once loaded (null before, and for none).
std::shared_ptr<const LoadedEnvironment> sceneEnvironment(const BenchScene& scene) {
    return loadedEnvironment(scene.environmentLoad, scene.environment);
}

// The reference of one scene: G-buffer from a renderer of its own, evaluated on the thread pool while the
// progress callback keeps the caller responsive.
bool computeSceneReference(const BenchScene& scene, const BenchOptions& o, Progress& progress,
                           ReferenceImage* out, QString* error) {
    OffscreenRenderer gl;
    if (!gl.initialize(error) || !gl.setModel(scene.model, error)) return false;
    gl.setRig(scene.rig);
    giveEnvironment(gl.renderer(), scene);
    if (!gl.renderer().waitForEnvironment(error)) return false; // the reference integrates it
    const RenderSettings settings = tierSettings(o, Quality::Exact, false);
    GBuffer g;
    if (!gl.renderGBuffer(scene.camera, o.size, settings, &g, error)) return false;
    const glm::dmat4 view = gl.renderer().effectiveCamera(scene.camera).view();
    std::optional<ReferenceScene> referenceScene =
        makeReferenceScene(gl.renderer().scene(), view, settings, error); // what the raster drew
    if (!referenceScene) return false;
    ReferenceJob job(std::move(g), std::move(*referenceScene));
    QFuture<void> future = job.start();
    const QString what = QStringLiteral("%1: double-precision reference").arg(scene.name);
    while (!future.isFinished()) {
        const int range = std::max(1, future.progressMaximum() - future.progressMinimum());
        const double fraction = double(future.progressValue() - future.progressMinimum()) / range;
        if (!progress.report(fraction, what)) {
            future.cancel();
            future.waitForFinished();
            return false;
        }
        QThread::msleep(progress.fn ? 15 : 2);
    }
    job.finish();
    *out = job.result();
    return true;
}

// One scene × tier in a fresh renderer.
bool measure(const BenchScene& scene, const BenchOptions& o, Quality q, bool uber,
             const ReferenceImage* reference, Progress& progress, BenchResult* r, QString* error,
             QString* glDescription) {
    const QString what =
        QStringLiteral("%1: %2%3")
            .arg(scene.name, toString(q), uber ? QStringLiteral(" (über-shader)") : QString());
    if (!progress.report(0.0, what)) return false;
    const RenderSettings settings = tierSettings(o, q, uber);
    r->scene = scene.name;
    r->quality = q;
    r->uberShader = uber;
    r->size = o.size;
    r->msaaSamples = settings.msaaSamples;
    r->loadMs = scene.loadMs;

    OffscreenRenderer gl;
    if (!gl.initialize(error)) return false;
    if (glDescription && glDescription->isEmpty()) *glDescription = gl.glDescription();
    QElapsedTimer clock;
    clock.start();
    if (!gl.setModel(scene.model, error)) return false;
    QOpenGLContext::currentContext()->functions()->glFinish();
    r->uploadMs = clock.nsecsElapsed() * 1e-6;
    gl.setRig(scene.rig);
    // The scene's first run loads its environment now, after the upload, as `render` does: the first
    // frame's G-pass is drawn while it is decoded and prefiltered.
    const bool concurrent = scene.environmentLoad && !scene.environmentLoad->started();
    giveEnvironment(gl.renderer(), scene);
    if (!gl.renderFrame(scene.camera, o.size, settings, error)) return false;
    if (!gl.renderer().waitForEnvironment(error)) return false; // a frame that never sampled it
    r->firstDrawMs = clock.nsecsElapsed() * 1e-6;
    r->firstFrameMs = r->loadMs + r->firstDrawMs;
    if (const auto environment = sceneEnvironment(scene)) {
        r->environmentDecodeMs = environment->decodeSeconds * 1e3;
        r->environmentPrefilterMs = environment->prefiltered.seconds * 1e3;
        r->environmentConcurrent = concurrent;
    }
    // The viewport's first frame is the full mesh; its proxies follow from a worker thread a moment later.
    if (o.interactive) gl.renderer().waitForInteractionProxies();
    const RenderStats& stats = gl.renderer().stats();
    r->variants = stats.shaderVariantsCached; // mesh variants (the fixed passes are not counted)
    r->triangles = stats.triangles;
    if (stats.deferred) r->msaaSamples = 0; // the deferred path never multisamples (renderer.h)
    r->trianglesDrawn = stats.trianglesDrawn;
    r->lightsInRig = stats.lightsInRig;
    r->lightsUploaded = stats.lightsUploaded;

    const int total = std::max(0, o.warmupFrames) + std::max(1, o.frames);
    std::vector<double> wall, gpu, cpu;
    const glm::dvec3 center = scene.model ? scene.model->bounds.center() : glm::dvec3(0.0);
    Rig dragged = scene.rig;
    for (int i = 0; i < total; ++i) {
        if (i % 8 == 0 && !progress.report(0.8 * i / total, what)) return false;
        const ViewCamera camera =
            o.orbitDegrees != 0.0
                ? orbitCamera(scene.camera, center, std::fmod(o.orbitDegrees * (i + 1), 360.0))
                : scene.camera;
        clock.restart();
        const std::clock_t cpu0 = std::clock();
        if (o.dragLight && !dragged.lights.empty()) {
            Light& l = dragged.lights.front();
            const double step = (i % 2 ? -0.01 : 0.01);
            if (l.usesPosition())
                l.position.x += step * (scene.model ? scene.model->bounds.radius() : 1.0);
            else
                l.direction = glm::normalize(l.direction + glm::dvec3(step, 0.0, 0.0));
            gl.setRig(dragged);
        }
        if (!gl.renderFrame(camera, o.size, settings, error)) return false;
        const double ms = clock.nsecsElapsed() * 1e-6;
        const double cpuMs = double(std::clock() - cpu0) * 1000.0 / CLOCKS_PER_SEC;
        if (i == 0) r->secondFrameMs = ms;
        if (i < o.warmupFrames) continue;
        r->keptFrames += stats.gbufferKept ? 1 : 0;
        r->shadowMapsRendered += stats.shadowMapsRendered;
        wall.push_back(ms);
        cpu.push_back(cpuMs);
        // The timer result read during this frame belongs to an earlier (already timed, steady) frame.
        if (stats.lastGpuMs >= 0.0 && i > o.warmupFrames) gpu.push_back(stats.lastGpuMs);
    }
    if (o.dragLight) gl.setRig(scene.rig); // the error figures are of the rig as given
    r->msMedian = median(wall);
    r->msMin = *std::min_element(wall.begin(), wall.end());
    r->msMax = *std::max_element(wall.begin(), wall.end());
    r->gpuMsMedian = median(gpu);
    r->cpuMsMedian = median(cpu);

    if (reference && !reference->isNull()) {
        if (!progress.report(0.85, what + QStringLiteral(": error"))) return false;
        RenderSettings single = settings;
        single.msaaSamples = 0;
        const QImage image = gl.renderImage(scene.camera, o.size, single, 1, error);
        if (image.isNull()) return false;
        FloatImage radiance;
        if (!gl.renderRadiance(scene.camera, o.size, single, &radiance, error)) return false;
        r->errors = compareWithReference(image, *reference);
        r->hasShadowErrors = reference->casters > 0;
        if (r->hasShadowErrors) r->shadow = compareShadows(image, *reference);
        if (o.keepImages) {
            r->image = image.convertToFormat(QImage::Format_RGBA8888);
            r->reference = reference->srgb;
            r->covered = reference->covered;
        }
        r->errors.nonFinite =
            countNonFinite(&radiance.pixels.data()->x, std::int64_t(radiance.pixels.size()), 4);
        r->hasErrors = true;
    }
    return true;
}

} // namespace

QImage benchDifferenceImage(const QImage& image, const QImage& reference, int gain) {
    if (image.isNull() || reference.isNull() || image.size() != reference.size()) return {};
    const QImage a = image.convertToFormat(QImage::Format_RGBA8888);
    const QImage b = reference.convertToFormat(QImage::Format_RGBA8888);
    QImage out(a.size(), QImage::Format_RGB32);
    for (int y = 0; y < a.height(); ++y) {
        const uchar* pa = a.constScanLine(y);
        const uchar* pb = b.constScanLine(y);
        auto* po = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < a.width(); ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d, std::abs(int(pa[4 * x + c]) - int(pb[4 * x + c])));
            const int v = std::min(765, d * std::max(1, gain)); // 0..765: black -> red -> yellow -> white
            po[x] = qRgb(std::min(255, v), std::clamp(v - 255, 0, 255), std::clamp(v - 510, 0, 255));
        }
    }
    return out;
}

int tierMsaaSamples(Quality quality) {
    return quality == Quality::Fast ? 0 : 4;
}

BenchStatus runQualityBench(const std::vector<BenchScene>& scenes, const BenchOptions& options,
                            BenchReport* report, QString* error, const BenchProgress& progressFn) {
    report->options = options;
    const int runsPerScene = int(options.tiers.size()) + (options.uberShader ? 1 : 0);
    Progress progress{progressFn};
    // Weights: a reference costs about as much as one run.
    progress.total = double(scenes.size()) * (runsPerScene + (options.errors ? 1 : 0));
    QString message;
    auto failed = [&](const QString& what) {
        if (progress.cancelled) return BenchStatus::Cancelled;
        if (error) *error = what.isEmpty() ? message : QStringLiteral("%1: %2").arg(what, message);
        return BenchStatus::Failed;
    };
    for (const BenchScene& scene : scenes) {
        ReferenceImage reference;
        double referenceMs = 0.0;
        const double referenceWork = benchReferenceWork(scene, options.size);
        const bool referenced = options.errors && referenceWork <= options.maxReferenceWork;
        if (options.errors && !referenced) {
            report->notes.append(
                QStringLiteral("%1: no reference and no error figures: it would evaluate %2 light·pixels "
                               "(more than %3; a smaller --size or fewer --lights bring it under, "
                               "--full-reference computes it anyway)")
                    .arg(scene.name)
                    .arg(referenceWork, 0, 'g', 2)
                    .arg(options.maxReferenceWork, 0, 'g', 2));
            progress.done += 1.0;
        }
        if (referenced) {
            QElapsedTimer clock;
            clock.start();
            if (!computeSceneReference(scene, options, progress, &reference, &message))
                return failed(scene.name);
            referenceMs = clock.nsecsElapsed() * 1e-6;
            report->referenceMs += referenceMs;
            progress.done += 1.0;
        }
        const size_t first = report->results.size();
        for (int run = 0; run < runsPerScene; ++run) {
            const bool uber = run >= int(options.tiers.size());
            const Quality q = uber ? Quality::Exact : options.tiers[size_t(run)];
            BenchResult r;
            if (!measure(scene, options, q, uber, referenced ? &reference : nullptr, progress, &r, &message,
                         &report->glDescription))
                return failed(QStringLiteral("%1 (%2)").arg(scene.name, toString(q)));
            r.referenceMs = referenceMs;
            if (r.hasErrors && reference.environment) {
                r.hasEnvironment = true;
                r.environment = environmentConvergence(reference);
                const auto environment = sceneEnvironment(scene);
                r.environmentSource = environment ? environment->source : QString();
            }
            if (r.hasErrors && reference.area) {
                r.hasArea = true;
                r.area = areaConvergence(reference);
            }
            report->results.push_back(r);
            progress.done += 1.0;
        }
        const auto exact =
            std::find_if(report->results.begin() + std::ptrdiff_t(first), report->results.end(),
                         [](const BenchResult& r) { return r.quality == Quality::Exact && !r.uberShader; });
        if (exact != report->results.end())
            for (size_t i = first; i < report->results.size(); ++i) {
                BenchResult& r = report->results[i];
                if (r.msMedian > 0.0) r.speedUp = exact->msMedian / r.msMedian;
                if (r.cpuMsMedian > 0.0) r.cpuSpeedUp = exact->cpuMsMedian / r.cpuMsMedian;
            }
    }
    QFile loadavg(QStringLiteral("/proc/loadavg"));
    if (loadavg.open(QIODevice::ReadOnly))
        report->loadAverage = QString::fromLatin1(loadavg.readAll()).section(QLatin1Char(' '), 0, 2);
    report->glibcTunables = qEnvironmentVariable("GLIBC_TUNABLES");
    if (progressFn) progressFn(1.0, QStringLiteral("done"));
    return BenchStatus::Ok;
}

} // namespace lr
