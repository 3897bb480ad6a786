// Turntables (issue 17): N frames around the model, frame k at k·360/N degrees about the up axis (+Y, the
// rig's world up) through the model's centre. Either the camera orbits (its elevation and distance to the
// centre kept: the whole camera turns rigidly) or the rig's lights turn and the camera stays. Shared by
// `lightrig render --turntable` (src/cli/turntable.cpp) and the editor's Export turntable
// (src/app/turntableexport.h). Plain math, no GL.
#pragma once

#include "core/rig.h"
#include "scene/camera.h"

#include <QString>
#include <glm/vec3.hpp>

namespace lr {

enum class TurntableRotation { Camera, Lights };

// k·360/frames, exactly 0 for frame 0.
double turntableDegrees(int frame, int frames);

// The camera turned by `degrees` about +Y through `center` (counter-clockwise seen from above): eye,
// target and up. 0 degrees returns the camera unchanged.
ViewCamera orbitCamera(const ViewCamera& camera, const glm::dvec3& center, double degrees);

// The rig with every light's position and direction turned by `degrees` about +Y through `center` (world
// units; a model-space rig turns about its own origin, which is the model's centre) and its environment
// turned with it (Environment::rotation), so the whole rig rotates. 0 degrees returns the rig unchanged.
Rig rotateRigLights(const Rig& rig, const glm::dvec3& center, double degrees);

// Output names of the frames: the last run of '#' in the file name (not the folder) is replaced by the
// frame number, zero-padded to the run's length ("out_####.png", 7 -> "out_0007.png").
bool hasFrameField(const QString& pattern);
QString framePath(const QString& pattern, int frame);

} // namespace lr
