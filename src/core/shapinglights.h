// A prepared light with the files its rig light names (issue 39, docs/light-shaping.md): its IES profile
// (core/iesshade.h applyIesProfile) and a spot's gobo image (core/gobo.h). The one place every renderer
// attaches them; scene/lightassets.h loads the files, and whoever calls this keeps them alive.
#pragma once

#include "gobo.h"
#include "iesshade.h"

namespace lr {

// `o` prepared from `light` for `view`: its profile (nullptr: none) and, on a spot with a gobo, its image
// (nullptr: none; the frame and half extent are prepareLight's).
void applyLightShaping(lighting::ShadeLight<double>& o, const Light& light, const IesProfile* profile,
                       const GoboImage* gobo, const glm::dmat4& view);

// The same for prepareLights()'s output (the rig's enabled lights, in order); the files per rig light,
// empty or shorter: none.
void applyLightShaping(std::vector<lighting::ShadeLight<double>>& lights, const Rig& rig,
                       const std::vector<std::shared_ptr<const IesProfile>>& profiles,
                       const std::vector<std::shared_ptr<const GoboImage>>& gobos, const glm::dmat4& view);

} // namespace lr
