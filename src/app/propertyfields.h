// Which light properties the Properties dock shows for a light: exactly the values its type and its
// falloff/cone models use (docs/rig-format.md), in display order.
#pragma once

#include "core/rig.h"
#include "editor/lightproperty.h"

#include <QList>

namespace lr {

// Every property the dock can show, in the order of its rows.
const QList<LightProperty>& propertyRows();
// The object name of a property's field widget ("coneOuter"), used by tests and style sheets.
QString propertyFieldName(LightProperty property);
// Whether the dock shows `property` for this light.
bool propertyShown(const Light& light, LightProperty property);

} // namespace lr
