// Several values of lights as ONE undo step, for gestures that change more than one property at once
// ("place the highlight" moves a light and turns it). Each edit sets one LightProperty of one light; the
// edits of a light are applied in order and validated as ChangeLightValue validates them
// (validateLightValue). Whole lights are stored before and after, keyed on ids, as ChangeLightValue does;
// views are told Any. ChangeLightValue stays the command of single-property edits (and the one that merges
// during drags).
#pragma once

#include "editor/rigcommand.h"

#include <QVariant>
#include <memory>
#include <vector>

namespace lr {

struct LightValueEdit {
    int row = -1;
    LightProperty property = LightProperty::Any;
    QVariant value;
};

class ChangeLightValues : public RigCommand {
  public:
    // nullptr and *error when a row is out of range, a property does not apply to its light or a value is
    // invalid (nothing is pushed then); nullptr with an empty *error when no light would change.
    static std::unique_ptr<ChangeLightValues> create(Document* document, const QList<LightValueEdit>& edits,
                                                     const QString& text, QString* error = nullptr);

    void undo() override;
    void redo() override;
    const QList<LightId>& lights() const { return m_ids; }

  private:
    ChangeLightValues(Document* document, QList<LightId> ids, std::vector<Light> before,
                      std::vector<Light> after, const QString& text);

    QList<LightId> m_ids;
    std::vector<Light> m_before, m_after;
};

} // namespace lr
