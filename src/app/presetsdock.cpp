#include "presetsdock.h"

#include "editor/document.h"
#include "errordialog.h"

#include <QDir>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPainter>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

namespace lr {

namespace {
constexpr int kEntryRole = Qt::UserRole + 1; // index into the store's list when the dock was filled

QString shadingBadge(const std::optional<ShadingModel>& shading) {
    return !shading                        ? QStringLiteral("?")
           : *shading == ShadingModel::Pbr ? QObject::tr("PBR")
                                           : QObject::tr("Classic");
}

QIcon placeholderIcon(const QString& name) {
    QPixmap pm(PresetsDock::kThumbnailSize, PresetsDock::kThumbnailSize);
    pm.fill(QColor(40, 42, 48));
    QPainter p(&pm);
    p.setPen(QColor(200, 200, 200));
    p.drawText(pm.rect().adjusted(4, 4, -4, -4), Qt::AlignCenter | Qt::TextWordWrap, name);
    return QIcon(pm);
}
} // namespace

PresetsDock::PresetsDock(Document* document, PresetStore* store, QWidget* parent)
    : QDockWidget(tr("Presets"), parent), m_doc(document), m_store(store), m_list(new QListWidget) {
    setObjectName(QStringLiteral("PresetsDock"));
    m_thumbnailTimer.setSingleShot(true);
    m_thumbnailTimer.setInterval(0);
    connect(&m_thumbnailTimer, &QTimer::timeout, this, &PresetsDock::renderNextThumbnail);
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    m_list->setViewMode(QListView::IconMode);
    m_list->setIconSize(QSize(kThumbnailSize, kThumbnailSize));
    m_list->setResizeMode(QListView::Adjust);
    m_list->setMovement(QListView::Static);
    m_list->setWordWrap(true);
    m_list->setToolTip(tr("Double-click a preset to apply it (one undo step)"));
    layout->addWidget(m_list, 1);
    auto* buttons = new QHBoxLayout;
    auto* apply = new QToolButton(body);
    apply->setText(tr("Apply"));
    auto* save = new QToolButton(body);
    save->setText(tr("Save rig as preset…"));
    m_delete = new QToolButton(body);
    m_delete->setText(tr("Delete"));
    m_delete->setEnabled(false);
    buttons->addWidget(apply);
    buttons->addWidget(save);
    buttons->addWidget(m_delete);
    buttons->addStretch(1);
    layout->addLayout(buttons);
    setWidget(body);

    connect(m_list, &QListWidget::itemActivated, this,
            [this](QListWidgetItem* item) { applyPreset(entryOf(item)); });
    connect(apply, &QToolButton::clicked, this, [this] {
        if (QListWidgetItem* item = m_list->currentItem()) applyPreset(entryOf(item));
    });
    connect(save, &QToolButton::clicked, this, qOverload<>(&PresetsDock::saveAsPreset));
    connect(m_delete, &QToolButton::clicked, this, &PresetsDock::deleteSelected);
    connect(m_list, &QListWidget::currentItemChanged, this,
            [this](QListWidgetItem* item) { m_delete->setEnabled(item && !entryOf(item).builtin); });
    connect(m_store, &PresetStore::changed, this, &PresetsDock::reload);
    reload();
}

PresetEntry PresetsDock::entryOf(const QListWidgetItem* item) const {
    const QVariantList v = item->data(kEntryRole).toList();
    return v.size() == 4 ? PresetEntry{v[0].toString(), v[1].toString(), v[2].toString(), v[3].toBool()}
                         : PresetEntry{};
}

void PresetsDock::setThumbnailRenderer(ThumbnailRenderer renderer) {
    m_renderThumbnail = std::move(renderer);
    invalidateThumbnails();
}

void PresetsDock::invalidateThumbnails() {
    m_rendered.clear();
    reload();
}

void PresetsDock::renderNextThumbnail() {
    if (m_pending.isEmpty() || !m_renderThumbnail) return;
    if (m_busy && m_busy()) {
        m_thumbnailTimer.start(kBusyRetryMs);
        return;
    }
    const QString path = m_pending.takeFirst();
    for (int i = 0; i < m_list->count(); ++i) {
        QListWidgetItem* item = m_list->item(i);
        const PresetEntry e = entryOf(item);
        if (e.path != path) continue;
        const RigReadResult r = m_store->read(e);
        const QImage image =
            r.ok() ? m_renderThumbnail(*r.rig, QSize(kThumbnailSize, kThumbnailSize) * 2) : QImage();
        if (!image.isNull()) {
            const QIcon icon(QPixmap::fromImage(
                image.scaled(kThumbnailSize, kThumbnailSize, Qt::KeepAspectRatio, Qt::SmoothTransformation)));
            m_rendered.insert(path, icon);
            item->setIcon(icon);
        }
        break;
    }
    if (!m_pending.isEmpty()) m_thumbnailTimer.start(0);
}

void PresetsDock::reload() {
    m_list->clear();
    m_pending.clear();
    for (const PresetEntry& e : m_store->presets()) {
        QIcon icon = !e.thumbnail.isEmpty()        ? QIcon(e.thumbnail)
                     : m_rendered.contains(e.path) ? m_rendered.value(e.path)
                                                   : placeholderIcon(e.name);
        if (e.thumbnail.isEmpty() && !m_rendered.contains(e.path)) m_pending.append(e.path);
        // The shading as a badge under the name (issue 13): "PBR" or "Classic".
        auto* item = new QListWidgetItem(icon, e.name + QLatin1Char('\n') + shadingBadge(e.shading), m_list);
        item->setData(kEntryRole, QVariantList{e.name, e.path, e.thumbnail, e.builtin});
        item->setData(kShadingRole, e.shading ? toString(*e.shading) : QString());
        item->setToolTip((e.builtin ? tr("%1 (built-in)").arg(e.name) : QDir::toNativeSeparators(e.path)) +
                         QLatin1Char('\n') +
                         (!e.shading ? tr("The preset cannot be read.")
                          : *e.shading == ShadingModel::Pbr
                              ? tr("Physically based shading (glTF BRDF, lights "
                                   "in candela and lux)")
                              : tr("Classic shading (Phong / Blinn-Phong)")));
    }
    if (!m_pending.isEmpty() && m_renderThumbnail) m_thumbnailTimer.start(0);
}

bool PresetsDock::applyPreset(const PresetEntry& entry) {
    const RigReadResult r = m_store->read(entry);
    if (!r.ok()) {
        showError(this, {tr("Apply preset"), tr("Could not read the preset %1.").arg(entry.name), r.errors});
        return false;
    }
    Rig rig = *r.rig; // the lights and settings of the preset; the rig's saved views stay
    rig.view = m_doc->rig().view;
    rig.views = m_doc->rig().views;
    QString error;
    if (!m_doc->replaceRig(rig, tr("Apply preset %1").arg(entry.name), &error)) {
        showError(this, {tr("Apply preset"), tr("Could not apply the preset %1.").arg(entry.name), {error}});
        return false;
    }
    return true;
}

void PresetsDock::saveAsPreset() {
    bool ok = false;
    const QString suggestion = m_doc->rig().name.isEmpty() ? tr("My rig") : m_doc->rig().name;
    const QString name = QInputDialog::getText(this, tr("Save rig as preset"), tr("Preset name:"),
                                               QLineEdit::Normal, suggestion, &ok);
    if (ok && !name.trimmed().isEmpty()) saveAsPreset(name);
}

bool PresetsDock::saveAsPreset(const QString& name) {
    for (const PresetEntry& e : m_store->presets()) {
        if (!e.builtin && e.name == PresetStore::fileBaseName(name) &&
            QMessageBox::question(this, tr("Save rig as preset"),
                                  tr("A preset called %1 exists. Replace it?").arg(e.name)) !=
                QMessageBox::Yes)
            return false;
    }
    const QImage thumbnail = m_renderThumbnail
                                 ? m_renderThumbnail(m_doc->rig(), QSize(kThumbnailSize, kThumbnailSize) * 2)
                                 : QImage();
    const QString error = m_store->save(name, m_doc->rig(), thumbnail);
    if (!error.isEmpty()) {
        showError(this, {tr("Save rig as preset"), tr("Could not save the preset %1.").arg(name), {error}});
        return false;
    }
    return true;
}

void PresetsDock::deleteSelected() {
    QListWidgetItem* item = m_list->currentItem();
    if (!item) return;
    const PresetEntry e = entryOf(item);
    if (QMessageBox::question(this, tr("Delete preset"), tr("Delete the preset %1?").arg(e.name)) !=
        QMessageBox::Yes)
        return;
    const QString error = m_store->remove(e);
    if (!error.isEmpty()) showError(this, {tr("Delete preset"), error, {}});
}

void PresetsDock::attachMenu(QMenu* menu) {
    rebuildMenu(menu);
    connect(m_store, &PresetStore::changed, menu, [this, menu] { rebuildMenu(menu); });
}

void PresetsDock::rebuildMenu(QMenu* menu) {
    menu->clear();
    bool userSection = false;
    for (const PresetEntry& e : m_store->presets()) {
        if (!e.builtin && !userSection) {
            menu->addSection(tr("My presets"));
            userSection = true;
        }
        connect(menu->addAction(e.name + QStringLiteral("  (%1)").arg(shadingBadge(e.shading))),
                &QAction::triggered, this, [this, e] { applyPreset(e); });
    }
    menu->addSeparator();
    connect(menu->addAction(tr("Save rig as preset…")), &QAction::triggered, this,
            qOverload<>(&PresetsDock::saveAsPreset));
}

} // namespace lr
