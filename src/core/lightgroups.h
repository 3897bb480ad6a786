// Light groups (issue 37; docs/light-mixing.md): light adds linearly, so an image is the sum of what each
// group of emitters contributes, and a finished render can be re-balanced per group without rendering again.
// The groups of a scene, in this order:
//   - one per distinct Light::group of the enabled lights (a light with none is a group of its own, named
//     after the light, or "light N" when unnamed), in the order of each group's first light;
//   - "environment": the environment's light and its visible background (when the rig has an environment);
//   - "emissive": the model's emissive surfaces (when it has any);
//   - "ambient": the rig's scene ambient term (when it is not black); a light's own ambient term belongs
//     to the light's group;
//   - "background": what no emitter lit: the background colour, and the shadow catcher's composite
//     (which is not linear in the lights: the catcher's pixels re-balance only approximately).
// A light group whose name is one of these four gets " (lights)" appended, so every name is unique. Rim
// lights and disabled lights belong to no group (the path tracer leaves rims out; a disabled light adds
// nothing).
#pragma once

#include "rig.h"

#include <QString>
#include <QStringList>
#include <vector>

namespace lr {

enum class LightGroupKind { Lights, Environment, Emissive, Ambient, Background };

struct LightGroup {
    QString name;
    LightGroupKind kind = LightGroupKind::Lights;
    std::vector<int> lights; // indices into Rig::lights (Lights only)
    bool operator==(const LightGroup&) const = default;
};

// What of the scene besides the rig decides its groups.
struct LightGroupScene {
    bool hasEmissive = false;     // the model has emissive surfaces
    bool includeRims = true;      // false for the path tracer, which leaves rim lights out
    bool alwaysBackground = true; // list "background" even when nothing could fall into it
};

// The name a light's group has: its `group`, else its name, else "light N" (N = index + 1).
QString lightGroupName(const Light& light, int index);

std::vector<LightGroup> lightGroups(const Rig& rig, const LightGroupScene& scene = {});

// For each light of the rig, the index of its group in `groups`, or -1 when it is in none.
std::vector<int> groupOfLights(const Rig& rig, const std::vector<LightGroup>& groups);

QStringList groupNames(const std::vector<LightGroup>& groups);

} // namespace lr
