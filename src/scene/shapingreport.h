// What `render` says about a rig's light shaping (issue 39, docs/light-shaping.md) before it renders: the IES
// and gobo files that did not load (the light then renders unshaped), and the shaping a renderer does not do.
#pragma once

#include "core/rig.h"

#include <QStringList>

namespace lr {

// Warnings for `rig` rendered by the raster tiers (`pathTraced` false) or the path tracer: one per file that
// did not load ("lights[0].ies.file: FILE:LINE: reason"), and with the raster one per enabled light whose
// IES profile or gobo it draws unshaped (the raster does not shape them yet; the path-traced tier and the
// double reference do).
QStringList shapingWarnings(const Rig& rig, bool pathTraced);

} // namespace lr
