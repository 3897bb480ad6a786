#include "lightimport.h"

#include "core/fallofftraits.h"

namespace lr {

std::vector<Light> lightsInRigSpace(const Rig& worldLights, const Rig& target, const SceneFrame& frame) {
    Rig worldRig; // a world-space rig: its distanceScale is 1
    worldRig.space = RigSpace::World;
    const double s =
        distanceScale(target, frame) / distanceScale(worldRig, frame); // world units -> rig units
    std::vector<Light> out;
    out.reserve(worldLights.lights.size());
    for (Light l : worldLights.lights) {
        if (l.usesPosition())
            l.position = worldToRig(target, frame, rigToWorld(worldLights, frame, l.position));
        // The shader measures d in rig units (d_rig = s * d_world): keep a(d) the same function of d_world.
        if (l.usesFalloff() && s != 1.0) scaleFalloffLengths(l.falloff, l.intensity, s);
        out.push_back(l);
    }
    return out;
}

} // namespace lr
