// Shared by the GL tests of the quality tiers: a tessellated plane (so per-vertex lighting has vertices to
// work with) with optional custom normals, and one frame of a tier compared with the double reference,
// both in linear radiance (glfixture.h's well-conditioned comparison) and in 8-bit levels (reference.h).
#pragma once

#include "render/glfixture.h"
#include "render/scenes.h"

#include "core/imagecompare.h"
#include "render/offscreen.h"
#include "render/reference.h"

#include <functional>
#include <memory>

namespace lr::test {

// A plane z = 0 (normal +Z) of (2·halfSize)² centred on `center`, n × n quads; normalAt(x, y) (plane
// coordinates in [-halfSize, halfSize]) may replace each vertex normal.
inline std::shared_ptr<Model> gridPlane(double halfSize, int n, const glm::dvec3& center = glm::dvec3(0.0),
                                        const std::function<glm::vec3(float, float)>& normalAt = {}) {
    auto m = std::make_shared<Model>(makePlane(halfSize, center));
    Mesh& mesh = m->meshes.front();
    mesh.vertices.clear();
    mesh.indices.clear();
    const float h = float(halfSize);
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            Vertex v;
            const float x = -h + 2.0f * h * float(i) / float(n), y = h - 2.0f * h * float(j) / float(n);
            v.position = {x, y, 0.0f};
            v.normal = normalAt ? normalAt(x, y) : glm::vec3(0.0f, 0.0f, 1.0f);
            v.uv = {float(i) / float(n), float(j) / float(n)};
            mesh.vertices.push_back(v);
        }
    }
    const auto at = [&](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) // counter-clockwise seen from +Z
            mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i, j),
                                                     at(i + 1, j + 1), at(i + 1, j)});
    m->materials[0].baseColor = {0.8f, 0.6f, 0.4f, 1.0f};
    m->materials[0].specular = {0.5f, 0.6f, 0.7f};
    m->materials[0].shininess = 24.0f;
    return m;
}

struct TierFrame {
    Comparison linear;   // GPU float radiance against shadeSurface<double>, well-conditioned pixels
    ErrorFigures levels; // GPU 8-bit output against the reference's 8-bit encoding, covered pixels
    QString error;       // non-empty: rendering failed
    QString summary() const {
        return error.isEmpty() ? QStringLiteral("%1 | 8-bit: max %2, mean %3, PSNR %4 dB, >1 level %5%")
                                     .arg(linear.summary())
                                     .arg(levels.maxLevels)
                                     .arg(levels.meanLevels, 0, 'f', 4)
                                     .arg(levels.psnrDb, 0, 'f', 1)
                                     .arg(100.0 * levels.shareOver1(), 0, 'f', 3)
                               : error;
    }
};

// Renders one frame of `quality` (single sample, float radiance and 8-bit output) and compares it with the
// double reference of the G-buffer; `tolerance` is glfixture's relative per-channel tolerance.
inline TierFrame renderTier(OffscreenRenderer& gl, std::shared_ptr<Model> model, const Rig& rig,
                            const ViewCamera& camera, QSize size, Quality quality, double tolerance,
                            RenderSettings settings = RenderSettings()) {
    TierFrame f;
    settings.msaaSamples = 0;
    settings.quality = quality;
    if (!gl.setModel(model, &f.error)) return f;
    gl.setRig(rig);
    FloatImage radiance;
    GBuffer g;
    RenderSettings floats = settings;
    floats.hdrFloat32 = true;
    if (!gl.renderRadiance(camera, size, floats, &radiance, &f.error) ||
        !gl.renderGBuffer(camera, size, floats, &g, &f.error))
        return f;
    const QImage image = gl.renderImage(camera, size, settings, 1, &f.error);
    if (image.isNull()) return f;
    const glm::dmat4 view = gl.renderer().effectiveCamera(camera).view();
    const SceneFrame frame = gl.renderer().sceneFrame();
    f.linear = compareWithReference(radiance, g, rig, frame, view, tolerance);
    const auto scene =
        makeReferenceScene(*model, rig, frame, view, settings, &f.error, gl.renderer().environment());
    if (!scene) return f;
    const ReferenceImage reference = computeReference(g, *scene);
    f.levels = lr::compareWithReference(image, reference);
    f.levels.nonFinite = countNonFinite(&radiance.pixels.data()->x, std::int64_t(radiance.pixels.size()), 4);
    return f;
}

inline const char* tierName(Quality q) {
    return EnumNames<Quality>::names[size_t(q)];
}

} // namespace lr::test
