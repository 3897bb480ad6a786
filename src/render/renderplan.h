// The chain of render passes for a kind of frame (f3d's idea): rebuilt only when the PlanKey changes
// (shading path, colour path, MSAA, overlays, blended meshes, shadows, a shadow catcher), not every frame.
// Every pass's reads must be written by an earlier pass or be inputs (the light set's Lights and Clusters);
// check() says which are not.
#pragma once

#include "passes.h"

#include <QString>
#include <memory>
#include <vector>

namespace lr::render {

struct PlanKey {
    bool deferred = false;
    bool hdr = false;
    bool msaa = false; // the scene target is multisampled
    bool overlays = false;
    bool blend = false;      // the model has alphaMode BLEND meshes (the blend pass)
    bool shadows = false;    // some light casts (the shadow pass)
    bool catcher = false;    // the ground is a shadow catcher (the catcher pass)
    bool background = false; // the environment is drawn behind the model (the background pass)
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
    bool run(const FrameContext& frame, PassScene& scene);

    int builds() const { return m_builds; } // chains built since construction
    QString describe() const;               // "geometry (shaded) > present > overlay"
    static QString check(const std::vector<RenderPass*>& passes, bool msaa); // empty when consistent
    GeometryPass& gbufferPass() { return m_gbuffer; }                        // Renderer::renderGBuffer

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
