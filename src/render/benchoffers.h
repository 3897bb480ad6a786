// The tiers' promise (core/tieroffer.h) applied to a BenchReport: each run times one interaction (still,
// a light dragged, orbiting), and each tier's result is compared with the exact result of the same scene
// in the same run. `lightrig bench` prints the verdicts under its table and writes them to its JSON.
#pragma once

#include "core/tieroffer.h"
#include "qualitybench.h"

#include <QString>

namespace lr {

// The interaction a run timed: orbiting when the camera turns between frames, else dragging when a light
// moves, else held still.
Interaction benchInteraction(const BenchOptions& options);

// The verdict for one result of the report: offered when it is exact, the über-shader's run, or has no
// exact result of its scene to compare with.
TierOffer benchTierOffer(const BenchReport& report, const BenchResult& result);

// "The tiers' promise …" and one line per scene with its cheaper tiers' ratios and verdicts; empty when no
// scene has an exact result and another tier.
QString benchOfferLines(const BenchReport& report);

} // namespace lr
