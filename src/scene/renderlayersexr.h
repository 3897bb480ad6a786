// RenderLayers in and out of multi-layer OpenEXR (issue 37; model/exrencode.h, exrdecode.h): what
// `render --aovs` writes and `lightrig mix` reads. Layers: the beauty as the unnamed R, G, B, A; one RGB
// layer per light group (its name made a valid layer name, exrLayerName, unique against the others and the
// auxiliary layers); "albedo" (R, G, B), "normal" (X, Y, Z) and "depth" (Z, always float) when rendered.
// The header's "lightrig/groups" attribute keeps each group layer's group name and kind as JSON
// ([{"layer": "Key_light", "group": "Key light", "kind": "lights"}, ...]), so a mix file names groups as
// the rig does; a file without it (another renderer's light groups) reads every other RGB layer as a
// group of its own layer name.
#pragma once

#include "model/exrdecode.h"
#include "model/exrencode.h"
#include "renderlayers.h"

#include <QByteArray>
#include <QString>
#include <optional>
#include <utility>
#include <vector>

namespace lr {

inline constexpr char kExrGroupsAttribute[] = "lightrig/groups";

QByteArray encodeRenderLayersExr(const RenderLayers& layers,
                                 std::vector<std::pair<QString, QString>> attributes, ExrPixel pixel,
                                 QString* error);

// The layers of a decoded file; nullopt and *error (the reason) when it has no beauty (unnamed R, G, B)
// or its group list is inconsistent.
std::optional<RenderLayers> renderLayersFromExr(const ExrFile& file, QString* error);

} // namespace lr
