// Switching a rig between world and model space (rig-format.md "space") without moving its lights: every
// point and spot light's position and range are converted through the model's bounding sphere, so the
// scene looks the same before and after. Inverse-square lights also scale their intensity (by radius² or
// 1/radius²) and inverse-polynomial lights their linear and quadratic terms (radius, radius²), since their
// falloff is measured in the rig's distance units. Directions do not change. One undo step; light ids and
// the selection stay.
#pragma once

#include "core/prepare.h"
#include "editor/rigcommand.h"

#include <memory>
#include <optional>

namespace lr {

// The rig in `space`, looking the same on the model framed by `frame`; nullopt and *error ("Key: the
// intensity would be 2.1e+08, above the limit of 1e+06") when a converted value leaves the rig format's
// limits. The same rig when it already is in that space.
std::optional<Rig> convertRigSpace(const Rig& rig, RigSpace space, const SceneFrame& frame,
                                   QString* error = nullptr);

class ChangeRigSpace : public RigCommand {
  public:
    // nullptr and *error when the space is already `space` or convertRigSpace refuses.
    static std::unique_ptr<ChangeRigSpace> create(Document* document, RigSpace space, const SceneFrame& frame,
                                                  QString* error = nullptr);
    void undo() override;
    void redo() override;

  private:
    ChangeRigSpace(Document* document, Rig before, Rig after);
    void apply(const Rig& rig);
    QList<LightId> m_ids; // the lights converted, in rig order
    Rig m_before, m_after;
};

// Creates and pushes the command; false and *error when refused.
bool changeRigSpace(Document* document, RigSpace space, const SceneFrame& frame, QString* error = nullptr);

} // namespace lr
