#include "app/lightsdock.h"

#include "app/delegates.h"
#include "app/lighttableview.h"
#include "core/rigjson.h"
#include "editor/document.h"
#include "editor/lighttablemodel.h"

#include <QAction>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QLabel>
#include <QTimer>
#include <QToolBar>
#include <QToolTip>
#include <QVBoxLayout>

namespace lr {

LightsDock::LightsDock(Document* document, QWidget* parent)
    : QDockWidget(tr("Lights"), parent), m_doc(document) {
    setObjectName(QStringLiteral("LightsDock"));
    auto* body = new QWidget(this);
    auto* layout = new QVBoxLayout(body);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);

    m_toolBar = new QToolBar(tr("Lights"), body);
    m_toolBar->setObjectName(QStringLiteral("LightsToolBar"));
    m_toolBar->setIconSize(QSize(16, 16));
    m_toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    for (const LightType t : allLightTypes()) {
        auto* a = new QAction(lightTypeLabel(t), this);
        a->setObjectName(QStringLiteral("addLight_%1").arg(toString(t)));
        a->setToolTip(tr("Add a %1 light").arg(toString(t)));
        a->setStatusTip(a->toolTip());
        connect(a, &QAction::triggered, this, [this, t] { addLight(t); });
        m_addActions[size_t(t)] = a;
        m_toolBar->addAction(a);
    }
    m_toolBar->addSeparator();
    m_duplicate = new QAction(tr("Duplicate"), this);
    m_duplicate->setObjectName(QStringLiteral("duplicateLights"));
    m_duplicate->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_D));
    m_duplicate->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(m_duplicate, &QAction::triggered, this, &LightsDock::duplicateSelected);
    m_delete = new QAction(tr("Delete"), this);
    m_delete->setObjectName(QStringLiteral("deleteLights"));
    m_delete->setShortcut(QKeySequence::Delete);
    m_delete->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(m_delete, &QAction::triggered, this, &LightsDock::deleteSelected);
    m_rename = new QAction(tr("Rename"), this);
    m_rename->setObjectName(QStringLiteral("renameLight"));
    m_rename->setShortcut(QKeySequence(Qt::Key_F2));
    m_rename->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    connect(m_rename, &QAction::triggered, this, &LightsDock::renameCurrent);
    for (QAction* a : {m_duplicate, m_delete, m_rename}) {
        a->setToolTip(
            QStringLiteral("%1 (%2)").arg(a->text(), a->shortcut().toString(QKeySequence::NativeText)));
        m_toolBar->addAction(a);
        addAction(a); // shortcuts work while the dock has focus
    }

    m_model = new LightTableModel(document, this);
    auto* proxy = new LightSortProxy(m_model, this);
    m_proxy = proxy;
    m_view = new LightTableView(body);
    m_view->setObjectName(QStringLiteral("LightsTable"));
    m_view->setModel(m_proxy);
    proxy->setSelectionModel(m_view->selectionModel());
    m_view->setItemDelegateForColumn(LightTableModel::ColorColumn, new ColorSwatchDelegate(m_view));
    m_view->setItemDelegateForColumn(LightTableModel::IntensityColumn, new NumberDelegate(m_view));
    m_view->setItemDelegateForColumn(LightTableModel::FalloffColumn, new NumberDelegate(m_view));
    m_view->setItemDelegateForColumn(LightTableModel::TypeColumn, new LightTypeDelegate(m_view));
    m_view->setItemDelegateForColumn(LightTableModel::GroupColumn, new GroupDelegate(m_view));
    // Sorting is a view of the table only; the third click on a header returns to the rig's order, where
    // dragging rows reorders the rig.
    QHeaderView* header = m_view->horizontalHeader();
    header->setSortIndicator(-1, Qt::AscendingOrder);
    header->setSortIndicatorClearable(true);
    m_view->setSortingEnabled(true);
    connect(header, &QHeaderView::sortIndicatorChanged, this, [this](int section, Qt::SortOrder order) {
        if (section < 0) m_proxy->sort(-1, order); // back to document order
        m_view->setDragEnabled(section < 0);
    });
    header->setSectionResizeMode(QHeaderView::Interactive);
    header->resizeSection(LightTableModel::NameColumn, 96);
    header->resizeSection(LightTableModel::GroupColumn, 64);
    header->resizeSection(LightTableModel::TypeColumn, 84); // "Directional"
    for (int c : {int(LightTableModel::OnColumn), int(LightTableModel::SoloColumn),
                  int(LightTableModel::ShadowColumn)})
        header->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    header->resizeSection(LightTableModel::ColorColumn, 48);
    // Numbers are short: narrower than the default section, so that every column (Shadow last) fits the
    // dock at the default window size.
    header->resizeSection(LightTableModel::IntensityColumn, 64);
    header->resizeSection(LightTableModel::FalloffColumn, 64);

    m_message = new QLabel(body);
    m_message->setObjectName(QStringLiteral("LightsMessage"));
    m_message->setWordWrap(true);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_message->setStyleSheet(QStringLiteral("color: #c0392b"));
    m_message->hide();

    layout->addWidget(m_toolBar);
    layout->addWidget(m_view, 1);
    layout->addWidget(m_message);
    setWidget(body);

    connect(m_model, &LightTableModel::editRefused, this, &LightsDock::showMessage);
    connect(m_view->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &LightsDock::syncSelectionToDocument);
    connect(m_view->selectionModel(), &QItemSelectionModel::currentChanged, this,
            &LightsDock::syncSelectionToDocument);
    connect(m_doc, &Document::selectionChanged, this, &LightsDock::syncSelectionFromDocument);
    connect(m_doc, &Document::rigChanged, this, [this](const RigChange& c) {
        if (c.isStructural()) syncSelectionFromDocument();
        updateActions();
    });
    syncSelectionFromDocument();
    updateActions();
}

QTableView* LightsDock::view() const {
    return m_view;
}

QList<QAction*> LightsDock::lightActions() const {
    QList<QAction*> actions(m_addActions.begin(), m_addActions.end());
    actions << m_duplicate << m_delete << m_rename;
    return actions;
}

QList<int> LightsDock::selectedRows() const {
    return static_cast<LightSortProxy*>(m_proxy)->selectedSourceRows();
}

void LightsDock::showMessage(const QString& text) {
    m_message->setText(text);
    m_message->setVisible(!text.isEmpty());
    if (text.isEmpty()) return;
    emit editRefused(text);
    // Also right at the cell that was being edited.
    const QRect cell = m_view->visualRect(m_view->currentIndex());
    if (m_view->isVisible() && cell.isValid())
        QToolTip::showText(m_view->viewport()->mapToGlobal(cell.bottomLeft()), text, m_view->viewport());
}

void LightsDock::addLight(LightType type) {
    QString error;
    if (!addPlacedLight(m_doc, type, m_placementView ? m_placementView() : PlacementView{}, &error)) {
        showMessage(error);
    } else {
        showMessage({});
        emit lightAdded(m_doc->lightCount() - 1);
    }
    m_view->setFocus();
}

void LightsDock::duplicateSelected() {
    QString error;
    if (!m_doc->duplicateLights(selectedRows(), &error)) showMessage(error);
}

void LightsDock::deleteSelected() {
    const QList<int> rows = selectedRows();
    if (rows.isEmpty()) return;
    QString error;
    if (!m_doc->removeLights(rows, &error)) showMessage(error);
}

void LightsDock::renameCurrent() {
    int row = m_doc->currentRow();
    if (row < 0) return;
    const QModelIndex index = m_proxy->mapFromSource(m_model->index(row, LightTableModel::NameColumn));
    m_view->setCurrentIndex(index); // keeps the selection (same row)
    m_view->scrollTo(index);
    m_view->edit(index);
}

void LightsDock::syncSelectionToDocument() {
    if (m_syncing) return;
    m_syncing = true;
    const QModelIndex current = m_view->selectionModel()->currentIndex();
    const int currentRow = current.isValid() ? m_proxy->mapToSource(current).row() : -1;
    const QList<int> rows = selectedRows();
    m_doc->setSelectedRows(rows, rows.contains(currentRow) ? currentRow : -1);
    m_syncing = false;
    updateActions();
}

void LightsDock::syncSelectionFromDocument() {
    if (m_syncing) return;
    m_syncing = true;
    // Proxy rows of the selected lights, merged into contiguous ranges.
    QList<int> proxyRows;
    for (int r : m_doc->selectedRows())
        proxyRows << m_proxy->mapFromSource(m_model->index(r, 0)).row();
    std::sort(proxyRows.begin(), proxyRows.end());
    QItemSelection selection;
    const int lastColumn = m_proxy->columnCount() - 1;
    for (int i = 0; i < proxyRows.size();) {
        int j = i;
        while (j + 1 < proxyRows.size() && proxyRows[j + 1] == proxyRows[j] + 1)
            ++j;
        selection.select(m_proxy->index(proxyRows[i], 0), m_proxy->index(proxyRows[j], lastColumn));
        i = j + 1;
    }
    QItemSelectionModel* sm = m_view->selectionModel();
    if (sm->selection() != selection) sm->select(selection, QItemSelectionModel::ClearAndSelect);
    const int cur = m_doc->currentRow();
    if (cur >= 0) {
        const QModelIndex idx =
            m_proxy->mapFromSource(m_model->index(cur, std::max(0, sm->currentIndex().column())));
        if (sm->currentIndex().row() != idx.row()) {
            sm->setCurrentIndex(idx, QItemSelectionModel::NoUpdate);
            m_view->scrollTo(idx);
        }
    }
    m_syncing = false;
    updateActions();
}

void LightsDock::updateActions() {
    const bool any = !m_doc->selection().isEmpty();
    m_duplicate->setEnabled(any);
    m_delete->setEnabled(any);
    m_rename->setEnabled(m_doc->currentRow() >= 0);
    for (QAction* a : m_addActions)
        a->setEnabled(m_doc->lightCount() < kMaxRigLights);
}

} // namespace lr
