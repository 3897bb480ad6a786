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
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

namespace lr {

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
    m_table = new QTableWidget(0, int(benchTableHeaders().size()), split);
    m_table->setHorizontalHeaderLabels(benchTableHeaders());
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->verticalHeader()->setVisible(false);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_chart = new QLabel(split);
    m_chart->setAlignment(Qt::AlignCenter);
    m_chart->setMinimumSize(200, 120);
    m_chart->installEventFilter(this);
    split->addWidget(m_table);
    split->addWidget(m_chart);
    layout->addWidget(split, 1);

    auto* bottom = new QHBoxLayout;
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
        const int row = m_table->currentRow();
        m_use->setEnabled(m_chooser && row >= 0 && row < int(m_report.results.size()) && !m_running);
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
    m_use->setEnabled(!running && m_chooser && m_table->currentRow() >= 0);
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
    m_cancelRequested = false;
    setRunning(true);
    m_progress->setValue(0);
    const BenchProgress progress = [this](double fraction, const QString& what) {
        m_progress->setValue(int(fraction * 1000.0));
        m_status->setText(what);
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        return !m_cancelRequested;
    };
    BenchReport report;
    QString error;
    const BenchStatus status = runQualityBench({request->scene}, options, &report, &error, progress);
    setRunning(false);
    switch (status) {
    case BenchStatus::Ok:
        m_report = report;
        showReport();
        m_progress->setValue(1000);
        m_status->setText(tr("%1 at %2×%3 on %4. Errors are 8-bit sRGB levels against the double-precision "
                             "reference over the model's pixels.")
                              .arg(request->scene.name)
                              .arg(options.size.width())
                              .arg(options.size.height())
                              .arg(report.glDescription));
        emit finished(true, m_status->text());
        break;
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

void QualityDock::showReport() {
    m_table->setRowCount(int(m_report.results.size()));
    for (int row = 0; row < int(m_report.results.size()); ++row) {
        const QStringList cells = benchTableRow(m_report.results[size_t(row)]);
        for (int c = 0; c < cells.size(); ++c) {
            auto* item = new QTableWidgetItem(cells[c]);
            if (c >= 3) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
            m_table->setItem(row, c, item);
        }
    }
    m_chartImage = benchChart(m_report);
    updateChart();
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
    if (watched == m_chart && event->type() == QEvent::Resize) updateChart();
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
        r.scene.camera = window->viewport()->camera();
        const ViewOptions& view = window->viewSettings()->options();
        r.exposureEV = view.exposure;
        r.toneMap = view.toneMap;
        r.viewportSize = window->viewport()->size() * window->viewport()->devicePixelRatioF();
        return r;
    });
    dock->setTierChooser([window](Quality q) { window->viewSettings()->setQuality(q); });
    window->addDockWidget(Qt::RightDockWidgetArea, dock);
    if (QDockWidget* render = window->renderSettingsDock()) {
        window->tabifyDockWidget(render, dock);
        render->raise();
    }
    return dock;
}

} // namespace lr
