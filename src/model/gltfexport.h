// Exporting a model and a rig as glTF (issue 17, docs/export.md), shared by `lightrig export` and the
// editor's File › Export glTF…: the rig's lights as KHR_lights_punctual (core/gltflights.h), the view as the
// first camera, the rig's environment as a note, written into the model's own glTF (core/gltfrewrite.h:
// everything else byte for byte) or, for other formats, into the GLB Assimp's exporter makes of it (in the
// import worker, like every read of an untrusted model). Or the lights alone, to merge into another scene.
// Nothing is written here: the caller writes `bytes` atomically (core/atomicwrite.h).
#pragma once

#include "core/gltfrewrite.h"
#include "isolatedimport.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>

namespace lr {

struct GltfExportRequest {
    QString modelPath;  // the source model (glTF, GLB, or anything Assimp reads)
    QString outputPath; // ends in .glb (binary) or .gltf (JSON, buffers as data URIs)
    bool lightsOnly = false;
    Rig rig;
    SceneFrame frame;                 // the model's bounding sphere in LightRig's world
    glm::dmat3 fileFromWorld{1.0};    // undoes the editor's up-axis rotation (model/upaxis.h)
    std::optional<GltfCamera> camera; // becomes cameras[0]; none: the file's cameras as they are
    ImportLimits limits;              // for the Assimp export (non-glTF sources)
};

struct GltfExportResult {
    QByteArray bytes;                    // the file to write; empty on error
    QString error;                       // "could not export models/x.glb: nodes[3]: must be an object"
    std::vector<LossyConversion> losses; // every lossy conversion (describeLoss), never silent
    QStringList notes;                   // other changes: "the model's 8 light(s) replaced by the rig's 3"
    int lights = 0;                      // glTF lights written
    bool ok() const { return error.isEmpty(); }
};

// Whether the output is a GLB (".glb", any case) rather than a .gltf.
bool isGlbPath(const QString& path);

// Builds the output file's bytes. Blocking (an Assimp export runs the import worker).
GltfExportResult exportGltf(const GltfExportRequest& request);

// The bytes of the GLB Assimp makes of `path` ("glb2"), in this process (the import worker calls it);
// empty and *error on failure.
QByteArray assimpGlb(const QString& path, QString* error);
// assimpGlb in the import worker; empty and *error (the path as given) on failure.
QByteArray assimpGlbIsolated(const QString& path, const ImportLimits& limits, QString* error);

} // namespace lr
