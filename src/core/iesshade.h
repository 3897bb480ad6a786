// An IES profile on a prepared light (issue 39, docs/light-shaping.md "IES profiles"): the photometric frame
// and the scale that turn the profile's candela into the factor lightArrival (shade.h) applies.
//   level "light":   factor = I(θ,φ) / peak × multiplier (the light's intensity sets the level)
//   level "profile": factor = I(θ,φ) × multiplier, and the light's colours lose its intensity (the file's
//                    candela set the level; under PBR a point light's intensity is candela, so the two agree
//                    when intensity = peak)
// The nadir (vertical angle 0) is the light's direction (a point light's too), horizontal angle 0 lies along
// areaAxes(direction, rotation).x and 90 along its y (= x × nadir).
#pragma once

#include "rig.h"
#include "shadetypes.h"

#include <glm/mat4x4.hpp>
#include <memory>
#include <vector>

namespace lr {

// Sets `o`'s IES fields (prepared from `light` for `view`) from `profile`; nothing when either has none.
void applyIesProfile(lighting::ShadeLight<double>& o, const Light& light, const IesProfile* profile,
                     const glm::dmat4& view);

// The factor's scale alone (what the raster packs): multiplier / peak ("light", 0 without light) or
// multiplier ("profile").
double iesScale(const IesSpec& spec, const IesProfile& profile);

} // namespace lr
