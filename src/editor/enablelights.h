// Switching lights on or off (the table's "on" checkbox, for one or many rows) as one undo step.
#pragma once

#include "editor/document.h"

#include <QUndoCommand>
#include <memory>

namespace lr {

class EnableLights : public QUndoCommand {
  public:
    // nullptr and *error when rows are empty/out of range, or when no light would change (*error empty then).
    static std::unique_ptr<EnableLights> create(Document* document, const QList<int>& rows, bool enabled,
                                                QString* error = nullptr);
    void undo() override;
    void redo() override;

  private:
    EnableLights(Document* document, QList<int> rows, QList<bool> before, bool enabled);
    void apply(bool undo);
    Document* m_doc;
    QList<int> m_rows; // only rows whose state changes
    QList<bool> m_before;
    bool m_enabled;
};

} // namespace lr
