// The ground plane as a mesh the renderer draws (issue 14): groundPlane()'s square (src/model/ground.h,
// the plane's one definition) as a grid of quads, so the fast tier's per-vertex lighting has vertices to
// light across it. A visible ground is a grey diffuse surface of Ground::color: classic Lambert without
// specular (ks 0), physically based roughness 1, metallic 0. A catcher uses the same mesh (its colour is
// never shown). Positions are relative to the plane's centre (Model::origin). No GL here.
#pragma once

#include "core/rig.h"
#include "model/ground.h"
#include "model/model.h"

namespace lr::render {

constexpr int kGroundGridCells = 16; // per side

Model groundModel(const GroundPlane& plane, const Ground& ground);
// The model's bounds grown by the ground's square when the ground is on (what the camera's clip planes,
// light culling and the deferred pass's scissor must enclose).
Bounds drawnBounds(const Bounds& model, const Ground& ground);

} // namespace lr::render
