// Importing a model file's own lights (world space, model.h) into the rig being edited, which may be in
// model space (units of the model's bounding-sphere radius): positions, ranges and the distance-dependent
// falloff terms are converted so every light lights the model exactly as it did in world units.
#pragma once

#include "core/prepare.h"

#include <vector>

namespace lr {

// `worldLights` in RigSpace::World; returns its lights expressed in `target`'s space.
std::vector<Light> lightsInRigSpace(const Rig& worldLights, const Rig& target, const SceneFrame& frame);

} // namespace lr
