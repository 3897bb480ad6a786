// Prefiltering an environment for shading (issue 15; docs/lighting-models.md "Environment"): irradiance
// as 9 SH coefficients and as a small equirectangular map, and the split-sum specular chain by roughness
// (PrefilteredEnvironment in core/environment.h). CPU, on the global thread pool; no GL.
#pragma once

#include "core/environment.h"

namespace lr {

PrefilteredEnvironment prefilterEnvironment(const EnvironmentImage& image);

} // namespace lr
