// Quality tiers: how the renderer evaluates a rig's lighting model (never what it is). Stored in the user's
// settings and given on the command line (--quality), not in rig files. Names via toString/fromString
// (types.h): "exact", "balanced", "fast".
#pragma once

#include "types.h"

namespace lr {

// Exact: per-pixel, exact acos, local viewer as the rig asks, MSAA on.
// Balanced: per-pixel with measured cheaper evaluations. Fast: per-vertex (Gouraud) lighting, no MSAA,
// bilinear texture filtering in the nearest mip level.
// docs/quality.md names and measures every approximation (and why fast keeps the rig's viewer).
enum class Quality { Exact, Balanced, Fast };

template <> struct EnumNames<Quality> { static constexpr std::array names{"exact", "balanced", "fast"}; };

} // namespace lr
