// glTF numbers its cameras by the `cameras` array, as three.js and every glTF tool do; Assimp 5.2.5 lists
// them in the order its node walk first meets them (children before their parent), so on a file whose
// nodes do not meet the cameras in array order `--camera-index 0` rendered another camera than the
// file's camera 0 (issue 41). The loader puts Model::cameras back in array order, from the file's JSON:
// which node holds which camera index. Assimp names each camera after its node (an unnamed node
// "nodes[N]", or "nodes_N" in older releases), which is how the two are matched.
#pragma once

#include "model.h"

#include <QByteArray>
#include <QString>
#include <vector>

namespace lr {

// The JSON of a .gltf, or the JSON chunk of a .glb (read up to core/gltfrewrite.h's kMaxGltfJsonBytes);
// empty when the file is neither or cannot be read.
QByteArray gltfJsonOf(const QString& file);

// Sorts `cameras` (Assimp's order) by the index into `cameras` of the glTF whose JSON is `json`, keeping
// cameras it cannot match (a name two nodes share with different cameras) after the matched ones, in
// their order. No change when the JSON does not parse.
void sortCamerasAsGltf(const QByteArray& json, std::vector<Camera>& cameras);

} // namespace lr
