// Procedural benchmark rigs: N lights of one type on a ring around the model, placed like the peer
// harness's ../shared/peers/three/add_lights.py (angle 2πi/N, height 1.2·sin(3.1·i), ring radius 2.5;
// one light: (0, 1, 2.5)), hue cycling at saturation 0.35, and a total intensity that does not depend on
// N, so frames stay comparable as N grows. The rig is in `model` space (units of the model's bounding
// radius, centred on it), so the same rig lights any model alike. Area lights (rect, disk) face the centre
// from the same places, a rect 1 × 0.6 radii, a disk of radius 0.4. Used by `lightrig bench` (standard
// suite, --lights) and its tests.
#pragma once

#include "rig.h"

#include <QString>

namespace lr {

struct ProceduralRigOptions {
    LightType type = LightType::Point;
    int count = 1;
    // Point and spot lights: inverse-square falloff with this range in bounding radii (< 0: no range,
    // the glTF default). A small range makes each light cover a small part of the model.
    double range = -1.0;
    // Sum of the lights' intensities; <= 0: a per-type default that exposes the model well at EV 0 with
    // the clamp tone map (point/spot 6, directional 1.6, rim 0.8, rect 20, disk 25 nits: lighttypes.h).
    double totalIntensity = 0.0;
};

Rig proceduralRig(const ProceduralRigOptions& options);

// "8 point", "256 spot", "1 directional" ...
QString proceduralRigName(const ProceduralRigOptions& options);

} // namespace lr
