// The Model dock (issue 13): what the open model holds — its meshes, materials (every value, textures with
// their roles and sizes, transforms, physically based from the file or converted), textures and every import
// warning in full (ModelTreeModel) — in a tree whose rows can be selected and copied (Ctrl+C or the context
// menu: "name<TAB>value" per row). Follows the scene: a new model, a reload or an up-axis change rebuilds it.
// The status bar's "N import warnings" button opens it on its Warnings branch (showWarnings). Issue 38: with
// a document, each mesh's "lit by" and "casts shadow of" rows follow the rig (light linking).
#pragma once

#include <QDockWidget>

class QAction;
class QLabel;
class QTreeView;

namespace lr {

class Document;
class ModelTreeModel;
class Scene;

class ModelDock : public QDockWidget {
    Q_OBJECT
  public:
    explicit ModelDock(QWidget* parent = nullptr);

    // The scene whose model is shown (nullptr: none); follows its modelChanged.
    void setScene(Scene* scene);
    // The document whose lights the meshes' linking rows count (nullptr: none); follows its rig.
    void setDocument(Document* document);
    ModelTreeModel* treeModel() const { return m_model; }
    QTreeView* view() const { return m_view; }
    QAction* copyAction() const { return m_copy; }

    // Shows and raises the dock with the Warnings branch expanded, current and scrolled to.
    void showWarnings();
    // The selected rows' text, as Copy puts it on the clipboard.
    QString selectedText() const;

  private:
    void reload();

    Scene* m_scene = nullptr;
    Document* m_doc = nullptr;
    ModelTreeModel* m_model;
    QTreeView* m_view;
    QLabel* m_summary;
    QAction* m_copy;
};

} // namespace lr
