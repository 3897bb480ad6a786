// `lightrig compare MODEL A.json B.json [-o DIFF.png] [--amplify N] [-a A.png] [-b B.png]
//  [--side-by-side OUT.png] [--size WxH] [--camera-index N | --view NAME] [--quality Q] [--supersample N]
//  [--exposure EV] [--tonemap OP] [--shading classic|pbr] [--ground ...] [--shadows on|off] [--environment
//  ...]`
// (issue 17, part 4): renders MODEL lit by rig A and by rig B through the same OffscreenRenderer, from the
// same camera and with the same settings as `lightrig render`, and prints how far apart they are
// (core/imagecompare.h, over every pixel's r, g and b):
//   PSNR 31.2 dB, mean 1.83 levels, max 87 levels, 12.4 % of pixels differ by more than 1 level
// ("PSNR inf dB" for identical images). -o writes the difference image (render/qualitybench.h
// benchDifferenceImage, the Quality dock's: each pixel's largest channel difference ×amplify, black where
// equal, then red, yellow and white at 255, 510 and 765); -a, -b and --side-by-side write the two renders
// and A | B. Every image is written atomically, after both renders succeeded. With --quality path (and the
// path tracer's options, tracedoptions.h) both are traced on the CPU with one seed, no display needed.
// Exit status: 0 compared (whatever the difference); 1 bad model, rig (naming which, A or B, its file and
// field), camera or path, or no OpenGL (one line on stderr, nothing written); 2 usage error.
#include "cli.h"
#include "outputfiles.h"
#include "sceneoptions.h"
#include "tracedoptions.h"

#include "core/imagecompare.h"
#include "core/rigjson.h"
#include "render/imagefile.h"
#include "render/offscreen.h"
#include "render/qualitybench.h"

#include <QCommandLineParser>
#include <QPainter>
#include <QTextStream>
#include <cmath>
#include <vector>

namespace lr::cli {

namespace {

const char* kUsage = "lightrig compare MODEL A.json B.json [-o DIFF.png] [--amplify N] [-a A.png] [-b B.png] "
                     "[--side-by-side OUT.png] [--size WxH] [--camera-index N | --view NAME] [--quality Q] "
                     "[--supersample N] [--exposure EV] [--tonemap OP] [--shading classic|pbr] "
                     "[--ground off|visible|catcher] [--shadows on|off] [--environment ...] [--samples N] "
                     "[--time-limit S] [--noise-threshold T] [--bounces B] [--threads T] [--firefly-clamp X] "
                     "[--seed S]";

struct Output {
    const QCommandLineOption* option;
    QString path;
    QByteArray format;
    QImage image;
    QString what; // for the "wrote" line
};

// "PSNR 31.2 dB, mean 1.83 levels, max 87 levels, 12.4 % of pixels differ by more than 1 level"
QString figuresLine(const ErrorFigures& f) {
    const QString psnr = std::isinf(f.psnrDb) ? QStringLiteral("inf") : QString::number(f.psnrDb, 'f', 1);
    return QStringLiteral(
               "PSNR %1 dB, mean %2 levels, max %3 levels, %4 % of pixels differ by more than 1 level")
        .arg(psnr)
        .arg(f.meanLevels, 0, 'f', 2)
        .arg(f.maxLevels)
        .arg(100.0 * f.shareOver1(), 0, 'f', 1);
}

} // namespace

int runCompare(const QStringList& args) {
    QTextStream err(stderr), out(stdout);
    const QString name = QStringLiteral("lightrig compare");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Renders MODEL lit by rig A and by rig B from the same camera with the same settings, prints their "
        "PSNR, mean and largest difference, and writes a difference image.\nThe difference image shows each "
        "pixel's largest channel difference |A-B| times --amplify as a heat map: black where equal, red at "
        "255, yellow at 510, white at 765 (at the default x4: 64, 128 and 192 levels).\nExit status: 0 "
        "compared, 1 bad model, rig, "
        "camera or output path (nothing written), 2 usage error.\nNeeds OpenGL 3.3: run it with a display, "
        "e.g. under xvfb-run -a; --quality path traces both on the CPU with the same random sequence "
        "(--seed), "
        "with no display."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Show this help."));
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    QStringLiteral("Difference image (.png, .jpg or .jpeg)."),
                                    QStringLiteral("DIFF"));
    const QCommandLineOption amplify(QStringLiteral("amplify"),
                                     QStringLiteral("Scale of the difference image, 1..255 (default 4)."),
                                     QStringLiteral("N"));
    const QCommandLineOption imageA({QStringLiteral("a"), QStringLiteral("image-a")},
                                    QStringLiteral("Also write the render with rig A."),
                                    QStringLiteral("A.png"));
    const QCommandLineOption imageB({QStringLiteral("b"), QStringLiteral("image-b")},
                                    QStringLiteral("Also write the render with rig B."),
                                    QStringLiteral("B.png"));
    const QCommandLineOption sideBySide(QStringLiteral("side-by-side"),
                                        QStringLiteral("Also write A and B side by side (A left)."),
                                        QStringLiteral("OUT"));
    const QCommandLineOption supersample(QStringLiteral("supersample"),
                                         QStringLiteral("Render N×N samples per pixel, 1..4 (default 1)."),
                                         QStringLiteral("N"));
    const SceneOptionSet scene;
    const TracedOptionSet tracedSet;
    parser.addOptions({help, output, amplify, imageA, imageB, sideBySide, supersample});
    scene.addTo(parser);
    tracedSet.addTo(parser);
    parser.addPositionalArgument(QStringLiteral("MODEL"), QStringLiteral("A model file Assimp reads."));
    parser.addPositionalArgument(QStringLiteral("A.json"), QStringLiteral("The first rig."));
    parser.addPositionalArgument(QStringLiteral("B.json"), QStringLiteral("The second rig."));

    const CommandUsage usage{name, kUsage, out, err};
    if (const std::optional<int> done = usage.parse(parser, args, help)) return *done;
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 3)
        return usage(QStringLiteral("needs MODEL A.json B.json, got %1 argument(s)").arg(positional.size()));
    for (const QString& p : positional)
        if (p.isEmpty()) return usage(QStringLiteral("an empty path among MODEL A.json B.json"));
    if (parser.isSet(scene.rig))
        return usage(QStringLiteral("--rig does not apply: the rigs are the arguments A.json and B.json"));
    std::vector<Output> outputs;
    for (const QCommandLineOption* o : {&output, &imageA, &imageB, &sideBySide}) {
        if (!parser.isSet(*o)) continue;
        const QString path = parser.value(*o);
        const QByteArray format = writableImageFormatOf(path);
        if (format.isEmpty())
            return usage(
                QStringLiteral("--%1 must end in .png, .jpg or .jpeg: '%2'").arg(o->names().last(), path));
        outputs.push_back({o, path, format, {}, {}});
    }
    QString message;
    std::optional<SceneOptions> options = scene.read(parser, &message, false, false, true);
    if (!options) return usage(message);
    const std::optional<TracedRenderOptions> traced = tracedSet.read(parser, options->pathTraced, &message);
    if (!traced) return usage(message);
    if (options->pathTraced && parser.isSet(supersample))
        return usage(QStringLiteral("--supersample does not apply to --quality path (it takes --samples)"));
    int gain = 4;
    if (parser.isSet(amplify)) {
        bool ok = false;
        gain = parser.value(amplify).toInt(&ok);
        if (!ok || gain < 1 || gain > 255)
            return usage(QStringLiteral("--amplify must be a whole number in 1..255, got '%1'")
                             .arg(parser.value(amplify)));
    }
    int ss = 1;
    if (parser.isSet(supersample)) {
        bool ok = false;
        ss = parser.value(supersample).toInt(&ok);
        if (!ok || ss < 1 || ss > 4) return usage(QStringLiteral("--supersample must be 1, 2, 3 or 4"));
    }

    auto failed = [&](const QString& reason) {
        err << name << ": " << QString(reason).replace(QLatin1Char('\n'), QLatin1String(" | ")) << '\n';
        return int(Failed);
    };
    std::vector<NamedFile> written;
    for (const Output& o : outputs)
        written.push_back({o.path, QStringLiteral("the --%1 image").arg(o.option->names().last())});
    if (!checkDistinctFiles({{positional[0], QStringLiteral("the model")},
                             {positional[1], QStringLiteral("rig A")},
                             {positional[2], QStringLiteral("rig B")},
                             {environmentFileOf(options->environment), QStringLiteral("the environment")}},
                            written, &message))
        return failed(message);
    if (!options->pathTraced && !displayAvailable())
        return failed(QStringLiteral("lightrig compare needs an X display; run it under xvfb-run -a"));
    for (const Output& o : outputs)
        if (!checkOutputPath(o.path, &message)) return failed(message);
    const QString& modelPath = positional[0];
    const QString rigPaths[2] = {positional[1], positional[2]};
    const char* labels[2] = {"A", "B"};
    // Both rigs are read before the model is imported: a bad one fails at once, naming it.
    for (int i = 0; i < 2; ++i) {
        const RigReadResult r = readRigFile(rigPaths[i]);
        if (r.ok()) continue;
        return failed(
            QStringLiteral("rig %1: %2").arg(QLatin1String(labels[i]), rigErrorLine(r, rigPaths[i])));
    }
    // The model once; then each rig with the same overrides and its environment resolved against its own
    // folder; the camera (chosen with rig A) serves both.
    LoadedScene loaded[2];
    if (!loadSceneModel(modelPath, &loaded[0], &message)) return failed(message);
    if (!checkDistinctFiles(textureFilesOf(*loaded[0].model), written, &message)) return failed(message);
    loaded[1].model = loaded[0].model;
    for (int i = 0; i < 2; ++i) {
        SceneOptions o = *options;
        o.rigPath = rigPaths[i];
        if (i == 1)
            loaded[1].environment = loaded[0].environment; // kept when B's is the same (loadCliEnvironment)
        if (!loadSceneRig(modelPath, o, &loaded[i], &message))
            return failed(i == 0 ? message : QStringLiteral("rig B: %1").arg(message));
    }
    if (!chooseSceneCamera(modelPath, *options, &loaded[0], &message)) return failed(message);
    for (const QString& w : loaded[0].model->warnings)
        err << name << ": warning: " << w << '\n';

    RenderSettings settings;
    settings.exposureEV = options->exposureEV;
    settings.toneMap = options->toneMap;
    settings.quality = options->quality;
    settings.msaaSamples = options->quality == Quality::Fast ? 0 : 4;
    QImage images[2];
    QString tracedLines[2];
    if (options->pathTraced) {
        // Both with the same seed: where a path meets the same surfaces under both rigs, its random numbers
        // are the same, so the difference image shows the rigs more than the noise.
        TracedImages tracer(*traced);
        const auto warn = [&](const QString& w) { err << name << ": warning: " << w << '\n'; };
        for (int i = 0; i < 2; ++i) {
            const std::optional<TracedImages::Result> t = tracer.render(
                loaded[i], loaded[i].rig, loaded[0].camera, options->size, settings, warn, &message);
            if (!t) return failed(QStringLiteral("rig %1: %2").arg(QLatin1String(labels[i]), message));
            images[i] = t->image.convertToFormat(QImage::Format_RGBA8888);
            tracedLines[i] = t->line;
        }
    } else {
        OffscreenRenderer gl;
        if (!gl.initialize(&message) || !gl.setModel(loaded[0].model, &message)) return failed(message);
        for (int i = 0; i < 2; ++i) {
            showScene(gl.renderer(), loaded[i]);
            images[i] = gl.renderImage(loaded[0].camera, options->size, settings, ss, &message)
                            .convertToFormat(QImage::Format_RGBA8888);
            if (images[i].isNull()) return failed(message);
        }
    }
    const QImage& a = images[0];
    const QImage& b = images[1];
    const qint64 pixels = qint64(a.width()) * a.height(); // Format_RGBA8888 rows have no padding
    const ErrorFigures figures = compareSrgb8(a.constBits(), b.constBits(), pixels);

    for (Output& o : outputs) {
        if (o.option == &output) {
            o.image = benchDifferenceImage(a, b, gain);
            o.what = QStringLiteral("largest channel difference x%1, black where equal").arg(gain);
        } else if (o.option == &imageA || o.option == &imageB) {
            o.image = o.option == &imageA ? a : b;
            o.what = o.option == &imageA ? QStringLiteral("rig A") : QStringLiteral("rig B");
        } else {
            o.image = QImage(a.width() * 2, a.height(), QImage::Format_RGBA8888);
            QPainter p(&o.image);
            p.setCompositionMode(QPainter::CompositionMode_Source);
            p.drawImage(0, 0, a);
            p.drawImage(a.width(), 0, b);
            p.end();
            o.what = QStringLiteral("A | B");
        }
    }
    for (int i = 0; i < 2; ++i)
        out << labels[i] << ": " << loaded[i].rigSource
            << (tracedLines[i].isEmpty() ? QString() : QStringLiteral(", ") + tracedLines[i]) << '\n';
    out << "camera: " << loaded[0].cameraSource << ", " << a.width() << 'x' << a.height() << '\n';
    out << figuresLine(figures) << '\n';
    // All or none: every image is encoded first, then written (writeOutputFiles puts back the ones
    // written when a later one fails).
    std::vector<OutputBytes> files;
    for (const Output& o : outputs) {
        const QByteArray bytes = encodeImage(o.image, o.format, &message);
        if (bytes.isEmpty()) return failed(QStringLiteral("cannot write %1: %2").arg(o.path, message));
        files.push_back({o.path, bytes});
    }
    if (!writeOutputFiles(files, &message)) return failed(message);
    for (const Output& o : outputs) {
        out << QStringLiteral("wrote %1 (%2x%3): %4\n")
                   .arg(o.path)
                   .arg(o.image.width())
                   .arg(o.image.height())
                   .arg(o.what);
    }
    return Ok;
}

} // namespace lr::cli
