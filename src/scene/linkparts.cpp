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
    if (ground)
        for (std::size_t i = 0; i < ground->meshes.size(); ++i) {
            PartNames p;
            p.ground = true;
            parts.push_back(p);
        }
    return parts;
}

std::vector<PartNames> linkParts(const Model& model, const Rig& rig) {
    std::vector<PartNames> parts = linkParts(&model, nullptr);
    if (rig.ground.mode != GroundMode::Off) {
        PartNames p;
        p.ground = true;
        parts.push_back(p);
    }
    return parts;
}

} // namespace lr
