// The editor's check of a rig's environment (issue 15; RigProperty::Environment in lightproperty.h): every
// value finite and within the rig format's ranges (docs/rig-format.md "environment"), so an edited rig always
// saves and loads again. The messages name the field as the rig file does ("environment.studio.softboxes[1].
// width must be ...").
#pragma once

#include "core/environment.h"

#include <QString>

namespace lr {

// The ranges, the rig format's (docs/rig-format.md "environment"). When the rig JSON's environment block is
// merged, core/rigjson.h's kMaxEnvironmentEV, kMaxSoftboxAngle, kMaxEnvironmentSpotAngle,
// kMaxEnvironmentSoftboxes, kMaxEnvironmentSpots and kMaxEnvironmentPathLength are the one table: these
// then name them (same values).
namespace envlimits {
inline constexpr double kMaxEv = 20.0;        // intensity in EV: -20 ... 20
inline constexpr double kMaxSoftbox = 170.0;  // softbox width and height, degrees: (0, 170]
inline constexpr double kMaxSpotAngle = 90.0; // a dimmed spot's radius, degrees: (0, 90]
inline constexpr int kMaxSoftboxes = 32;      // the studio's softbox list
inline constexpr int kMaxSpots = 64;          // dimmed spots
inline constexpr int kMaxFileLength = 4096;   // characters
} // namespace envlimits

// Empty when valid, else the first problem.
QString validateEnvironment(const Environment& environment);

} // namespace lr
