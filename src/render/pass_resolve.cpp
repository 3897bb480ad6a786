// Resolving the multisampled scene target, and presenting the display path's colours.
#include "passes.h"
#include "targets.h"

namespace lr::render {

bool ResolvePass::run(const FrameContext& frame, PassScene& scene) {
    Targets& targets = *scene.targets;
    const int w = frame.targetSize.width(), h = frame.targetSize.height();
    // The HDR path tone-maps resolved radiance; the display path resolves its colours while presenting.
    // The overlay's occlusion test reads resolved depth.
    const GLbitfield mask = (frame.colourPath == ColourPath::Hdr ? GL_COLOR_BUFFER_BIT : 0) |
                            (frame.overlays ? GL_DEPTH_BUFFER_BIT : 0);
    m_resolvedDepth = targets.samples > 1 && (mask & GL_DEPTH_BUFFER_BIT);
    if (targets.samples <= 1 || !mask) return true;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.msaaFbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets.fbo);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, mask, GL_NEAREST);
    return true;
}

bool PresentPass::run(const FrameContext& frame, PassScene& scene) {
    const int w = frame.targetSize.width(), h = frame.targetSize.height();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, scene.targets->drawFbo());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, frame.outputFbo);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST); // resolves MSAA
    glBindFramebuffer(GL_FRAMEBUFFER, frame.outputFbo);
    return true;
}

} // namespace lr::render
