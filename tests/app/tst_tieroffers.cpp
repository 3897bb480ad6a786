// Issue 40's rule in the editor: a tier that does not keep the tiers' promise for the scene
// (core/tieroffer.h, measured by the Quality panel) is greyed out in the Render settings' Quality box with
// the reason as its tooltip; the view leaves it for exact and the status bar says why; a new model offers
// every tier again.
#include "app/qualitydock.h"
#include "app/rendersettingsdock.h"
#include "app/viewsettings.h"
#include "startwindow.h"

#include <QComboBox>
#include <QStandardItemModel>
#include <QStatusBar>
#include <memory>

using namespace lr;

namespace {

// Fast twice exact's time with a light dragged, balanced within its budget everywhere.
TierTimesTable fastTooSlowWhileDragging() {
    TierTimesTable times;
    for (Interaction i : {Interaction::Still, Interaction::Drag, Interaction::Orbit}) {
        times[size_t(Quality::Exact)][i] = 10.0;
        times[size_t(Quality::Balanced)][i] = 9.0;
        times[size_t(Quality::Fast)][i] = 4.0;
    }
    times[size_t(Quality::Fast)][Interaction::Drag] = 20.0;
    return times;
}

} // namespace

class TestTierOffers : public QObject {
    Q_OBJECT
    std::unique_ptr<MainWindow> m_window;

    QComboBox* qualityBox() const {
        return m_window->renderSettingsDock()->findChild<QComboBox*>(QStringLiteral("quality"));
    }
    bool itemEnabled(Quality q) const {
        auto* items = qobject_cast<QStandardItemModel*>(qualityBox()->model());
        return items && items->item(int(q))->isEnabled();
    }
    QString itemToolTip(Quality q) const {
        return qualityBox()->itemData(int(q), Qt::ToolTipRole).toString();
    }

  private slots:
    void initTestCase() {
        test::prepareEditorTest(QStringLiteral("tst_tieroffers"));
        m_window = std::make_unique<MainWindow>();
        const QString error = test::startMainWindow(*m_window);
        QVERIFY2(error.isEmpty(), qPrintable(error));
    }

    void everyTierOfferedBeforeAMeasurement() {
        for (Quality q : {Quality::Exact, Quality::Balanced, Quality::Fast})
            QVERIFY(itemEnabled(q));
    }

    void aTierThatBreaksThePromiseIsWithdrawn() {
        m_window->viewSettings()->setQuality(Quality::Fast);
        auto* dock = m_window->findChild<QualityDock*>();
        QVERIFY(dock);
        dock->setMeasuredTimes(fastTooSlowWhileDragging());
        const TierOffer fast = dock->offers()[size_t(Quality::Fast)];
        QVERIFY(!fast.offered);
        QVERIFY(!itemEnabled(Quality::Fast));
        QCOMPARE(itemToolTip(Quality::Fast), fast.why);
        QVERIFY(itemEnabled(Quality::Exact) && itemEnabled(Quality::Balanced));
        // The view was in fast: it draws in exact now, and says why.
        QVERIFY(m_window->viewSettings()->options().quality == Quality::Exact);
        QCOMPARE(qualityBox()->currentIndex(), int(Quality::Exact));
        QVERIFY2(m_window->statusBar()->currentMessage().contains(fast.why),
                 qPrintable(m_window->statusBar()->currentMessage()));
    }

    void aViewInAnOfferedTierStaysInIt() {
        m_window->viewSettings()->setQuality(Quality::Balanced);
        auto* dock = m_window->findChild<QualityDock*>();
        dock->setMeasuredTimes(fastTooSlowWhileDragging());
        QVERIFY(m_window->viewSettings()->options().quality == Quality::Balanced);
    }

    void aNewModelOffersEveryTierAgain() {
        QVERIFY(!itemEnabled(Quality::Fast));
        emit m_window->scene()->modelChanged();
        QVERIFY(itemEnabled(Quality::Fast));
        QVERIFY(itemToolTip(Quality::Fast).isEmpty());
    }
};

QTEST_MAIN(TestTierOffers)
#include "tst_tieroffers.moc"
