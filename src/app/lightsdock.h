// The Lights dock: a lighting console over the document's light table. A sortable QTableView (through a
// QSortFilterProxyModel) with multi-selection synced both ways with Document::selection(), in-place editing
// (colour and number delegates) where an edit on one of several selected rows applies to all of them as one
// undo step, drag-to-reorder (in document order, i.e. when the view is unsorted), and a toolbar: add point /
// spot / directional / rim, duplicate, delete, rename (F2). The actions are public so the main window can put
// them in its menus.
#pragma once

#include "core/lighttypes.h"
#include "editor/placement.h"

#include <array>

#include <QDockWidget>
#include <functional>

class QAction;
class QLabel;
class QSortFilterProxyModel;
class QTableView;
class QToolBar;

namespace lr {

class Document;
class LightTableModel;
class LightTableView;

class LightsDock : public QDockWidget {
    Q_OBJECT
  public:
    explicit LightsDock(Document* document, QWidget* parent = nullptr); // objectName "LightsDock"

    Document* document() const { return m_doc; }
    LightTableModel* model() const { return m_model; }
    QSortFilterProxyModel* proxyModel() const { return m_proxy; }
    QTableView* view() const;
    QToolBar* toolBar() const { return m_toolBar; }

    QAction* addLightAction(LightType type) const { return m_addActions[size_t(type)]; }
    QAction* duplicateAction() const { return m_duplicate; } // Ctrl+D
    QAction* deleteAction() const { return m_delete; }       // Delete (while the table has focus)
    QAction* renameAction() const { return m_rename; }       // F2
    QList<QAction*> lightActions() const;                    // all of the above, for a menu

    // Document rows of the view's selection (sorted). The selection model is kept equal to the document's.
    QList<int> selectedRows() const;

    // Where new lights go (editor/placement.h): the model's bounds and the view, asked at each add. Unset:
    // a unit model seen from +Z.
    void setPlacementView(std::function<PlacementView()> view) { m_placementView = std::move(view); }

  signals:
    // An edit was refused (reason for the status bar); also shown in the dock's message line.
    void editRefused(const QString& reason);
    // A light was added with the toolbar (row: its index), e.g. for the viewport to bring it into view.
    void lightAdded(int row);

  private:
    void addLight(LightType type);
    void duplicateSelected();
    void deleteSelected();
    void renameCurrent();
    void syncSelectionToDocument();
    void syncSelectionFromDocument();
    void updateActions();
    void showMessage(const QString& text);

    Document* m_doc;
    LightTableModel* m_model;
    QSortFilterProxyModel* m_proxy;
    LightTableView* m_view;
    QToolBar* m_toolBar;
    QLabel* m_message;
    std::array<QAction*, kLightTypeCount> m_addActions{};
    QAction* m_duplicate = nullptr;
    QAction* m_delete = nullptr;
    QAction* m_rename = nullptr;
    bool m_syncing = false;
    std::function<PlacementView()> m_placementView;
};

} // namespace lr
