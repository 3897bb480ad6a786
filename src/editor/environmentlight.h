// "Light from environment" (issue 15, part 7) as one undo step: the bright spot of the environment around a
// clicked direction (core/envlight.h) becomes a directional light named "Env light N", and — when asked —
// a dimmed spot appended to the rig's environment.spots so the environment does not light the model twice.
#pragma once

#include "core/envlight.h"

#include <QString>

namespace lr {

class Document;

struct EnvironmentLightResult {
    bool added = false;
    int row = -1;           // the new light's row
    QString message;        // what was done ("Added Env light 1 ...") or why not ("nothing bright here: ...")
    EnvironmentLight light; // what the core function found
};

// `image`: the loaded environment's radiance for the document's current environment (LoadedEnvironment::
// image); its rotation, intensity and the shading model are the rig's. One undo step ("Light from
// environment"); nothing changes when nothing bright is found or the rig cannot take it.
EnvironmentLightResult addLightFromEnvironment(Document* document, const EnvironmentImage& image,
                                               const glm::dvec3& clickedWorldDirection, bool dimSpot);

} // namespace lr
