// Renaming one light (F2 in the light table) as one undo step.
#pragma once

#include "editor/document.h"

#include <QUndoCommand>
#include <memory>

namespace lr {

class RenameLight : public QUndoCommand {
  public:
    // nullptr and *error when row is out of range or the name is invalid (validateLightValue(Name, ...)), or
    // when it equals the current name (*error empty then).
    static std::unique_ptr<RenameLight> create(Document* document, int row, const QString& name,
                                               QString* error = nullptr);
    void undo() override;
    void redo() override;

  private:
    RenameLight(Document* document, int row, QString before, QString after);
    Document* m_doc;
    int m_row;
    QString m_before, m_after;
};

} // namespace lr
