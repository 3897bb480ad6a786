// A light mix (issue 37; docs/light-mixing.md): per light group an on/off, an exposure change in EV and a
// tint, applied to the per-group images of a finished render (the mixed image is Σ factor(g) × image(g)),
// written to mix files ("format": "lightrig-mix") for `lightrig mix`, and applied back to a rig so that a
// fresh render gives the mixed image.
#pragma once

#include "lightgroups.h"
#include "rig.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <glm/vec3.hpp>
#include <map>
#include <optional>

namespace lr {

inline constexpr double kMaxMixEV = 20.0;  // ev: -20 ... 20
inline constexpr double kMaxMixTint = 1e3; // tint components: 0 ... 1000
inline constexpr int kLightMixFormatVersion = 1;

struct GroupMix {
    bool enabled = true;
    double ev = 0.0;      // × 2^ev
    glm::dvec3 tint{1.0}; // linear RGB, × per channel
    // What the group's image is multiplied by: tint × 2^ev, or 0 when off.
    glm::dvec3 factor() const;
    bool isIdentity() const { return enabled && ev == 0.0 && tint == glm::dvec3(1.0); }
    bool operator==(const GroupMix&) const = default;
};

struct LightMix {
    std::map<QString, GroupMix> groups; // by group name; a group not listed is left as rendered
    GroupMix of(const QString& group) const;
    bool isIdentity() const;
    bool operator==(const LightMix&) const = default;
};

struct LightMixReadResult {
    std::optional<LightMix> mix; // set only when errors is empty
    QStringList errors;          // "FILE: groups.key.ev: must be a finite number >= -20 and <= 20, got 40"
    QStringList warnings;        // unknown keys
};

// displayName is the FILE part of messages. `known`, when not empty, are the groups the mix will be
// applied to: a group it names that is not among them is an error naming the groups there are.
LightMixReadResult readLightMix(const QByteArray& data, const QString& displayName,
                                const QStringList& known = {});
QByteArray writeLightMix(const LightMix& mix); // canonical, groups in name order, identity groups left out

// The mix written into a rig (the editor's "Apply to rig"): each light group's lights get intensity ×
// 2^ev and colour (and a specular colour, and an ambient term) × tint, with the colour's largest component
// moved into the intensity when it would exceed 1, and are switched off when the group is; the ambient
// group scales the rig's ambient; the environment group adds ev to the environment's intensity. What a
// rig cannot hold (the environment's tint or off, the emissive and background groups, an intensity over
// the format's limit) is left as it is and listed in *notApplied, one line each.
Rig applyLightMix(const Rig& rig, const std::vector<LightGroup>& groups, const LightMix& mix,
                  QStringList* notApplied);

} // namespace lr
