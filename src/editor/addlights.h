// Inserting lights (Add point/spot/directional/rim, paste, import) as one undo step. The new lights get ids
// on the first redo and keep them through undo/redo; redo selects them.
#pragma once

#include "editor/rigcommand.h"

#include <memory>
#include <vector>

namespace lr {

class AddLights : public RigCommand {
  public:
    // row: insertion index (-1: append). nullptr and *error when the rig would exceed kMaxRigLights, when
    // lights is empty or a light is invalid (validateLight).
    static std::unique_ptr<AddLights> create(Document* document, int row, std::vector<Light> lights,
                                             const QString& text, QString* error = nullptr);
    void undo() override;
    void redo() override;
    int row() const { return m_row; }
    int count() const { return int(m_lights.size()); }

  protected:
    AddLights(Document* document, int row, std::vector<Light> lights, const QString& text);

  private:
    int m_row;
    std::vector<Light> m_lights;
    QList<LightId> m_ids; // assigned on first redo
};

} // namespace lr
