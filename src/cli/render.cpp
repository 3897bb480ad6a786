// `lightrig render MODEL... [--rig RIG.json]... -o OUT.png|PATTERN|FOLDER [--size WxH] [--camera-index N |
//  --view NAME[,NAME...]] [--turntable N [--rotate camera|lights]] [--summary FILE|-] [--quality Q]
//  [--supersample N] [--transparent] [--exposure EV] [--tonemap ...] [--shading classic|pbr] [--ground ...]
//  [--shadows on|off] [--msaa N] [--environment ...]`
// renders images with the same Renderer as the viewport (OffscreenRenderer) and writes each atomically: one
// model, rig and view into OUT.png as always, or a catalog (several models, rigs, views: catalog.h names the
// files) and turntables (N frames around the model, render/turntable.h), rendered by renderrun.h.
// Exit status: 0 written; 1 bad model, rig, camera or path, or no OpenGL (one line on stderr each; with
// several items the others still render); 2 usage error (nothing rendered). --msaa N overrides the samples
// (default 4; 0 for --quality fast). Hidden: --frames N times N more frames (glFinish each) and prints the
// median.
#include "catalog.h"
#include "cli.h"
#include "outputfiles.h"
#include "renderestimate.h"
#include "renderrun.h"
#include "sceneoptions.h"
#include "tracedoptions.h"

#include "core/rigjson.h"
#include "render/imagefile.h"

#include <QCommandLineParser>
#include <QFileInfo>
#include <QTextStream>
#include <cmath>
#include <optional>

namespace lr::cli {

namespace {

const char* kUsage =
    "lightrig render MODEL... [--rig RIG.json]... -o OUT.png|PATTERN|FOLDER [--size WxH] [--camera-index N | "
    "--view NAME[,NAME...]] [--turntable N [--rotate camera|lights]] [--summary FILE|-] [--quality Q] "
    "[--supersample N] [--transparent] [--exposure EV] [--tonemap clamp|reinhard|aces|neutral|agx] "
    "[--shading classic|pbr] [--ground off|visible|catcher] [--shadows on|off] [--msaa N] "
    "[--environment FILE|builtin:NAME|studio|none] [--environment-intensity EV] "
    "[--environment-rotation DEGREES] [--environment-background visible|blurred|color] "
    "[--samples N] [--time-limit S] [--noise-threshold T] [--bounces B] [--threads T] [--firefly-clamp X] "
    "[--seed S]";

} // namespace

int runRender(const QStringList& args) {
    QTextStream err(stderr), out(stdout);
    const QString name = QStringLiteral("lightrig render");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Renders MODEL lit by a rig into a PNG or JPEG image, exactly as the editor's viewport shows "
        "it; several models, rigs and views into one image each, and turntables (docs/batch.md).\nExit "
        "status: 0 written, 1 bad model, rig, camera or output path (nothing written for it; the other "
        "images still render), 2 usage error.\nNeeds OpenGL 3.3: run it with a display, e.g. under "
        "xvfb-run -a."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Show this help."));
    const QCommandLineOption output(
        {QStringLiteral("o"), QStringLiteral("output")},
        QStringLiteral("Output image (.png, .jpg or .jpeg); with several models, rigs "
                       "or views a folder or a pattern with {model}, {rig}, {view} "
                       "(folder: {model}_{rig}_{view}.png); a turntable's frame "
                       "number replaces the last run of # (out_####.png)."),
        QStringLiteral("OUT"));
    const QCommandLineOption supersample(QStringLiteral("supersample"),
                                         QStringLiteral("Render N×N samples per pixel, 1..4 (default 1)."),
                                         QStringLiteral("N"));
    const QCommandLineOption aovs(
        QStringLiteral("aovs"),
        QStringLiteral(
            "With -o OUT.exr: one multi-layer EXR with the beauty, one layer per light group, albedo, "
            "normal and depth (docs/light-mixing.md); lightrig mix re-balances it."));
    const QCommandLineOption half(
        QStringLiteral("half"), QStringLiteral("With -o OUT.exr: 16-bit half floats instead of 32-bit (depth "
                                               "stays 32-bit)."));
    const QCommandLineOption transparent(QStringLiteral("transparent"),
                                         QStringLiteral("Transparent background (PNG alpha)."));
    QCommandLineOption frames(QStringLiteral("frames"), QStringLiteral("Time N more frames."),
                              QStringLiteral("N"));
    frames.setFlags(QCommandLineOption::HiddenFromHelp);
    const QCommandLineOption msaa(QStringLiteral("msaa"),
                                  QStringLiteral("Multisample antialiasing samples per pixel, 0..32 (default "
                                                 "4; 0 for --quality fast)."),
                                  QStringLiteral("N"));
    const QCommandLineOption noMemoryCheck(
        QStringLiteral("no-memory-check"),
        QStringLiteral("Render even when --size and --supersample need more memory than the machine has."));
    const QCommandLineOption turntable(
        QStringLiteral("turntable"),
        QStringLiteral("Render N frames around the model, frame k at k·360/N degrees about the up axis."),
        QStringLiteral("N"));
    const QCommandLineOption rotate(QStringLiteral("rotate"),
                                    QStringLiteral("What turns in a turntable: camera (orbits the model's "
                                                   "centre; default) or lights (the rig turns, the camera "
                                                   "stays)."),
                                    QStringLiteral("camera|lights"));
    const QCommandLineOption summary(QStringLiteral("summary"),
                                     QStringLiteral("Write one JSON line per image (file, model, rig, view, "
                                                    "status, seconds, error) to FILE, or to stdout for -."),
                                     QStringLiteral("FILE|-"));
    const TracedOptionSet tracedSet;
    SceneOptionSet scene;
    scene.rig.setDescription(QStringLiteral("Rig file (.json); repeat it for several rigs. Default: the "
                                            "model's own lights when it has some, else the default rig."));
    scene.view.setDescription(scene.view.description() +
                              QStringLiteral(" A comma list (or repeated) renders each; cameraN is camera N "
                                             "of the model file."));
    parser.addOption(help);
    parser.addOption(output);
    scene.addTo(parser);
    parser.addOptions(
        {aovs, half, supersample, transparent, frames, msaa, turntable, rotate, summary, noMemoryCheck});
    tracedSet.addTo(parser);
    parser.addPositionalArgument(QStringLiteral("MODEL"),
                                 QStringLiteral("Model files Assimp reads (glTF, OBJ, FBX, ...)."),
                                 QStringLiteral("MODEL..."));

    const CommandUsage usage{name, kUsage, out, err};
    if (const std::optional<int> done = usage.parse(parser, args, help)) return *done;
    RenderRequest request;
    request.models = parser.positionalArguments();
    if (request.models.isEmpty()) return usage(QStringLiteral("no MODEL given"));
    if (request.models.contains(QString())) return usage(QStringLiteral("MODEL is an empty path"));
    if (!parser.isSet(output) || parser.value(output).isEmpty())
        return usage(QStringLiteral("-o OUT is required"));
    request.output = parser.value(output);
    request.outputIsFolder = request.output.endsWith(QLatin1Char('/')) || QFileInfo(request.output).isDir();
    request.format = request.outputIsFolder ? QByteArray("png") : writableImageFormatOf(request.output);
    request.aovs = parser.isSet(aovs);
    request.half = parser.isSet(half);
    const bool exr = request.outputIsFolder
                         ? request.aovs
                         : request.output.endsWith(QLatin1String(".exr"), Qt::CaseInsensitive);
    if (exr) request.format = "exr";
    if (request.format.isEmpty())
        return usage(
            QStringLiteral("the output must end in .png, .jpg, .jpeg or .exr: %1").arg(request.output));
    if ((request.aovs || request.half) && !exr)
        return usage(
            QStringLiteral("--%1 writes OpenEXR: the output must end in .exr: %2")
                .arg(request.aovs ? QStringLiteral("aovs") : QStringLiteral("half"), request.output));
    QString message;
    const std::optional<SceneOptions> options = scene.read(parser, &message, false, true, true);
    if (!options) return usage(message);
    if (exr && parser.isSet(supersample))
        return usage(
            QStringLiteral("--supersample does not apply to an .exr (its pixels are the render's own)"));
    const std::optional<TracedRenderOptions> traced = tracedSet.read(parser, options->pathTraced, &message);
    if (!traced) return usage(message);
    request.traced = *traced;
    request.traced.layers = request.aovs;
    if (options->pathTraced)
        for (const QCommandLineOption* o :
             std::initializer_list<const QCommandLineOption*>{&supersample, &msaa, &frames})
            if (parser.isSet(*o))
                return usage(QStringLiteral("--%1 does not apply to --quality path (it takes --samples)")
                                 .arg(o->names().constLast()));
    request.options = *options;
    for (const QString& rig : parser.values(scene.rig)) {
        if (rig.isEmpty()) return usage(QStringLiteral("--rig needs a file name"));
        if (!request.rigs.contains(rig)) request.rigs.append(rig);
    }
    int& ss = request.supersample;
    int& frameCount = request.timedFrames;
    int& samples = request.msaa;
    samples = options->quality == Quality::Fast ? 0 : 4;
    request.transparent = parser.isSet(transparent);
    request.summary = parser.value(summary);
    if (parser.isSet(summary) && request.summary.isEmpty())
        return usage(QStringLiteral("--summary needs a file name or -"));
    if (parser.isSet(turntable)) {
        bool ok = false;
        request.turntable = parser.value(turntable).toInt(&ok);
        if (!ok || request.turntable < 1 || request.turntable > 100000)
            return usage(QStringLiteral("--turntable must be a number of frames in 1..100000, got '%1'")
                             .arg(parser.value(turntable)));
    }
    if (parser.isSet(rotate)) {
        const QString v = parser.value(rotate);
        if (v != QLatin1String("camera") && v != QLatin1String("lights"))
            return usage(QStringLiteral("--rotate must be \"camera\" or \"lights\", got '%1'").arg(v));
        if (!parser.isSet(turntable)) return usage(QStringLiteral("--rotate needs --turntable N"));
        request.rotate = v == QLatin1String("lights") ? TurntableRotation::Lights : TurntableRotation::Camera;
    }
    if (parser.isSet(supersample)) {
        bool ok = false;
        ss = parser.value(supersample).toInt(&ok);
        if (!ok || ss < 1 || ss > 4) return usage(QStringLiteral("--supersample must be 1, 2, 3 or 4"));
    }
    if (parser.isSet(frames)) {
        bool ok = false;
        frameCount = parser.value(frames).toInt(&ok);
        if (!ok || frameCount < 0 || frameCount > 100000)
            return usage(QStringLiteral("--frames must be 0..100000"));
    }
    if (parser.isSet(msaa)) {
        bool ok = false;
        samples = parser.value(msaa).toInt(&ok);
        if (!ok || samples < 0 || samples > 32) return usage(QStringLiteral("--msaa must be 0..32"));
    }
    const std::optional<std::vector<RenderItem>> items = planRender(request, &message);
    if (!items) return usage(message);
    // Before anything is written: no image, nor the summary, may be a file this call reads or writes.
    std::vector<NamedFile> inputs, outputs;
    for (const QString& m : request.models)
        inputs.push_back({m, QStringLiteral("the model")});
    for (const QString& rig : request.rigs)
        inputs.push_back({rig, QStringLiteral("the rig")});
    inputs.push_back({environmentFileOf(request.options.environment), QStringLiteral("the environment")});
    for (const RenderItem& item : *items)
        outputs.push_back({item.file, QStringLiteral("the image")});
    if (!request.summary.isEmpty() && request.summary != QLatin1String("-"))
        outputs.push_back({request.summary, QStringLiteral("the --summary file")});
    if (!checkDistinctFiles(inputs, outputs, &message)) {
        err << name << ": " << message << '\n';
        return Failed;
    }
    if (request.options.pathTraced) { // on the CPU: no OpenGL, no display
        // With --aovs, the most light groups any of the rigs splits into (the model's emission counted); a
        // rig not known yet (the default rule: maybe the model's own lights) or not readable (said
        // later): 16.
        int groups = 0;
        if (request.aovs)
            for (const QString& rig : request.rigs.isEmpty() ? QStringList{QString()} : request.rigs) {
                const RigReadResult read = rig.isEmpty() ? RigReadResult{} : readRigFile(rig);
                groups = std::max(groups, read.ok() ? tracedLayerGroups(*read.rig) : 16);
            }
        if (!checkTracedMemory(request.options.size, parser.isSet(noMemoryCheck), &message, groups))
            return usage(message);
        return runRenderRequest(request, *items);
    }
    // Issue 41: said, and refused beyond the machine's memory, before a byte of the image is allocated.
    if (!checkRenderMemory(estimateRender(request.options.size, ss, samples), parser.isSet(noMemoryCheck),
                           err))
        return Usage;

    if (!displayAvailable()) {
        err << name << ": lightrig render needs an X display; run it under xvfb-run -a\n";
        return Failed;
    }
    return runRenderRequest(request, *items);
}

} // namespace lr::cli
