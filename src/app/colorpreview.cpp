#include "colorpreview.h"

#include "colorbutton.h"
#include "editor/document.h"
#include "undodiscard.h"

#include <memory>

namespace lr {

void previewColorEdits(ColorButton* button, Document* document, LightProperty property) {
    struct State {
        std::unique_ptr<ContinuousEdit> edit;
        QList<int> rows;
        int startIndex = 0;
    };
    auto state = std::make_shared<State>();
    QObject::connect(button, &ColorButton::previewStarted, button, [state, document] {
        state->rows = document->selectedRows();
        state->startIndex = document->undoStack()->index();
        state->edit = std::make_unique<ContinuousEdit>(document);
    });
    QObject::connect(button, &ColorButton::colorPreviewed, button,
                     [state, document, property](const glm::dvec3& c) {
                         if (!state->edit || state->rows.isEmpty()) return;
                         document->setLightValue(state->rows, property, QVariant::fromValue(c));
                     });
    QObject::connect(button, &ColorButton::previewFinished, button, [state, document](bool accepted) {
        if (!state->edit) return;
        state->edit.reset();
        if (!accepted) discardStepsAbove(document, state->startIndex);
    });
}

} // namespace lr
