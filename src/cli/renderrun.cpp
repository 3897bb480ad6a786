#include "renderrun.h"

#include "catalog.h"
#include "cli.h"
#include "coverage.h"
#include "outputfiles.h"

#include "renderexr.h"

#include "core/colour.h"
#include "core/statistics.h"
#include "render/offscreen.h"
#include "render/rasterlayers.h"
#include "scene/displayimage.h"
#include "scene/linkparts.h"
#include "scene/shapingreport.h"

#include <QElapsedTimer>
#include <QTextStream>
#include <algorithm>
#include <cmath>
#include <ctime>
#include <map>
#include <memory>
#include <optional>
#include <utility>

namespace lr::cli {

namespace {

// The end of the items [begin, end) before `limit` that share the value of `key` with items[begin].
template <typename Key>
size_t runEnd(const std::vector<RenderItem>& items, size_t begin, size_t limit, Key key) {
    size_t end = begin + 1;
    while (end < limit && key(items[end]) == key(items[begin]))
        ++end;
    return end;
}

// The raster's radiance has no background (the tone-map pass composites the background colour over its
// alpha, after tone mapping): an opaque .exr gets it as radiance, uncovered shares in the beauty and in the
// "background" group, as the path tracer's background is (the colour's linear value; exposed and tone mapped
// with the rest when displayed, where the raster shows it as it is: equal at exposure 0 with clamp).
void composeBackground(RenderLayers* layers, const QColor& background) {
    const QColor bg = background.toRgb();
    const glm::vec3 c = colour::srgbToLinear(glm::vec3(bg.redF(), bg.greenF(), bg.blueF()));
    FloatImage* group = nullptr;
    for (size_t g = 0; g < layers->groups.size() && g < layers->groupImages.size(); ++g)
        if (layers->groups[g].kind == LightGroupKind::Background) group = &layers->groupImages[g];
    for (size_t i = 0; i < layers->beauty.pixels.size(); ++i) {
        glm::vec4& p = layers->beauty.pixels[i];
        const float uncovered = 1.0f - std::clamp(p.w, 0.0f, 1.0f);
        p += glm::vec4(c * uncovered, 0.0f);
        p.w = 1.0f;
        if (group && i < group->pixels.size()) group->pixels[i] += glm::vec4(c * uncovered, 0.0f);
    }
    for (FloatImage& g : layers->groupImages)
        for (glm::vec4& p : g.pixels)
            p.w = 1.0f;
}

class Runner {
  public:
    Runner(const RenderRequest& request, const std::vector<RenderItem>& items) : r(request), items(items) {
        if (r.options.pathTraced) traced.emplace(r.traced);
    }
    int run();

  private:
    void warn(const QString& warning) { err << name << ": warning: " << warning << '\n'; }
    // Reports items [begin, end) that are not done yet as failed for `reason` (said once on stderr).
    void fail(size_t begin, size_t end, const QString& reason);
    void done(size_t i, const QString& error, const QJsonObject& extra = {});
    void renderModel(size_t begin, size_t end);
    void renderView(const QString& modelPath, LoadedScene& scene, size_t begin, size_t end, double loadMs);
    void reportLinks(const LoadedScene& scene);
    bool ensureGl(const LoadedScene& scene, QString* error);
    void timeFrames(const ViewCamera& camera, const RenderSettings& settings);
    // The raster's scene-linear layers for an .exr: the beauty, or with --aovs every layer.
    std::optional<RenderLayers> renderRasterExr(const ViewCamera& camera, const RenderSettings& settings,
                                                QString* error);
    std::optional<RenderLayers> renderRasterRadiance(const ViewCamera& camera, const RenderSettings& settings,
                                                     QString* error);

    const RenderRequest& r;
    const std::vector<RenderItem>& items;
    const QString name = QStringLiteral("lightrig render");
    QTextStream err{stderr}, out{stdout};
    std::vector<bool> finished;
    std::vector<QByteArray> summary;
    QElapsedTimer itemClock; // since the last item was reported: an item's seconds include its loading
    bool anyFailed = false;
    std::unique_ptr<OffscreenRenderer> gl;
    std::shared_ptr<const Model> uploaded; // the model gl draws
    QString glError;                       // why gl could not be created
    bool warnedJpeg = false;
    std::optional<TracedImages> traced; // --quality path
    // Each rig's environment as last loaded (by rig index; -1 the default rig): offered to the next model's
    // loadSceneRig, which keeps it when it serves, so a catalog decodes and prefilters it once.
    std::map<int, std::shared_ptr<const LoadedEnvironment>> environments;
};

void Runner::fail(size_t begin, size_t end, const QString& reason) {
    bool said = false;
    for (size_t i = begin; i < end; ++i) {
        if (finished[i]) continue;
        if (!said)
            err << name << ": " << QString(reason).replace(QLatin1Char('\n'), QLatin1String(" | ")) << '\n';
        said = true;
        done(i, reason);
    }
}

void Runner::done(size_t i, const QString& error, const QJsonObject& extra) {
    finished[i] = true;
    anyFailed = anyFailed || !error.isEmpty();
    const QByteArray line =
        summaryLine(r, items[i], error.isEmpty(), itemClock.nsecsElapsed() * 1e-9, error, extra) + '\n';
    itemClock.restart();
    if (r.summary == QLatin1String("-")) {
        out << line;
        out.flush();
    } else if (!r.summary.isEmpty()) {
        summary.push_back(line);
    }
}

int Runner::run() {
    QString message;
    itemClock.start();
    finished.assign(items.size(), false);
    if (!r.summary.isEmpty() && r.summary != QLatin1String("-") && !checkOutputPath(r.summary, &message)) {
        err << name << ": " << message << '\n';
        return Failed;
    }
    for (size_t i = 0; i < items.size(); ++i)
        if (!checkOutputPath(items[i].file, &message)) fail(i, i + 1, message);
    for (size_t begin = 0; begin < items.size();) {
        const size_t end =
            runEnd(items, begin, items.size(), [](const RenderItem& item) { return item.model; });
        if (std::any_of(finished.begin() + long(begin), finished.begin() + long(end),
                        [](bool f) { return !f; }))
            renderModel(begin, end);
        begin = end;
    }
    if (!r.summary.isEmpty() && r.summary != QLatin1String("-") &&
        !writeOutputFile(r.summary, summary.empty() ? QByteArray() : [&] {
            QByteArray all;
            for (const QByteArray& line : summary)
                all += line;
            return all;
        }(), &message)) {
        err << name << ": " << message << '\n';
        return Failed;
    }
    return anyFailed ? Failed : Ok;
}

void Runner::renderModel(size_t begin, size_t end) {
    QElapsedTimer clock;
    clock.start();
    const QString modelPath = r.models.value(items[begin].model);
    LoadedScene base;
    QString message;
    if (!loadSceneModel(modelPath, &base, &message)) return fail(begin, end, message);
    // Its textures are known now: an image that is one of them is not written (issue 41).
    const std::vector<NamedFile> textures = textureFilesOf(*base.model);
    for (size_t i = begin; i < end && !textures.empty(); ++i)
        if (!finished[i] &&
            !checkDistinctFiles(textures, {{items[i].file, QStringLiteral("the image")}}, &message))
            fail(i, i + 1, message);
    bool warned = false;
    for (size_t rigBegin = begin; rigBegin < end;) {
        const size_t rigEnd = runEnd(items, rigBegin, end, [](const RenderItem& item) { return item.rig; });
        SceneOptions options = r.options;
        if (items[rigBegin].rig >= 0) options.rigPath = r.rigs.value(items[rigBegin].rig);
        LoadedScene withRig = base;
        std::shared_ptr<const LoadedEnvironment>& environment = environments[items[rigBegin].rig];
        withRig.environment = environment;
        // The environment loads after the model's upload, beside the first frame (showScene); every
        // view of the rig shares that one load. The path tracer needs it before anything is traced.
        if (!loadSceneRig(modelPath, options, &withRig, &message,
                          traced ? EnvironmentLoading::Now : EnvironmentLoading::AfterUpload)) {
            fail(rigBegin, rigEnd, message);
        } else {
            for (size_t viewBegin = rigBegin; viewBegin < rigEnd;) {
                const size_t viewEnd =
                    runEnd(items, viewBegin, rigEnd, [](const RenderItem& item) { return item.view; });
                if (const int v = items[viewBegin].view; v >= 0) {
                    options.cameraIndex = viewCameraIndex(r.options.views.value(v));
                    options.view = options.cameraIndex ? QString() : r.options.views.value(v);
                }
                LoadedScene scene = withRig;
                if (!chooseSceneCamera(modelPath, options, &scene, &message)) {
                    fail(viewBegin, viewEnd, message);
                } else {
                    if (!warned)
                        for (const QString& w : scene.model->warnings)
                            warn(w);
                    warned = true;
                    if (viewBegin == rigBegin) reportLinks(scene);
                    renderView(modelPath, scene, viewBegin, viewEnd, clock.nsecsElapsed() * 1e-6);
                }
                clock.restart();
                viewBegin = viewEnd;
            }
            environment = loadedEnvironment(withRig.environmentLoad, withRig.environment);
        }
        rigBegin = rigEnd;
    }
}

// Light linking (issue 38): what each name of the rig's links matches in this model, once per model and
// rig; names that match nothing are also warnings (kept in the rig, which may be meant for another model).
// Then the shaping files that did not load (issue 39).
void Runner::reportLinks(const LoadedScene& scene) {
    const std::vector<PartNames> parts = linkParts(*scene.model, scene.rig);
    for (const QString& line : describeLinkMatches(scene.rig.lights, parts))
        err << name << ": linking: " << line << '\n';
    for (const QString& w : resolveLinks(scene.rig.lights, parts).warnings)
        warn(w);
    for (const QString& w : shapingWarnings(scene.rig)) // issue 39
        warn(w);
}

bool Runner::ensureGl(const LoadedScene& scene, QString* error) {
    if (!gl) {
        auto offscreen = std::make_unique<OffscreenRenderer>();
        if (!glError.isEmpty() || !offscreen->initialize(&glError)) { // no OpenGL: once is enough to try
            *error = glError;
            return false;
        }
        gl = std::move(offscreen);
    }
    if (uploaded != scene.model) {
        uploaded.reset();
        if (!gl->setModel(scene.model, error)) return false;
        uploaded = scene.model;
    }
    showScene(gl->renderer(), scene);
    return true;
}

void Runner::renderView(const QString& modelPath, LoadedScene& scene, size_t begin, size_t end,
                        double loadMs) {
    QString message;
    RenderSettings settings;
    settings.exposureEV = r.options.exposureEV;
    settings.toneMap = r.options.toneMap;
    settings.quality = r.options.quality;
    settings.transparentBackground = r.transparent;
    settings.msaaSamples = r.msaa;
    const auto warning = [this](const QString& w) { warn(w); };
    if (!traced) {
        if (!ensureGl(scene, &message)) return fail(begin, end, message);
        const bool viewChosenHere =
            !r.options.cameraIndex && r.options.view.isEmpty() && r.options.views.isEmpty();
        if (!showsTheModel(*gl, modelPath, r.options.size, settings, viewChosenHere, &scene, warning,
                           &message))
            return fail(begin, end, message);
    }
    const glm::dvec3 center = scene.model->bounds.center();
    for (size_t i = begin; i < end; ++i) {
        const RenderItem& item = items[i];
        if (finished[i]) continue;
        const double degrees = turntableDegrees(item.frame, r.turntable);
        const ViewCamera camera =
            r.rotate == TurntableRotation::Camera ? orbitCamera(scene.camera, center, degrees) : scene.camera;
        const bool turnLights = r.rotate == TurntableRotation::Lights && r.turntable > 0;
        const Rig rig = turnLights ? rotateRigLights(scene.rig, center, degrees) : scene.rig;
        QElapsedTimer clock;
        clock.start();
        QImage image;
        QString line;      // what the "wrote" line says of the image
        QJsonObject extra; // and the summary line
        std::optional<TracedImages::Result> tracedResult;
        std::optional<RenderLayers> layers; // an .exr's
        if (traced) {
            tracedResult = traced->render(scene, rig, camera, r.options.size, settings, warning, &message);
            const std::optional<TracedImages::Result>& t = tracedResult;
            if (t) {
                image = t->image;
                extra = {
                    {QStringLiteral("samples"), t->samples},
                    {QStringLiteral("noise"), std::isfinite(t->noise) ? QJsonValue(t->noise) : QJsonValue()},
                    {QStringLiteral("stopped_by"), t->stoppedBy}};
                line = QStringLiteral("%1, %2, %3, load %4 s")
                           .arg(t->line, scene.rigSource, scene.cameraSource)
                           .arg(i == begin ? loadMs * 1e-3 : 0.0, 0, 'f', 2);
            }
        } else if (r.format == "exr") {
            if (turnLights) gl->setRig(rig);
            clock.restart();
            layers = renderRasterExr(camera, settings, &message);
            if (layers)
                image = displayImage(layers->beauty, settings.exposureEV, settings.toneMap,
                                     settings.transparentBackground);
            line = QStringLiteral("scene-linear%1, %2 light groups, %3, %4, %5 ms, load %6 ms")
                       .arg(r.aovs ? QStringLiteral(" layers") : QString())
                       .arg(layers ? layers->groups.size() : 0)
                       .arg(scene.rigSource, scene.cameraSource)
                       .arg(clock.nsecsElapsed() * 1e-6, 0, 'f', 1)
                       .arg(i == begin ? loadMs : 0.0, 0, 'f', 1);
        } else {
            if (turnLights) gl->setRig(rig);
            clock.restart();
            image = gl->renderImage(camera, r.options.size, settings, r.supersample, &message);
            const RenderStats& stats = gl->renderer().stats();
            line = QStringLiteral("%1 triangles, %2 of %3 lights (%4), %5, first image %6 ms, load %7 ms")
                       .arg(stats.triangles)
                       .arg(stats.lightsUploaded)
                       .arg(stats.lightsInRig)
                       .arg(scene.rigSource, scene.cameraSource)
                       .arg(clock.nsecsElapsed() * 1e-6, 0, 'f', 1)
                       .arg(i == begin ? loadMs : 0.0, 0, 'f', 1);
        }
        if (image.isNull()) {
            fail(i, i + 1, message);
            continue;
        }
        if (settings.transparentBackground && r.format == "jpeg" && !std::exchange(warnedJpeg, true))
            err << name
                << ": warning: JPEG has no alpha channel; the transparent background is written black\n";
        if (r.format == "exr") {
            if (tracedResult) {
                layers = r.aovs ? std::move(tracedResult->layers) : RenderLayers{};
                layers->beauty = tracedResult->linear;
            }
            const QByteArray bytes = encodeRenderExr(
                *layers, r.aovs, r.half, settings,
                traced ? QStringLiteral("path") : toString(settings.quality),
                tracedResult ? std::optional<int>(tracedResult->samples) : std::nullopt, &message);
            if (bytes.isEmpty() || !writeOutputFile(item.file, bytes, &message)) {
                fail(i, i + 1, message);
                continue;
            }
        } else if (!writeOutputImage(image, item.file, r.format, &message)) {
            fail(i, i + 1, message);
            continue;
        }
        if (r.summary != QLatin1String("-"))
            out << QStringLiteral("wrote %1 (%2x%3): %4\n")
                       .arg(item.file)
                       .arg(image.width())
                       .arg(image.height())
                       .arg(line);
        done(i, QString(), extra);
        if (r.timedFrames > 0 && !traced) timeFrames(camera, settings);
    }
}

std::optional<RenderLayers> Runner::renderRasterExr(const ViewCamera& camera, const RenderSettings& settings,
                                                    QString* error) {
    std::optional<RenderLayers> layers = renderRasterRadiance(camera, settings, error);
    if (layers && !settings.transparentBackground) composeBackground(&*layers, settings.background);
    return layers;
}

std::optional<RenderLayers> Runner::renderRasterRadiance(const ViewCamera& camera,
                                                         const RenderSettings& settings, QString* error) {
    if (r.aovs) return renderRasterLayers(*gl, camera, r.options.size, settings, error);
    RenderLayers layers;
    if (r.options.size.width() > gl->maxTileSize() || r.options.size.height() > gl->maxTileSize()) {
        *error = QStringLiteral(
                     "an .exr of the raster qualities is at most %1 pixels a side (one tile), got %2x%3")
                     .arg(gl->maxTileSize())
                     .arg(r.options.size.width())
                     .arg(r.options.size.height());
        return std::nullopt;
    }
    if (!gl->renderRadiance(camera, r.options.size, settings, &layers.beauty, error)) return std::nullopt;
    return layers;
}

void Runner::timeFrames(const ViewCamera& camera, const RenderSettings& settings) {
    const QSize size = r.options.size;
    std::vector<double> wall, gpu, cpu;
    QString message;
    for (int i = 0; i < r.timedFrames; ++i) {
        QElapsedTimer clock;
        clock.start();
        const std::clock_t cpu0 = std::clock();
        if (!gl->renderFrame(camera, size, settings, &message)) {
            err << name << ": " << message << '\n';
            anyFailed = true;
            return;
        }
        wall.push_back(clock.nsecsElapsed() * 1e-6);
        cpu.push_back(double(std::clock() - cpu0) * 1000.0 / CLOCKS_PER_SEC);
        if (gl->renderer().stats().lastGpuMs >= 0) gpu.push_back(gl->renderer().stats().lastGpuMs);
    }
    out << QStringLiteral("frames: %1 at %2x%3, msaa %4: median %5 ms, min %6 ms, max %7 ms (glFinish); "
                          "gpu median %8 ms; process CPU median %9 ms (all threads)\n")
               .arg(r.timedFrames)
               .arg(size.width())
               .arg(size.height())
               .arg(settings.msaaSamples)
               .arg(median(wall, 0.0), 0, 'f', 2)
               .arg(*std::min_element(wall.begin(), wall.end()), 0, 'f', 2)
               .arg(*std::max_element(wall.begin(), wall.end()), 0, 'f', 2)
               .arg(median(gpu, 0.0), 0, 'f', 2)
               .arg(median(cpu, 0.0), 0, 'f', 2);
}

} // namespace

int runRenderRequest(const RenderRequest& request, const std::vector<RenderItem>& items) {
    return Runner(request, items).run();
}

} // namespace lr::cli
