// Rig-wide values (name, space, ambient, shading, ground) as undo steps; merges within a continuous-edit
// session.
#pragma once

#include "editor/changelightvalue.h" // CommandId

#include <memory>

namespace lr {

class ChangeRigValue : public RigCommand {
  public:
    // nullptr and *error when the value is invalid (validateRigValue).
    static std::unique_ptr<ChangeRigValue> create(Document* document, RigProperty property,
                                                  const QVariant& value, QString* error = nullptr);
    void undo() override;
    void redo() override;
    int id() const override { return kChangeRigValueId; }
    bool mergeWith(const QUndoCommand* other) override;
    RigProperty property() const { return m_property; }

  private:
    ChangeRigValue(Document* document, RigProperty property, QVariant before, QVariant after);
    QString describe() const; // the history's text
    RigProperty m_property;
    QVariant m_before, m_after;
    int m_session;
};

} // namespace lr
