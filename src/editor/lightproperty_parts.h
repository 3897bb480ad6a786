// The light-property table's two halves, which lightProperties() (lightproperty_link.cpp) joins in the
// Properties dock's order: the value rows (lightproperty_rows.cpp) and the linking row (issue 38).
#pragma once

#include "editor/lightproperty.h"

namespace lr {

std::span<const LightPropertyInfo> valueLightProperties(); // every row but Link
const LightPropertyInfo& linkLightProperty();
std::span<const LightPropertyInfo> iesLightProperties(); // issue 39 (lightproperty_ies.cpp)

} // namespace lr
