#include "linkparts.h"

namespace lr {

PartNames partNames(const Model& model, const Mesh& mesh) {
    PartNames p;
    p.node = mesh.node;
    p.mesh = mesh.name;
    if (mesh.material >= 0 && std::size_t(mesh.material) < model.materials.size())
        p.material = model.materials[std::size_t(mesh.material)].name;
    return p;
}

std::vector<PartNames> linkParts(const Model* model, const Model* ground) {
    std::vector<PartNames> parts;
    if (model)
        for (const Mesh& mesh : model->meshes)
            parts.push_back(partNames(*model, mesh));
    if (ground) parts.insert(parts.end(), ground->meshes.size(), PartNames::theGround());
    return parts;
}

std::vector<PartNames> linkParts(const Model& model, const Rig& rig) {
    std::vector<PartNames> parts = linkParts(&model, nullptr);
    if (rig.ground.mode != GroundMode::Off) parts.push_back(PartNames::theGround());
    return parts;
}

} // namespace lr
