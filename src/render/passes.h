// The render passes, one file each (pass_*.cpp); RenderPlan (renderplan.h) chains them. Reads and writes
// are PassResource bits (renderpass.h).
//
//   pass                 file                 reads                         writes
//   geometry (G-buffer)  pass_geometry.cpp    lights                        G-buffer, scene depth
//   geometry (shaded)    pass_geometry.cpp    lights, clusters              scene colour, scene depth
//   deferred lighting    pass_lighting.cpp    G-buffer, scene depth, ...    scene colour
//   resolve              pass_resolve.cpp     scene colour, scene depth     resolved (single-sample)
//   present              pass_resolve.cpp     scene colour                  output (display path)
//   tone map             pass_tonemap.cpp     resolved                      output (HDR path)
//   overlay              pass_overlay.cpp     resolved (depth)              output (gizmos, grid)
#pragma once

#include "renderpass.h"

namespace lr::render {

// Draws the model: its surfaces into the G-buffer (deferred path, renderGBuffer) or shaded into the scene
// target (forward and clustered forward; display colours or radiance by the colour path).
class GeometryPass final : public RenderPass {
  public:
    enum class Output { GBuffer, Shaded };
    explicit GeometryPass(Output output) : m_output(output) {}
    const char* name() const override;
    PassResources reads() const override;
    PassResources writes() const override;
    bool run(const FrameContext& frame, PassScene& scene) override;

  private:
    Output m_output;
};

// Shades every covered G-buffer pixel once: a full-screen triangle on the far plane, depth-tested
// GL_GREATER, scissored to the model's screen rectangle.
class DeferredLightingPass final : public RenderPass {
  public:
    const char* name() const override { return "deferred lighting"; }
    PassResources reads() const override {
        return resource::Lights | resource::Clusters | resource::GBuffer | resource::SceneDepth;
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

// Light gizmos and the ground grid over the output, occluded by the resolved scene depth.
class OverlayPass final : public RenderPass {
  public:
    const char* name() const override { return "overlay"; }
    PassResources reads() const override { return resource::Resolved | resource::Output; }
    PassResources writes() const override { return resource::Output; }
    bool initialize() override;
    void release() override;
    bool run(const FrameContext& frame, PassScene& scene) override;

  private:
    GLuint m_vao = 0, m_vbo = 0;
};

} // namespace lr::render
