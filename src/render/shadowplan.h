// The shadow plan, no GL (issue 14; docs/lighting-models.md "Shadows", docs/architecture.md "Shadow maps").
//
// planShadows() turns the rig's casting lights (Light::hasShadow(), the first kMaxShadowCasters in
// rig order) into ShadowViews in world space: a spot light gets a perspective map, a directional light an
// orthographic one, a point light six perspective faces (90°, slightly widened so filters near a face's
// edge stay on it). An area light (rect, disk) gets a perspective map from its centre fitted to the
// model's sphere when that sphere fits in one cube face's angle, else a cube in the light's own frame
// without its back face (5 layers; 6 when two-sided): see areaShadowKind(). Every map is fitted to the
// model's bounding sphere, never to the view, so orbiting never re-renders one. The ground is not fitted: it
// casts nothing, and a receiver outside a map's frustum cannot have the model between it and the light (the
// frustum contains the model's sphere as seen from the light), so it reads the border depth (1: lit).
#pragma once

#include "core/lightlink.h"
#include "core/prepare.h"
#include "core/rig.h"
#include "model/model.h"

#include <QtGlobal>
#include <array>
#include <glm/mat4x4.hpp>
#include <vector>

namespace lr::render {

// The array never grows past this: the resolution is halved until it fits (docs: the limits).
inline constexpr qint64 kMaxShadowBytes = qint64(512) << 20;
// vec4s per caster in the uShadowRecords uniform array (layout in shaders/shadows.glsl): uniforms, not
// texels of the light buffer, because a texelFetch costs a software rasteriser far more per pixel.
inline constexpr int kShadowTexels = 8;
// A casting light's slot + 1 rides on its type in the light buffer (texel 1.w = type + this × (slot + 1)),
// so finding its shadow costs no extra fetch; a light without a shadow packs exactly as before.
inline constexpr int kShadowSlotScale = 8;
static_assert(kLightTypeCount <= kShadowSlotScale);
// The cube faces' half-angle tangent is 1 + this many texels' worth (each side), so a filter kernel near
// a face's edge still finds depths; the shader projects with the same value (ShadowView::tanHalf).
inline constexpr double kCubeMarginTexels = 24.0;
// PCSS's search and filter radius at most, texels: 24 for point, spot and directional emitters
// (kCubeMarginTexels); for area lights, whose penumbrae are wider, this on a cube (its margin) and
// kAreaMapFilterTexels on a perspective map (whose border is lit: no margin needed).
inline constexpr double kAreaFilterTexels = 64.0;
inline constexpr double kAreaMapFilterTexels = 128.0;

enum class ShadowKind { Perspective = 0, Orthographic = 1, Cube = 2 };
// The map a casting light of this type gets: spot perspective, directional orthographic, point a cube;
// an area light's depends on where the model is (areaShadowKind), this says Cube (it may need one).
// Read from the type's traits: without a position it is orthographic; an area light or a positioned light
// without a cone lights every way round (a cube); a cone fits one perspective map.
constexpr ShadowKind shadowKindOf(LightType type) {
    const LightTypeTraits& t = traitsOf(type);
    return !t.usesPosition && !t.isArea ? ShadowKind::Orthographic
           : t.isArea || !t.usesCone    ? ShadowKind::Cube
                                        : ShadowKind::Perspective;
}
// An area light at world `position` over a model sphere (centre c, radius r) at `resolution`: a
// perspective map when the light is outside the sphere and the sphere's half-angle is within a cube
// face's (its tan at most the face's 1 + 2·kAreaFilterTexels/resolution: then one fitted map has at
// least a face's texel density, at a fifth of the cost), else a cube.
ShadowKind areaShadowKind(const glm::dvec3& position, const glm::dvec3& c, double r, int resolution);
// The diameter an area light's PCSS uses for its penumbra (world units per rig unit of size): a disk's
// diameter, a rect's equal-area disk diameter 2·sqrt(w·h/π); and for its blocker search the largest
// extent (a disk's diameter, a rect's diagonal), so a blocker anywhere the emitter sees past is found.
double areaPenumbraSize(const Light& l);
double areaSearchSize(const Light& l);
// Whether a casting light's emitter has an extent (a size, an area light's shape, or a directional
// light's angle): only then do the balanced and exact tiers filter (PCF, PCSS); a point emitter is one
// compared tap in every tier.
inline bool hasSoftShadow(const Light& l) {
    if (l.isArea()) return areaSearchSize(l) > 0.0;
    return shadowKindOf(l.type) == ShadowKind::Orthographic ? l.shadow.angle > 0.0 : l.shadow.size > 0.0;
}

struct ShadowView {
    int rigIndex = -1; // the light in Rig::lights
    ShadowKind kind = ShadowKind::Perspective;
    int layer = 0;            // first layer in the array (a cube uses `faces`)
    int faces = 6;            // cube: 6, or 5 for a one-sided area light (no face behind its plane)
    int resolution = 0;       // texels per side (the array's)
    glm::dmat4 viewProj{1.0}; // world -> light clip (perspective, orthographic; a cube: unused)
    glm::dvec3 position;      // world: the light (cube), the eye (perspective)
    // Cube: the frame its faces are laid out in (columns, world): the world axes, or for an area light
    // (y × x of its in-plane axes, its direction), so face 4 (+Z) looks where it shines, face 5 behind.
    glm::dmat3 axes{1.0};
    double znear = 0.0, zfar = 1.0;
    double tanHalf = 1.0;   // perspective, cube: tangent of the map's half-angle
    double halfWidth = 1.0; // orthographic: half the map's width in world units
    // Sampling (the light's Shadow, scaled to world units): bias and normal offset in texels, the emitter
    // (perspective and cube: its diameter in world units; orthographic: 2·tan(angle / 2)).
    double bias = 1.0, normalOffset = 1.0, emitter = 0.0;
    // The blocker search's emitter (as `emitter`; an area light's largest extent) and the PCSS radius cap.
    double searchEmitter = 0.0, maxFilterTexels = kCubeMarginTexels;
    // Shadow linking (core/lightlink.h): per model mesh (its part index), whether it casts this light's
    // shadow; empty when every mesh does (no link, or one that excludes none). Part of the map's depths.
    std::vector<bool> casters;
    int layers() const { return kind == ShadowKind::Cube ? faces : 1; }
    // World size of one texel: at distance 1 along the axis (perspective, cube), or anywhere (ortho).
    double texelScale() const;
    // world -> clip of one layer (face 0..5 of a cube; 0 otherwise).
    glm::dmat4 faceViewProj(int face) const;
    // What the map's depths depend on (not bias, offset or emitter: those only change sampling).
    bool sameMap(const ShadowView& o) const;
};

// The casting lights' maps for this rig over a model with `bounds` (world). Lights beyond
// kMaxShadowCasters are left out (the rig reader refuses such rigs; the editor says so).
std::vector<ShadowView> planShadows(const Rig& rig, const SceneFrame& frame, const Bounds& bounds);
// Shadow linking: fills each view's `casters` from `links` (SceneDescription::links(), per rig light) for a
// model of `modelParts` meshes; nothing when the links are inactive. The ground casts nothing anyway.
void linkShadowCasters(std::vector<ShadowView>& views, const LinkResolution& links, std::size_t modelParts);
// Bytes of the array for these views (0 when none).
qint64 shadowMapBytes(const std::vector<ShadowView>& views);

// The per-caster record (uShadowRecords): view -> light matrices for this camera view,
// computed in double and rounded once. `lightIndex`: where the light was uploaded (-1: not uploaded).
std::array<float, 4 * kShadowTexels> packShadow(const ShadowView& v, const glm::dmat4& view, int lightIndex);

} // namespace lr::render
