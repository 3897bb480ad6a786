// Which light properties the Properties dock shows for a light, in which order and with which editor widget.
// What a property is (label, limits, suffix, which types use it, when it is shown) is its row in the
// light-property table (editor/lightproperty.h); this file adds only how the dock edits it.
#pragma once

#include "core/rig.h"
#include "editor/lightproperty.h"

#include <QList>

namespace lr {

// The widget a row of the dock edits its property with.
enum class PropertyEditor {
    LineEdit,       // QLineEdit (Text)
    ComboBox,       // QComboBox of the row's choices (Enum)
    CheckBox,       // QCheckBox (Bool)
    ColorButton,    // ColorButton (Color)
    Number,         // NumberEdit with the row's limits and suffix (Number)
    LogSlider,      // LogSliderEdit: a logarithmic slider beside a NumberEdit (wide Number ranges)
    OptionalNumber, // a "has a value" QCheckBox beside a NumberEdit (OptionalNumber)
    OptionalColor,  // a "has a value" QCheckBox beside a ColorButton (OptionalColor)
    Vector,         // Vec3Edit (Vector)
    FactorOrColor,  // a factor/colour QComboBox beside a NumberEdit and a ColorButton (FactorOrColor)
    PowerOfTwo,     // QComboBox of the powers of two within the row's limits (a shadow map's resolution)
    File,           // a QLineEdit (Text) with a "…" button that chooses a file (PropertyField::fileFilter)
};

struct PropertyField {
    LightProperty property;
    PropertyEditor editor;
    double initial = 0.0;             // OptionalNumber: the value offered when "none" is switched on
    double sliderMin = 0.0;           // LogSlider: the smallest non-zero slider value
    const char* fileFilter = nullptr; // File: the open dialog's name filter
};

// Every property the dock shows as a field, in the order of its rows (the property table's order); not the
// linking, which has a section of its own (linkingsection.h).
const QList<LightProperty>& propertyRows();
// How the dock edits a property: the default editor of its kind unless kFieldEditors names another.
PropertyField propertyField(LightProperty property);
// The object name of a property's field widget ("coneOuter": the row's key), used by tests and style sheets.
QString propertyFieldName(LightProperty property);
// The intensity's unit as a field suffix (docs/rig-format.md): under physically based shading " cd"
// (candela: point, spot), " lx" (lux: directional), " nits" (cd/m²: rect, disk), " (classic)" for the rim
// light's unitless term; under classic shading " (classic)" for every light.
QString intensitySuffix(LightType type, ShadingModel shading);
// The value a File field takes for the file `chosen` (absolute) in a rig saved at `rigPath` (empty:
// untitled): relative to the rig's folder when the file lies in it or below (the rig and its files then
// move together), else absolute (issue 39: IES profiles, gobo images).
QString fileFieldValue(const QString& chosen, const QString& rigPath);
// Whether the dock shows `property` for this light (LightPropertyInfo::isShown).
bool propertyShown(const Light& light, LightProperty property);

} // namespace lr
