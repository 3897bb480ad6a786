#include "undodiscard.h"

#include "editor/document.h"

#include <QUndoStack>

namespace lr {

void discardStepsAbove(Document* document, int index) {
    QUndoStack* stack = document->undoStack();
    if (stack->index() <= index) return;
    stack->setIndex(index);
    // Pushing an obsolete command deletes the commands above the index and adds nothing (QUndoStack::push).
    auto* nothing = new QUndoCommand;
    nothing->setObsolete(true);
    stack->push(nothing);
}

} // namespace lr
