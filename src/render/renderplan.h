// The chain of render passes for a kind of frame (f3d's idea): rebuilt only when the PlanKey changes
// (shading path, colour path, MSAA, overlays, blended meshes, shadows, a shadow catcher, a background), not
// every frame. Every pass's reads must be written by an earlier pass or provided by the lit inputs
// (litinput.h); check() says which are not. run() keeps the one rule passes share outside their targets:
// a pass that writes the G-buffer or the depth it shares counts a revision of them (targets.h).
#pragma once

#include "passes.h"

#include <QString>
#include <memory>
#include <vector>

namespace lr::render {

class LitInputs;

// The kinds of frame as named bits (Filament's variant bits). The renderer sets the first five; the lit
// inputs set theirs in LitInput::prepare.
enum class PlanBit : unsigned {
    Deferred = 1u << 0, // G-pass, then deferred lighting
    Hdr = 1u << 1,      // radiance into a float target, then the tone-map pass
    Msaa = 1u << 2,     // the scene target is multisampled
    Overlays = 1u << 3, // gizmos or grid
    Blend = 1u << 4,    // the model has alphaMode BLEND meshes (the blend pass)
    Shadows = 1u << 5,  // some light casts (the shadow pass; input_shadows.h)
    Catcher = 1u << 6,  // the ground is a shadow catcher (the catcher pass; input_ground.h)
    Background =
        1u << 7, // the environment is drawn behind the model (the background pass; input_environment.h)
};

struct PlanKey {
    unsigned bits = 0;
    bool has(PlanBit b) const { return (bits & unsigned(b)) != 0; }
    PlanKey& set(PlanBit b, bool on = true) {
        bits = on ? bits | unsigned(b) : bits & ~unsigned(b);
        return *this;
    }
    bool operator==(const PlanKey&) const = default;
};

class RenderPlan {
  public:
    RenderPlan();
    ~RenderPlan();
    bool initialize(); // context current
    void release();

    // Makes the chain for `key` current (rebuilding it only when the key changed) and returns it.
    const std::vector<RenderPass*>& select(const PlanKey& key);
    // Runs the current chain; false when a pass failed (scene.error says why; later passes still run).
    // Before the first pass that reads a resource an input is still making, that input finishes it.
    bool run(const FrameContext& frame, PassScene& scene);
    // Runs one pass with the plan's bookkeeping: a pass whose writes include resource::kDepthSharing and
    // that did not keep them counts a revision of the G-buffer and depth (targets.h).
    static bool runPass(RenderPass& pass, const FrameContext& frame, PassScene& scene);

    int builds() const { return m_builds; } // chains built since construction
    QString describe() const;               // "geometry (shaded) > present > overlay"
    // Empty when consistent: `provided` is what the lit inputs provide before the first pass.
    static QString check(const std::vector<RenderPass*>& passes, bool msaa,
                         PassResources provided = resource::Lights | resource::Clusters |
                                                  resource::Environment);
    GeometryPass& gbufferPass() { return m_gbuffer; } // Renderer::renderGBuffer

  private:
    ShadowPass m_shadow;
    CatcherPass m_catcher;
    GeometryPass m_gbuffer{GeometryPass::Output::GBuffer};
    GeometryPass m_shaded{GeometryPass::Output::Shaded};
    DeferredLightingPass m_lighting;
    BackgroundPass m_background;
    BlendPass m_blend;
    ResolvePass m_resolve;
    PresentPass m_present;
    ToneMapPass m_toneMap;
    OverlayPass m_overlay;
    std::vector<RenderPass*> m_passes;
    bool m_hasKey = false;
    PlanKey m_key;
    int m_builds = 0;
};

} // namespace lr::render
