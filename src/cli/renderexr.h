// `lightrig render -o OUT.exr` (issue 37): the render's scene-linear layers as OpenEXR — the beauty alone
// (float or --half RGBA), or with --aovs every layer (scene/renderlayersexr.h: one per light group, albedo,
// normal, depth). What the image is goes in the header: lightrig/quality, lightrig/exposureEV and
// lightrig/toneMap (not applied to the pixels: `lightrig mix` and a compositor apply them), and with the
// path tracer lightrig/samples.
#pragma once

#include "render/rendersettings.h"
#include "scene/renderlayers.h"

#include <QByteArray>
#include <QString>
#include <optional>

namespace lr::cli {

QByteArray encodeRenderExr(const RenderLayers& layers, bool aovs, bool half, const RenderSettings& settings,
                           const QString& quality, std::optional<int> samples, QString* error);

} // namespace lr::cli
