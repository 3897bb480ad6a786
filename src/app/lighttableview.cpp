#include "app/lighttableview.h"

#include "editor/lightproperty.h"
#include "editor/lighttablemodel.h"

#include <QDropEvent>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <algorithm>

namespace lr {

LightSortProxy::LightSortProxy(LightTableModel* source, QObject* parent)
    : QSortFilterProxyModel(parent), m_source(source) {
    setSourceModel(source);
    setSortRole(LightTableModel::SortRole);
    setSortCaseSensitivity(Qt::CaseInsensitive);
    setDynamicSortFilter(true);
}

QList<int> LightSortProxy::selectedSourceRows() const {
    QList<int> rows;
    if (!m_selection) return rows;
    for (const QModelIndex& i : m_selection->selectedRows())
        rows << mapToSource(i).row();
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    return rows;
}

bool LightSortProxy::spreadsToSelection(int column) {
    const LightPropertyInfo* row = lightPropertyInfo(LightTableModel::propertyOf(column));
    return !row || !(row->uniquePerLight || row->deliberateForMany);
}

bool LightSortProxy::setData(const QModelIndex& index, const QVariant& value, int role) {
    if (!index.isValid()) return false;
    // An editor closed without a change (clicking into a cell, then elsewhere) edits nothing, on no row.
    if (role == Qt::EditRole && value == index.data(Qt::EditRole)) return true;
    const int row = mapToSource(index).row();
    const QList<int> rows = selectedSourceRows();
    if (rows.size() > 1 && rows.contains(row) && spreadsToSelection(index.column()))
        return m_source->setDataForRows(rows, index.column(), value, role);
    return QSortFilterProxyModel::setData(index, value, role);
}

LightTableView::LightTableView(QWidget* parent) : QTableView(parent) {
    setSelectionBehavior(SelectRows);
    setSelectionMode(ExtendedSelection);
    setDragEnabled(true);
    setAcceptDrops(true);
    setDragDropMode(DragDrop); // the model accepts only its own rows (MoveAction)
    setDefaultDropAction(Qt::MoveAction);
    setDragDropOverwriteMode(false); // drops land between rows
    setDropIndicatorShown(true);
    // No EditKeyPressed: F2 is the Lights dock's Rename action, which renames only the current selected light
    // (the view's own F2 edited its current index, still set on an unselected row after a Delete).
    setEditTriggers(DoubleClicked | SelectedClicked);
    setAlternatingRowColors(true);
    setWordWrap(false);
    verticalHeader()->hide();
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 8);
    horizontalHeader()->setHighlightSections(false);
    // The last (stretched) column keeps at least the default size when space is short: a narrow default
    // lets all nine columns fit the default layout's table (the Lights dock sizes the others).
    horizontalHeader()->setDefaultSectionSize(64);
    horizontalHeader()->setStretchLastSection(true);
}

void LightTableView::dropEvent(QDropEvent* event) {
    QTableView::dropEvent(event);
    // IgnoreAction (always allowed, unlike Copy when only Move was offered): QDrag::exec then returns no
    // move.
    if (event->isAccepted() && event->dropAction() == Qt::MoveAction) event->setDropAction(Qt::IgnoreAction);
}

} // namespace lr
