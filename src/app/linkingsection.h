// The Properties dock's Linking section (issue 38, core/lightlink.h): the model's parts, one row per node
// name (editor/linkedit.h linkPartRows; "ground" while the rig's ground is on), with two checkable columns:
// whether the selected light(s) light the part, and whether the part casts their shadow. With several lights
// selected a part some of them link shows the mixed state; a click sets it for all of them as one undo step.
// Names in the lights' lists that match no part of this model are listed greyed with a warning: they are
// kept, never dropped. Reset linking gives the selected lights the default link (one undo step). The section
// folds; while it is open and a light is current, highlightedParts() lists the parts that light lights (the
// viewport tints them).
#pragma once

#include "core/lightlink.h"
#include "editor/linkedit.h"

#include <QWidget>
#include <vector>

class QLabel;
class QPushButton;
class QToolButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace lr {

class Document;

class LinkingSection : public QWidget {
    Q_OBJECT
  public:
    enum Column { PartColumn, LitColumn, ShadowColumn };

    explicit LinkingSection(Document* document, QWidget* parent = nullptr);

    // The model's parts (scene/linkparts.h linkParts(model, nullptr)); the ground is added while it is on.
    void setModelParts(std::vector<PartNames> parts);
    // The parts the rows index: the model's, then the ground's one part while the rig's ground is on (the
    // renderers' part indices, scene/linkparts.h).
    const std::vector<PartNames>& parts() const { return m_parts; }
    const std::vector<LinkPartRow>& rows() const { return m_rows; }

    QTreeWidget* tree() const { return m_tree; }
    QPushButton* resetButton() const { return m_reset; }
    QToolButton* foldButton() const { return m_fold; }
    bool isOpen() const;
    void setOpen(bool open);
    // The tree's item of a part row and of an unmatched name (nullptr when none).
    QTreeWidgetItem* itemOfRow(int row) const;
    QTreeWidgetItem* itemOfUnmatched(const QString& name) const;

    // While the section is open and visible: the parts the current light lights; else none.
    std::vector<std::size_t> highlightedParts() const;

  public slots:
    void refresh();

  signals:
    void highlightChanged();
    void refused(const QString& reason); // a refused edit's reason ("" on success)

  protected:
    void showEvent(QShowEvent* event) override;
    void hideEvent(QHideEvent* event) override;

  private:
    void rebuildRows();
    void onItemChanged(QTreeWidgetItem* item, int column);
    void updateHighlight();

    Document* m_doc;
    std::vector<PartNames> m_modelParts, m_parts;
    std::vector<LinkPartRow> m_rows;
    bool m_groundOn = false;
    QToolButton* m_fold;
    QWidget* m_body;
    QLabel* m_note;
    QTreeWidget* m_tree;
    QPushButton* m_reset;
    bool m_loading = false;
    std::vector<std::size_t> m_highlight;
};

} // namespace lr
