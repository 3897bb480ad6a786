#include "benchoffers.h"

#include <QStringList>

namespace lr {

Interaction benchInteraction(const BenchOptions& options) {
    if (options.orbitDegrees != 0.0) return Interaction::Orbit;
    return options.dragLight ? Interaction::Drag : Interaction::Still;
}

namespace {

const BenchResult* exactOf(const BenchReport& report, const QString& scene) {
    for (const BenchResult& r : report.results)
        if (!r.uberShader && r.quality == Quality::Exact && r.scene == scene) return &r;
    return nullptr;
}

TierTimes timesOf(Interaction interaction, double ms) {
    TierTimes t;
    t[interaction] = ms;
    return t;
}

} // namespace

TierOffer benchTierOffer(const BenchReport& report, const BenchResult& result) {
    const BenchResult* exact = result.uberShader ? nullptr : exactOf(report, result.scene);
    if (!exact) return {};
    const Interaction interaction = benchInteraction(report.options);
    return tierOffer(result.quality, timesOf(interaction, result.msMedian),
                     timesOf(interaction, exact->msMedian));
}

QString benchOfferLines(const BenchReport& report) {
    QStringList lines;
    QStringList seen;
    for (const BenchResult& r : report.results) {
        if (r.uberShader || seen.contains(r.scene) || !exactOf(report, r.scene)) continue;
        seen << r.scene;
        QStringList verdicts;
        for (const BenchResult& t : report.results) {
            if (t.uberShader || t.scene != r.scene || t.quality == Quality::Exact) continue;
            const TierOffer o = benchTierOffer(report, t);
            if (o.ratio <= 0.0) continue;
            verdicts << QStringLiteral("%1 %2× exact (at most %3×): %4")
                            .arg(toString(t.quality), QString::number(o.ratio, 'f', 2),
                                 QString::number(tierTimeBudget(t.quality), 'g', 2),
                                 o.offered ? QStringLiteral("offered") : QStringLiteral("not offered"));
        }
        if (!verdicts.isEmpty())
            lines << QStringLiteral("  %1: %2").arg(r.scene, verdicts.join(QStringLiteral("; ")));
    }
    if (lines.isEmpty()) return {};
    return QStringLiteral("\nThe tiers' promise, %1 (a tier more than %2% over its share of exact's time is "
                          "not offered for the scene):\n")
               .arg(interactionPhrase(benchInteraction(report.options)))
               .arg(int(kTierTimeTolerance * 100.0)) +
           lines.join(QLatin1Char('\n')) + QLatin1Char('\n');
}

} // namespace lr
