#include "modelloader.h"

#include "gltfcameras.h"
#include "importdetail.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <exception>
#include <new>

namespace lr {

namespace {

// Share of the progress bar for Assimp's reading and post-processing; the rest is ours.
constexpr double kAssimpShare = 0.8;
// Above this many pairs of coincident vertices (detail::coincidentVertexPairs) the SpatialSort-based
// post-processing steps are skipped: at ~3e8 pairs a second in SpatialSort, about a second in all.
constexpr qint64 kMaxCoincidentPairs = 100'000'000;

struct ProgressState {
    std::function<bool(double)> callback;
    bool cancelled = false;
    double last = 0.0;
    bool report(double fraction) {
        if (cancelled) return false;
        if (!callback) return true;
        if (fraction >= 0.0 && fraction <= 1.0) last = std::max(last, fraction);
        if (!callback(last)) cancelled = true;
        return !cancelled;
    }
};

// Owned and deleted by the Assimp::Importer, which the ProgressState outlives.
class AssimpProgress : public Assimp::ProgressHandler {
  public:
    explicit AssimpProgress(ProgressState& state) : m_state(state) {}
    bool Update(float percentage) override {
        return m_state.report(percentage >= 0.0f ? double(percentage) * kAssimpShare : -1.0);
    }

  private:
    ProgressState& m_state;
};

bool isGltf(const QString& path) {
    const QString suffix = QFileInfo(path).suffix().toLower();
    return suffix == QLatin1String("gltf") || suffix == QLatin1String("glb");
}

// Errors name the model as the caller gave it (a file name alone is ambiguous in batch runs); warnings,
// which come with the loaded model, name just the file.
ModelLoadResult failure(const QString& givenPath, const QString& reason, bool cancelled = false) {
    ModelLoadResult r;
    r.error = QStringLiteral("could not import %1: %2").arg(givenPath, reason);
    r.cancelled = cancelled;
    return r;
}

ModelLoadResult import(const QString& path, const ModelLoadOptions& options) {
    QElapsedTimer timer;
    timer.start();
    const detail::ModelFolder folder(path, options.allowTexturesOutsideFolder);
    const QString& name = folder.displayName();
    const QFileInfo info(folder.modelFile());
    if (!info.exists()) return failure(path, QStringLiteral("no such file"));
    if (!info.isFile())
        return failure(path, QStringLiteral("not a regular file (a folder, FIFO, socket or device)"));

    const bool gltf = isGltf(path);
    if (const QString refusal = detail::preflight(folder.modelFile(), options.maxDataUriBytes);
        !refusal.isEmpty())
        return failure(path, refusal);

    ProgressState progress{options.progress};
    if (!progress.report(0.0)) return failure(path, QStringLiteral("cancelled"), true);

    Assimp::Importer importer;
    auto* io = new detail::QtIOSystem(folder);
    importer.SetIOHandler(io); // the importer owns it
    importer.SetProgressHandler(new AssimpProgress(progress));
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, 80.0f);
    // Two passes of Assimp's post-processing, in its own order: the linear steps while reading; the steps
    // built on SpatialSort (smooth normals, tangents, joining vertices) only when few vertices share a
    // position, since SpatialSort is quadratic in the number of coincident vertices (an OBJ of 100,000
    // copies of one triangle took minutes). Without them meshes.cpp computes flat normals per face.
    const unsigned readFlags =
        aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure;
    const unsigned smoothFlags =
        aiProcess_GenSmoothNormals | aiProcess_CalcTangentSpace | aiProcess_JoinIdenticalVertices;
    const aiScene* scene = importer.ReadFile(folder.modelFile().toUtf8().constData(), readFlags);
    if (progress.cancelled) return failure(path, QStringLiteral("cancelled"), true);
    qint64 coincidentPairs = 0;
    if (scene && (coincidentPairs = detail::coincidentVertexPairs(scene)) <= kMaxCoincidentPairs) {
        scene = importer.ApplyPostProcessing(smoothFlags);
        if (progress.cancelled) return failure(path, QStringLiteral("cancelled"), true);
    }

    const QStringList refusals = io->refusals();
    if (!scene) {
        QString reason = QString::fromUtf8(importer.GetErrorString()).trimmed();
        if (reason.isEmpty()) reason = QStringLiteral("Assimp gave no reason");
        if (!refusals.isEmpty())
            reason += QStringLiteral(" (refused: %1)").arg(refusals.join(QStringLiteral("; ")));
        return failure(path, reason);
    }

    auto model = std::make_shared<Model>();
    model->path = path;
    for (const QString& r : refusals)
        model->warnings << QStringLiteral("%1: refused: %2").arg(name, r);
    if (coincidentPairs > kMaxCoincidentPairs)
        model->warnings << QStringLiteral("%1: %2 pairs of vertices share a position; normals are flat and "
                                          "vertices not joined (smoothing them would take quadratic time)")
                               .arg(name)
                               .arg(coincidentPairs);
    const auto keepGoing = [&](double f) {
        return progress.report(kAssimpShare + f * (0.95 - kAssimpShare));
    };
    if (!detail::convertMeshes(scene, name, *model, keepGoing))
        return failure(path, QStringLiteral("cancelled"), true);
    if (model->meshes.empty()) {
        QString reason = QStringLiteral("the file has no triangles");
        if (!model->warnings.isEmpty())
            reason += QStringLiteral(" (%1)").arg(model->warnings.join(QStringLiteral("; ")));
        return failure(path, reason);
    }
    // The glTF's JSON, read once for what Assimp 5.2.5 does not read of it.
    const QByteArray json = gltf ? gltfJsonOf(folder.modelFile()) : QByteArray();
    detail::convertMaterials(scene, folder, options.maxDataUriBytes, detail::materialSource(path), json,
                             *model);
    detail::convertLightsAndCameras(scene, gltf, name, *model);
    if (gltf) {
        sortCamerasAsGltf(json, model->cameras); // glTF's numbering
        // Issue 39: EXT_lights_ies and LightRig's extras.lightrig on light nodes, which Assimp does not read.
        detail::readGltfLightExtras(json, folder, options.maxDataUriBytes, *model);
        if (const QStringList variants = detail::readGltfVariantNames(json); !variants.isEmpty())
            model->warnings << QStringLiteral(
                                   "%1: KHR_materials_variants is not read: the file's %2 variants (%3) "
                                   "are not offered; each mesh shows its default material")
                                   .arg(name)
                                   .arg(variants.size())
                                   .arg(variants.mid(0, 8).join(QStringLiteral(", ")) +
                                        (variants.size() > 8 ? QStringLiteral(", …") : QString()));
    }
    if (!progress.report(1.0)) return failure(path, QStringLiteral("cancelled"), true);
    model->loadMs = double(timer.nsecsElapsed()) / 1e6;
    ModelLoadResult result;
    result.model = std::move(model);
    return result;
}

} // namespace

ModelLoadResult loadModel(const QString& path, const ModelLoadOptions& options) {
    try {
        return import(path, options);
    } catch (const std::bad_alloc&) {
        return failure(path, QStringLiteral("out of memory"));
    } catch (const std::exception& e) {
        return failure(path, QString::fromUtf8(e.what()));
    } catch (...) {
        return failure(path, QStringLiteral("unknown error"));
    }
}

QStringList importableSuffixes() {
    std::string list;
    Assimp::Importer().GetExtensionList(list); // "*.3d;*.3ds;..."
    QStringList out;
    for (QString s : QString::fromStdString(list).split(QLatin1Char(';'), Qt::SkipEmptyParts)) {
        s = s.trimmed().toLower();
        if (s.startsWith(QLatin1String("*."))) s = s.mid(2);
        if (!s.isEmpty() && !out.contains(s)) out << s;
    }
    out.sort();
    return out;
}

QString modelFileFilter() {
    QStringList globs;
    for (const QString& s : importableSuffixes())
        globs << QStringLiteral("*.") + s;
    return QStringLiteral("3D models (%1)").arg(globs.join(QLatin1Char(' ')));
}

} // namespace lr
