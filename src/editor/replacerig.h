// Replacing the whole rig (apply a preset, import the lights of a model) as one undo step. The new lights get
// fresh ids; undo restores the previous rig with its ids. Selection and solo of vanished lights are dropped.
#pragma once

#include "editor/rigcommand.h"

#include <memory>

namespace lr {

class ReplaceRig : public RigCommand {
  public:
    // nullptr and *error when the rig has more than kMaxRigLights lights or an invalid value (validateRig).
    static std::unique_ptr<ReplaceRig> create(Document* document, const Rig& rig, const QString& text,
                                              QString* error = nullptr);
    void undo() override;
    void redo() override;

  private:
    ReplaceRig(Document* document, Rig rig, const QString& text);
    Rig m_before, m_after;
    QList<LightId> m_beforeIds, m_afterIds;
};

} // namespace lr
