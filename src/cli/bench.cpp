// `lightrig bench [MODEL...] [--rig RIG] [--camera-index N | --view NAME] [--lights N,...] [--size WxH]
//  [--frames N] [--quality LIST] [--json OUT.json] [--chart OUT.png]`: speed against accuracy per scene and
// quality tier (src/render/qualitybench.h), printed as a table, optionally written as JSON and a chart.
// Scene options are those of `lightrig render` (sceneoptions.h). Without MODEL: the standard suite, the
// bundled Suzanne lit by 1, 8, 64 and 256 procedural lights of each type (area lights: 1, 4 and 16;
// core/proceduralrig.h).
// Exit status: 0 measured; 1 a model, rig or output failed, or no OpenGL; 2 usage error.
#include "benchtraced.h"
#include "cli.h"
#include "outputfiles.h"
#include "sceneoptions.h"

#include "core/proceduralrig.h"
#include "render/benchestimate.h"
#include "render/benchreport.h"
#include "render/benchscaling.h"
#include "render/groupbench.h"
#include "render/qualitybench.h"
#include "render/tracebench.h"

#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonDocument>
#include <QTextStream>
#include <cmath>
#include <limits>

namespace lr::cli {

namespace {

const char* kUsage =
    "lightrig bench [MODEL...] [--rig RIG] [--camera-index N | --view NAME] [--lights N,...] "
    "[--light-type T,...] [--size WxH] [--shading classic|pbr] [--ground off|visible|catcher] "
    "[--shadows on|off] [--frames N] [--msaa N] [--interactive] [--orbit DEG] [--drag] [--scale S] "
    "[--quality LIST[,path] [--path-samples N] [--converged-samples N] [--bounces B] [--threads T]] "
    "[--approximations LIST] [--json OUT.json] [--chart OUT.png] [--scaling-chart OUT.png] [--groups]";

const char* kBundledModel = ":/resources/models/suzanne/Suzanne.gltf";

// The most procedural lights a bench scene may have: the renderer shades a fragment's lights in a shader
// loop, and Mesa's llvmpipe ends a shader's loops after 65,535 iterations (LP_MAX_TGSI_LOOP_ITERATIONS),
// so at 100,000 lights those past ~65,536 were silently dropped (73% of the pixels off) while the report
// said all were uploaded.
constexpr int kMaxBenchLights = 65535;

// "1,8,64" -> {1, 8, 64}; each in 0..kMaxBenchLights.
std::optional<std::vector<int>> parseCounts(const QString& text) {
    std::vector<int> out;
    for (const QString& part : text.split(QLatin1Char(','))) {
        bool ok = false;
        const int n = part.trimmed().toInt(&ok);
        if (!ok || n < 0 || n > kMaxBenchLights) return std::nullopt;
        out.push_back(n);
    }
    return out;
}

template <typename E> std::optional<std::vector<E>> parseNames(const QString& text) {
    std::vector<E> out;
    for (const QString& part : text.split(QLatin1Char(','))) {
        const auto v = fromString<E>(part.trimmed());
        if (!v) return std::nullopt;
        if (std::find(out.begin(), out.end(), *v) == out.end()) out.push_back(*v);
    }
    return out;
}

} // namespace

int runBench(const QStringList& args) {
    QTextStream err(stderr), out(stdout);
    const QString name = QStringLiteral("lightrig bench");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Measures speed against accuracy: per scene and quality tier the median/min/max ms per frame, the "
        "first "
        "frame, shader variants, and the error of the 8-bit output against a double-precision reference.\n"
        "Without MODEL: the standard suite (the bundled Suzanne with 1, 8, 64 and 256 procedural lights of "
        "each "
        "type). With lights that cast shadows, the reference traces their visibility and two more columns "
        "give each tier's shadow error: the share of pixels off the traced shadow outside the penumbra band "
        "(shadow off) and their mean error (shadow err; docs/quality.md).\n"
        "With path in --quality (e.g. exact,balanced,fast,path): a converged path-traced image per scene, "
        "the path tracer's seconds per sample and PSNR after 1, 2, 4, 8, ... samples, and two more columns "
        "with each tier's error against the traced image (path PSNR, path err; docs/path-tracing.md).\n"
        "Needs OpenGL 3.3: run it with a display, e.g. under xvfb-run -a.\n"
        "Exit status: 0 measured, 1 bad model, rig or output path, 2 usage error."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Show this help."));
    const QCommandLineOption lights(
        QStringLiteral("lights"),
        QStringLiteral("Replace the rig by N procedural lights on a ring (constant total "
                       "intensity), one scene per N. Default for the suite: 1,8,64,256 (area lights 1,4,16: "
                       "their reference integrates each by Monte Carlo)."),
        QStringLiteral("N,..."));
    const QCommandLineOption lightType(
        QStringLiteral("light-type"),
        QStringLiteral("Types of the procedural lights: %1 (default: point for MODEL, "
                       "all four for the suite).")
            .arg(allowedNames<LightType>()),
        QStringLiteral("T,..."));
    const QCommandLineOption lightRange(
        QStringLiteral("light-range"),
        QStringLiteral("Range of procedural point and spot lights in model bounding "
                       "radii (default: none)."),
        QStringLiteral("R"));
    const QCommandLineOption frames(
        QStringLiteral("frames"), QStringLiteral("Timed frames per run (default 60)."), QStringLiteral("N"));
    const QCommandLineOption warmup(QStringLiteral("warmup"),
                                    QStringLiteral("Untimed frames after the first one (default 5)."),
                                    QStringLiteral("N"));
    const QCommandLineOption json(QStringLiteral("json"), QStringLiteral("Write the results as JSON."),
                                  QStringLiteral("OUT.json"));
    const QCommandLineOption chart(QStringLiteral("chart"),
                                   QStringLiteral("Write a PNG chart of time against error."),
                                   QStringLiteral("OUT.png"));
    const QCommandLineOption scalingChart(
        QStringLiteral("scaling-chart"),
        QStringLiteral("Write a PNG chart of ms/frame against the number of lights (or of triangles, when "
                       "the scenes differ only in that), one line per tier."),
        QStringLiteral("OUT.png"));
    const QCommandLineOption noErrors(
        QStringLiteral("no-errors"),
        QStringLiteral("Skip the double-precision reference and the error figures."));
    const QCommandLineOption fullReference(
        QStringLiteral("full-reference"),
        QStringLiteral("Compute the reference however long it takes (default: a scene over 1e10 "
                       "light·pixels, area lights weighted, gets no reference and no error figures)."));
    const QCommandLineOption noUber(QStringLiteral("no-uber"),
                                    QStringLiteral("Skip the über-shader comparison."));
    const QCommandLineOption msaa(
        QStringLiteral("msaa"),
        QStringLiteral("MSAA samples for every tier's timed frames, 0..16 (default: 4 for exact and "
                       "balanced, none for fast; 0 matches peers that render without antialiasing)."),
        QStringLiteral("N"));
    const QCommandLineOption interactive(
        QStringLiteral("interactive"),
        QStringLiteral("Time what the editor's viewport draws while you navigate: dense models (300k+ "
                       "triangles) as their simplified interaction proxy."));
    const QCommandLineOption orbit(
        QStringLiteral("orbit"),
        QStringLiteral("Degrees the camera orbits the model between timed frames, -360..360 (default 0: a "
                       "still camera, as while a light is dragged; then the G-buffer and the background "
                       "are kept between frames, while orbiting they are drawn every frame)."),
        QStringLiteral("DEG"));
    const QCommandLineOption drag(
        QStringLiteral("drag"),
        QStringLiteral("Move the rig's first light a little between timed frames, as while it is dragged: "
                       "its shadow map (if it casts) is rendered every frame, the others are kept."));
    const QCommandLineOption scale(
        QStringLiteral("scale"),
        QStringLiteral(
            "Draw every raster frame at this fraction of --size, %1..1, and stretch it to the size "
            "(default 1): the editor's frames while the view moves. The errors are of the "
            "stretched image.")
            .arg(kMinRenderScale),
        QStringLiteral("S"));
    const QCommandLineOption approximations(
        QStringLiteral("approximations"),
        QStringLiteral("The balanced and fast tiers' approximations to compile in, for measuring each "
                       "(docs/quality.md): a comma-separated list of b1, b2, b3, b4, f2, b5, b6 (b5, b6: "
                       "physically based rigs only), or none (default b1,b2,b4, what the tiers ship with)."),
        QStringLiteral("LIST"));
    const QCommandLineOption groups(
        QStringLiteral("groups"),
        QStringLiteral(
            "Measure what per-light-group output costs instead (docs/light-mixing.md): per scene and "
            "raster tier the beauty alone against the beauty split into one image per group, "
            "median ms of --frames (default 3) after --warmup (default 1) frames, and the layers' "
            "memory; and the double reference without and with the split (unless --no-errors)."));
    const SceneOptionSet scene;
    const PathBenchOptionSet pathSet;
    parser.addOption(help);
    scene.addTo(parser);
    pathSet.addTo(parser);
    parser.addOptions({lights, lightType, lightRange, frames, warmup, msaa, interactive, orbit, drag, scale,
                       json, chart, scalingChart, noErrors, fullReference, noUber, approximations, groups});
    parser.addPositionalArgument(QStringLiteral("MODEL"),
                                 QStringLiteral("Model files (default: the standard suite)."),
                                 QStringLiteral("[MODEL...]"));

    const CommandUsage usage{name, kUsage, out, err};
    if (const std::optional<int> done = usage.parse(parser, args, help)) return *done;
    QString message;
    const std::optional<SceneOptions> sceneOptions = scene.read(parser, &message, true, false, true);
    if (!sceneOptions) return usage(message);
    const std::optional<PathBenchOptions> pathOptions =
        pathSet.read(parser, sceneOptions->pathTraced, &message);
    if (!pathOptions) return usage(message);
    BenchOptions options;
    options.size = sceneOptions->size;
    if (parser.isSet(scene.quality)) options.tiers = sceneOptions->qualities; // default: every tier
    options.exposureEV = sceneOptions->exposureEV;
    options.toneMap = sceneOptions->toneMap;
    // The direct-light reference is what the raster tiers are compared with: the path tier alone needs none.
    options.errors = !parser.isSet(noErrors) && !options.tiers.empty();
    if (parser.isSet(fullReference)) options.maxReferenceWork = std::numeric_limits<double>::infinity();
    options.uberShader = !parser.isSet(noUber) && !options.tiers.empty();
    options.keepImages = sceneOptions->pathTraced; // the path tier compares each tier's image
    options.interactive = parser.isSet(interactive);
    options.dragLight = parser.isSet(drag);
    if (parser.isSet(approximations) &&
        !render::approx::parseApproximations(parser.value(approximations), &options.approximations, &message))
        return usage(QStringLiteral("--approximations: ") + message);
    auto readInt = [&](const QCommandLineOption& o, int lo, int hi, int* value) {
        if (!parser.isSet(o)) return true;
        bool ok = false;
        *value = parser.value(o).toInt(&ok);
        return ok && *value >= lo && *value <= hi;
    };
    if (!readInt(frames, 1, 100000, &options.frames))
        return usage(QStringLiteral("--frames must be 1..100000"));
    if (!readInt(warmup, 0, 100000, &options.warmupFrames))
        return usage(QStringLiteral("--warmup must be 0..100000"));
    if (!readInt(msaa, 0, 16, &options.msaaSamples)) return usage(QStringLiteral("--msaa must be 0..16"));
    if (parser.isSet(orbit)) {
        bool ok = false;
        options.orbitDegrees = parser.value(orbit).toDouble(&ok);
        if (!ok || !(std::abs(options.orbitDegrees) <= 360.0))
            return usage(
                QStringLiteral("--orbit must be degrees in -360..360, got '%1'").arg(parser.value(orbit)));
    }
    if (parser.isSet(scale)) {
        bool ok = false;
        options.renderScale = parser.value(scale).toDouble(&ok);
        if (!ok || !(options.renderScale >= kMinRenderScale && options.renderScale <= 1.0))
            return usage(QStringLiteral("--scale must be a fraction in %1..1, got '%2'")
                             .arg(kMinRenderScale)
                             .arg(parser.value(scale)));
    }
    const QStringList models = parser.positionalArguments();
    std::vector<int> counts;
    if (parser.isSet(lights)) {
        const auto c = parseCounts(parser.value(lights));
        if (!c)
            return usage(QStringLiteral("--lights must be a list of counts 0..%1 like 1,8,64 (the renderer "
                                        "shades at most %1 lights), got '%2'")
                             .arg(kMaxBenchLights)
                             .arg(parser.value(lights)));
        counts = *c;
        if (parser.isSet(scene.rig))
            return usage(QStringLiteral("--lights replaces the rig: it excludes --rig"));
    }
    std::vector<LightType> types;
    if (parser.isSet(lightType)) {
        const auto t = parseNames<LightType>(parser.value(lightType));
        if (!t)
            return usage(QStringLiteral("--light-type must be a list of %1, got '%2'")
                             .arg(allowedNames<LightType>(), parser.value(lightType)));
        types = *t;
    }
    double range = -1.0;
    if (parser.isSet(lightRange)) {
        bool ok = false;
        range = parser.value(lightRange).toDouble(&ok);
        if (!ok || !(range > 0.0) || range > 1e6)
            return usage(QStringLiteral("--light-range must be a number of radii in (0, 1e6]"));
    }
    const bool suite = models.isEmpty();
    const bool procedural = !counts.empty() || !types.empty() || (suite && !parser.isSet(scene.rig));
    if (procedural && counts.empty()) counts = suite ? std::vector<int>{1, 8, 64, 256} : std::vector<int>{8};
    if (procedural && types.empty()) {
        constexpr auto all = allLightTypes();
        types =
            suite ? std::vector<LightType>(all.begin(), all.end()) : std::vector<LightType>{LightType::Point};
    }

    auto failed = [&](const QString& reason) {
        err << name << ": " << QString(reason).replace(QLatin1Char('\n'), QLatin1String(" | ")) << '\n';
        return int(Failed);
    };
    std::vector<NamedFile> inputs, outputs;
    for (const QString& m : models)
        inputs.push_back({m, QStringLiteral("the model")});
    for (const QString& rig : parser.values(scene.rig))
        inputs.push_back({rig, QStringLiteral("the rig")});
    inputs.push_back({environmentFileOf(sceneOptions->environment), QStringLiteral("the environment")});
    for (const auto& [option, what] :
         {std::pair{&json, "the --json file"}, std::pair{&chart, "the --chart image"},
          std::pair{&scalingChart, "the --scaling-chart image"}})
        if (parser.isSet(*option)) outputs.push_back({parser.value(*option), QLatin1String(what)});
    if (!checkDistinctFiles(inputs, outputs, &message)) return failed(message);
    if (parser.isSet(json) && !checkOutputPath(parser.value(json), &message)) return failed(message);
    if (parser.isSet(chart) && !checkOutputPath(parser.value(chart), &message)) return failed(message);
    if (parser.isSet(scalingChart) && !checkOutputPath(parser.value(scalingChart), &message))
        return failed(message);
    if (!options.tiers.empty() && !displayAvailable()) // the path tier alone draws nothing with OpenGL
        return failed(QStringLiteral("lightrig bench needs an X display; run it under xvfb-run -a"));

    // Scenes: each model once (its rig), or once per procedural light count and type.
    std::vector<BenchScene> scenes;
    const QStringList paths = suite ? QStringList{QString::fromLatin1(kBundledModel)} : models;
    for (const QString& path : paths) {
        QElapsedTimer clock;
        clock.start();
        LoadedScene loaded;
        // The environment loads after the first run's upload, beside its first frame (as `render`).
        if (!loadScene(path, *sceneOptions, &loaded, &message, EnvironmentLoading::AfterUpload))
            return failed(message);
        const double loadMs = clock.nsecsElapsed() * 1e-6;
        const QString base = QFileInfo(path).completeBaseName();
        if (!procedural) {
            scenes.push_back({base, loaded.model, loadMs, loaded.rig, loaded.camera});
            scenes.back().environment = loaded.environment;
            scenes.back().environmentLoad = loaded.environmentLoad;
            continue;
        }
        for (LightType type : types) {
            // The suite's area lights (rect, disk): 1, 4 and 16, as the issue's performance report; the
            // reference integrates each one at every pixel, which 256 of them would take an hour for.
            const bool areaSuite = suite && !parser.isSet(lights) && traitsOf(type).isArea;
            for (int n : areaSuite ? std::vector<int>{1, 4, 16} : counts) {
                ProceduralRigOptions p;
                p.type = type;
                p.count = n;
                p.range = range;
                // The procedural lights shaded as the model's default rig would be (or as --shading says),
                // over its ground (or --ground's) in its environment (or --environment's), casting when
                // --shadows on says so.
                Rig rig = proceduralRig(p);
                rig.shading.model = loaded.rig.shading.model;
                rig.ground = loaded.rig.ground;
                rig.environment = loaded.rig.environment;
                if (sceneOptions->shadows && !applyShadowsOption(rig, *sceneOptions->shadows, &message))
                    return failed(message);
                scenes.push_back({QStringLiteral("%1 · %2").arg(base, proceduralRigName(p)), loaded.model,
                                  loadMs, std::move(rig), loaded.camera});
                scenes.back().environment = loaded.environment;
                scenes.back().environmentLoad = loaded.environmentLoad;
            }
        }
    }

    if (parser.isSet(groups)) {
        if (sceneOptions->pathTraced || parser.isSet(chart) || parser.isSet(scalingChart) ||
            parser.isSet(json))
            return usage(QStringLiteral("--groups measures the raster tiers and the reference alone: it "
                                        "excludes the path tier, --json and the charts"));
        GroupBenchOptions g;
        g.size = options.size;
        g.tiers = options.tiers;
        g.msaaSamples = options.msaaSamples;
        g.approximations = options.approximations;
        g.reference = options.errors;
        g.frames = parser.isSet(frames) ? options.frames : g.frames;
        g.warmupFrames = parser.isSet(warmup) ? options.warmupFrames : g.warmupFrames;
        std::vector<GroupBenchResult> results;
        QString gl;
        if (!runGroupBench(scenes, g, &results, &gl, &message)) return failed(message);
        out << QStringLiteral(
                   "lightrig bench --groups: %1, %2x%3, %4 timed frames after %5, load average %6\n")
                   .arg(gl)
                   .arg(g.size.width())
                   .arg(g.size.height())
                   .arg(g.frames)
                   .arg(g.warmupFrames)
                   .arg(loadAverageNow());
        out << groupBenchTable(results);
        return Ok;
    }

    BenchReport report;
    QString last;
    int step = 0;
    const int runs = int(scenes.size()) * int(options.tiers.size() + (options.uberShader ? 1 : 0));
    const BenchProgress progress = [&](double, const QString& what) {
        const QString run = what.section(QStringLiteral(": error"), 0, 0);
        if (run != last && !run.endsWith(QLatin1String("reference")) && run != QLatin1String("done")) {
            err << QStringLiteral("[%1/%2] %3\n").arg(++step).arg(runs).arg(run);
            err.flush();
        }
        last = run;
        return true;
    };
    // Issue 41: 65,535 lights ran for hours with no word of it; beyond the standard suite's scale a probe
    // frame says how long before the first run starts.
    if (benchIsHeavy(scenes, options)) {
        const std::optional<BenchEstimate> estimate = estimateBench(scenes, options, &message);
        if (!estimate) return failed(message);
        err << name << ": " << describeBenchEstimate(*estimate, options) << '\n';
        err.flush();
    }
    const BenchStatus status = runQualityBench(scenes, options, &report, &message, progress);
    if (status != BenchStatus::Ok) return failed(message);
    if (sceneOptions->pathTraced) {
        err << QStringLiteral("lightrig bench: path tier: %1 converged images of %2 samples, then 1 … %3\n")
                   .arg(scenes.size())
                   .arg(pathOptions->convergedSamples)
                   .arg(pathOptions->samples);
        err.flush();
        runPathBench(scenes, *pathOptions, &report);
    }
    // Issue 15: which environment each model's scenes used, and what loading it cost.
    const EnvironmentLoad* said = nullptr;
    for (const BenchScene& s : scenes) {
        const std::shared_ptr<const LoadedEnvironment> e =
            loadedEnvironment(s.environmentLoad, s.environment);
        if (!e || (s.environmentLoad && s.environmentLoad.get() == said)) continue;
        said = s.environmentLoad.get();
        out << QStringLiteral("lightrig bench: %1 (%2), %3\n")
                   .arg(environmentName(s.rig.environment), e->source, environmentTimes(*e));
    }

    out << QStringLiteral(
               "lightrig bench: %1, %2x%3, %4 timed frames after %5 warm-up frames, load average %6\n")
               .arg(report.glDescription)
               .arg(options.size.width())
               .arg(options.size.height())
               .arg(options.frames)
               .arg(options.warmupFrames)
               .arg(report.loadAverage.isEmpty() ? QStringLiteral("unknown") : report.loadAverage);
    out << benchTable(report);
    for (const QString& note : report.notes)
        out << QStringLiteral("note: ") << note << '\n';
    if (parser.isSet(json) &&
        !writeOutputFile(parser.value(json), QJsonDocument(benchJson(report)).toJson(QJsonDocument::Indented),
                         &message))
        return failed(message);
    if (parser.isSet(chart) && !writeOutputImage(benchChart(report), parser.value(chart), "png", &message))
        return failed(message);
    if (parser.isSet(scalingChart) &&
        !writeOutputImage(benchScalingChart(report), parser.value(scalingChart), "png", &message))
        return failed(message);
    return Ok;
}

} // namespace lr::cli
