#include "groupbench.h"

#include "core/statistics.h"
#include "offscreen.h"
#include "rasterlayers.h"
#include "referencelayers.h"

#include <QElapsedTimer>
#include <QFile>
#include <QTextStream>
#include <algorithm>
#include <ctime>

namespace lr {

namespace {

// Wall and process CPU ms of `frames` runs of `run` after `warmup` untimed ones (medians).
template <typename F> bool timed(int warmup, int frames, double* wallMs, double* cpuMs, F&& run) {
    for (int i = 0; i < warmup; ++i)
        if (!run()) return false;
    std::vector<double> wall, cpu;
    for (int i = 0; i < frames; ++i) {
        QElapsedTimer clock;
        clock.start();
        const std::clock_t cpu0 = std::clock();
        if (!run()) return false;
        cpu.push_back(double(std::clock() - cpu0) * 1000.0 / CLOCKS_PER_SEC);
        wall.push_back(double(clock.nsecsElapsed()) * 1e-6);
    }
    *wallMs = median(wall);
    *cpuMs = median(cpu);
    return true;
}

qint64 imageBytes(QSize size) {
    return qint64(size.width()) * size.height() * qint64(sizeof(glm::vec4));
}

bool benchReference(OffscreenRenderer& gl, const BenchScene& scene, const GroupBenchOptions& o,
                    GroupBenchResult* r, QString* error) {
    RenderSettings s;
    s.msaaSamples = 0;
    GBuffer g;
    if (!gl.renderGBuffer(scene.camera, o.size, s, &g, error)) return false;
    const glm::dmat4 view = gl.renderer().effectiveCamera(scene.camera).view();
    std::optional<ReferenceScene> plain = makeReferenceScene(gl.renderer().scene(), view, s, error);
    if (!plain) return false;
    QElapsedTimer clock;
    clock.start();
    std::clock_t cpu0 = std::clock();
    const ReferenceImage beauty = computeReference(g, *plain);
    r->beautyMs = double(clock.nsecsElapsed()) * 1e-6;
    r->beautyCpuMs = double(std::clock() - cpu0) * 1000.0 / CLOCKS_PER_SEC;
    const qint64 pixels = qint64(o.size.width()) * o.size.height();
    r->beautyBytes = pixels * qint64(sizeof(glm::dvec3));
    clock.restart();
    cpu0 = std::clock();
    const std::optional<RenderLayers> layers =
        computeReferenceLayers(gl.renderer().scene(), g, view, s, error);
    if (!layers) return false;
    r->layersMs = double(clock.nsecsElapsed()) * 1e-6;
    r->layersCpuMs = double(std::clock() - cpu0) * 1000.0 / CLOCKS_PER_SEC;
    r->groups = int(layers->groups.size());
    r->passes = 1;
    // Its double radiance and per-group radiance, and the float layers (no emission scratch image).
    r->layersBytes = r->beautyBytes + pixels * r->groups * qint64(sizeof(glm::dvec3)) +
                     rasterLayersBytes(o.size, r->groups) - imageBytes(o.size);
    return true;
}

} // namespace

bool runGroupBench(const std::vector<BenchScene>& scenes, const GroupBenchOptions& o,
                   std::vector<GroupBenchResult>* results, QString* glDescription, QString* error) {
    for (const BenchScene& scene : scenes) {
        OffscreenRenderer gl;
        if (!gl.initialize(error) || !gl.setModel(scene.model, error)) return false;
        if (glDescription && glDescription->isEmpty()) *glDescription = gl.glDescription();
        gl.setRig(scene.rig);
        if (scene.environmentLoad)
            gl.renderer().setEnvironment(scene.environmentLoad->start());
        else
            gl.renderer().setEnvironment(scene.environment);
        if (!gl.renderer().waitForEnvironment(error)) return false;
        const int lights = int(std::count_if(scene.rig.lights.begin(), scene.rig.lights.end(),
                                             [](const Light& l) { return l.enabled; }));
        for (Quality q : o.tiers) {
            RenderSettings s;
            s.quality = q;
            s.msaaSamples = o.msaaSamples >= 0 ? o.msaaSamples : tierMsaaSamples(q);
            s.approximations = o.approximations;
            GroupBenchResult r{scene.name, toString(q), lights};
            FloatImage beauty;
            if (!timed(o.warmupFrames, o.frames, &r.beautyMs, &r.beautyCpuMs,
                       [&] { return gl.renderRadiance(scene.camera, o.size, s, &beauty, error); }))
                return false;
            r.beautyBytes = imageBytes(o.size);
            double readbackCpuMs = 0.0;
            if (!timed(0, o.frames, &r.readbackMs, &readbackCpuMs, [&] {
                    return gl.renderer().readRadiance(&beauty) || (*error = gl.renderer().lastError(), false);
                }))
                return false;
            RasterLayersStats stats;
            if (!timed(o.warmupFrames, o.frames, &r.layersMs, &r.layersCpuMs, [&] {
                    return renderRasterLayers(gl, scene.camera, o.size, s, error, &stats).has_value();
                }))
                return false;
            r.passes = stats.passes;
            r.layersBytes = stats.bytes;
            r.groups = stats.groups;
            results->push_back(r);
        }
        if (o.reference) {
            GroupBenchResult r{scene.name, QStringLiteral("reference"), lights};
            if (!benchReference(gl, scene, o, &r, error)) return false;
            results->push_back(r);
        }
    }
    return true;
}

QString loadAverageNow() {
    QFile file(QStringLiteral("/proc/loadavg"));
    if (!file.open(QIODevice::ReadOnly)) return QStringLiteral("unknown");
    return QString::fromLatin1(file.readAll()).section(QLatin1Char(' '), 0, 2);
}

QString groupBenchTable(const std::vector<GroupBenchResult>& results) {
    QString text;
    QTextStream out(&text);
    const auto mib = [](qint64 b) { return QString::number(double(b) / double(1 << 20), 'f', 1); };
    out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10 %11 %12\n")
               .arg(QStringLiteral("scene"), -24)
               .arg(QStringLiteral("tier"), -10)
               .arg(QStringLiteral("groups"), 6)
               .arg(QStringLiteral("passes"), 6)
               .arg(QStringLiteral("beauty ms"), 10)
               .arg(QStringLiteral("layers ms"), 10)
               .arg(QStringLiteral("x"), 6)
               .arg(QStringLiteral("cpu x"), 6)
               .arg(QStringLiteral("beauty MiB"), 10)
               .arg(QStringLiteral("layers MiB"), 10)
               .arg(QStringLiteral("ms/group"), 9)
               .arg(QStringLiteral("1-pass >= ms"), 12);
    for (const GroupBenchResult& r : results) {
        const double extra = r.groups > 0 ? (r.layersMs - r.beautyMs) / r.groups : 0.0;
        const double bound = r.accumulationBoundMs();
        out << QStringLiteral("%1 %2 %3 %4 %5 %6 %7 %8 %9 %10 %11 %12\n")
                   .arg(r.scene, -24)
                   .arg(r.tier, -10)
                   .arg(r.groups, 6)
                   .arg(r.passes, 6)
                   .arg(r.beautyMs, 10, 'f', 1)
                   .arg(r.layersMs, 10, 'f', 1)
                   .arg(r.beautyMs > 0 ? r.layersMs / r.beautyMs : 0.0, 6, 'f', 1)
                   .arg(r.beautyCpuMs > 0 ? r.layersCpuMs / r.beautyCpuMs : 0.0, 6, 'f', 1)
                   .arg(mib(r.beautyBytes), 10)
                   .arg(mib(r.layersBytes), 10)
                   .arg(extra, 9, 'f', 1)
                   .arg(bound > 0.0 ? QString::number(bound, 'f', 1) : QStringLiteral("-"), 12);
    }
    return text;
}

} // namespace lr
