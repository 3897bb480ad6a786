// The editor's check of a rig's environment (issue 15; RigProperty::Environment in lightproperty.h): every
// value finite and within the rig format's ranges (docs/rig-format.md "environment"), so an edited rig always
// saves and loads again. The messages name the field as the rig file does ("environment.studio.softboxes[1].
// width must be ...").
#pragma once

#include "core/environment.h"

#include <QString>

namespace lr {

// The ranges (core/environment.h documents them on the fields).
inline constexpr double kMaxEnvironmentEv = 20.0;         // intensity in EV: -20 ... 20
inline constexpr double kMaxSoftboxExtent = 170.0;        // softbox width and height, degrees: (0, 170]
inline constexpr double kMaxEnvironmentSpotAngle = 180.0; // a dimmed spot's radius, degrees: (0, 180]
inline constexpr int kMaxSoftboxes = 64;                  // the studio's softbox list
inline constexpr int kMaxEnvironmentSpots = 256;          // dimmed spots
inline constexpr int kMaxEnvironmentFileLength = 4096;    // characters

// Empty when valid, else the first problem.
QString validateEnvironment(const Environment& environment);

} // namespace lr
