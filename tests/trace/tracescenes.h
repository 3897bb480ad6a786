// Scenes built in code for the path tracer's tests: quads, boxes and spheres with glTF materials, uniform
// environments, physically based rigs; and what the tests measure on a traced image.
#pragma once

#include "core/shadetypes.h"
#include "scene/scenedescription.h"
#include "trace/camerarays.h"
#include "trace/pathtracer.h"

#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace tracetest {

lr::Material pbrMaterial(const glm::vec3& base, float metallic, float roughness);
// One mesh of quads (each 4 corners counter-clockwise seen from the side its normal points to), world
// positions, one material.
lr::Model quadsModel(const std::vector<std::array<glm::dvec3, 4>>& quads, const lr::Material& material);
// A box open at the top (+Y): floor and four walls facing inwards, centred on the origin, side 2.
lr::Model openBox(const lr::Material& material);
// Appends b's meshes (and its materials) to a.
void merge(lr::Model& a, const lr::Model& b);
// A uniform environment of radiance L (equirectangular w × w/2).
std::shared_ptr<const lr::LoadedEnvironment> uniformEnvironment(const glm::vec3& radiance, int width = 16);
// A physically based rig, world space, no lights, no ground, and its environment source set when `env`.
lr::Rig pbrRig(bool environment);
std::unique_ptr<lr::SceneDescription> describe(const lr::Model& model, const lr::Rig& rig,
                                               std::shared_ptr<const lr::LoadedEnvironment> environment = {});
// The mean of channel c (0..3) over the image, or over the pixels where `mask` is non-zero.
double meanChannel(const lr::FloatImage& image, int c);
// Whether every channel of every pixel is finite.
bool allFinite(const lr::FloatImage& image);
// The surface the eye ray through the centre of pixel (x, y) hits, in view space (`view`: world -> view), as
// core shades it (base colour, metallic, roughness); nullopt where the ray hits nothing. What a test of
// direct light compares the traced image with: lighting::shadeSurface of it.
std::optional<lr::lighting::Surface<double>> viewSurfaceAt(const lr::trace::TraceScene& traced,
                                                           const lr::trace::CameraRays& rays,
                                                           const glm::dmat4& view, int x, int y);
lr::ViewCamera lookAt(const glm::dvec3& eye, const glm::dvec3& target, double fovDeg,
                      const glm::dvec3& up = glm::dvec3(0.0, 1.0, 0.0));

} // namespace tracetest
