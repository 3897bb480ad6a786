#include "interactionbench.h"

namespace lr {

namespace {

// Degrees the camera turns between orbiting frames, as `lightrig bench --orbit 1`.
constexpr double kOrbitDegreesPerFrame = 1.0;

void addTimes(const BenchReport& report, const QString& scene, Interaction interaction,
              TierTimesTable* times) {
    for (const BenchResult& r : report.results)
        if (!r.uberShader && r.scene == scene) (*times)[size_t(r.quality)][interaction] = r.msMedian;
}

} // namespace

void addStillTimes(const BenchReport& report, const QString& scene, TierTimesTable* times) {
    addTimes(report, scene, Interaction::Still, times);
}

BenchStatus timeInteractions(const BenchScene& scene, const BenchOptions& options, TierTimesTable* times,
                             QString* error, const BenchProgress& progress) {
    BenchOptions timing = options;
    timing.errors = false;
    timing.keepImages = false;
    timing.uberShader = false;
    std::vector<Interaction> interactions;
    if (!scene.rig.lights.empty()) interactions.push_back(Interaction::Drag);
    interactions.push_back(Interaction::Orbit);
    for (size_t i = 0; i < interactions.size(); ++i) {
        timing.dragLight = interactions[i] == Interaction::Drag;
        timing.orbitDegrees = interactions[i] == Interaction::Orbit ? kOrbitDegreesPerFrame : 0.0;
        const double start = double(i) / double(interactions.size());
        const double share = 1.0 / double(interactions.size());
        const BenchProgress part = [&](double fraction, const QString& what) {
            return !progress || progress(start + share * fraction, what);
        };
        BenchReport report;
        const BenchStatus status = runQualityBench({scene}, timing, &report, error, part);
        if (status != BenchStatus::Ok) return status;
        addTimes(report, scene.name, interactions[i], times);
    }
    return BenchStatus::Ok;
}

TierOffers tierOffers(const TierTimesTable& times) {
    TierOffers offers;
    const TierTimes& exact = times[size_t(Quality::Exact)];
    for (int q = 0; q < enumCount<Quality>(); ++q)
        offers[size_t(q)] = tierOffer(Quality(q), times[size_t(q)], exact);
    return offers;
}

} // namespace lr
