#include "benchestimate.h"

#include "offscreen.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cmath>
#include <map>

namespace lr {

namespace {

double pixels(QSize size) {
    return double(std::max(0, size.width())) * double(std::max(0, size.height()));
}

int enabledLights(const BenchScene& scene) {
    return int(std::count_if(scene.rig.lights.begin(), scene.rig.lights.end(),
                             [](const Light& l) { return l.enabled; }));
}

// The probe's size: the bench's aspect, at most 64×64 pixels in all, at least 1 a side.
QSize probeSize(QSize size) {
    const double scale = std::min(1.0, std::sqrt(64.0 * 64.0 / std::max(1.0, pixels(size))));
    return QSize(std::max(1, int(std::lround(size.width() * scale))),
                 std::max(1, int(std::lround(size.height() * scale))));
}

QString duration(double seconds) {
    if (seconds < 120.0) return QStringLiteral("%1 s").arg(seconds, 0, 'f', seconds < 10.0 ? 1 : 0);
    if (seconds < 7200.0) return QStringLiteral("%1 min").arg(seconds / 60.0, 0, 'f', 0);
    if (seconds < 2.0 * 86400.0) return QStringLiteral("%1 h").arg(seconds / 3600.0, 0, 'f', 1);
    return QStringLiteral("%1 days").arg(seconds / 86400.0, 0, 'f', 1);
}

} // namespace

double benchFrameWork(const BenchScene& scene, QSize size) {
    return pixels(size) * enabledLights(scene);
}

double benchReferenceWork(const BenchScene& scene, QSize size) {
    double lights = 0.0;
    for (const Light& l : scene.rig.lights)
        if (l.enabled) lights += l.isArea() ? kAreaReferenceWeight : 1.0;
    return pixels(size) * lights;
}

bool benchIsHeavy(const std::vector<BenchScene>& scenes, const BenchOptions& options) {
    return std::any_of(scenes.begin(), scenes.end(), [&](const BenchScene& s) {
        return enabledLights(s) > 256 || benchFrameWork(s, options.size) > 1280.0 * 720.0 * 256.0;
    });
}

std::optional<BenchEstimate> estimateBench(const std::vector<BenchScene>& scenes, const BenchOptions& options,
                                           QString* error) {
    BenchEstimate e;
    const int runs = int(options.tiers.size()) + (options.uberShader ? 1 : 0);
    // Each run: the first frame, the warm-up and timed frames, and (with errors) the image and radiance.
    const int perRun =
        1 + std::max(0, options.warmupFrames) + std::max(1, options.frames) + (options.errors ? 2 : 0);
    e.probeSize = probeSize(options.size);
    // The exact tier, single sample, without the environment (which costs per pixel, not per light).
    RenderSettings settings;
    settings.quality = Quality::Exact;
    settings.msaaSamples = 0;
    settings.approximations = options.approximations;
    // Seconds per light·pixel, probed on the heaviest scene of each set of light types (an area light
    // shades at several times a point light's cost).
    std::map<unsigned, double> perWork;
    const auto typesOf = [](const BenchScene& s) {
        unsigned mask = 0;
        for (const Light& l : s.rig.lights)
            if (l.enabled) mask |= 1u << unsigned(l.type);
        return mask;
    };
    for (const BenchScene& s : scenes) {
        const unsigned types = typesOf(s);
        if (perWork.count(types)) continue;
        const BenchScene* heaviest = &s;
        for (const BenchScene& t : scenes)
            if (typesOf(t) == types &&
                benchFrameWork(t, options.size) > benchFrameWork(*heaviest, options.size))
                heaviest = &t;
        OffscreenRenderer gl;
        if (!gl.initialize(error) || !gl.setModel(heaviest->model, error)) return std::nullopt;
        gl.setRig(heaviest->rig);
        if (!gl.renderFrame(heaviest->camera, e.probeSize, settings, error)) return std::nullopt; // compiles
        QElapsedTimer clock;
        clock.start();
        if (!gl.renderFrame(heaviest->camera, e.probeSize, settings, error)) return std::nullopt;
        perWork[types] = clock.nsecsElapsed() * 1e-9 / std::max(1.0, benchFrameWork(*heaviest, e.probeSize));
        const double frame = perWork[types] * benchFrameWork(*heaviest, options.size);
        if (frame > e.frameSeconds) e.frameSeconds = frame, e.scene = heaviest->name;
    }
    for (const BenchScene& s : scenes) {
        e.frames += runs * perRun;
        e.framesSeconds += runs * perRun * perWork[typesOf(s)] * benchFrameWork(s, options.size);
        const double reference = benchReferenceWork(s, options.size);
        if (!options.errors) continue;
        if (reference > options.maxReferenceWork)
            ++e.referencesSkipped;
        else
            e.referenceWork += reference;
    }
    return e;
}

QString describeBenchEstimate(const BenchEstimate& e, const BenchOptions& options) {
    QString text =
        QStringLiteral("estimated %1 for %2 frames: one frame of %3 at %4x%5 takes about %6 (probed at "
                       "%7x%8; a frame shades every pixel with every light)")
            .arg(duration(e.framesSeconds))
            .arg(e.frames)
            .arg(e.scene)
            .arg(options.size.width())
            .arg(options.size.height())
            .arg(duration(e.frameSeconds))
            .arg(e.probeSize.width())
            .arg(e.probeSize.height());
    if (e.referenceWork > 0.0)
        text += QStringLiteral(", plus the references (%1 light·pixels in double)")
                    .arg(e.referenceWork, 0, 'g', 2);
    if (e.referencesSkipped > 0)
        text += QStringLiteral("; %1 scene(s) get no reference (over %2 light·pixels; --full-reference)")
                    .arg(e.referencesSkipped)
                    .arg(options.maxReferenceWork, 0, 'g', 2);
    return text +
           QStringLiteral(". --size, --frames, --warmup, --quality, --no-uber and --no-errors bound it.");
}

} // namespace lr
