// The raster tiers' light-group split (issue 37; docs/light-mixing.md "The raster"): the renderer's current
// model, rig and environment rendered as linear radiance (OffscreenRenderer::renderRadiance), once whole
// (the beauty) and once per light group with the rig reduced to that group, so that the group images sum
// to the beauty to float rounding; albedo, world-space normal and view-axis depth from the G-buffer.
//
// One pass per group. Each group's pass holds what the beauty's frame coupled between groups:
//   - lights: only the group's lights are on; a caster keeps the shadow map resolution the beauty's array
//     had (the array's resolution is the largest any caster asks for, halved to fit), and a light beyond
//     the first kMaxShadowCasters casters casts in no pass (as in the beauty);
//   - the shading path: the beauty's (deferred or forward: Auto picks by light count under MSAA), so that
//     edge pixels resolve alike;
//   - environment: its light and its visible background in the "environment" pass alone; other passes run
//     with the rig's environment off (its textures stay uploaded);
//   - emission: a surface always adds its emission, so one pass with nothing lit is the "emissive" image
//     and is subtracted from every other pass;
//   - ambient: the rig's scene ambient in the "ambient" pass alone (a light's own ambient is its group's);
//   - background: the radiance has none (the background colour is composited at display, over alpha):
//     "background" is zero, except over a shadow catcher, whose composite is not linear in the lights:
//     there it holds beauty − Σ other groups (with an environment background visible behind the catcher,
//     the environment group holds it unshadowed and "background" the catcher's darkening).
// The renderer's rig is restored afterwards (also on failure).
#pragma once

#include "offscreen.h"
#include "scene/renderlayers.h"

#include <QSize>
#include <QString>
#include <optional>
#include <vector>

namespace lr {

// What one split cost (lightrig bench --groups).
struct RasterLayersStats {
    int passes = 0;        // radiance passes: the beauty's, each group's, the emission's (when it emits)
    int groups = 0;        // group images
    double beautyMs = 0.0; // the beauty pass (with its read-back)
    double splitMs = 0.0;  // every other pass, the G-buffer and the subtractions
    qint64 bytes = 0;      // of the layers returned (rasterLayersBytes)
};

// Needs renderer.renderer() to hold a model (else fails) and `size` within one tile (renderer.maxTileSize():
// larger sizes are refused, naming the limit). Float RGBA32F read-backs; no supersampling. `progress`, when
// given, is called with (passes done, passes in all) before the first pass and after each; returning false
// cancels ("cancelled"). It may run the event loop: the renderer's rig is the group's meanwhile.
std::optional<RenderLayers> renderRasterLayers(OffscreenRenderer& renderer, const ViewCamera& camera,
                                               QSize size, const RenderSettings& settings, QString* error,
                                               RasterLayersStats* stats = nullptr,
                                               const TileProgress& progress = {});

// The rig one group's pass renders: `rig` with only `group`'s share on. `shadowResolution` (> 0): every
// caster's map resolution (the beauty's array's); `casts[i]` false: light i casts no shadow (it did not in
// the beauty). The background group's rig has nothing on (as the emission's).
Rig groupPassRig(const Rig& rig, const LightGroup& group, int shadowResolution,
                 const std::vector<bool>& casts);

// Bytes of the layers for `groups` groups at `size`: the beauty, the groups and three auxiliary images
// (RGBA32F each), and the emission's scratch image; the renderer's own targets are not counted.
qint64 rasterLayersBytes(QSize size, int groups);

} // namespace lr
