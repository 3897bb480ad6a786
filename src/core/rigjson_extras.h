// Issue 39: a light's "link", "gobo" and "barnDoors" found outside a rig file (a glTF light node's
// extras.lightrig, docs/export.md), read by the rig's own readers (rigjson_extras.cpp) as the current
// format version, so that a bad value gets the rig format's reason.
#pragma once

#include "rig.h"

#include <QByteArray>
#include <QString>
#include <QStringList>
#include <optional>

namespace lr {

struct LightExtras {
    std::optional<LightLink> link;
    std::optional<GoboSpec> gobo;
    std::optional<BarnDoors> barnDoors;
    QStringList errors, warnings; // "FILE: PATH.gobo.scale: reason"
};

// `objectJson` is the object's JSON text and `path` its JSON path in `file` ("nodes[3].extras.lightrig").
// Each key is read on its own: an invalid gobo is left unset (its errors listed) and the link is still read.
// Other keys are left alone (they are not the rig's).
LightExtras readLightExtras(const QByteArray& objectJson, const QString& file, const QString& path);

} // namespace lr
