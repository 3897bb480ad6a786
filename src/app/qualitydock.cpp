#include "qualitydock.h"

#include "editor/document.h"
#include "mainwindow.h"
#include "render/benchreport.h"
#include "rendersettingsdock.h"
#include "scene.h"
#include "viewport.h"
#include "viewsettings.h"

#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QScreen>
#include <QSpinBox>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>
#include <cmath>

namespace lr {

namespace {
constexpr QSize kMinChartSize(360, 230);
constexpr int kDifferenceGain = 16;
constexpr int kShadowColumns = 12; // the first of the shadow measure's columns (columnNames)
constexpr int kOfferedColumn = 5;
// The share of the progress bar the still measurement (with the reference) takes; the two interactions
// without errors take the rest.
constexpr double kStillShare = 0.75;
} // namespace

QualityDock::QualityDock(QWidget* parent) : QDockWidget(tr("Quality"), parent) {
    setObjectName(QStringLiteral("QualityDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);

    auto* controls = new QHBoxLayout;
    m_sizeChoice = new QComboBox(body);
    m_sizeChoice->addItem(tr("Viewport size"), QSize());
    for (const QSize s : {QSize(640, 360), QSize(1280, 720), QSize(1920, 1080)})
        m_sizeChoice->addItem(QStringLiteral("%1×%2").arg(s.width()).arg(s.height()), s);
    m_sizeChoice->setToolTip(tr("Image size the tiers are measured at"));
    m_frames = new QSpinBox(body);
    m_frames->setRange(3, 1000);
    m_frames->setValue(30);
    m_frames->setSuffix(tr(" frames"));
    m_frames->setToolTip(tr("Timed frames per tier (after 5 warm-up frames)"));
    m_run = new QPushButton(tr("Measure"), body);
    m_run->setToolTip(
        tr("Time every quality tier on the current scene and view and measure its error against the "
           "double-precision reference"));
    m_stop = new QPushButton(tr("Cancel"), body);
    controls->addWidget(m_sizeChoice);
    controls->addWidget(m_frames);
    controls->addStretch(1);
    controls->addWidget(m_run);
    controls->addWidget(m_stop);
    layout->addLayout(controls);

    m_progress = new QProgressBar(body);
    m_progress->setRange(0, 1000);
    m_progress->setValue(0);
    m_progress->setTextVisible(false);
    m_status =
        new QLabel(tr("Measure the price of each tier (time) and its cost (error) for this scene."), body);
    m_status->setWordWrap(true);
    layout->addWidget(m_progress);
    layout->addWidget(m_status);

    auto* split = new QSplitter(Qt::Vertical, body);
    split->setObjectName(QStringLiteral("qualitySplitter"));
    split->setChildrenCollapsible(false);
    const QStringList names = columnNames(), tips = columnToolTips();
    m_table = new QTableWidget(0, int(names.size()), split);
    for (int c = 0; c < names.size(); ++c) {
        auto* header = new QTableWidgetItem(names[c]);
        header->setToolTip(tips[c]);
        m_table->setHorizontalHeaderItem(c, header);
        m_table->setColumnHidden(c, c >= kShadowColumns); // until a report with shadow casters
    }
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setWordWrap(true);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->horizontalHeader()->setDefaultAlignment(
        Qt::Alignment(QFlag(int(Qt::AlignCenter) | int(Qt::TextWordWrap))));
    m_table->setMinimumHeight(120);

    auto* views = new QTabWidget(split);
    views->setObjectName(QStringLiteral("qualityViews"));
    m_chart = new QLabel(views);
    m_chart->setObjectName(QStringLiteral("qualityChart"));
    m_chart->setAlignment(Qt::AlignCenter);
    m_chart->setMinimumSize(kMinChartSize);
    m_chart->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    m_chart->setToolTip(tr("Each tier as a point: time per frame across, average error up; lower left is "
                           "cheaper and closer to the reference"));
    m_chart->installEventFilter(this);
    views->addTab(m_chart, tr("Chart"));

    auto* compare = new QWidget(views);
    auto* grid = new QGridLayout(compare);
    m_compareCaption =
        new QLabel(tr("Measure, then pick a row to compare its image with the reference."), compare);
    m_compareCaption->setWordWrap(true);
    grid->addWidget(m_compareCaption, 0, 0, 1, 3);
    auto image = [&](const QString& name, const QString& title, const QString& tip, int column) {
        auto* caption = new QLabel(title, compare);
        caption->setAlignment(Qt::AlignCenter);
        caption->setToolTip(tip);
        auto* label = new QLabel(compare);
        label->setObjectName(name);
        label->setAlignment(Qt::AlignCenter);
        label->setMinimumSize(120, 90);
        label->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
        label->setToolTip(tip);
        label->installEventFilter(this);
        grid->addWidget(caption, 1, column);
        grid->addWidget(label, 2, column);
        return label;
    };
    m_tierImage = image(QStringLiteral("tierImage"), tr("This tier"),
                        tr("The selected tier's picture (single sample, as measured)"), 0);
    m_referenceImage =
        image(QStringLiteral("referenceImage"), tr("Reference"),
              tr("The same view computed in double precision on the CPU: what the tiers aim for"), 1);
    m_differenceImage =
        image(QStringLiteral("differenceImage"), tr("Difference (×%1)").arg(kDifferenceGain),
              tr("Where the two differ: black is identical; red to yellow to white is a larger "
                 "difference, amplified %1 times so single levels show")
                  .arg(kDifferenceGain),
              2);
    grid->setRowStretch(2, 1);
    views->addTab(compare, tr("Compare images"));
    split->addWidget(m_table);
    split->addWidget(views);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 2);
    layout->addWidget(split, 1);

    auto* bottom = new QHBoxLayout;
    m_large = new QPushButton(tr("Open large"), body);
    m_large->setToolTip(tr("Float this panel in its own large window (drag it back to dock it again)"));
    connect(m_large, &QPushButton::clicked, this, &QualityDock::openLarge);
    bottom->addWidget(m_large);
    m_use = new QPushButton(tr("Use tier"), body);
    m_use->setToolTip(tr("Render the viewport with the tier of the selected row"));
    m_use->setEnabled(false);
    bottom->addStretch(1);
    bottom->addWidget(m_use);
    layout->addLayout(bottom);
    setWidget(body);

    connect(m_run, &QPushButton::clicked, this, &QualityDock::measure);
    connect(m_stop, &QPushButton::clicked, this, &QualityDock::cancel);
    connect(m_table, &QTableWidget::itemSelectionChanged, this, [this] {
        setRunning(m_running); // the Use button follows the row
        updateComparison();
    });
    connect(m_use, &QPushButton::clicked, this, [this] {
        const int row = m_table->currentRow();
        if (m_chooser && row >= 0 && row < int(m_report.results.size()))
            m_chooser(m_report.results[size_t(row)].quality);
    });
    setRunning(false);
}

void QualityDock::setFrames(int frames) {
    m_frames->setValue(frames);
}

void QualityDock::setRunning(bool running) {
    m_running = running;
    m_run->setEnabled(!running);
    m_stop->setEnabled(running);
    m_sizeChoice->setEnabled(!running);
    m_frames->setEnabled(!running);
    const int row = m_table->currentRow();
    const bool result = row >= 0 && row < int(m_report.results.size());
    const TierOffer offer = result ? m_offers[size_t(m_report.results[size_t(row)].quality)] : TierOffer{};
    m_use->setEnabled(!running && m_chooser && result && offer.offered);
    m_use->setToolTip(offer.offered ? tr("Render the viewport with the tier of the selected row")
                                    : offer.why);
}

void QualityDock::setMeasuredTimes(const TierTimesTable& times) {
    m_times = times;
    m_offers = tierOffers(times);
    setRunning(m_running);
    emit offersChanged();
}

void QualityDock::clearOffers() {
    setMeasuredTimes({});
}

void QualityDock::cancel() {
    if (m_running) m_cancelRequested = true;
}

void QualityDock::measure() {
    if (m_running) return;
    QString why;
    const std::optional<QualityRequest> request = m_provider ? m_provider(&why) : std::nullopt;
    if (!request) {
        m_status->setText(tr("Nothing to measure: %1").arg(why.isEmpty() ? tr("no scene") : why));
        emit finished(false, m_status->text());
        return;
    }
    BenchOptions options;
    const QSize chosen = m_sizeChoice->currentData().toSize();
    options.size = chosen.isValid()
                       ? chosen
                       : request->viewportSize.expandedTo(QSize(16, 16)).boundedTo(QSize(4096, 4096));
    options.frames = m_frames->value();
    options.exposureEV = request->exposureEV;
    options.toneMap = request->toneMap;
    options.keepImages = true; // the visual comparison
    m_cancelRequested = false;
    setRunning(true);
    m_progress->setValue(0);
    double progressStart = 0.0, progressShare = kStillShare;
    const BenchProgress progress = [&, this](double fraction, const QString& what) {
        m_progress->setValue(int((progressStart + progressShare * fraction) * 1000.0));
        m_status->setText(what);
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        return !m_cancelRequested;
    };
    BenchReport report;
    QString error;
    BenchStatus status = runQualityBench({request->scene}, options, &report, &error, progress);
    TierTimesTable times;
    if (status == BenchStatus::Ok) { // the tiers' promise: a light dragged and the camera orbiting too
        addStillTimes(report, request->scene.name, &times);
        progressStart = kStillShare;
        progressShare = 1.0 - kStillShare;
        status = timeInteractions(request->scene, options, &times, &error, progress);
    }
    setRunning(false);
    switch (status) {
    case BenchStatus::Ok: {
        m_report = report;
        setMeasuredTimes(times); // the verdicts first: the table shows them
        showReport();
        m_progress->setValue(1000);
        QStringList withdrawn;
        for (int q = 0; q < enumCount<Quality>(); ++q)
            if (!m_offers[size_t(q)].offered) withdrawn << toString(Quality(q));
        m_status->setText(tr("%1 at %2×%3 on %4. Errors are 8-bit sRGB levels against the double-precision "
                             "reference over the model's pixels.%5")
                              .arg(request->scene.name)
                              .arg(options.size.width())
                              .arg(options.size.height())
                              .arg(report.glDescription,
                                   withdrawn.isEmpty()
                                       ? QString()
                                       : tr(" Not offered for this scene, too slow for what they give up: %1 "
                                            "(hover Offered for why).")
                                             .arg(withdrawn.join(QStringLiteral(", ")))));
        emit finished(true, m_status->text());
        break;
    }
    case BenchStatus::Cancelled:
        m_progress->setValue(0);
        m_status->setText(tr("Cancelled."));
        emit finished(false, m_status->text());
        break;
    case BenchStatus::Failed:
        m_progress->setValue(0);
        m_status->setText(tr("Measurement failed: %1").arg(error));
        emit finished(false, m_status->text());
        break;
    }
}

QStringList QualityDock::columnNames() {
    return {tr("Tier"),
            tr("Time per frame"),
            tr("Dragging a light"),
            tr("Orbiting"),
            tr("Speed"),
            tr("Offered"),
            tr("First frame"),
            tr("Worst pixel"),
            tr("Average error"),
            tr("Pixels visibly off"),
            tr("Similarity"),
            tr("Broken pixels"),
            tr("Shadow pixels off"),
            tr("Shadow error")};
}

QStringList QualityDock::columnToolTips() {
    return {
        tr("The quality tier. exact: every light per pixel, as the double-precision model; balanced: cheaper "
           "evaluations per pixel; fast: lighting per vertex. \"exact, all models\" is exact drawn with one "
           "shader that has every light model compiled in, to show what specialised shaders save."),
        tr("Median time to draw one frame at the measured size with the view held still, in milliseconds "
           "(lower is better). Hover a cell for the fastest and slowest frame and the processor time."),
        tr("Median time per frame while the first light moves a little every frame, as while you drag it: "
           "what the view keeps of a still frame helps, the moved light's shadow is drawn again."),
        tr("Median time per frame while the camera turns a degree every frame, as while you orbit: nothing "
           "the view keeps of a still frame helps."),
        tr("How many times faster than the exact tier with the view held still (2.0× = twice as fast)."),
        tr("Whether the tier is worth its lower accuracy for this scene: balanced must take at most exact's "
           "time per frame and fast at most half of it, held still, with a light dragged and while "
           "orbiting (%1% leeway for the measurement's noise). A tier that is not is greyed out in the "
           "Render settings; hover a cell for the reason.")
            .arg(int(kTierTimeTolerance * 100.0)),
        tr("Time to the first picture in a fresh window, in milliseconds: loading the model, uploading it, "
           "compiling the shaders and drawing."),
        tr("The largest difference from the reference on any pixel, in 8-bit colour levels (0 = identical, "
           "255 = white instead of black)."),
        tr("The average difference from the reference over the model's pixels, in 8-bit colour levels."),
        tr("Share of the model's pixels that differ from the reference by more than one colour level (a "
           "difference of one level cannot be seen)."),
        tr("Peak signal-to-noise ratio against the reference, in decibels: higher is closer; above about 40 "
           "dB "
           "a difference is hard to see; ∞ means identical."),
        tr("Pixels whose lighting computed to NaN or infinity; should be 0."),
        tr("Shown when some light casts a shadow. Share of the model's pixels, outside the soft edges of "
           "the shadows, that are more than %1 colour levels off the reference whose shadows are traced "
           "with rays: shadows where there are none, or none where there are.")
            .arg(kShadowThresholdLevels),
        tr("Shown when some light casts a shadow. The average difference from the ray-traced reference, "
           "in 8-bit colour levels, over the same pixels."),
    };
}

void QualityDock::showReport() {
    const QString none = QStringLiteral("–");
    auto number = [](double v, int decimals) { return QString::number(v, 'f', decimals); };
    auto interactionCell = [&](const BenchResult& r, Interaction i) {
        const TierTimes& t = m_times[size_t(r.quality)];
        return r.uberShader || !t.has(i) ? none : tr("%1 ms").arg(number(t[i], 2));
    };
    m_table->setRowCount(int(m_report.results.size()));
    for (int row = 0; row < int(m_report.results.size()); ++row) {
        const BenchResult& r = m_report.results[size_t(row)];
        const ErrorFigures& e = r.errors;
        const TierOffer& offer = m_offers[size_t(r.quality)];
        const QStringList cells{
            r.uberShader ? tr("exact, all models") : toString(r.quality),
            tr("%1 ms").arg(number(r.msMedian, 2)),
            interactionCell(r, Interaction::Drag),
            interactionCell(r, Interaction::Orbit),
            r.speedUp > 0.0 ? QStringLiteral("%1×").arg(number(r.speedUp, 2)) : none,
            r.uberShader    ? none
            : offer.offered ? tr("yes")
                            : tr("no"),
            tr("%1 ms").arg(number(r.firstFrameMs, 0)),
            r.hasErrors ? tr("%n level(s)", nullptr, e.maxLevels) : none,
            r.hasErrors ? number(e.meanLevels, 3) : none,
            r.hasErrors ? QStringLiteral("%1%").arg(number(100.0 * e.shareOver1(), 2)) : none,
            r.hasErrors
                ? (std::isfinite(e.psnrDb) ? tr("%1 dB").arg(number(e.psnrDb, 1)) : QStringLiteral("∞"))
                : none,
            r.hasErrors ? QString::number(e.nonFinite) : none,
            r.hasShadowErrors ? QStringLiteral("%1%").arg(number(100.0 * r.shadow.shareDiffering(), 2))
                              : none,
            r.hasShadowErrors ? number(r.shadow.meanLevels, 3) : none,
        };
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c >= 1) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(row, c, item);
        }
        m_table->item(row, 0)->setToolTip(
            tr("%1: %2 of %3 lights drawn, %4 triangles, %5 shader variant(s), MSAA %6×")
                .arg(r.scene)
                .arg(r.lightsUploaded)
                .arg(r.lightsInRig)
                .arg(r.triangles)
                .arg(r.variants)
                .arg(r.msaaSamples));
        m_table->item(row, 1)->setToolTip(
            tr("fastest %1 ms, slowest %2 ms; processor time %3 ms%4")
                .arg(number(r.msMin, 2), number(r.msMax, 2), number(r.cpuMsMedian, 1),
                     r.gpuMsMedian >= 0.0 ? tr("; GPU time %1 ms").arg(number(r.gpuMsMedian, 2))
                                          : QString()));
        if (!r.uberShader && !offer.offered) m_table->item(row, kOfferedColumn)->setToolTip(offer.why);
    }
    const bool shadows = benchHasShadows(m_report); // the shadow columns only for rigs with casters
    for (int c = kShadowColumns; c < m_table->columnCount(); ++c)
        m_table->setColumnHidden(c, !shadows);
    m_table->resizeColumnsToContents();
    m_differenceRow = -1; // a new report: the cached difference image is stale
    m_chartImage = benchChart(m_report);
    updateChart();
    updateComparison();
}

void QualityDock::updateComparison() {
    const int row = std::max(0, m_table->currentRow()); // the first tier until a row is picked
    const bool have =
        row >= 0 && row < int(m_report.results.size()) && !m_report.results[size_t(row)].image.isNull();
    auto show = [](QLabel* label, const QImage& image) {
        if (image.isNull()) {
            label->clear();
            return;
        }
        const QSize room = label->size() * label->devicePixelRatioF();
        QPixmap pixmap =
            QPixmap::fromImage(image.scaled(room, Qt::KeepAspectRatio, Qt::SmoothTransformation));
        pixmap.setDevicePixelRatio(label->devicePixelRatioF());
        label->setPixmap(pixmap);
    };
    if (!have) {
        show(m_tierImage, {});
        show(m_referenceImage, {});
        show(m_differenceImage, {});
        return;
    }
    const BenchResult& r = m_report.results[size_t(row)];
    if (m_differenceRow != row) {
        m_differenceCache = benchDifferenceImage(r.image, r.reference, kDifferenceGain);
        m_differenceRow = row;
    }
    m_compareCaption->setText(
        tr("%1 against the double-precision reference: worst pixel %n level(s) off, "
           "%2% of the pixels visibly off.",
           nullptr, r.errors.maxLevels)
            .arg(m_table->item(row, 0)->text(), QString::number(100.0 * r.errors.shareOver1(), 'f', 2)));
    show(m_tierImage, r.image);
    show(m_referenceImage, r.reference);
    show(m_differenceImage, m_differenceCache);
}

void QualityDock::openLarge() {
    setFloating(true);
    const QRect screen = this->screen() ? this->screen()->availableGeometry() : QRect(0, 0, 1280, 800);
    resize(std::min(1100, screen.width() - 40), std::min(760, screen.height() - 40));
    move(screen.center() - rect().center());
    show();
    raise();
}

void QualityDock::updateChart() {
    if (m_chartImage.isNull()) return;
    const QSize room = m_chart->size() * m_chart->devicePixelRatioF();
    QPixmap pixmap =
        QPixmap::fromImage(m_chartImage.scaled(room, Qt::KeepAspectRatio, Qt::SmoothTransformation));
    pixmap.setDevicePixelRatio(m_chart->devicePixelRatioF());
    m_chart->setPixmap(pixmap);
}

bool QualityDock::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Resize) {
        if (watched == m_chart)
            updateChart();
        else if (watched == m_tierImage || watched == m_referenceImage || watched == m_differenceImage)
            updateComparison();
    }
    return QDockWidget::eventFilter(watched, event);
}

QualityDock* addQualityDock(MainWindow* window) {
    auto* dock = new QualityDock(window);
    dock->setSceneProvider([window](QString* whyNot) -> std::optional<QualityRequest> {
        const Scene* scene = window->scene();
        if (scene->isEmpty()) {
            *whyNot = QObject::tr("no model is loaded");
            return std::nullopt;
        }
        QualityRequest r;
        const QString path = scene->path();
        r.scene.name = path.isEmpty() ? QObject::tr("scene") : QFileInfo(path).completeBaseName();
        r.scene.model = scene->model();
        r.scene.loadMs = scene->model()->loadMs;
        r.scene.rig = window->document()->renderRig();
        r.scene.environment = scene->environment(); // what the viewport shades with (issue 15)
        r.scene.camera = window->viewport()->camera();
        const ViewOptions& view = window->viewSettings()->options();
        r.exposureEV = view.exposure;
        r.toneMap = view.toneMap;
        r.viewportSize = window->viewport()->size() * window->viewport()->devicePixelRatioF();
        return r;
    });
    dock->setTierChooser([window](Quality q) { window->viewSettings()->setQuality(q); });
    // The tiers' promise (core/tieroffer.h): a tier not offered for this scene is greyed out, and the view
    // leaves it for exact, saying why.
    QObject::connect(dock, &QualityDock::offersChanged, window, [window, dock] {
        window->renderSettingsDock()->setTierOffers(dock->offers());
        const ViewOptions& view = window->viewSettings()->options();
        const TierOffer& offer = dock->offers()[size_t(view.quality)];
        if (offer.offered) return;
        window->viewSettings()->setQuality(Quality::Exact);
        window->statusBar()->showMessage(offer.why + QObject::tr(" The view now draws in exact."));
    });
    QObject::connect(window->scene(), &Scene::modelChanged, dock, &QualityDock::clearOffers);
    QObject::connect(window->scene(), &Scene::environmentChanged, dock, &QualityDock::clearOffers);
    window->addDockWidget(Qt::RightDockWidgetArea, dock);
    if (QDockWidget* render = window->renderSettingsDock()) {
        window->tabifyDockWidget(render, dock);
        render->raise();
    }
    return dock;
}

} // namespace lr
