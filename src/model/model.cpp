#include "model.h"
namespace lr {
double Bounds::radius() const {
    const double r = 0.5 * glm::length(max - min);
    return r > 0.0 ? r : 1.0;
}
std::size_t Model::triangleCount() const {
    std::size_t n = 0;
    for (const Mesh& m : meshes)
        n += m.indices.size() / 3;
    return n;
}
bool Model::hasPbrMaterials() const {
    for (const Material& m : materials)
        if (m.pbr) return true;
    return false;
}
bool materialExtensionRendered(const QString& name) {
    return name == QLatin1String("KHR_materials_emissive_strength");
}
std::size_t Model::vertexCount() const {
    std::size_t n = 0;
    for (const Mesh& m : meshes)
        n += m.vertices.size();
    return n;
}
} // namespace lr
