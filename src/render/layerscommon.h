// What the raster's and the reference's light-group splits (rasterlayers.h, referencelayers.h) share: the
// groups of what a renderer draws, and the auxiliary layers (albedo, normal, depth) read off the G-buffer.
#pragma once

#include "floatimage.h"
#include "scene/renderlayers.h"
#include "scene/scenedescription.h"

#include <glm/mat4x4.hpp>
#include <vector>

namespace lr {

// Whether some material of the model emits (a non-zero emissive factor; an emissive texture is × it).
bool modelEmits(const Model* model);

// The light groups (core/lightgroups.h) of what `scene` draws: rim lights included (both renderers shade
// them), "emissive" when the model emits, "background" always.
std::vector<LightGroup> sceneLightGroups(const SceneDescription& scene);

// Fills layers->albedo, normal and depth from a G-buffer read-back (one sample per pixel: no MSAA) seen
// through `view` (world -> view): the base colour, the shading normal turned to world space and the
// distance along the view axis; rgb 0 (depth kBackgroundDepth) and alpha 0 where no surface is, alpha 1
// where one is.
void fillAuxiliaryLayers(const GBuffer& gbuffer, const glm::dmat4& view, RenderLayers* layers);

} // namespace lr
