// The parts light linking names (core/lightlink.h): one per mesh of the model, in Model::meshes order, then
// one per mesh of the ground (which answers to "ground"). A renderer's part index is therefore the mesh's
// index, or the model's mesh count plus the ground mesh's index (linkPartOfGround).
#pragma once

#include "core/lightlink.h"
#include "model/model.h"

#include <vector>

namespace lr {

PartNames partNames(const Model& model, const Mesh& mesh);
std::vector<PartNames> linkParts(const Model* model, const Model* ground);
// For reports: the model's parts and one "ground" when the rig has a ground.
std::vector<PartNames> linkParts(const Model& model, const Rig& rig);
inline std::size_t linkPartOfGround(const Model* model, std::size_t groundMesh) {
    return (model ? model->meshes.size() : 0) + groundMesh;
}

} // namespace lr
