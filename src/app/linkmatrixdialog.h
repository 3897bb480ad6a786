// View › Light linking (issue 38): the linking matrix, lights × the model's parts (editor/linkmatrixmodel.h),
// in Lit mode (whether each light lights each part) or Shadow mode (whether each part casts each light's
// shadow). Checking a cell is one undo step. Not modal: it follows the document while the editor is used.
#pragma once

#include "core/lightlink.h"

#include <QDialog>
#include <vector>

class QButtonGroup;
class QLabel;
class QRadioButton;
class QTableView;

namespace lr {

class Document;
class LinkMatrixModel;

class LinkMatrixDialog : public QDialog {
    Q_OBJECT
  public:
    explicit LinkMatrixDialog(Document* document, QWidget* parent = nullptr);

    void setModelParts(std::vector<PartNames> parts);
    LinkMatrixModel* matrix() const { return m_model; }
    QTableView* view() const { return m_view; }
    QRadioButton* litButton() const { return m_lit; }
    QRadioButton* shadowButton() const { return m_shadow; }
    QString message() const;

  private:
    LinkMatrixModel* m_model;
    QTableView* m_view;
    QRadioButton* m_lit;
    QRadioButton* m_shadow;
    QLabel* m_message;
};

} // namespace lr
