// The editor's check of a rig's environment (issue 15; RigProperty::Environment in lightproperty.h): every
// value finite and within the rig format's ranges (docs/rig-format.md "environment"), so an edited rig always
// saves and loads again. The messages name the field as the rig file does ("environment.studio.softboxes[1].
// width must be ...").
#pragma once

#include "core/environment.h"
#include "core/rigjson.h"

#include <QString>

namespace lr {

// The ranges: the rig format's one table (core/rigjson.h, docs/rig-format.md "environment").
namespace envlimits {
inline constexpr double kMaxEv = kMaxEnvironmentEV;
inline constexpr double kMaxSoftbox = kMaxSoftboxAngle;
inline constexpr double kMaxSpotAngle = kMaxEnvironmentSpotAngle;
inline constexpr int kMaxSoftboxes = kMaxEnvironmentSoftboxes;
inline constexpr int kMaxSpots = kMaxEnvironmentSpots;
inline constexpr int kMaxFileLength = kMaxEnvironmentPathLength;
} // namespace envlimits

// Empty when valid, else the first problem.
QString validateEnvironment(const Environment& environment);

// The history's text for an edit from `before` to `after`, naming the one field that changed ("Change
// environment intensity", "Change studio softboxes"); "Change environment" when several did.
QString environmentChangeText(const Environment& before, const Environment& after);

} // namespace lr
