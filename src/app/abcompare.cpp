#include "abcompare.h"

#include "abcompareframe.h"
#include "core/rigjson.h"
#include "documentfiles.h"
#include "editor/document.h"
#include "environmentloading.h"
#include "errordialog.h"
#include "scene.h"
#include "scene/environmentloader.h"

#include <QAction>
#include <QActionGroup>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QTime>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cmath>

namespace lr {

AbCompare::AbCompare(Document* document, Scene* scene, QWidget* window, QObject* parent)
    : QObject(parent), m_doc(document), m_scene(scene), m_window(window),
      m_watcher(new QFutureWatcher<EnvironmentLoadResult>(this)) {
    connect(m_watcher, &QFutureWatcherBase::finished, this, &AbCompare::environmentLoaded);
    askOpenPath = [this](const QString& title, const QString& filter) {
        return QFileDialog::getOpenFileName(m_window, title,
                                            DocumentFiles::lastFolder(DocumentFiles::FileKind::Rig), filter);
    };
    auto action = [this](const QString& text, const QString& tip) {
        auto* a = new QAction(text, this);
        a->setToolTip(tip);
        a->setStatusTip(tip);
        return a;
    };
    m_snapshot = action(tr("Take &snapshot as B"),
                        tr("Keep a copy of the rig as it is drawn now as B, and compare it with the rig "
                           "as you go on editing (A)"));
    m_snapshot->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_B));
    m_open = action(tr("&Open rig as B…"), tr("Compare the rig with another rig file (B); the rig you "
                                              "edit stays as it is"));
    m_wipe = action(tr("&Wipe"), tr("A left of a line you drag, B right of it"));
    m_sideBySide = action(tr("Side &by side"), tr("A in the left half of the view, B in the right"));
    m_swap = action(tr("S&wap A and B"), tr("Show B on the left and A on the right"));
    m_leave = action(tr("&Leave compare"), tr("Back to the normal view (B is kept)"));
    for (QAction* a : {m_wipe, m_sideBySide, m_swap})
        a->setCheckable(true);
    auto* group = new QActionGroup(this);
    group->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    group->addAction(m_wipe);
    group->addAction(m_sideBySide);
    connect(m_snapshot, &QAction::triggered, this, &AbCompare::takeSnapshot);
    connect(m_open, &QAction::triggered, this, [this] { openB(); });
    connect(m_wipe, &QAction::triggered, this,
            [this](bool on) { setLayout(on ? CompareLayout::Wipe : CompareLayout::Off); });
    connect(m_sideBySide, &QAction::triggered, this,
            [this](bool on) { setLayout(on ? CompareLayout::SideBySide : CompareLayout::Off); });
    connect(m_swap, &QAction::toggled, this, &AbCompare::setSwapped);
    connect(m_leave, &QAction::triggered, this, &AbCompare::leave);
    syncActions();
}

AbCompare::~AbCompare() {
    m_watcher->disconnect(this);
    m_watcher->waitForFinished(); // loadEnvironment cannot be interrupted
}

void AbCompare::addActions(QMenu* menu) const {
    QMenu* sub = menu->addMenu(tr("&Compare A/B"));
    sub->addAction(m_snapshot);
    sub->addAction(m_open);
    sub->addSeparator();
    sub->addAction(m_wipe);
    sub->addAction(m_sideBySide);
    sub->addAction(m_swap);
    sub->addAction(m_leave);
}

QRectF AbCompare::documentRect(const QSizeF& size) const {
    if (!isActive() || m_layout != CompareLayout::SideBySide) return QRectF(QPointF(0, 0), size);
    const double half = std::floor(size.width() / 2.0);
    return QRectF(m_swapped ? size.width() - half : 0.0, 0.0, half, size.height());
}

bool AbCompare::onWipeHandle(const QPointF& position, const QSizeF& size) const {
    return isActive() && m_layout == CompareLayout::Wipe &&
           std::abs(position.x() - splitX(size.width())) <= kHandlePixels;
}

void AbCompare::attachLabels(QWidget* viewport) {
    new CompareLabels(this, viewport);
}

void AbCompare::takeSnapshot() {
    setB(m_doc->renderRig(), tr("snapshot %1").arg(QTime::currentTime().toString(QStringLiteral("HH:mm:ss"))),
         EnvironmentLoading::rigFolder(m_doc));
    emit statusMessage(tr("B is a snapshot of the rig: edit it (A) and drag the line to compare"));
}

bool AbCompare::openB(const QString& requested) {
    const QString path = requested.isEmpty()
                             ? askOpenPath(tr("Open rig as B"), tr("LightRig rigs (*.json);;All files (*)"))
                             : requested;
    if (path.isEmpty()) return false;
    const RigReadResult read = readRigFile(path);
    if (!read.ok()) {
        const QStringList lines =
            read.errors.isEmpty() ? QStringList{tr("%1: could not be read").arg(path)} : read.errors;
        showError(m_window, {tr("Open rig as B"),
                             tr("Could not open %1: %n error(s). Nothing was compared; the rig is unchanged.",
                                nullptr, int(lines.size()))
                                 .arg(QFileInfo(path).fileName()),
                             lines});
        return false;
    }
    DocumentFiles::rememberFolder(DocumentFiles::FileKind::Rig, path);
    setB(*read.rig, QFileInfo(path).fileName(), QFileInfo(path).absolutePath());
    emit statusMessage(read.warnings.isEmpty()
                           ? tr("B is %1").arg(QDir::toNativeSeparators(path))
                           : tr("B is %1, with %n warning(s): %2", nullptr, int(read.warnings.size()))
                                 .arg(QDir::toNativeSeparators(path), read.warnings.first()));
    return true;
}

void AbCompare::setB(const Rig& rig, const QString& name, const QString& folder) {
    m_rigB = rig;
    m_nameB = name;
    m_hasB = true;
    m_environmentB.reset();
    ++m_loadGeneration; // a load still running for an earlier B is dropped when it ends
    const Environment& spec = rig.environment;
    const std::shared_ptr<const LoadedEnvironment>& shown = m_scene->environment();
    const bool sameFile = spec.source != EnvironmentSource::Image ||
                          (shown && shown->source == resolveEnvironmentFile(spec.file, folder));
    if (!spec.isNone() && shown && shown->spec.sameRadiance(spec) && sameFile) {
        m_environmentB = shown; // the viewport's, already on the GPU
    } else if (!spec.isNone()) {
        m_runningGeneration = m_loadGeneration;
        m_watcher->setFuture(QtConcurrent::run([spec, folder] { return loadEnvironment(spec, folder); }));
    }
    if (m_layout == CompareLayout::Off) m_layout = CompareLayout::Wipe;
    syncActions();
    emit changed();
}

void AbCompare::environmentLoaded() {
    if (m_runningGeneration != m_loadGeneration) return; // for a B replaced since
    const EnvironmentLoadResult result = m_watcher->result();
    if (!result.environment) {
        emit statusMessage(tr("B's environment is not drawn: %1").arg(result.error));
        return;
    }
    m_environmentB = result.environment;
    emit changed();
}

void AbCompare::setLayout(CompareLayout layout) {
    if (layout != CompareLayout::Off && !m_hasB) layout = CompareLayout::Off;
    if (m_layout == layout) return syncActions();
    m_layout = layout;
    syncActions();
    emit changed();
}

void AbCompare::setSplit(double fraction) {
    const double f = std::clamp(std::isfinite(fraction) ? fraction : 0.5, 0.0, 1.0);
    if (f == m_split) return;
    m_split = f;
    emit changed();
}

void AbCompare::setSwapped(bool swapped) {
    if (m_swapped == swapped) return;
    m_swapped = swapped;
    syncActions();
    emit changed();
}

void AbCompare::syncActions() {
    const QSignalBlocker blockSwap(m_swap);
    m_wipe->setChecked(isActive() && m_layout == CompareLayout::Wipe);
    m_sideBySide->setChecked(isActive() && m_layout == CompareLayout::SideBySide);
    m_swap->setChecked(m_swapped);
    for (QAction* a : {m_wipe, m_sideBySide, m_swap})
        a->setEnabled(m_hasB);
    m_leave->setEnabled(isActive());
}

} // namespace lr
