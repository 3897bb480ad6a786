// The light table's view side: a sort proxy that turns an edit of one selected row into the same edit of
// every selected row (one undo step, via LightTableModel::setDataForRows), and a QTableView that reorders by
// drag and drop through the model's MoveLights command (never by the view's own remove-after-move). An
// editor closed without changing its value edits nothing. Values that are each light's own (names) and
// changes that must be deliberate for several lights (type: use the Properties dock) edit only their row.
#pragma once

#include <QPointer>
#include <QSortFilterProxyModel>
#include <QTableView>

class QItemSelectionModel;

namespace lr {

class LightTableModel;

class LightSortProxy : public QSortFilterProxyModel {
    Q_OBJECT
  public:
    explicit LightSortProxy(LightTableModel* source, QObject* parent = nullptr);
    LightTableModel* lightModel() const { return m_source; }
    // The selection whose rows an edit applies to (the view's selection model, over this proxy).
    void setSelectionModel(QItemSelectionModel* selection) { m_selection = selection; }
    // Source rows of the selection, sorted.
    QList<int> selectedSourceRows() const;
    // When index is one of several selected rows: the edit goes to all of them, as one undo step (if the
    // column spreadsToSelection and the value changed).
    bool setData(const QModelIndex& index, const QVariant& value, int role = Qt::EditRole) override;
    // Whether an edit of the column's cell on one selected row applies to every selected row.
    static bool spreadsToSelection(int column);

  private:
    LightTableModel* m_source;
    QPointer<QItemSelectionModel> m_selection;
};

class LightTableView : public QTableView {
    Q_OBJECT
  public:
    explicit LightTableView(QWidget* parent = nullptr);

  protected:
    // The model moved the rows itself (a MoveLights command); report no move to the drag source so that
    // QAbstractItemView does not also clear or remove the dragged rows.
    void dropEvent(QDropEvent* event) override;
};

} // namespace lr
