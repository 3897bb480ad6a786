// Removing any set of lights as one undo step; undo puts them back at their indices with their ids (and
// selects them again).
#pragma once

#include "editor/rigcommand.h"

#include <memory>
#include <vector>

namespace lr {

class RemoveLights : public RigCommand {
  public:
    // nullptr and *error when rows is empty or out of range. Duplicate rows are ignored.
    static std::unique_ptr<RemoveLights> create(Document* document, const QList<int>& rows,
                                                QString* error = nullptr);
    void undo() override;
    void redo() override;

  private:
    RemoveLights(Document* document, QList<int> rows);
    QList<int> m_rows; // sorted ascending: where undo puts the lights back
    std::vector<Light> m_lights;
    QList<LightId> m_ids;
};

} // namespace lr
