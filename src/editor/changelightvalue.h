// The generic property command: sets one LightProperty on N lights (one value for all, or one value per
// light) as a single undo step. Inside a continuous-edit session (Document::beginContinuousEdit) consecutive
// commands on the same lights and property merge, so a slider or gizmo drag is one step.
#pragma once

#include "editor/document.h"

#include <QUndoCommand>
#include <memory>
#include <vector>

namespace lr {

enum CommandId { kChangeLightValueId = 1001, kChangeRigValueId = 1002 };

class ChangeLightValue : public QUndoCommand {
  public:
    // Validates every value against its light (validateLightValue). Rows where the property does not apply
    // are skipped. Returns nullptr and sets *error when rows are out of range, when the property applies to
    // none of them, or when any value is invalid (nothing is pushed then).
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
    const QList<int>& rows() const { return m_rows; }

  private:
    ChangeLightValue(Document* document, QList<int> rows, LightProperty property, std::vector<Light> before,
                     std::vector<Light> after);
    void updateObsolete();

    Document* m_doc;
    QList<int> m_rows; // sorted, unique
    LightProperty m_property;
    std::vector<Light> m_before, m_after; // whole lights: exact undo even when applying adjusted other values
    int m_session;
};

} // namespace lr
