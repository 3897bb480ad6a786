#include "tieroffer.h"

#include <QCoreApplication>
#include <cmath>

namespace lr {

namespace {
QString tr(const char* text) {
    return QCoreApplication::translate("TierOffer", text);
}
} // namespace

QString interactionPhrase(Interaction interaction) {
    switch (interaction) {
    case Interaction::Still:
        return tr("held still");
    case Interaction::Drag:
        return tr("with a light dragged");
    case Interaction::Orbit:
        return tr("while orbiting");
    }
    return {};
}

double tierTimeBudget(Quality tier) {
    return tier == Quality::Fast ? 0.5 : 1.0;
}

bool TierTimes::has(Interaction i) const {
    const double v = (*this)[i];
    return std::isfinite(v) && v > 0.0;
}

TierOffer tierOffer(Quality tier, const TierTimes& times, const TierTimes& exact) {
    TierOffer offer;
    if (tier == Quality::Exact) return offer;
    const double budget = tierTimeBudget(tier);
    for (int i = 0; i < enumCount<Interaction>(); ++i) {
        const auto interaction = Interaction(i);
        if (!times.has(interaction) || !exact.has(interaction)) continue;
        const double ratio = times[interaction] / exact[interaction];
        if (offer.ratio > 0.0 && ratio <= offer.ratio) continue; // keep the worst
        offer.interaction = interaction;
        offer.ratio = ratio;
        offer.tierMs = times[interaction];
        offer.exactMs = exact[interaction];
    }
    if (offer.ratio <= budget * (1.0 + kTierTimeTolerance)) return offer;
    offer.offered = false;
    const QString most = tier == Quality::Fast ? tr("half of exact's time") : tr("exact's time");
    offer.why =
        tr("%1 is not offered for this scene: %2 it takes %3 ms a frame, %4× exact's %5 ms, and it "
           "is worth its lower accuracy only at %6 or less. %7")
            .arg(toString(tier), interactionPhrase(offer.interaction), QString::number(offer.tierMs, 'f', 2),
                 QString::number(offer.ratio, 'f', 2), QString::number(offer.exactMs, 'f', 2), most,
                 offer.ratio > 1.0 ? tr("Exact is both faster and more accurate here.")
                                   : tr("Exact is more accurate for little more time here."));
    return offer;
}

} // namespace lr
