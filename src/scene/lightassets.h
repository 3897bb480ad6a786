// The files a rig's lights name (issue 39): IES profiles and gobo images, loaded once and shared. Every
// renderer reads them from the scene description (SceneDescription::lightAssets()).
#pragma once

#include "core/gobo.h"
#include "core/ies.h"
#include "core/rig.h"

#include <QStringList>
#include <memory>
#include <vector>

namespace lr {

struct LightAssets {
    // Per rig light (Rig::lights order): its profile and gobo, or nullptr (none, or it did not load).
    std::vector<std::shared_ptr<const IesProfile>> ies;
    std::vector<std::shared_ptr<const GoboImage>> gobos;
    // One line per file that did not load: "lights[2].ies.file: FILE:LINE: reason".
    QStringList errors;
    bool anyIes() const;
    bool anyGobo() const;
};

// Loads what `rig` names (IesSpec::resolved, else ::file), each file once per process while it is
// unchanged on disk (same size and modification time). A light whose file fails renders without it.
LightAssets loadLightAssets(const Rig& rig);

// Whether two rigs name the same files (loadLightAssets would return the same).
bool sameLightFiles(const Rig& a, const Rig& b);

} // namespace lr
