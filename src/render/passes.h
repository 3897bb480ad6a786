// The render passes, one file each (pass_*.cpp); RenderPlan (renderplan.h) chains them. Reads and writes
// are PassResource bits (renderpass.h).
//
//   pass                 file                 reads                         writes
//   shadow               pass_shadow.cpp      (the rig, the model)          shadow maps (changed ones only)
//   geometry (G-buffer)  pass_geometry.cpp    lights                        G-buffer, scene depth
//   geometry (shaded)    pass_geometry.cpp    lights, clusters              scene colour, scene depth
//   deferred lighting    pass_lighting.cpp    G-buffer, scene depth, ...    scene colour
//                                             (scene colour: the background, when the plan has one)
//   background           pass_background.cpp  scene depth                   scene colour (the environment
//                                                                           where no surface is)
//   blend                pass_blend.cpp       lights, clusters, scene       scene colour (alphaMode BLEND)
//                                             colour and depth
//   shadow catcher       pass_catcher.cpp     lights, shadow maps, scene    scene colour (the ground's
//                                             colour and depth              shadows only)
// Every lit pass also reads the lit inputs it samples (resource::kLitInputs: lights, clusters, shadow maps,
// environment); shadow maps and environment only where the frame has them.
//   resolve              pass_resolve.cpp     scene colour, scene depth     resolved (single-sample)
//   present              pass_resolve.cpp     scene colour                  output (display path)
//   tone map             pass_tonemap.cpp     resolved                      output (HDR path)
//   overlay              pass_overlay.cpp     resolved (depth)              output (gizmos, grid)
#pragma once

#include "renderpass.h"
#include "shadergen.h"

#include <cstdint>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <utility>
#include <vector>

namespace lr::render {

struct GpuDraw;
struct MeshProgram;

// What the passes that draw the model's meshes share (pass_geometry.cpp): the program key of a draw and
// the drawing of a list of draws in order, each with its material's uniforms and textures.
class MeshPass : public RenderPass {
  protected:
    using DrawOrder = std::vector<std::pair<FeatureKey, const GpuDraw*>>;
    // `source`: the model whose draw `d` is (the scene's, or the ground's).
    FeatureKey meshKey(const FrameContext& frame, const PassScene& scene, const GpuDraw& d,
                       ShaderOutput output, bool clustered, const RigFeatures& shaded,
                       const GpuModel* source = nullptr) const;
    // blended: depth test without depth writes, premultiplied "over" (GL_ONE, GL_ONE_MINUS_SRC_ALPHA).
    // `source`: whose draws these are (nullptr: the scene's model).
    bool drawMeshes(const FrameContext& frame, PassScene& scene, const DrawOrder& order, bool clustered,
                    bool blended, const GpuModel* source = nullptr);
    // The draw's material features a lit program samples: no PBR textures under classic shading, no
    // occlusion texture without ambient light to scale.
    static MaterialFeatures sampledFeatures(const GpuDraw& d, const Rig& rig, const RigFeatures& shaded);
    // The draw's material uniforms and textures for program `p` (keyed `key`), each texture with its
    // sampling's sampler of `targets` (`fast`: the fast tier's filtering, F4).
    void bindMaterial(const FeatureKey& key, const MeshProgram& p, const GpuDraw& d, const Model& model,
                      const Rig& rig, const Targets& targets, bool fast);
    void unbindMaterialSamplers();
    // Light linking: the lighting class (LinkResolution::litClass) of draw `d` of `source` (nullptr: the
    // scene's model; else the ground's: SceneDescription::groundPart), 0 when the frame does not link.
    static int litClassOf(const FrameContext& frame, const PassScene& scene, const GpuDraw& d,
                          const GpuModel* source);
    // Mesa's state tracker binds no sampler state into a texture buffer's slot (uLights, the cluster lists)
    // and leaves there whatever the last program bound; llvmpipe keys its compiled fragment shaders on that
    // state too. A pass after the lit ones that samples a real texture in that slot (the environment
    // background) thus made every lit program compile again on the second frame (helmet_1pt in an
    // environment: 0.5-0.8 s). One draw that covers no pixel (kSlotPrimerShader) binds the same sampler
    // state into the first 20 slots before the lit passes, so every frame's lit draws see the same key.
    void primeSamplerSlots(PassScene& scene);
};

// Renders the depth maps of the casting lights whose map changed (input_shadows.h): first in the chain, in
// the plan when some light casts (PlanBit::Shadows).
class ShadowPass final : public RenderPass {
  public:
    const char* name() const override { return "shadow"; }
    PassResources reads() const override { return 0; }
    PassResources writes() const override { return resource::ShadowMaps; }
    bool run(const FrameContext& frame, PassScene& scene) override;
};

// Draws the model: its surfaces into the G-buffer (deferred path, renderGBuffer) or shaded into the scene
// target (forward and clustered forward; display colours or radiance by the colour path). Meshes whose
// material is alphaMode BLEND are left to the blend pass.
//
// The G-buffer is kept while nothing it holds changes (Key): when the frame before drew or kept it with the
// same key, the G-pass draws nothing and the lighting pass shades the kept surfaces again (with the
// scene depth and the material stencil they were drawn with). A light dragged under a still camera thus
// costs the lighting, not the model's geometry. Anything since that wrote the G-buffer or the depth it
// shares (the forward path, a read-back, new targets) is Targets::gbufferWriter and ends the keeping.
class GeometryPass final : public MeshPass {
  public:
    enum class Output { GBuffer, Shaded };
    explicit GeometryPass(Output output) : m_output(output) {}
    const char* name() const override;
    PassResources reads() const override;
    PassResources writes() const override;
    bool run(const FrameContext& frame, PassScene& scene) override;
    void release() override { m_keptValid = false; }
    bool keptOutputs() const override { return m_keptThisRun; }

    // What the G-pass's pixels depend on: the view, the target size, the scene's revisions and every
    // draw's program key (material features, shading model, attributes or surfaces) in order.
    struct Key {
        glm::dmat4 view{0.0}, projection{0.0};
        int width = 0, height = 0;
        int model = -1, ground = -1; // PassScene's revisions
        bool proxies = false, cullBackFaces = false;
        double shininess = 0.0; // the rig's, for materials without their own (classic)
        DrawOrder draws, groundDraws;
        std::vector<std::uint8_t>
            litClasses; // light linking: each part's class (the link target); else empty
        bool operator==(const Key&) const = default;
    };

  private:
    Output m_output;
    Key m_kept;                 // what the G-buffer holds while this pass is Targets::gbufferWriter
    bool m_keptValid = false;   // m_kept was drawn for keeping (not a read-back)
    bool m_keptThisRun = false; // the last run() kept the G-buffer
};

// Shades every covered G-buffer pixel once: a full-screen triangle on the far plane, depth-tested
// GL_GREATER, scissored to the model's screen rectangle.
//
// The kept surfaces: under the attribute G-buffer each pixel's Surface is built from its attributes and
// its material's textures, most of this pass's work. The pass writes them into a second set of targets in
// the Surface layout (Targets::surfaces, up to kKeptSurfacePixels; one program per material, without the
// lights) and shades those with the Surface G-buffer path's program, so while the G-pass keeps the
// G-buffer (a still camera) the frames after the first shade the kept Surfaces without reading the
// textures again. The same programs every frame: a still view compiles nothing of its own.
//
// After a background pass (setOverBackground; RenderPlan::select) it reads the scene colour the background
// left and shades the covered pixels over it; else it clears the colour first.
class DeferredLightingPass final : public MeshPass {
  public:
    const char* name() const override { return "deferred lighting"; }
    PassResources reads() const override {
        return resource::kLitInputs | resource::GBuffer | resource::SceneDepth |
               (m_overBackground ? resource::SceneColor : 0u);
    }
    PassResources writes() const override { return resource::SceneColor; }
    bool run(const FrameContext& frame, PassScene& scene) override;
    void release() override;
    void setOverBackground(bool over) { m_overBackground = over; }

  private:
    // Writes each material's Surfaces into Targets::surfaces with the programs of `keys`.
    bool buildSurfaces(const FrameContext& frame, PassScene& scene, const std::vector<FeatureKey>& keys);
    std::vector<FeatureKey> m_surfaceKeys; // the programs that built Targets::surfaces
    bool m_overBackground = false;
};

// The most pixels the kept surfaces are made for (a second set of four RGBA32F targets: 64 bytes a pixel,
// 256 MiB at this size); beyond it every frame builds the Surfaces from the attributes.
constexpr long long kKeptSurfacePixels = 2048LL * 2048LL;

// The environment behind the model (Environment::background Visible or Blurred, an environment loaded, the
// image not transparent): a full-screen triangle on the far plane, depth-tested LEQUAL without depth
// writes, so it covers exactly the pixels no opaque surface was drawn on; display colours or radiance by
// the colour path, with the frame's exposure and tone map. After the opaque surfaces (deferred: after the
// G-pass, before the lighting), before the catcher's shadows and the blended meshes (neither writes depth,
// both go over it). In the plan when PlanBit::Background.
//
// The background is rendered into a texture of the scene colour's format and copied: on the forward path
// where no surface is (kBackgroundCopyShader), on the deferred path whole (glBlitFramebuffer, no program
// to compile) before the lighting pass shades the covered pixels over it: the same values either way. While
// nothing it depends on changes (Key; a light dragged under a still camera) the environment's lookups are not
// repeated, only the copy. On the deferred path it is rendered depth-tested against the G-buffer's depth, so
// only the pixels no surface covers are looked up (an orbiting camera renders it every frame), and it stays
// valid while that depth does (Key::depth, Targets::gbufferRevision); on the forward path every pixel is,
// against a depth of its own cleared to the far plane. Both draws have the same state, so the lookup compiles
// once. When it cannot draw, on the deferred path it clears the scene colour, which the lighting pass reads.
class BackgroundPass final : public RenderPass {
  public:
    const char* name() const override { return "background"; }
    PassResources reads() const override { return resource::SceneDepth | resource::Environment; }
    PassResources writes() const override { return resource::SceneColor; }
    bool run(const FrameContext& frame, PassScene& scene) override;
    void release() override;

    // What the background's pixels depend on.
    struct Key {
        int environment = -1; // EnvironmentGl::generation(), >= 1 once one is uploaded
        glm::mat3 fromView{0.0f};
        float scale = 0.0f, lod = -1.0f, exposureScale = 0.0f;
        glm::mat4 projection{0.0f};
        int width = 0, height = 0;
        GLenum format = 0; // the scene colour's
        ToneMap toneMap = ToneMap::Clamp;
        bool display = false;
        // The G-buffer revision whose depth the texture was rendered against (only where it is the far
        // plane); -1: every pixel, valid for any depth.
        int depth = -1;
        bool operator==(const Key&) const = default;
    };

  private:
    bool ensureCache(const Key& key);
    GLuint cacheDepth(const Key& key); // m_cacheDepth, made at the first forward render
    Key m_cached; // what the texture holds (environment -1: nothing yet) and its size and format
    GLuint m_cacheTexture = 0, m_cacheFbo = 0;
    GLuint m_cacheDepth = 0; // cleared to the far plane for the forward path's renders
    int m_builds = 0;
};

// Meshes whose material is alphaMode BLEND, after all opaque geometry (forward or deferred): shaded
// forward, sorted back to front by the view depth of their bounds' centre each frame, depth-tested
// against the opaque surfaces without writing depth, composited "over" the scene colour (premultiplied;
// display colours or radiance by the colour path). Never in the G-buffer. In the plan when the model has
// blended meshes (PlanBit::Blend).
class BlendPass final : public MeshPass {
  public:
    const char* name() const override { return "blend"; }
    PassResources reads() const override {
        return resource::kLitInputs | resource::SceneColor | resource::SceneDepth;
    }
    PassResources writes() const override { return resource::SceneColor; }
    bool run(const FrameContext& frame, PassScene& scene) override;
};

// The ground as a shadow catcher (Rig::ground Catcher): invisible except for its shadows. Shaded forward
// after the opaque surfaces of either path, depth-tested without writing depth, it writes black with
// alpha = the shadow's opacity (premultiplied "over"): over an opaque background it darkens it, in a
// transparent image the shadow is the alpha. In the plan when the ground catches (PlanBit::Catcher).
class CatcherPass final : public MeshPass {
  public:
    const char* name() const override { return "shadow catcher"; }
    PassResources reads() const override {
        return resource::Lights | resource::ShadowMaps | resource::SceneColor | resource::SceneDepth;
    }
    PassResources writes() const override { return resource::SceneColor; }
    bool run(const FrameContext& frame, PassScene& scene) override;
};

// MSAA: resolves the scene colour (HDR path) and depth (for the overlay's occlusion test) into the
// single-sample target. In the plan only with MSAA and something to read the result.
class ResolvePass final : public RenderPass {
  public:
    const char* name() const override { return "resolve"; }
    PassResources reads() const override { return resource::SceneColor | resource::SceneDepth; }
    PassResources writes() const override { return resource::Resolved; }
    bool run(const FrameContext& frame, PassScene& scene) override;
    // Only a resolve of depth changes the single-sample depth the G-buffer shares.
    bool keptOutputs() const override { return !m_resolvedDepth; }

  private:
    bool m_resolvedDepth = false;
};

// Display path: the scene's display colours to the output (resolving MSAA on the way).
class PresentPass final : public RenderPass {
  public:
    const char* name() const override { return "present"; }
    PassResources reads() const override { return resource::SceneColor; }
    PassResources writes() const override { return resource::Output; }
    bool run(const FrameContext& frame, PassScene& scene) override;
};

// HDR path: exposure, tone map and sRGB of the resolved radiance into the output, over the background.
class ToneMapPass final : public RenderPass {
  public:
    const char* name() const override { return "tone map"; }
    PassResources reads() const override { return resource::Resolved; }
    PassResources writes() const override { return resource::Output; }
    bool run(const FrameContext& frame, PassScene& scene) override;
};

// Light gizmos, the ground grid and highlighted parts (RenderSettings::highlightedParts) over the output,
// occluded by the resolved scene depth.
class OverlayPass final : public RenderPass {
  public:
    const char* name() const override { return "overlay"; }
    PassResources reads() const override { return resource::Resolved | resource::Output; }
    PassResources writes() const override { return resource::Output; }
    bool initialize() override;
    void release() override;
    bool run(const FrameContext& frame, PassScene& scene) override;

  private:
    // RenderSettings::highlightedParts: each highlighted mesh tinted over the output (before the gizmos).
    bool drawHighlights(const FrameContext& frame, PassScene& scene);
    GLuint m_vao = 0, m_vbo = 0;
};

} // namespace lr::render
