// `lightrig render MODEL [--rig RIG.json] -o OUT.png [--size WxH] [--camera-index N | --view NAME]
//  [--quality Q] [--supersample N] [--transparent] [--exposure EV] [--tonemap clamp|reinhard|aces]
//  [--shading classic|pbr] [--ground off|visible|catcher] [--shadows on|off]`
// renders one image with the same Renderer as the viewport (OffscreenRenderer) and writes it atomically.
// Exit status: 0 written; 1 bad model, rig, camera or path, or no OpenGL (one line on stderr, nothing
// written); 2 usage error. Hidden: --frames N times N more frames (glFinish each) and prints the median,
// --msaa N overrides the samples (default 4; 0 for --quality fast).
#include "cli.h"
#include "outputfiles.h"
#include "sceneoptions.h"

#include "render/camera.h"
#include "render/offscreen.h"

#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTextStream>
#include <algorithm>
#include <ctime>
#include <optional>
#include <vector>

namespace lr::cli {

namespace {

const char* kUsage =
    "lightrig render MODEL [--rig RIG.json] -o OUT.png [--size WxH] [--camera-index N | --view NAME] "
    "[--quality Q] [--supersample N] [--transparent] [--exposure EV] [--tonemap clamp|reinhard|aces] "
    "[--shading classic|pbr] [--ground off|visible|catcher] [--shadows on|off]";

// The image format for the output's suffix, or empty.
QByteArray formatFor(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    if (suffix == QLatin1String("png")) return "png";
    if (suffix == QLatin1String("jpg") || suffix == QLatin1String("jpeg")) return "jpeg";
    return {};
}

// Pixels of the model seen through `camera`, from a small render with a transparent background (alpha is
// 0 where nothing was drawn); -1 when the render failed (*error says why).
int coveredPixels(OffscreenRenderer& gl, const ViewCamera& camera, QSize size, RenderSettings settings,
                  QString* error) {
    settings.transparentBackground = true;
    const QImage probe =
        gl.renderImage(camera, size.scaled(64, 64, Qt::KeepAspectRatio).expandedTo(QSize(1, 1)), settings, 1,
                       error)
            .convertToFormat(QImage::Format_RGBA8888);
    if (probe.isNull()) return -1;
    int covered = 0;
    for (int y = 0; y < probe.height(); ++y)
        for (int x = 0; x < probe.width(); ++x)
            covered += probe.constScanLine(y)[4 * x + 3] > 0 ? 1 : 0;
    return covered;
}

double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

} // namespace

int runRender(const QStringList& args) {
    QTextStream err(stderr), out(stdout);
    const QString name = QStringLiteral("lightrig render");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Renders MODEL lit by a rig into a PNG or JPEG image, exactly as the editor's viewport shows "
        "it.\nExit status: 0 written, 1 bad model, rig, camera or output path (nothing written), "
        "2 usage error.\nNeeds OpenGL 3.3: run it with a display, e.g. under xvfb-run -a."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Show this help."));
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    QStringLiteral("Output image (.png, .jpg or .jpeg)."),
                                    QStringLiteral("OUT"));
    const QCommandLineOption supersample(QStringLiteral("supersample"),
                                         QStringLiteral("Render N×N samples per pixel, 1..4 (default 1)."),
                                         QStringLiteral("N"));
    const QCommandLineOption transparent(QStringLiteral("transparent"),
                                         QStringLiteral("Transparent background (PNG alpha)."));
    QCommandLineOption frames(QStringLiteral("frames"), QStringLiteral("Time N more frames."),
                              QStringLiteral("N"));
    frames.setFlags(QCommandLineOption::HiddenFromHelp);
    QCommandLineOption msaa(QStringLiteral("msaa"), QStringLiteral("MSAA samples."), QStringLiteral("N"));
    msaa.setFlags(QCommandLineOption::HiddenFromHelp);
    const SceneOptionSet scene;
    parser.addOption(help);
    parser.addOption(output);
    scene.addTo(parser);
    parser.addOptions({supersample, transparent, frames, msaa});
    parser.addPositionalArgument(QStringLiteral("MODEL"),
                                 QStringLiteral("A model file Assimp reads (glTF, OBJ, FBX, ...)."));

    auto usage = [&](const QString& message) {
        err << name << ": " << message << "\nUsage: " << kUsage << "\nTry '" << name << " --help'.\n";
        return int(Usage);
    };
    if (!parser.parse(args)) return usage(parser.errorText());
    if (parser.isSet(help)) {
        QString text = parser.helpText();
        text.replace(0, text.indexOf(QLatin1Char('\n')), QStringLiteral("Usage: ") + QLatin1String(kUsage));
        out << text;
        return Ok;
    }
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1)
        return usage(positional.isEmpty() ? QStringLiteral("no MODEL given")
                                          : QStringLiteral("one MODEL only"));
    if (positional.first().isEmpty()) return usage(QStringLiteral("MODEL is an empty path"));
    if (!parser.isSet(output) || parser.value(output).isEmpty())
        return usage(QStringLiteral("-o OUT is required"));
    const QString outPath = parser.value(output);
    const QByteArray format = formatFor(outPath);
    if (format.isEmpty())
        return usage(QStringLiteral("the output must end in .png, .jpg or .jpeg: %1").arg(outPath));
    QString message;
    const std::optional<SceneOptions> options = scene.read(parser, &message);
    if (!options) return usage(message);
    int ss = 1, frameCount = 0, samples = options->quality == Quality::Fast ? 0 : 4;
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

    auto failed = [&](const QString& reason) {
        err << name << ": " << QString(reason).replace(QLatin1Char('\n'), QLatin1String(" | ")) << '\n';
        return int(Failed);
    };
    if (!displayAvailable())
        return failed(QStringLiteral("lightrig render needs an X display; run it under xvfb-run -a"));
    if (!checkOutputPath(outPath, &message)) return failed(message);

    QElapsedTimer clock;
    clock.start();
    LoadedScene loaded;
    if (!loadScene(positional.first(), *options, &loaded, &message)) return failed(message);
    const double loadMs = clock.nsecsElapsed() * 1e-6;
    auto warn = [&](const QString& warning) { err << name << ": warning: " << warning << '\n'; };
    for (const QString& w : loaded.model->warnings)
        warn(w);

    OffscreenRenderer gl;
    if (!gl.initialize(&message) || !gl.setModel(loaded.model, &message)) return failed(message);
    showScene(gl.renderer(), loaded);
    RenderSettings settings;
    settings.exposureEV = options->exposureEV;
    settings.toneMap = options->toneMap;
    settings.quality = options->quality;
    settings.transparentBackground = parser.isSet(transparent);
    settings.msaaSamples = samples;
    // Never an empty image in silence (a model at scale 1e38, or seen through a broken camera, rendered as
    // the background alone with exit 0): when the model covers no pixel, a view chosen here (no --view or
    // --camera-index) moves to the first standard view that shows it, with a warning; a view the user
    // chose is kept, with a warning; and when no view shows anything, nothing is written (exit 1).
    const int covered = coveredPixels(gl, loaded.camera, options->size, settings, &message);
    if (covered < 0) return failed(message);
    if (covered == 0) {
        const double aspect = double(options->size.width()) / double(options->size.height());
        std::optional<QString> visibleFrom;
        for (const QString& view : standardViewNames()) {
            const std::optional<ViewCamera> camera = standardView(view, loaded.model->bounds, aspect);
            if (!camera) continue;
            const int n = coveredPixels(gl, *camera, options->size, settings, &message);
            if (n < 0) return failed(message);
            if (n == 0) continue;
            visibleFrom = view;
            if (!options->cameraIndex && options->view.isEmpty()) {
                warn(QStringLiteral("%1 covers no pixel from %2; rendered from view %3 instead")
                         .arg(positional.first(), loaded.cameraSource, view));
                loaded.camera = *camera;
                loaded.cameraSource = QStringLiteral("view ") + view;
            } else {
                warn(QStringLiteral("%1 covers no pixel from %2 (the image shows only the background; it is "
                                    "visible from view %3)")
                         .arg(positional.first(), loaded.cameraSource, view));
            }
            break;
        }
        if (!visibleFrom)
            return failed(QStringLiteral("nothing of %1 can be drawn: it covers no pixel from any view (its "
                                         "bounds run from [%2, %3, %4] to [%5, %6, %7])")
                              .arg(positional.first())
                              .arg(loaded.model->bounds.min.x, 0, 'g', 3)
                              .arg(loaded.model->bounds.min.y, 0, 'g', 3)
                              .arg(loaded.model->bounds.min.z, 0, 'g', 3)
                              .arg(loaded.model->bounds.max.x, 0, 'g', 3)
                              .arg(loaded.model->bounds.max.y, 0, 'g', 3)
                              .arg(loaded.model->bounds.max.z, 0, 'g', 3));
    }
    clock.restart();
    const QImage image = gl.renderImage(loaded.camera, options->size, settings, ss, &message);
    const double firstMs = clock.nsecsElapsed() * 1e-6;
    if (image.isNull()) return failed(message);
    if (settings.transparentBackground && format == "jpeg")
        err << name << ": warning: JPEG has no alpha channel; the transparent background is written black\n";
    if (!writeOutputImage(image, outPath, format, &message)) return failed(message);
    const RenderStats& stats = gl.renderer().stats();
    out << QStringLiteral(
               "wrote %1 (%2x%3): %4 triangles, %5 of %6 lights (%7), %8, first image %9 ms, load %10 ms\n")
               .arg(outPath)
               .arg(image.width())
               .arg(image.height())
               .arg(stats.triangles)
               .arg(stats.lightsUploaded)
               .arg(stats.lightsInRig)
               .arg(loaded.rigSource, loaded.cameraSource)
               .arg(firstMs, 0, 'f', 1)
               .arg(loadMs, 0, 'f', 1);
    if (frameCount > 0) {
        const QSize size = options->size;
        std::vector<double> wall, gpu, cpu;
        for (int i = 0; i < frameCount; ++i) {
            clock.restart();
            const std::clock_t cpu0 = std::clock();
            if (!gl.renderFrame(loaded.camera, size, settings, &message)) return failed(message);
            wall.push_back(clock.nsecsElapsed() * 1e-6);
            cpu.push_back(double(std::clock() - cpu0) * 1000.0 / CLOCKS_PER_SEC);
            if (gl.renderer().stats().lastGpuMs >= 0) gpu.push_back(gl.renderer().stats().lastGpuMs);
        }
        out << QStringLiteral("frames: %1 at %2x%3, msaa %4: median %5 ms, min %6 ms, max %7 ms (glFinish); "
                              "gpu median %8 ms; process CPU median %9 ms (all threads)\n")
                   .arg(frameCount)
                   .arg(size.width())
                   .arg(size.height())
                   .arg(samples)
                   .arg(median(wall), 0, 'f', 2)
                   .arg(*std::min_element(wall.begin(), wall.end()), 0, 'f', 2)
                   .arg(*std::max_element(wall.begin(), wall.end()), 0, 'f', 2)
                   .arg(median(gpu), 0, 'f', 2)
                   .arg(median(cpu), 0, 'f', 2);
    }
    return Ok;
}

} // namespace lr::cli
