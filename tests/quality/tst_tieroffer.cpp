// The tiers' promise (core/tieroffer.h): balanced within exact's time, fast within half of it, in every
// interaction measured, with the stated tolerance; what is not measured (NaN, ∞, ≤ 0) does not count; the
// reason names the tier, the interaction, both times and the ratio.
#include "core/tieroffer.h"

#include <QTest>
#include <cmath>
#include <limits>

using namespace lr;

namespace {

TierTimes times(double still, double drag = std::nan(""), double orbit = std::nan("")) {
    TierTimes t;
    t[Interaction::Still] = still;
    t[Interaction::Drag] = drag;
    t[Interaction::Orbit] = orbit;
    return t;
}

} // namespace

class TestTierOffer : public QObject {
    Q_OBJECT
  private slots:
    void exactIsAlwaysOffered() {
        const TierOffer o = tierOffer(Quality::Exact, times(100.0), times(1.0));
        QVERIFY(o.offered);
        QVERIFY(o.why.isEmpty());
    }

    void budgets() {
        QCOMPARE(tierTimeBudget(Quality::Exact), 1.0);
        QCOMPARE(tierTimeBudget(Quality::Balanced), 1.0);
        QCOMPARE(tierTimeBudget(Quality::Fast), 0.5);
    }

    void fastWithinHalfIsOffered() {
        const TierOffer o = tierOffer(Quality::Fast, times(4.0, 4.5, 5.0), times(10.0, 10.0, 10.0));
        QVERIFY2(o.offered, qPrintable(o.why));
        QVERIFY(o.interaction == Interaction::Orbit); // the least room
        QCOMPARE(o.ratio, 0.5);
    }

    void theToleranceAndNoMore() {
        const double edge = 0.5 * (1.0 + kTierTimeTolerance);
        QVERIFY(tierOffer(Quality::Fast, times(edge * 10.0 - 1e-9), times(10.0)).offered);
        QVERIFY(!tierOffer(Quality::Fast, times(edge * 10.0 + 0.01), times(10.0)).offered);
        const double balancedEdge = 10.0 * (1.0 + kTierTimeTolerance);
        QVERIFY(tierOffer(Quality::Balanced, times(balancedEdge - 0.05), times(10.0)).offered);
        QVERIFY(!tierOffer(Quality::Balanced, times(balancedEdge + 0.05), times(10.0)).offered);
    }

    // Still and orbiting are fine; a dragged light is not: one interaction is enough to withdraw it.
    void oneBrokenInteractionIsEnough() {
        const TierOffer o = tierOffer(Quality::Fast, times(4.0, 18.0, 5.0), times(10.0, 9.0, 12.0));
        QVERIFY(!o.offered);
        QVERIFY(o.interaction == Interaction::Drag);
        QCOMPARE(o.ratio, 2.0);
        QCOMPARE(o.tierMs, 18.0);
        QCOMPARE(o.exactMs, 9.0);
        QVERIFY2(o.why.contains(QLatin1String("fast")), qPrintable(o.why));
        QVERIFY2(o.why.contains(interactionPhrase(Interaction::Drag)), qPrintable(o.why));
        QVERIFY2(o.why.contains(QLatin1String("18.00")) && o.why.contains(QLatin1String("9.00")),
                 qPrintable(o.why));
        QVERIFY2(o.why.contains(QStringLiteral("2.00×")), qPrintable(o.why));
        QVERIFY2(o.why.contains(QLatin1String("faster and more accurate")), qPrintable(o.why));
    }

    // Fast at 0.85× exact: faster, but not enough to be worth its error.
    void slightlyFasterIsNotEnough() {
        const TierOffer o = tierOffer(Quality::Fast, times(8.5), times(10.0));
        QVERIFY(!o.offered);
        QVERIFY2(o.why.contains(QLatin1String("little more time")), qPrintable(o.why));
    }

    void unmeasuredTimesDoNotCount() {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        const double inf = std::numeric_limits<double>::infinity();
        for (double bad : {nan, inf, -inf, 0.0, -1.0}) {
            // The bad figure on either side of the one broken interaction hides it.
            QVERIFY(tierOffer(Quality::Fast, times(4.0, bad), times(10.0, 2.0)).offered);
            QVERIFY(tierOffer(Quality::Fast, times(4.0, 30.0), times(10.0, bad)).offered);
            // and does not hide another.
            QVERIFY(!tierOffer(Quality::Fast, times(9.0, bad), times(10.0, 2.0)).offered);
        }
        QVERIFY(tierOffer(Quality::Fast, TierTimes{}, times(10.0)).offered); // nothing to compare
        QVERIFY(!TierTimes{}.has(Interaction::Still));
    }
};

QTEST_GUILESS_MAIN(TestTierOffer)
#include "tst_tieroffer.moc"
