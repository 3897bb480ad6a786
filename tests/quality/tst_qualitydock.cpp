// The editor's Quality panel: a measurement of the current scene fills the table (one row per tier and
// the über-shader) and the chart, reports progress, can be cancelled, says why when there is nothing to
// measure, and "Use tier" hands the selected row's tier to the view settings.
#include "app/qualitydock.h"
#include "render/glfixture.h"
#include "render/scenes.h"

#include <QApplication>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <QTimer>

using namespace lr;
using namespace lr::test;

namespace {

QualityRequest sphereRequest() {
    QualityRequest r;
    r.scene.name = QStringLiteral("sphere");
    r.scene.model = sphereScene();
    r.scene.rig = rigCases().back().make(); // mixed-all-types
    r.scene.camera = sphereCamera();
    r.viewportSize = QSize(96, 72);
    return r;
}

} // namespace

class TestQualityDock : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { LR_REQUIRE_DISPLAY(); }

    void measuresTheCurrentScene() {
        QualityDock dock;
        dock.setFrames(3);
        dock.setSceneProvider([](QString*) { return std::optional<QualityRequest>(sphereRequest()); });
        std::optional<Quality> chosen;
        dock.setTierChooser([&](Quality q) { chosen = q; });
        auto* progress = dock.findChild<QProgressBar*>();
        QVERIFY(progress);
        int progressUpdates = 0;
        connect(progress, &QProgressBar::valueChanged, this, [&] { ++progressUpdates; });
        QSignalSpy finished(&dock, &QualityDock::finished);
        dock.measure();
        QCOMPARE(finished.count(), 1);
        QVERIFY2(finished.first().at(0).toBool(), qPrintable(finished.first().at(1).toString()));
        QVERIFY(!dock.isRunning());
        QVERIFY(progressUpdates > 3);
        QCOMPARE(progress->value(), progress->maximum());

        auto* table = dock.findChild<QTableWidget*>();
        QVERIFY(table);
        QCOMPARE(table->rowCount(), 4); // exact, balanced, fast, über-shader
        QCOMPARE(int(dock.report().results.size()), 4);
        QCOMPARE(dock.report().results[0].size, QSize(96, 72)); // the viewport's size by default
        QCOMPARE(table->item(2, 0)->text(), QStringLiteral("fast"));
        for (const BenchResult& r : dock.report().results)
            QVERIFY(r.hasErrors && r.errors.nonFinite == 0);
        bool chart = false;
        for (QLabel* label : dock.findChildren<QLabel*>())
            chart |= !label->pixmap().isNull();
        QVERIFY(chart);

        auto* use = [&]() -> QPushButton* {
            for (QPushButton* b : dock.findChildren<QPushButton*>())
                if (b->text() == QLatin1String("Use tier")) return b;
            return nullptr;
        }();
        QVERIFY(use);
        QVERIFY(!use->isEnabled());

        // Issue 40: every tier timed held still, with a light dragged and orbiting; the Offered column and
        // the Use button follow each tier's verdict on those times.
        const QStringList names = QualityDock::columnNames();
        const int offeredColumn = int(names.indexOf(QStringLiteral("Offered")));
        QVERIFY(offeredColumn > 0);
        for (int q = 0; q < 3; ++q) {
            const TierTimes& t = dock.times()[size_t(q)];
            for (Interaction i : {Interaction::Still, Interaction::Drag, Interaction::Orbit})
                QVERIFY2(t.has(i), qPrintable(toString(Quality(q)) + QLatin1Char(' ') + toString(i)));
            QCOMPARE(t[Interaction::Still], dock.report().results[size_t(q)].msMedian);
            const TierOffer expected = tierOffer(Quality(q), t, dock.times()[0]);
            QCOMPARE(dock.offers()[size_t(q)].offered, expected.offered);
            QCOMPARE(table->item(q, offeredColumn)->text(),
                     expected.offered ? QStringLiteral("yes") : QStringLiteral("no"));
            QCOMPARE(table->item(q, offeredColumn)->toolTip(), expected.why);
            table->selectRow(q);
            QCOMPARE(use->isEnabled(), expected.offered);
        }
        QCOMPARE(table->item(3, offeredColumn)->text(), QStringLiteral("–")); // the über-shader is no tier
        table->selectRow(0);
        QVERIFY(use->isEnabled()); // exact is always offered
        use->click();
        QVERIFY(chosen && *chosen == Quality::Exact);
        table->selectRow(1);

        // Issue 12 item 9: the visual comparison of the selected tier (balanced now) with the reference.
        const BenchResult& balanced = dock.report().results[1];
        QCOMPARE(balanced.image.size(), QSize(96, 72));
        QCOMPARE(balanced.reference.size(), QSize(96, 72));
        dock.resize(900, 700);
        dock.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dock));
        for (const char* name : {"tierImage", "referenceImage", "differenceImage"}) {
            auto* label = dock.findChild<QLabel*>(QLatin1String(name));
            QVERIFY2(label && !label->pixmap().isNull(), name);
        }
        table->selectRow(2); // fast: per-vertex lighting differs visibly from the reference
        const BenchResult& fast = dock.report().results[2];
        QVERIFY(fast.errors.maxLevels > 1);
        const QImage diff = benchDifferenceImage(fast.image, fast.reference);
        QVERIFY(!diff.isNull() && diff.size() == fast.image.size());
        QVERIFY(diff != benchDifferenceImage(fast.reference, fast.reference));
        // The chart has room: at least kMinChartSize, growing with the dock.
        auto* chartLabel = dock.findChild<QLabel*>(QStringLiteral("qualityChart"));
        QVERIFY(chartLabel && chartLabel->width() >= 360 && chartLabel->height() >= 230);
    }

    // The table speaks plainly: no engineer's shorthand in the headers, a tooltip on every column.
    void columnsHavePlainNamesAndTooltips() {
        QualityDock dock;
        auto* table = dock.findChild<QTableWidget*>();
        QVERIFY(table);
        QCOMPARE(table->columnCount(), int(QualityDock::columnNames().size()));
        for (int c = 0; c < table->columnCount(); ++c) {
            const QTableWidgetItem* header = table->horizontalHeaderItem(c);
            QVERIFY(header);
            for (const char* jargon : {"PSNR", ">1 lvl", "×exact", "cpu×", "ms med", "lvl"})
                QVERIFY2(!header->text().contains(QLatin1String(jargon)), qPrintable(header->text()));
            QVERIFY2(header->toolTip().size() > 30, qPrintable(header->text()));
        }
    }

    // The shadow measure's two columns show only for a rig with casting lights (issue 14).
    void shadowColumnsOnlyWithCasters() {
        for (bool shadows : {false, true}) {
            QualityDock dock;
            dock.setFrames(2);
            dock.setSceneProvider([shadows](QString*) {
                QualityRequest r = sphereRequest();
                for (Light& l : r.scene.rig.lights)
                    l.shadow.enabled = shadows;
                return std::optional<QualityRequest>(r);
            });
            QSignalSpy finished(&dock, &QualityDock::finished);
            dock.measure();
            QVERIFY2(finished.count() == 1 && finished.first().at(0).toBool(),
                     qPrintable(finished.first().at(1).toString()));
            auto* table = dock.findChild<QTableWidget*>();
            const QStringList names = QualityDock::columnNames();
            const int first = int(names.indexOf(QStringLiteral("Shadow pixels off")));
            QVERIFY(first > 0 && names.indexOf(QStringLiteral("Shadow error")) == first + 1);
            for (int c : {first, first + 1})
                QCOMPARE(table->isColumnHidden(c), !shadows);
            QCOMPARE(table->item(0, first)->text().endsWith(QLatin1Char('%')), shadows);
            QVERIFY(!table->isColumnHidden(first - 1)); // the columns before stay
        }
    }

    // Times that break the promise withdraw the tier (Use greyed out, the reason as its tooltip);
    // clearOffers offers every tier again. Each emits offersChanged.
    void measuredTimesDecideTheOffers() {
        QualityDock dock;
        dock.setTierChooser([](Quality) {});
        QSignalSpy changed(&dock, &QualityDock::offersChanged);
        TierTimesTable times;
        for (int q = 0; q < 3; ++q)
            times[size_t(q)][Interaction::Orbit] = 10.0;
        times[size_t(Quality::Fast)][Interaction::Orbit] = 4.0;
        times[size_t(Quality::Fast)][Interaction::Drag] = 12.0;
        times[size_t(Quality::Exact)][Interaction::Drag] = 6.0;
        dock.setMeasuredTimes(times);
        QCOMPARE(changed.count(), 1);
        QVERIFY(dock.offers()[size_t(Quality::Balanced)].offered);
        const TierOffer fast = dock.offers()[size_t(Quality::Fast)];
        QVERIFY(!fast.offered);
        QVERIFY(fast.interaction == Interaction::Drag);
        QCOMPARE(fast.ratio, 2.0);
        dock.clearOffers();
        QCOMPARE(changed.count(), 2);
        for (const TierOffer& o : dock.offers())
            QVERIFY(o.offered);
        QVERIFY(!dock.times()[0].has(Interaction::Orbit));
    }

    void differenceImage_blackWhereEqual_brightWhereNot() {
        QImage a(4, 2, QImage::Format_RGBA8888);
        a.fill(QColor(100, 100, 100));
        QImage b = a;
        b.setPixelColor(1, 1, QColor(100, 110, 100)); // 10 levels in green
        const QImage d = benchDifferenceImage(a, b, 16);
        QCOMPARE(d.pixel(0, 0), qRgb(0, 0, 0));
        QCOMPARE(d.pixel(1, 1), qRgb(160, 0, 0)); // 10 levels × 16 = 160: dark red
        QCOMPARE(benchDifferenceImage(a, b, 60).pixel(1, 1), qRgb(255, 255, 90)); // 600: yellow towards white
        QVERIFY(benchDifferenceImage(a, QImage(3, 3, QImage::Format_RGBA8888)).isNull());
    }

    void cancelStopsTheMeasurement() {
        QualityDock dock;
        dock.setFrames(200);
        dock.setSceneProvider([](QString*) { return std::optional<QualityRequest>(sphereRequest()); });
        QSignalSpy finished(&dock, &QualityDock::finished);
        QTimer::singleShot(0, &dock, &QualityDock::cancel); // runs inside the measurement's event processing
        dock.measure();
        QCOMPARE(finished.count(), 1);
        QVERIFY(!finished.first().at(0).toBool());
        QVERIFY(!dock.isRunning());
        QVERIFY(dock.report().results.empty());
    }

    void saysWhyWhenThereIsNothingToMeasure() {
        QualityDock dock;
        dock.setSceneProvider([](QString* why) {
            *why = QStringLiteral("no model is loaded");
            return std::optional<QualityRequest>();
        });
        QSignalSpy finished(&dock, &QualityDock::finished);
        dock.measure();
        QCOMPARE(finished.count(), 1);
        QVERIFY(!finished.first().at(0).toBool());
        QVERIFY(finished.first().at(1).toString().contains(QStringLiteral("no model is loaded")));
    }
};

int main(int argc, char** argv) {
    if (!lr::test::haveDisplay()) qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    TestQualityDock tc;
    QTEST_SET_MAIN_SOURCE_PATH
    return QTest::qExec(&tc, argc, argv);
}

#include "tst_qualitydock.moc"
