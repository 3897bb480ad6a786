// What `render` says about a rig's light shaping (issue 39, docs/light-shaping.md) before it renders: the IES
// and gobo files that did not load (the light then renders unshaped, in every renderer alike).
#pragma once

#include "core/rig.h"

#include <QStringList>

namespace lr {

// One warning per file of `rig` that did not load ("lights[0].ies.file: FILE:LINE: reason").
QStringList shapingWarnings(const Rig& rig);

} // namespace lr
