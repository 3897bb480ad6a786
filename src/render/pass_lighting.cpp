// The deferred lighting pass: the G-buffer's surfaces shaded once per covered pixel.
#include "gpumodel.h"
#include "litinput.h"
#include "passes.h"
#include "programcache.h"
#include "scene/scenedescription.h"
#include "shadergen.h"
#include "targets.h"
#include "textureunits.h"

#include <algorithm>
#include <cmath>

namespace lr::render {

namespace {

// The pixels of a `size` target that the box can cover under `viewProjection` (conservative; the whole
// target when a corner is behind the eye).
QRect screenBounds(const Bounds& box, const glm::dmat4& viewProjection, QSize size) {
    double x0 = 1, y0 = 1, x1 = -1, y1 = -1;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 c((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                           (i & 4) ? box.max.z : box.min.z);
        const glm::dvec4 p = viewProjection * glm::dvec4(c, 1.0);
        if (!(p.w > 1e-12)) return QRect(QPoint(0, 0), size);
        x0 = std::min(x0, p.x / p.w), x1 = std::max(x1, p.x / p.w);
        y0 = std::min(y0, p.y / p.w), y1 = std::max(y1, p.y / p.w);
    }
    const auto px = [&](double ndc, int extent) {
        return std::clamp((ndc * 0.5 + 0.5) * extent, 0.0, double(extent));
    };
    const int left = int(std::floor(px(x0, size.width()))) - 1,
              right = int(std::ceil(px(x1, size.width()))) + 1;
    const int bottom = int(std::floor(px(y0, size.height()))) - 1,
              top = int(std::ceil(px(y1, size.height()))) + 1;
    return QRect(QPoint(0, 0), size).intersected(QRect(left, bottom, right - left, top - bottom)); // GL rows
}

} // namespace

void DeferredLightingPass::release() {
    m_surfaceKeys.clear();
}

bool DeferredLightingPass::buildSurfaces(const FrameContext& frame, PassScene& scene,
                                         const std::vector<FeatureKey>& keys) {
    glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->surfaceFbo);
    bool ok = true;
    for (size_t m = 0; m < keys.size(); ++m) {
        const AttributeMaterial& material = frame.attributeMaterials[m];
        glStencilFunc(GL_EQUAL, int(m) + 1, 0xFF);
        QString error;
        MeshProgram* p = scene.programs->meshProgram(keys[m], &error);
        if (!p) {
            ok = fail(scene, error);
            continue;
        }
        p->program->bind();
        bindMaterial(keys[m], *p, *material.draw, *material.source->model(), frame.scene->rig(),
                     *scene.targets, false);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        p->program->release();
    }
    glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->fbo);
    return ok;
}

bool DeferredLightingPass::run(const FrameContext& frame, PassScene& scene) {
    Targets& targets = *scene.targets;
    glBindFramebuffer(GL_FRAMEBUFFER, targets.fbo);
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    // Where the background pass ran first it covered every pixel (reads() declares its colour); the
    // surfaces are shaded over it.
    if (!m_overBackground) {
        glClearColor(frame.clearColour.r, frame.clearColour.g, frame.clearColour.b, frame.clearColour.a);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    const Model* model = scene.model->model();
    if (!model) return true;
    const RenderSettings& settings = *frame.settings;
    const Rig& rig = frame.scene->rig();
    FeatureKey key;
    key.rig = frame.features;
    key.quality = settings.quality; // never Fast: the fast tier is always forward
    key.approximations = approx::forTier(settings.approximations, key.quality);
    key.output = frame.colourPath == ColourPath::Hdr ? ShaderOutput::Radiance : ShaderOutput::Display;
    if (key.output == ShaderOutput::Display) key.toneMap = frame.toneMap;
    key.deferredLighting = true;
    key.clustered = frame.clustered;
    // Only the model's screen rectangle: a software rasteriser runs the shader for background blocks too,
    // even where the depth test rejects every pixel.
    const QRect scissor =
        screenBounds(frame.scene->drawnBounds(), frame.projection * frame.view, frame.targetSize);
    if (scissor.isEmpty()) return true;
    const std::vector<AttributeMaterial>& materials = frame.attributeMaterials;
    // The programs that build each material's Surfaces (the lighting programs' own, without the lights).
    std::vector<FeatureKey> surfaceKeys;
    for (const AttributeMaterial& material : materials) {
        FeatureKey k = key;
        k.rig = RigFeatures();
        k.rig.shading = key.rig.shading;
        k.material = sampledFeatures(*material.draw, rig, key.rig);
        k.attributes = true;
        k.output = ShaderOutput::GBuffer;
        k.toneMap = ToneMap::Clamp;
        k.clustered = false;
        surfaceKeys.push_back(k);
    }
    // Under the attribute G-buffer the Surfaces go through Targets::surfaces: built when the G-buffer was
    // drawn again (or for other programs), kept while it is kept.
    const int revision = targets.gbufferRevision;
    const bool keepable =
        !materials.empty() &&
        (long long)frame.targetSize.width() * frame.targetSize.height() <= kKeptSurfacePixels;
    const bool kept = keepable && targets.surfacesRevision == revision && surfaceKeys == m_surfaceKeys;

    // A full-screen triangle on the far plane, depth-tested GL_GREATER: it passes where a surface was
    // drawn; under the attribute G-buffer each material's pixels are those whose stencil holds its value
    // (the G-pass wrote it).
    const auto fullScreenState = [&](bool stencil) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glDepthMask(GL_FALSE);
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
        glEnable(GL_SCISSOR_TEST);
        glScissor(scissor.x(), scissor.y(), scissor.width(), scissor.height());
        if (stencil) {
            glEnable(GL_STENCIL_TEST);
            glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
            glStencilMask(0);
        }
        glBindVertexArray(scene.targets->emptyVao);
    };
    const auto bindTargets = [&](const GLuint(&textures)[kGBufferTargets]) {
        for (int i = 0; i < kGBufferTargets; ++i) {
            glActiveTexture(textureUnit(TextureUnit::GBuffer0, i));
            glBindTexture(GL_TEXTURE_2D, textures[i]);
        }
        glActiveTexture(GL_TEXTURE0);
    };
    bool ok = true;
    if (keepable && !kept) {
        fullScreenState(true);
        bindTargets(targets.gbuffer);
        QString error;
        targets.surfacesRevision = -1;
        m_surfaceKeys.clear();
        if (!targets.createSurfaces(this, &error)) {
            ok = fail(scene, error);
        } else if (buildSurfaces(frame, scene, surfaceKeys)) {
            targets.surfacesRevision = revision;
            m_surfaceKeys = surfaceKeys;
            ++scene.stats->surfaceBuilds;
        } else {
            ok = false;
        }
        unbindMaterialSamplers();
        glDisable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
    }
    scene.stats->surfacesKept = kept;
    // Whatever ran since the G-pass primed the slots (the programs that built the Surfaces, the
    // background's lookup) left its sampler state in slots the lighting programs' texture buffers use, and
    // a frame that keeps the Surfaces and the background runs none of them: llvmpipe would compile the
    // lighting program again on the second frame (passes.h primeSamplerSlots). The same state every frame.
    primeSamplerSlots(scene);
    // One full-screen triangle over every material's Surfaces, or under the attribute G-buffer one per
    // material, each where the stencil holds that material's value, its Surface built with that material.
    const bool fromSurfaces = keepable && targets.surfacesRevision == revision;
    fullScreenState(!materials.empty() && !fromSurfaces);
    bindTargets(fromSurfaces ? targets.surfaces : targets.gbuffer);
    if (key.rig.linking) { // each pixel's lighting class, as the G-pass wrote it (the kept surfaces too)
        glActiveTexture(textureUnit(TextureUnit::GBufferLink));
        glBindTexture(GL_TEXTURE_2D, targets.gbufferLink);
        glActiveTexture(GL_TEXTURE0);
    }
    scene.inputs->bind(this, frame, key.clustered);
    const size_t draws = fromSurfaces ? 1 : std::max<size_t>(1, materials.size());
    for (size_t m = 0; m < draws; ++m) {
        const AttributeMaterial* material = fromSurfaces || materials.empty() ? nullptr : &materials[m];
        if (material) {
            key.material = sampledFeatures(*material->draw, rig, key.rig);
            key.attributes = true;
            glStencilFunc(GL_EQUAL, int(m) + 1, 0xFF);
        }
        QString error;
        MeshProgram* p = scene.programs->meshProgram(key, &error);
        if (!p) {
            ok = fail(scene, error);
            continue;
        }
        p->program->bind();
        if (material)
            bindMaterial(key, *p, *material->draw, *material->source->model(), rig, *scene.targets, false);
        scene.inputs->setUniforms(this, *p, key, frame);
        if (p->exposureScale >= 0) glUniform1f(p->exposureScale, frame.exposureScale);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        p->program->release();
    }
    if (!materials.empty()) {
        unbindMaterialSamplers();
        glDisable(GL_STENCIL_TEST);
        glStencilMask(0xFF);
    }
    glBindVertexArray(0);
    glDisable(GL_SCISSOR_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    scene.inputs->unbind(this);
    return ok;
}

} // namespace lr::render
