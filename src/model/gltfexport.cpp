#include "gltfexport.h"

#include "importprotocol.h"
#include "isolatedworker.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonObject>
#include <assimp/Exporter.hpp>
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

namespace lr {

namespace {

constexpr qint64 kMaxSourceBytes = 2ll << 30; // glTF's GLB length field is 32 bits

// Whether `data` is glTF JSON (an object whose first key is any; glTF files start with '{').
bool looksLikeJson(const QByteArray& data) {
    for (const char c : data) {
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r') continue;
        return c == '{';
    }
    return false;
}

// The folder a file lies in, symbolic links resolved (a relative path through a link would climb out of
// the link's target, not its parent).
QString folderOf(const QString& path) {
    const QFileInfo folder(QFileInfo(path).absolutePath());
    const QString canonical = folder.canonicalFilePath();
    return canonical.isEmpty() ? folder.absoluteFilePath() : canonical;
}

} // namespace

bool isGlbPath(const QString& path) {
    return path.endsWith(QLatin1String(".glb"), Qt::CaseInsensitive);
}

GltfExportResult exportGltf(const GltfExportRequest& request) {
    GltfExportResult r;
    const QString& model = request.modelPath;
    auto fail = [&](const QString& why) {
        r.error = QStringLiteral("could not export %1: %2").arg(model, why);
        r.bytes.clear();
        return r;
    };
    const GltfRigExport converted = convertRigToGltf(request.rig, request.frame, request.fileFromWorld);
    r.losses = converted.losses;
    r.lights = int(converted.lights.size());
    GltfAdditions add;
    add.lights = converted.lights;
    add.note = converted.note;
    const bool glbOut = isGlbPath(request.outputPath);
    if (request.lightsOnly) {
        const QByteArray json = lightsOnlyGltfJson(add);
        r.bytes = glbOut ? writeGlb(json, {}) : json;
        return r;
    }
    add.camera = request.camera;

    QFile file(model);
    if (!file.open(QIODevice::ReadOnly)) return fail(file.errorString().toLower());
    if (file.size() > kMaxSourceBytes) return fail(QStringLiteral("larger than 2 GiB"));
    QByteArray source = file.readAll();
    QString error;
    QByteArray json, rest;
    bool fromGlb = isGlb(source);
    if (!fromGlb && !looksLikeJson(source)) {
        // Not glTF: Assimp's GLB of it, made in the import worker; then as any GLB.
        source = assimpGlbIsolated(model, request.limits, &error);
        if (source.isEmpty()) {
            r.error = error;
            return r;
        }
        fromGlb = true;
        r.notes << QStringLiteral("converted to glTF by Assimp's exporter (what it does not export is lost: "
                                  "see docs/export.md)");
    }
    if (fromGlb) {
        const std::optional<GlbParts> parts = parseGlb(source, &error);
        if (!parts) return fail(error);
        json = parts->json;
        rest = parts->rest;
        if (!glbOut && parts->hasBin) add.embedBinAsUri = parts->bin;
        if (!glbOut && parts->rest.size() > (parts->hasBin ? parts->bin.size() + 8 : 0))
            r.notes << QStringLiteral("chunks of unknown types are not kept in a .gltf");
    } else {
        if (source.size() > kMaxGltfJsonBytes)
            return fail(QStringLiteral("a .gltf of %1 bytes; at most %2 are read")
                            .arg(source.size())
                            .arg(kMaxGltfJsonBytes));
        json = source;
    }
    // Files the JSON names beside the source stay there: named from the output's folder. A bundled model's
    // files are inside LightRig, where no file can name them.
    const QStringList files = externalUris(json);
    if (!files.isEmpty() && model.startsWith(QLatin1String(":/")))
        return fail(QStringLiteral("a bundled model refers to files inside LightRig (%1); open a copy of it")
                        .arg(files.mid(0, 3).join(QStringLiteral(", "))));
    add.sourceFolder = folderOf(model);
    add.outputFolder = folderOf(request.outputPath);
    const GltfRewriteResult rewritten = rewriteGltfJson(json, add);
    if (!rewritten.ok()) return fail(rewritten.error);
    r.notes += rewritten.notes;
    r.bytes = glbOut ? writeGlb(rewritten.json, rest) : rewritten.json;
    return r;
}

QByteArray assimpGlb(const QString& path, QString* error) {
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(QFile::encodeName(path).constData(),
                                             aiProcess_Triangulate | aiProcess_ValidateDataStructure);
    if (!scene) {
        *error =
            QStringLiteral("could not import %1: %2").arg(path, QString::fromUtf8(importer.GetErrorString()));
        return {};
    }
    Assimp::Exporter exporter;
    const aiExportDataBlob* blob = exporter.ExportToBlob(scene, "glb2");
    if (!blob || !blob->data || blob->size == 0) {
        *error = QStringLiteral("could not export %1 as glTF: %2")
                     .arg(path, QString::fromUtf8(exporter.GetErrorString()));
        return {};
    }
    return QByteArray(static_cast<const char*>(blob->data), qsizetype(blob->size));
}

QByteArray assimpGlbIsolated(const QString& path, const ImportLimits& limits, QString* error) {
    namespace ip = importprotocol;
    const auto keepGoing = [&limits](double) { return !(limits.cancel && limits.cancel->load()); };
    const QJsonObject request{{QStringLiteral("kind"), QStringLiteral("gltf-export")},
                              {QStringLiteral("path"), path}};
    isolated::WorkerOutcome run = isolated::runWorker(request, limits, -1, keepGoing, kMaxSourceBytes);
    if (!run.ok()) {
        *error =
            run.fromWorker ? run.failure : QStringLiteral("could not export %1: %2").arg(path, run.failure);
        return {};
    }
    if (run.type != ip::kGltf) {
        *error =
            QStringLiteral("could not export %1: the importer sent a reply of type '%2' to an export request")
                .arg(path, QString(QLatin1Char(run.type)));
        return {};
    }
    return run.payload;
}

} // namespace lr
