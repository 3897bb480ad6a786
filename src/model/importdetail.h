// Internal to lightrig_model: the steps of loadModel (modelloader.cpp), one file each.
#pragma once

#include "model.h"
#include "modelfolder.h"

#include <QByteArrayView>
#include <assimp/matrix4x4.h>
#include <functional>
#include <glm/mat4x4.hpp>

struct aiNode;
struct aiScene;

namespace lr::detail {

glm::dmat4 toGlm(const aiMatrix4x4& m);
// The node's transform to world space (the product of its and its ancestors' transforms), in double.
glm::dmat4 worldTransform(const aiNode* node);

// meshes.cpp: instances every mesh of every node into model.meshes (world positions relative to the
// bounds centre, which becomes model.origin), drops invalid geometry with a warning, sets bounds.
// Returns false when `keepGoing` asked to stop.
bool convertMeshes(const aiScene* scene, const QString& displayName, Model& model,
                   const std::function<bool(double)>& keepGoing);

// materials.cpp: model.materials (one per aiMaterial, never empty) and the textures they use.
void convertMaterials(const aiScene* scene, const ModelFolder& folder, qint64 maxDataUriBytes, Model& model);

// lights.cpp: model.lights and model.cameras. `gltf`: the scene came from Assimp's glTF importers.
void convertLightsAndCameras(const aiScene* scene, bool gltf, const QString& displayName, Model& model);

// meshes.cpp: the number of pairs of vertices within Assimp's smoothing distance of each other (1e-4 of
// a mesh's bounding-box diagonal), estimated per mesh from a grid of cells of that size: the work of
// the post-processing steps built on SpatialSort (smooth normals, tangents, joining), which grows with
// the square of the vertices at one position.
qint64 coincidentVertexPairs(const aiScene* scene);

// preflight.cpp: why the file must not reach Assimp (empty when it may): a data URI over the limit, GLB
// lengths beyond the file, an OFF/PLY header declaring more elements than the file holds or (PLY) not
// ending, non-numeric lines in ASCII PLY data.
QString preflight(const QString& path, qint64 maxDataUriBytes);
// The length of the longest "data:" URI in glTF JSON or a GLB's JSON chunk.
qint64 largestDataUri(QByteArrayView bytes);

} // namespace lr::detail
