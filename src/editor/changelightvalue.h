// The one command that changes values of lights: sets one LightProperty on N lights (one value for all, or
// one value per light) as a single undo step, keyed on the lights' ids (so it stays right when rows move).
// Names, on/off, type, colour, ... all go through it; its undo text comes from the property's row
// (lightproperty.h: "Change intensity of Key", "Rename Key to Rim", "Switch off 3 lights"). Inside a
// continuous-edit session (Document::beginContinuousEdit) consecutive commands on the same lights and
// property merge, so a slider or gizmo drag, or typing x, y and z of one vector, is one step (never Link:
// each linking edit, a click, is a step of its own).
#pragma once

#include "editor/rigcommand.h"

#include <memory>
#include <vector>

namespace lr {

enum CommandId { kChangeLightValueId = 1001, kChangeRigValueId = 1002 };

class ChangeLightValue : public RigCommand {
  public:
    // Validates every value against its light (validateLightValue). Rows where the property does not apply
    // are skipped. Returns nullptr and sets *error when rows are out of range, when the property applies to
    // none of them or when any value is invalid (nothing is pushed then); nullptr with an empty *error when
    // no light would change. A value no two lights may share (a name) that another light has, or that several
    // lights get, is numbered as Add numbers new lights: "Key", "Key 2", "Key 3".
    static std::unique_ptr<ChangeLightValue> create(Document* document, const QList<int>& rows,
                                                    LightProperty property, const QVariant& value,
                                                    QString* error = nullptr);
    static std::unique_ptr<ChangeLightValue> create(Document* document, const QList<int>& rows,
                                                    LightProperty property, const QVariantList& values,
                                                    QString* error = nullptr);

    void undo() override;
    void redo() override;
    int id() const override { return kChangeLightValueId; }
    bool mergeWith(const QUndoCommand* other) override;

    LightProperty property() const { return m_property; }
    const QList<LightId>& lights() const { return m_ids; }

  private:
    ChangeLightValue(Document* document, QList<LightId> ids, LightProperty property,
                     std::vector<Light> before, std::vector<Light> after, const QVariant& value);
    void updateObsolete();

    QList<LightId> m_ids; // in row order at creation
    LightProperty m_property;
    std::vector<Light> m_before, m_after; // whole lights: exact undo even when applying adjusted other values
    int m_session;
};

} // namespace lr
