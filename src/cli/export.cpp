// `lightrig export MODEL [--rig RIG.json] [--shading classic|pbr] [--camera-index N | --view NAME]
//  [--lights-only] -o OUT.glb|OUT.gltf` writes the model with the rig's lights as KHR_lights_punctual, the
// view as its first camera and the rig's environment as a note (model/gltfexport.h, docs/export.md), or
// the lights alone. Every lossy conversion is one line on stderr ("lightrig export: lossy: ...").
// Exit status: 0 written; 1 bad model, rig, camera or output path (nothing written); 2 usage error.
#include "cli.h"
#include "outputfiles.h"

#include "core/defaultrig.h"
#include "core/rigjson.h"
#include "model/gltfexport.h"
#include "scene/camera.h"

#include <QCommandLineParser>
#include <QTextStream>

namespace lr::cli {

namespace {

const char* kUsage =
    "lightrig export MODEL [--rig RIG.json] [--shading classic|pbr] [--camera-index N | --view "
    "NAME] [--lights-only] -o OUT.glb|OUT.gltf";

// The camera render would use (sceneoptions.cpp's rule), or nullopt with *error. `exists`: it is the
// file's own camera 0, which a glTF source already has first.
std::optional<GltfCamera> chooseCamera(const Model& model, std::optional<int> index, const QString& view,
                                       bool* exists, QString* error) {
    *exists = false;
    ViewCamera camera;
    QString name;
    if (index && *index >= int(model.cameras.size())) {
        *error = QStringLiteral("%1 has %2 camera(s); --camera-index %3 is out of range")
                     .arg(model.path.isEmpty() ? QStringLiteral("the model") : model.path)
                     .arg(model.cameras.size())
                     .arg(*index);
        return std::nullopt;
    }
    if (index || (view.isEmpty() && !model.cameras.empty())) {
        const int i = index.value_or(0);
        const Camera& c = model.cameras[size_t(i)];
        const double focus = glm::dot(model.bounds.center() - c.position, c.forward);
        camera = fromModelCamera(c, focus > 0.0 ? focus : model.bounds.radius());
        name = c.name;
        *exists = i == 0;
    } else {
        name = view.isEmpty() ? QStringLiteral("three-quarter") : view;
        camera = *standardView(name, model.bounds, 16.0 / 9.0);
        name = QStringLiteral("LightRig %1 view").arg(name);
    }
    camera = camera.withExportClipPlanes(model.bounds.center(), model.bounds.radius());
    return makeGltfCamera(name, camera.eye, camera.forward(), camera.trueUp(), camera.yfovDeg, camera.znear,
                          camera.zfar);
}

} // namespace

int runExport(const QStringList& args) {
    QTextStream err(stderr), out(stdout);
    const QString name = QStringLiteral("lightrig export");
    QCommandLineParser parser;
    parser.setApplicationDescription(QStringLiteral(
        "Writes MODEL as glTF with the rig's lights (KHR_lights_punctual: candela, lux, spot cones, range), "
        "the view as its first camera and the rig's environment as a note in extras; every lossy conversion "
        "is listed on stderr. A glTF source keeps everything else byte for byte; other formats go through "
        "Assimp's exporter.\nExit status: 0 written, 1 bad model, rig, camera or output path (nothing "
        "written), 2 usage error."));
    parser.setSingleDashWordOptionMode(QCommandLineParser::ParseAsLongOptions);
    const QCommandLineOption help({QStringLiteral("h"), QStringLiteral("help")},
                                  QStringLiteral("Show this help."));
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    QStringLiteral("Output file (.glb or .gltf)."), QStringLiteral("OUT"));
    const QCommandLineOption rig(QStringLiteral("rig"),
                                 QStringLiteral("Rig file (.json). Default: as lightrig render chooses."),
                                 QStringLiteral("RIG"));
    const QCommandLineOption shading(
        QStringLiteral("shading"),
        QStringLiteral("Shading the rig is read with: %1.").arg(allowedNames<ShadingModel>()),
        QStringLiteral("MODEL"));
    const QCommandLineOption cameraIndex(
        QStringLiteral("camera-index"),
        QStringLiteral("Export camera N of the model file as the first camera."), QStringLiteral("N"));
    const QCommandLineOption view(QStringLiteral("view"),
                                  QStringLiteral("Export a standard view as the first camera: %1.")
                                      .arg(standardViewNames().join(QStringLiteral(", "))),
                                  QStringLiteral("NAME"));
    const QCommandLineOption lightsOnly(
        QStringLiteral("lights-only"),
        QStringLiteral("Write the lights alone (no meshes, no camera), to merge into another scene."));
    parser.addOptions({help, output, rig, shading, cameraIndex, view, lightsOnly});
    parser.addPositionalArgument(QStringLiteral("MODEL"),
                                 QStringLiteral("A model file (glTF, GLB, or any Assimp reads)."));
    const CommandUsage usage{name, kUsage, out, err};
    if (const std::optional<int> done = usage.parse(parser, args, help)) return *done;
    const QStringList positional = parser.positionalArguments();
    if (positional.size() != 1 || positional.first().isEmpty())
        return usage(positional.isEmpty() ? QStringLiteral("no MODEL given")
                                          : QStringLiteral("one MODEL only"));
    const QString outPath = parser.value(output);
    if (outPath.isEmpty()) return usage(QStringLiteral("-o OUT is required"));
    if (!outPath.endsWith(QLatin1String(".glb"), Qt::CaseInsensitive) &&
        !outPath.endsWith(QLatin1String(".gltf"), Qt::CaseInsensitive))
        return usage(QStringLiteral("the output must end in .glb or .gltf: %1").arg(outPath));
    if (parser.isSet(cameraIndex) && parser.isSet(view))
        return usage(QStringLiteral("--camera-index and --view exclude each other"));
    std::optional<int> index;
    if (parser.isSet(cameraIndex)) {
        bool ok = false;
        index = parser.value(cameraIndex).toInt(&ok);
        if (!ok || *index < 0)
            return usage(QStringLiteral("--camera-index must be a whole number >= 0, got '%1'")
                             .arg(parser.value(cameraIndex)));
    }
    if (parser.isSet(view) && !standardViewNames().contains(parser.value(view)))
        return usage(QStringLiteral("--view must be one of %1, got '%2'")
                         .arg(standardViewNames().join(QStringLiteral(", ")), parser.value(view)));
    std::optional<ShadingModel> shadingModel;
    if (parser.isSet(shading)) {
        shadingModel = fromString<ShadingModel>(parser.value(shading));
        if (!shadingModel)
            return usage(QStringLiteral("--shading must be %1, got '%2'")
                             .arg(allowedNames<ShadingModel>(), parser.value(shading)));
    }

    auto failed = [&](const QString& reason) {
        err << name << ": " << QString(reason).replace(QLatin1Char('\n'), QLatin1String(" | ")) << '\n';
        return int(Failed);
    };
    QString message;
    if (!checkOutputPath(outPath, &message)) return failed(message);
    const QString modelPath = positional.first();
    if (!checkDistinctFiles(
            {{modelPath, QStringLiteral("the model")}, {parser.value(rig), QStringLiteral("the rig")}},
            {{outPath, QStringLiteral("the output")}}, &message))
        return failed(message);
    const ModelLoadResult loaded = importModelIsolated(modelPath);
    if (!loaded.ok())
        return failed(loaded.error.isEmpty() ? QStringLiteral("could not import %1").arg(modelPath)
                                             : loaded.error);
    const Model& model = *loaded.model;
    GltfExportRequest request;
    request.modelPath = modelPath;
    request.outputPath = outPath;
    request.lightsOnly = parser.isSet(lightsOnly);
    request.frame = {model.bounds.center(), model.bounds.radius()};
    if (parser.isSet(rig)) {
        const RigReadResult r = readRigFile(parser.value(rig));
        if (!r.ok())
            return failed(
                r.errors.value(0, QStringLiteral("%1: cannot read the rig").arg(parser.value(rig))));
        request.rig = shadingModel ? withShading(*r.rig, *shadingModel) : *r.rig;
    } else {
        request.rig = chooseDefaultRig(model.hasPbrMaterials(), model.lights, modelPath, shadingModel).rig;
    }
    bool cameraExists = false;
    std::optional<GltfCamera> camera =
        chooseCamera(model, index, parser.value(view), &cameraExists, &message);
    if (!camera) return failed(message);
    if (!(cameraExists && !index && !parser.isSet(view))) request.camera = camera;
    const GltfExportResult result = exportGltf(request);
    if (!result.ok()) return failed(result.error);
    for (const LossyConversion& loss : result.losses)
        err << name << ": lossy: " << describeLoss(loss) << '\n';
    for (const QString& note : result.notes)
        err << name << ": note: " << note << '\n';
    if (!writeOutputFile(outPath, result.bytes, &message)) return failed(message);
    out << QStringLiteral("wrote %1 (%2 bytes): %3 lights%4, %5 lossy conversions\n")
               .arg(outPath)
               .arg(result.bytes.size())
               .arg(result.lights)
               .arg(request.lightsOnly ? QStringLiteral(", lights only")
                    : request.camera   ? QStringLiteral(", camera \"%1\" first").arg(request.camera->name)
                                       : QStringLiteral(", the model's camera 0"))
               .arg(result.losses.size());
    return Ok;
}

} // namespace lr::cli
