// The double reference's light-group split (issue 37; docs/light-mixing.md "The reference"): the same
// evaluation as ReferenceJob (reference.h), each covered pixel's radiance kept per group as well — each
// light's shade.h terms × its traced visibility, an area light's integrated direct terms, the environment's
// integral, the scene ambient, the emission — so the groups sum to the reference's radiance to double
// rounding. The radiance has no background colour (uncovered pixels are 0, alpha 0): "background" is zero.
#pragma once

#include "reference.h"
#include "scene/renderlayers.h"

#include <glm/mat4x4.hpp>
#include <optional>
#include <span>
#include <vector>

namespace lr {

// Asks `scene` (made from `rig`: its lights are the rig's enabled ones, in order) to split by `groups`.
void setReferenceGroups(ReferenceScene* scene, const Rig& rig, const std::vector<LightGroup>& groups);

// One covered pixel's radiance per group into groups[0 .. scene.groups.count): `lights` the pixel's
// (ReferenceScene::lightsAt), `shaded` and `visibility` per light as ReferenceJob uses them (shade.h's
// visibility; the traced one), `areaDirect` each light's unshadowed integrated direct terms (0 for other
// types), `environment` the environment's integral.
void splitReferencePixel(const ReferenceScene& scene, std::span<const lighting::ShadeLight<double>> lights,
                         const lighting::Surface<double>& s, std::span<const double> shaded,
                         std::span<const double> visibility, std::span<const glm::dvec3> areaDirect,
                         const glm::dvec3& environment, glm::dvec3* groups);

// The reference as layers: beauty = its radiance (alpha: covered), one image per group (the split, when
// the scene asked for it; else none), albedo, normal and depth from the G-buffer it evaluated, seen
// through `view` (world -> view).
RenderLayers referenceLayers(const ReferenceImage& reference, const std::vector<LightGroup>& groups,
                             const GBuffer& gbuffer, const glm::dmat4& view);

// The whole of it for what a renderer draws (Renderer::scene()), on the thread pool: the reference scene,
// split by sceneLightGroups, evaluated at `gbuffer`. Null with *error when the reference scene fails.
std::optional<RenderLayers> computeReferenceLayers(const SceneDescription& scene, const GBuffer& gbuffer,
                                                   const glm::dmat4& view, const RenderSettings& settings,
                                                   QString* error = nullptr,
                                                   ReferenceImage* reference = nullptr);

} // namespace lr
