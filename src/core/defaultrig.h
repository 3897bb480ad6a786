// Which rig a model gets when it is opened without one — the one rule the editor and the CLI (`render`,
// `bench`) share (issue 13, "Defaults"):
//   - physically based materials (Model::hasPbrMaterials()), or --shading pbr: physically based shading,
//     with the model's own lights when it has some (KHR_lights_punctual semantics already: inverse-square
//     with the range window, smooth cone of exponent 2, candela / lux), else the physically based default
//     studio rig (the "pbr-three-point" preset);
//   - a bundled sample model (resources/models/NAME/) with a "showcase.json" beside it: that rig (issue 41:
//     the editor opens on the Avocado sample lit as a product shot), in the shading chosen as above;
//   - otherwise classic shading, as before: the model's own lights when it has some, else the "default"
//     preset. The bundled Suzanne is the classic showcase: it keeps the classic default (its pixels and the
//     render baselines do not change) although glTF gives it metal-rough values.
// An explicit shading (--shading classic|pbr) overrides the materials' choice; the lights stay as chosen.
#pragma once

#include "rig.h"

#include <QString>
#include <optional>

namespace lr {

struct DefaultRigChoice {
    Rig rig;
    QString source; // "the model's lights", "the default rig" or "the physically based default rig"
};

// modelLights: the model's own lights (world space; empty when it has none). modelPath: as opened (for the
// bundled-model exception, isClassicShowcase).
DefaultRigChoice chooseDefaultRig(bool hasPbrMaterials, const Rig& modelLights, const QString& modelPath,
                                  std::optional<ShadingModel> shadingOverride = std::nullopt);

// The shading chooseDefaultRig picks for a model without an override.
ShadingModel defaultShadingFor(bool hasPbrMaterials, const QString& modelPath);

// The bundled model (":/resources/models/suzanne/Suzanne.gltf", or that file in a source tree).
bool isClassicShowcase(const QString& modelPath);

// The rig beside a bundled sample model (resources/models/NAME/showcase.json), when there is one.
std::optional<Rig> sampleRig(const QString& modelPath);

// The physically based default studio rig: the "pbr-three-point" preset (a built-in fallback, made
// physically based, if it were ever unreadable).
Rig pbrDefaultRig();

// `rig` switched to `model` shading. To Pbr, lights keep their own falloff, cone and diffuse models (as the
// rig format says); the classic keys stay but are neither read nor written.
Rig withShading(Rig rig, ShadingModel model);

} // namespace lr
