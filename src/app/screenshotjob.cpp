#include "screenshotjob.h"

#include "snapshotrenderer.h"
#include "tracedshot.h"
#include "tracedview.h"
#include "viewport.h"

#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMainWindow>
#include <QProgressBar>
#include <QStatusBar>
#include <QToolButton>
#include <QtConcurrent/QtConcurrentRun>

namespace lr {

ScreenshotJob::ScreenshotJob(Viewport* viewport, const ScreenshotOptions& options, QObject* parent)
    : QObject(parent), m_viewport(viewport), m_options(options) {
    m_slice.setInterval(0); // one tile per pass of the event loop: input and repaints in between
    connect(&m_slice, &QTimer::timeout, this, &ScreenshotJob::step);
    connect(&m_write, &QFutureWatcher<QString>::finished, this, [this] {
        m_writing = false;
        m_result.cancelled = m_stopped; // a cancel after the commit comes too late: the file is written
        if (!m_stopped) m_result.error = m_write.result();
        if (m_result.ok()) setPercent(100);
        finish();
    });
    connect(&m_trace, &QFutureWatcher<QImage>::finished, this, [this] {
        m_traceProgress.stop();
        QImage image = m_trace.result();
        m_traced.reset();
        if (m_cancel) {
            m_result.cancelled = true;
            return finish();
        }
        if (image.isNull()) {
            m_result.error = m_traceError;
            return finish();
        }
        m_writing = true; // the status bar says "Writing" from here
        setPercent(kRenderedPercent);
        write(std::move(image));
    });
    m_traceProgress.setInterval(100);
    connect(&m_traceProgress, &QTimer::timeout, this, [this] {
        if (m_traced) setPercent(kRenderedPercent * m_traced->samplesDone() / m_traced->samples());
    });
}

ScreenshotJob::~ScreenshotJob() {
    m_cancel = true;
    if (m_traced) m_traced->cancel();
    m_trace.waitForFinished(); // within one tile, or after a scene build
    m_write.waitForFinished();
}

void ScreenshotJob::startTraced() {
    m_traced = std::make_shared<TracedShot>(m_viewport->tracedView()->inputs(), m_options.size,
                                            m_options.traceSamples, m_options.transparent);
    emit progressChanged(0);
    m_traceProgress.start();
    m_trace.setFuture(
        QtConcurrent::run([shot = m_traced, error = &m_traceError] { return shot->render(error); }));
}

void ScreenshotJob::start() {
    m_running = true;
    if (m_options.pathTraced && m_viewport) return startTraced();
    QString error;
    m_job = m_viewport ? m_viewport->beginScreenshot(m_options, &error) : nullptr;
    if (!m_job) {
        m_result.error = error.isEmpty() ? tr("the viewport is gone") : error;
        QTimer::singleShot(0, this, &ScreenshotJob::finish); // finished() after start() returned
        return;
    }
    emit progressChanged(0);
    m_slice.start();
}

void ScreenshotJob::cancel() {
    m_cancel = true;
    if (m_traced) m_traced->cancel();
}

void ScreenshotJob::setPercent(int percent) {
    if (percent <= m_percent) return;
    m_percent = percent;
    emit progressChanged(percent);
}

void ScreenshotJob::step() {
    if (m_cancel) {
        m_result.cancelled = true;
        return finish();
    }
    QString error;
    if (!m_viewport || !m_viewport->renderScreenshotTile(m_job.get(), &error)) {
        m_result.error = error.isEmpty() ? tr("rendering failed") : error;
        return finish();
    }
    const TiledImage& tiles = m_job->tiles;
    m_result.tiles = tiles.tilesDone;
    m_writing = tiles.finished();
    setPercent(int(kRenderedPercent * tiles.pixelsDone / std::max<qint64>(1, tiles.pixelsTotal)));
    if (!m_writing) return; // the next tile on the next pass
    m_slice.stop();
    QImage image = std::move(m_job->tiles.image);
    m_job.reset(); // the snapshot of the scene is no longer needed
    write(std::move(image));
}

void ScreenshotJob::write(QImage image) {
    m_writing = true;
    m_write.setFuture(
        QtConcurrent::run([this, image = std::move(image), path = m_options.path, format = m_options.format] {
            return saveImageAtomically(image, path, format, &m_cancel, &m_stopped);
        }));
}

void ScreenshotJob::finish() {
    m_slice.stop();
    m_job.reset();
    if (!m_running) return;
    m_running = false;
    emit finished();
}

void showInStatusBar(QMainWindow* window, ScreenshotJob* job) {
    auto* box = new QWidget(window->statusBar());
    auto* layout = new QHBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* label =
        new QLabel(QObject::tr("Screenshot %1").arg(QFileInfo(job->options().path).fileName()), box);
    auto* bar = new QProgressBar(box);
    bar->setObjectName(QStringLiteral("screenshotProgress"));
    bar->setRange(0, 100);
    bar->setMaximumWidth(160);
    bar->setValue(job->percent());
    auto* cancel = new QToolButton(box);
    cancel->setObjectName(QStringLiteral("screenshotCancel"));
    cancel->setText(QObject::tr("Cancel"));
    cancel->setToolTip(QObject::tr("Stop the screenshot export; an existing file is left as it was"));
    layout->addWidget(label);
    layout->addWidget(bar);
    layout->addWidget(cancel);
    window->statusBar()->addPermanentWidget(box);
    QObject::connect(job, &ScreenshotJob::progressChanged, bar, [bar, label, job](int percent) {
        bar->setValue(percent);
        if (job->isWriting())
            label->setText(QObject::tr("Writing %1").arg(QFileInfo(job->options().path).fileName()));
    });
    QObject::connect(cancel, &QToolButton::clicked, job, &ScreenshotJob::cancel);
    QObject::connect(job, &ScreenshotJob::finished, box, &QObject::deleteLater);
}

} // namespace lr
