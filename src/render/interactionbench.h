// The three interactions of the tiers' promise (core/tieroffer.h) for one scene: a still run of
// runQualityBench times each tier with the view held still; this times the same tiers with a light dragged
// (when the rig has a light) and with the camera orbiting, and gives each tier's verdict. What the
// editor's Quality panel runs after its still measurement (src/app/qualitydock.h).
#pragma once

#include "core/tieroffer.h"
#include "qualitybench.h"

#include <array>

namespace lr {

// Per tier (indexed by Quality), its median ms per frame in each interaction.
using TierTimesTable = std::array<TierTimes, 3>;
using TierOffers = std::array<TierOffer, 3>;

// The still times of a report's specialised runs of `scene` (the über-shader's run is not a tier).
void addStillTimes(const BenchReport& report, const QString& scene, TierTimesTable* times);

// Times every tier of `options.tiers` dragging the rig's first light, then orbiting, with the size and
// frames of `options` and no errors, no über-shader; adds the medians to *times. Progress runs from 0 to 1
// over both runs. A rig without lights is not dragged.
BenchStatus timeInteractions(const BenchScene& scene, const BenchOptions& options, TierTimesTable* times,
                             QString* error, const BenchProgress& progress = {});

// Each tier's verdict against exact's times.
TierOffers tierOffers(const TierTimesTable& times);

} // namespace lr
