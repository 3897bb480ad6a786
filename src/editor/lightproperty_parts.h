// The light-property table's parts, which lightProperties() (lightproperty_link.cpp) joins in the
// Properties dock's order: the value rows (lightproperty_rows.cpp) and the linking row (issue 38).
#pragma once

#include "editor/lightproperty.h"

namespace lr {

std::span<const LightPropertyInfo> valueLightProperties(); // every row but Link
const LightPropertyInfo& linkLightProperty();
// A spot's gobo (issue 39, lightproperty_gobo.cpp): file, scale, rotation; between the values and Link.
inline constexpr std::size_t kGoboLightPropertyCount = 3;
std::span<const LightPropertyInfo> goboLightProperties();
std::span<const LightPropertyInfo> barnDoorLightProperties(); // lightproperty_barndoors.cpp (issue 39)
std::span<const LightPropertyInfo> iesLightProperties();      // issue 39 (lightproperty_ies.cpp)
// A direction row's check (a vector within the row's limits, not zero), named after the row: the light's
// Direction and a point light's IES nadir.
QString checkDirection(const LightPropertyInfo& row, const QVariant& v);

} // namespace lr
