// Live colour preview: while a ColorButton's dialog is open the selected lights take each colour it shows
// (one continuous edit, so the viewport follows); OK keeps the last one as one undo step, Cancel takes the
// preview back and leaves nothing on the undo or redo stack.
#pragma once

#include "editor/lightproperty.h"

namespace lr {

class ColorButton;
class Document;

// `property` is a colour of the selected lights (Color, Specular, Ambient).
void previewColorEdits(ColorButton* button, Document* document, LightProperty property);

} // namespace lr
