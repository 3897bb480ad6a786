// Issue 38's editor tools wired into the main window: the model's parts for the Properties dock's Linking
// section and the linking matrix, the viewport's highlight of the parts the current light lights (while the
// Linking section is open), View › Light linking (linkmatrixdialog.h), and Alt+click on the model, which
// switches whether the selected lights light the part under the cursor (one undo step).
#pragma once

#include "core/lightlink.h"
#include "picking.h"

#include <QObject>
#include <QPointer>
#include <vector>

class QAction;

namespace lr {

class Document;
class LinkMatrixDialog;
class MainWindow;
struct Model;

// The model's parts (scene/linkparts.h, one per mesh): what the Linking section and the matrix list.
std::vector<PartNames> modelLinkParts(const Model& model);

enum class LinkPick { Missed, NothingSelected, Linked, Unlinked, Refused };
// Alt+click: the part of `model` under `screen` in or out of the lit set of every selected light (in when
// some selected light does not light all of its row, else out). *message says what happened (or why not).
LinkPick toggleLitPartAt(Document* document, const Model& model, const ScreenProjector& projector,
                         const QPointF& screen, QString* message);

class LinkTools : public QObject {
    Q_OBJECT
  public:
    explicit LinkTools(MainWindow* window);

    QAction* matrixAction() const { return m_matrixAction; } // View › Light linking
    LinkMatrixDialog* matrixDialog();                        // created on first use
    void showMatrix();

  private:
    void modelChanged();
    void updateHighlight();

    MainWindow* m_window;
    QAction* m_matrixAction;
    QPointer<LinkMatrixDialog> m_matrix;
};

} // namespace lr
