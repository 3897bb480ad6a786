// Cancelling a gesture that already changed the rig (Esc during a viewport drag, Cancel in the colour
// dialog's live preview): its steps are taken back and dropped from the redo side too, since a cancelled
// gesture never happened.
#pragma once

namespace lr {

class Document;

// Undoes the steps above undo index `index` and deletes them (nothing to redo afterwards). Nothing happens
// when the stack is at or below `index`.
void discardStepsAbove(Document* document, int index);

} // namespace lr
