#include "editorstatusbar.h"

#include <QLabel>
#include <QProgressBar>
#include <QStyle>
#include <QToolButton>
#include <algorithm>
#include <cmath>
#include <utility>

namespace lr {

EditorStatusBar::EditorStatusBar(QWidget* parent)
    : QStatusBar(parent), m_rig(new QLabel(this)), m_frameTime(new QLabel(this)),
      m_progress(new QProgressBar(this)), m_cancel(new QToolButton(this)), m_warnings(new QToolButton(this)),
      m_frameTimeTimer(new QTimer(this)) {
    m_frameTimeTimer->setSingleShot(true);
    connect(m_frameTimeTimer, &QTimer::timeout, this, &EditorStatusBar::showFrameTime);
    m_frameTime->setObjectName(QStringLiteral("frameTime"));
    m_frameTime->setToolTip(tr("Time to render the last viewport frame (GPU timer query)"));
    m_frameTime->setMinimumWidth(
        m_frameTime->fontMetrics().horizontalAdvance(QStringLiteral("GPU 000.0 ms")));
    m_progress->setRange(0, 1000);
    m_progress->setMaximumWidth(160);
    m_progress->setTextVisible(false);
    m_cancel->setText(tr("Cancel"));
    m_cancel->setToolTip(tr("Stop loading the model (the current one stays)"));
    m_warnings->setObjectName(QStringLiteral("importWarnings"));
    m_warnings->setAutoRaise(true);
    m_warnings->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_warnings->setIcon(style()->standardIcon(QStyle::SP_MessageBoxWarning));
    m_warnings->hide();
    connect(m_warnings, &QToolButton::clicked, this, &EditorStatusBar::warningsRequested);
    addPermanentWidget(m_warnings);
    addPermanentWidget(m_progress);
    addPermanentWidget(m_cancel);
    addPermanentWidget(m_rig);
    addPermanentWidget(m_frameTime);
    connect(m_cancel, &QToolButton::clicked, this, &EditorStatusBar::cancelLoadRequested);
    hideLoading();
}

void EditorStatusBar::setFrameTime(double gpuMs, double cpuMs) {
    if (gpuMs >= 0.0 && std::isfinite(gpuMs))
        m_pendingFrameTime = tr("GPU %1 ms").arg(gpuMs, 0, 'f', 1);
    else if (cpuMs >= 0.0 && std::isfinite(cpuMs))
        m_pendingFrameTime = tr("frame %1 ms").arg(cpuMs, 0, 'f', 1);
    else
        return;
    if (!m_sinceFrameTime.isValid() || m_sinceFrameTime.elapsed() >= kFrameTimeIntervalMs)
        showFrameTime();
    else if (!m_frameTimeTimer->isActive())
        m_frameTimeTimer->start(int(kFrameTimeIntervalMs - m_sinceFrameTime.elapsed()));
}

void EditorStatusBar::showFrameTime() {
    m_frameTimeTimer->stop();
    m_sinceFrameTime.start();
    if (!m_pendingFrameTime.isEmpty()) m_frameTime->setText(std::exchange(m_pendingFrameTime, QString()));
}

QString EditorStatusBar::frameTimeText() const {
    return m_frameTime->text();
}

void EditorStatusBar::setRigSummary(const QString& text) {
    m_rig->setText(text);
}

void EditorStatusBar::showLoading(const QString& fileName) {
    m_progress->setValue(0);
    m_progress->setToolTip(tr("Loading %1").arg(fileName));
    m_progress->show();
    m_cancel->show();
}

void EditorStatusBar::setLoadProgress(double fraction) {
    m_progress->setValue(int(std::lround(std::clamp(fraction, 0.0, 1.0) * 1000.0)));
}

void EditorStatusBar::setModelWarnings(const QString& fileName, const QStringList& warnings) {
    m_warnings->setText(tr("%n import warning(s)", nullptr, int(warnings.size())));
    m_warnings->setToolTip(
        warnings.isEmpty()
            ? QString()
            : tr("%1 was imported with warnings; click to read them in the Model dock").arg(fileName));
    m_warnings->setVisible(!warnings.isEmpty());
}

void EditorStatusBar::hideLoading() {
    m_progress->hide();
    m_cancel->hide();
}

} // namespace lr
