// One frame, computed once by Renderer and the lit inputs (litinput.h) before any pass runs: the scene
// description it draws, the camera's matrices, the target, the colour path and its exposure, the shading
// path, the lit programs' feature bits and whether the lights were binned into clusters. Passes read it and
// nothing else of the frame: no pass leaves state for another except through the targets their reads() and
// writes() declare (renderpass.h).
#pragma once

#include "core/shade.h"
#include "environmentgl.h"
#include "gpumodel.h"
#include "rendersettings.h"
#include "scene/camera.h"
#include "shadergen.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QRect>
#include <QSize>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vector>

namespace lr {
class SceneDescription;
}

namespace lr::render {

// Display: exposure, tone map and sRGB per fragment into an 8-bit target. Hdr: linear radiance into a
// float target, then the tone-map pass. Both give the same pixels without MSAA.
enum class ColourPath { Display, Hdr };

struct FrameContext {
    const SceneDescription* scene = nullptr; // what is drawn: the model, the rig, the ground, the environment
    const RenderSettings* settings = nullptr;
    ViewCamera camera;                     // with its clip planes (Renderer::effectiveCamera)
    glm::dmat4 view{1.0}, projection{1.0}; // projection of the tile when there is one
    QSize imageSize;                       // the whole image
    QSize targetSize;                      // what this frame renders: the tile or the image
    ColourPath colourPath = ColourPath::Display;
    float exposureScale = 1.0f; // colour::exposureScale(settings.exposureEV)
    ToneMap toneMap = ToneMap::Clamp;
    glm::vec4 clearColour{0.0f};           // what the scene target is cleared to
    glm::vec3 backgroundLinear{0.0f};      // the tone-map pass composites over it
    bool transparent = false;              // straight alpha, 0 where there is no model
    lighting::ShadeSettings<double> shade; // the rig's scene-wide settings (ambient, scale)
    bool fast = false;                     // Quality::Fast: per vertex, no MSAA, forward only
    bool deferred = false;                 // G-pass + deferred lighting
    bool clustered = false;                // the lights were binned for this frame
    bool farLights = false;                // LightSet::farLights(): PBR programs rescale L (LR_FAR_LIGHTS)
    int lightCount = 0;                    // the lights uploaded (enabled, able to reach the scene)
    bool linking = false;                  // SceneDescription::links().active (RigFeatures::linking)
    // The lit programs' rig features this frame (the lights' rigFeatures(), the far-lights bound, the
    // environment; every feature for the über-shader): every lit pass builds its keys from these.
    RigFeatures features;
    bool overlays = false;        // gizmos, grid or highlighted parts
    int samples = 0;              // of the scene target (> 1: MSAA)
    bool gbufferReadBack = false; // renderGBuffer: clear the G-buffer's colour too
    // The deferred G-buffer holds attributes (FeatureKey::attributes) and the lighting pass builds each
    // pixel's Surface with the material its stencil value names: index + 1 into this list of every opaque
    // material drawn, the ground's too (GpuModel::appendMaterials). Empty: the G-buffer holds Surfaces.
    std::vector<AttributeMaterial> attributeMaterials;
    GLuint outputFbo = 0; // the caller's framebuffer
    // The rig's environment lights the frame (its source is not None and one is loaded and uploaded:
    // LR_ENVIRONMENT in every lit program); its rotation, intensity and classic diffuse model.
    bool environment = false;
    EnvironmentUniforms environmentUniforms;
    // The background pass's chain level (Visible 0, Blurred blur · 5); < 0: no environment background
    // (Color, a transparent image, or no environment).
    float environmentBackgroundLod = -1.0f;
};

} // namespace lr::render
