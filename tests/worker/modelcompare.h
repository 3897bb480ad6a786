// Field-by-field comparison of two Models for the worker tests: the codec round trip and the isolated
// import must reproduce every field exactly (bit for bit: the same code imported the same file).
#pragma once

#include "model/model.h"

#include <QColorSpace>
#include <QString>
#include <cstring>

namespace lr::test {

inline bool sameBytes(const void* a, const void* b, std::size_t n) {
    return n == 0 || std::memcmp(a, b, n) == 0;
}

// Empty when equal; otherwise the first difference. loadMs is compared only when `withTime`.
inline QString modelDifference(const Model& a, const Model& b, bool withTime = true) {
    if (a.path != b.path) return QStringLiteral("path: %1 vs %2").arg(a.path, b.path);
    if (a.origin != b.origin) return QStringLiteral("origin");
    if (a.meshes.size() != b.meshes.size()) return QStringLiteral("mesh count");
    for (std::size_t i = 0; i < a.meshes.size(); ++i) {
        const Mesh &x = a.meshes[i], &y = b.meshes[i];
        const QString at = QStringLiteral("mesh %1 ").arg(i);
        if (x.name != y.name) return at + QStringLiteral("name");
        if (x.vertices.size() != y.vertices.size() ||
            !sameBytes(x.vertices.data(), y.vertices.data(), x.vertices.size() * sizeof(Vertex)))
            return at + QStringLiteral("vertices");
        if (x.indices != y.indices) return at + QStringLiteral("indices");
        if (x.material != y.material) return at + QStringLiteral("material");
        if (x.hasVertexColors != y.hasVertexColors) return at + QStringLiteral("hasVertexColors");
        if (x.hasTangents != y.hasTangents) return at + QStringLiteral("hasTangents");
    }
    if (a.materials != b.materials) return QStringLiteral("materials");
    if (a.textures.size() != b.textures.size()) return QStringLiteral("texture count");
    for (std::size_t i = 0; i < a.textures.size(); ++i) {
        if (a.textures[i].name != b.textures[i].name) return QStringLiteral("texture %1 name").arg(i);
        const QImage &x = a.textures[i].image, &y = b.textures[i].image;
        if (x.isNull() != y.isNull() || x.size() != y.size() ||
            (!x.isNull() && x.convertToFormat(QImage::Format_RGBA8888) != y) ||
            x.colorSpace() != y.colorSpace())
            return QStringLiteral("texture %1 image").arg(i);
    }
    if (a.cameras.size() != b.cameras.size()) return QStringLiteral("camera count");
    for (std::size_t i = 0; i < a.cameras.size(); ++i) {
        const Camera &x = a.cameras[i], &y = b.cameras[i];
        if (x.name != y.name || x.position != y.position || x.forward != y.forward || x.up != y.up ||
            x.yfovDegrees != y.yfovDegrees || x.znear != y.znear || x.zfar != y.zfar || x.aspect != y.aspect)
            return QStringLiteral("camera %1").arg(i);
    }
    if (a.lights != b.lights) return QStringLiteral("lights");
    if (a.bounds.min != b.bounds.min || a.bounds.max != b.bounds.max) return QStringLiteral("bounds");
    if (a.warnings != b.warnings)
        return QStringLiteral("warnings: [%1] vs [%2]").arg(a.warnings.join(u"; "), b.warnings.join(u"; "));
    if (a.texturesOutsideFolder != b.texturesOutsideFolder)
        return QStringLiteral("textures outside the folder: [%1] vs [%2]")
            .arg(a.texturesOutsideFolder.join(u"; "), b.texturesOutsideFolder.join(u"; "));
    if (withTime && a.loadMs != b.loadMs) return QStringLiteral("loadMs");
    return {};
}

} // namespace lr::test
