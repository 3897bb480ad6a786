// The tiers' promise (issue 40): a cheaper tier is worth offering only where it is cheaper. Balanced takes
// at most exact's time per frame and fast at most half of it, in every interaction measured: the view held
// still, a light dragged, the camera orbiting. A tier that breaks the promise for a scene is not offered
// for it: the editor's Quality panel measures the three interactions for the user's scene and the Render
// settings dock then greys the tier out, with the reason as its tooltip; `lightrig bench` says it under
// its table. GL-free: median times in, a verdict and its reason in plain words out.
#pragma once

#include "quality.h"

#include <QString>
#include <array>
#include <limits>

namespace lr {

// What the user does while the frames are drawn (BenchOptions: neither, dragLight, orbitDegrees).
enum class Interaction { Still, Drag, Orbit };
template <> struct EnumNames<Interaction> { static constexpr std::array names{"still", "drag", "orbit"}; };

// "held still", "with a light dragged", "while orbiting": for sentences.
QString interactionPhrase(Interaction interaction);

// The share of exact's frame time a tier may take: exact and balanced 1, fast ½.
double tierTimeBudget(Quality tier);

// How far over its budget a tier may be before it is not offered. On the 2-core llvmpipe VM the median of
// 30 frames of one scene and tier moved by ±20 % between runs of the same command minutes apart
// (helmet_8pt exact: 6.45–10.09 ms over nine runs, 2026-12-07, docs/quality.md), and balanced, which costs
// about what exact does, should not come and go with that noise.
constexpr double kTierTimeTolerance = 0.20;

// One tier's median milliseconds per frame in each interaction; NaN: not measured. Values that are not
// finite or not above 0 count as not measured.
struct TierTimes {
    std::array<double, 3> ms{std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::quiet_NaN()};
    double& operator[](Interaction i) { return ms[size_t(i)]; }
    double operator[](Interaction i) const { return ms[size_t(i)]; }
    bool has(Interaction i) const;
};

struct TierOffer {
    bool offered = true;
    // Where the promise is broken worst (not offered), or kept with least room: the interaction, the tier's
    // time there over exact's, and both times. ratio 0: nothing to compare (offered).
    Interaction interaction = Interaction::Still;
    double ratio = 0.0;
    double tierMs = 0.0, exactMs = 0.0;
    QString why; // not offered: the reason in plain words; empty otherwise
};

// The verdict for `tier` from its times and exact's, over the interactions both have. Exact is always
// offered, and so is a tier with no interaction to compare.
TierOffer tierOffer(Quality tier, const TierTimes& times, const TierTimes& exact);

} // namespace lr
