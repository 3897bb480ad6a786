// The geometry pass: the model's draws grouped by shader variant, into the G-buffer or shaded.
#include "gpumodel.h"
#include "input_ground.h"
#include "litinput.h"
#include "passes.h"
#include "programcache.h"
#include "scene/scenedescription.h"
#include "shadergen.h"
#include "targets.h"
#include "textureunits.h"

#include <algorithm>
#include <cmath>
#include <glm/ext/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>

namespace lr::render {

const char* GeometryPass::name() const {
    return m_output == Output::GBuffer ? "geometry (G-buffer)" : "geometry (shaded)";
}

PassResources GeometryPass::reads() const {
    return m_output == Output::GBuffer ? PassResources(0) : PassResources(resource::kLitInputs);
}

PassResources GeometryPass::writes() const {
    return m_output == Output::GBuffer ? PassResources(resource::GBuffer | resource::SceneDepth)
                                       : PassResources(resource::SceneColor | resource::SceneDepth);
}

bool GeometryPass::run(const FrameContext& frame, PassScene& scene) {
    const bool gpass = m_output == Output::GBuffer;
    Targets& targets = *scene.targets;
    glViewport(0, 0, frame.targetSize.width(), frame.targetSize.height());
    primeSamplerSlots(scene);
    const ShaderOutput output = gpass                                 ? ShaderOutput::GBuffer
                                : frame.colourPath == ColourPath::Hdr ? ShaderOutput::Radiance
                                                                      : ShaderOutput::Display;
    const RenderSettings& settings = *frame.settings;
    const Rig& rig = frame.scene->rig();
    const Model* model = scene.model->model();
    const GroundInput* groundInput = scene.inputs->find<GroundInput>();
    const GpuModel* groundModel = groundInput ? groundInput->gpu() : nullptr;
    m_keptThisRun = false;
    const bool drawsModel = model && !scene.model->draws().empty();
    // Fast lights the vertices, each with every light: clusters (per fragment) do not apply.
    const bool clustered = !gpass && frame.clustered;
    // Group the draws by program so each variant is bound once per frame. Blended (alphaMode BLEND)
    // meshes are the blend pass's (pass_blend.cpp): after all opaque geometry, never in the G-buffer. A
    // visible ground is one more opaque surface (in the G-buffer too); a catcher is the catcher pass's.
    DrawOrder order, ground;
    if (drawsModel) {
        const RigFeatures& shaded = frame.features;
        order.reserve(scene.model->draws().size());
        for (const GpuDraw& d : scene.model->draws())
            if (!d.features.alphaBlend)
                order.emplace_back(meshKey(frame, scene, d, output, clustered, shaded), &d);
        std::stable_sort(order.begin(), order.end(),
                         [](const auto& a, const auto& b) { return a.first.bits() < b.first.bits(); });
        if (groundModel && groundInput->mode() == GroundMode::Visible)
            for (const GpuDraw& d : groundModel->draws())
                ground.emplace_back(meshKey(frame, scene, d, output, clustered, shaded, groundModel), &d);
    }
    Key key;
    if (gpass) {
        key = {frame.view,
               frame.projection,
               frame.targetSize.width(),
               frame.targetSize.height(),
               frame.scene->modelGeneration(),
               groundModel ? groundInput->revision() : -1,
               settings.interactive && scene.model->updateProxies(this),
               settings.cullBackFaces,
               rig.shading.shininess,
               order,
               ground,
               frame.features.linking ? frame.scene->links().litClass : std::vector<std::uint8_t>()};
        // Nothing else wrote the G-buffer or its depth since this pass drew it (a forward frame, a
        // read-back, new targets would be Targets::gbufferWriter), and it would draw the same.
        const bool keep = drawsModel && !frame.gbufferReadBack && m_keptValid &&
                          targets.gbufferWriter == this && key == m_kept;
        scene.stats->gbufferKept = keep;
        if (keep) {
            m_keptThisRun = true;
            scene.stats->drawCalls = 0;
            scene.stats->trianglesDrawn = 0;
            return true;
        }
        // The G-buffer's colour needs no clear for the lighting pass (it reads only pixels a surface was
        // drawn on); a read-back reads every pixel.
        // The attribute G-buffer marks each pixel with its material's stencil value (materialSlot).
        glBindFramebuffer(GL_FRAMEBUFFER, targets.gbufferFbo);
        // Light linking: each pixel's lighting class goes into the link target as well.
        QString error;
        if (!targets.useGBufferLink(this, frame.features.linking, &error)) return fail(scene, error);
        if (frame.gbufferReadBack) glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
        const bool stencil = !frame.attributeMaterials.empty();
        if (stencil) glClearStencil(0);
        glClear(GL_DEPTH_BUFFER_BIT | (frame.gbufferReadBack ? GL_COLOR_BUFFER_BIT : 0) |
                (stencil ? GL_STENCIL_BUFFER_BIT : 0));
    } else {
        glBindFramebuffer(GL_FRAMEBUFFER, targets.drawFbo());
        glClearColor(frame.clearColour.r, frame.clearColour.g, frame.clearColour.b, frame.clearColour.a);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    // RenderPlan::runPass counts a revision of the G-buffer and depth after this run: what was built from
    // them is stale.
    scene.stats->drawCalls = 0;
    scene.stats->trianglesDrawn = 0;
    if (!drawsModel) return true;
    bool ok = drawMeshes(frame, scene, order, clustered, false);
    if (!ground.empty()) ok = drawMeshes(frame, scene, ground, clustered, false, groundModel) && ok;
    m_keptValid = false;
    if (gpass && ok && !frame.gbufferReadBack) {
        m_kept = std::move(key);
        m_keptValid = true;
        ++scene.stats->gbufferBuilds;
    }
    return ok;
}

FeatureKey MeshPass::meshKey(const FrameContext& frame, const PassScene& scene, const GpuDraw& d,
                             ShaderOutput output, bool clustered, const RigFeatures& shaded,
                             const GpuModel* source) const {
    const RenderSettings& settings = *frame.settings;
    const Rig& rig = frame.scene->rig();
    const Model* model = (source ? source : scene.model)->model();
    const bool gpass = output == ShaderOutput::GBuffer;
    FeatureKey key;
    if (!gpass) key.rig = shaded;     // the G-pass does no lighting,
    key.rig.shading = shaded.shading; // but writes the physically based fields under PBR
    key.rig.linking = shaded.linking; // ... and the part's lighting class when the rig links
    key.material = sampledFeatures(d, rig, shaded);
    key.attributes = gpass && !frame.attributeMaterials.empty(); // then it writes attributes, not Surfaces
    key.quality = gpass ? Quality::Exact : settings.quality;     // the G-buffer is the exact surface
    key.approximations = approx::forTier(settings.approximations, key.quality);
    // B2: an integer shininess becomes a chain of products (classic: PBR has no shininess)
    if ((key.approximations & approx::kB2) && shaded.shading == ShadingModel::Classic) {
        const Material& m = d.material >= 0 ? model->materials[size_t(d.material)] : Material();
        const double n = m.shininess >= 0.0f ? double(m.shininess) : rig.shading.shininess;
        if (n >= 1.0 && n <= kMaxShininessInt && n == std::floor(n)) key.shininessInt = std::uint16_t(n);
    }
    key.output = output;
    if (output == ShaderOutput::Display) key.toneMap = frame.toneMap;
    key.clustered = clustered;
    return key;
}

void MeshPass::primeSamplerSlots(PassScene& scene) {
    QString error;
    QOpenGLShaderProgram* p = scene.programs->fixedProgram(kSlotPrimerShader, &error);
    if (!p) return; // a cost only: every frame still renders the same image
    p->bind();      // its samplers keep the default unit 0
    // A fixed target and state, so that this program's own compiled variant is the same every frame.
    glBindFramebuffer(GL_FRAMEBUFFER, scene.targets->fbo);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, scene.targets->slotTexture);
    glBindSampler(0, 0);
    glBindVertexArray(scene.targets->emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glEnable(GL_DEPTH_TEST);
    p->release();
}

MaterialFeatures MeshPass::sampledFeatures(const GpuDraw& d, const Rig& rig, const RigFeatures& shaded) {
    MaterialFeatures f = d.features;
    if (shaded.shading != ShadingModel::Pbr) // classic programs never sample the PBR textures
        f.metalRoughTexture = f.occlusionTexture = false;
    // Occlusion scales ambient light only (glTF): without any (no scene ambient, no light's ambient colour,
    // no environment) it changes nothing, so the texture is not read (the G-buffer then holds occlusion 1).
    if (rig.ambient == glm::dvec3(0.0) && !shaded.lightAmbient && !shaded.environment)
        f.occlusionTexture = false;
    return f;
}

void MeshPass::bindMaterial(const FeatureKey& key, const MeshProgram& p, const GpuDraw& d, const Model& model,
                            const Rig& rig, const Targets& targets, bool fast) {
    static const Material defaultMaterial;
    const Material& m = d.material >= 0 ? model.materials[size_t(d.material)] : defaultMaterial;
    glUniform4fv(p.baseColor, 1, glm::value_ptr(m.baseColor));
    glUniform3fv(p.emissive, 1, glm::value_ptr(m.emissive));
    glUniform3fv(p.specular, 1, glm::value_ptr(m.specular));
    glUniform1f(p.shininess, m.shininess >= 0.0f ? m.shininess : float(rig.shading.shininess));
    if (p.normalScale >= 0) glUniform1f(p.normalScale, m.normalScale);
    if (p.alphaCutoff >= 0) glUniform1f(p.alphaCutoff, m.alphaCutoff);
    const auto transforms = textureTransforms(m);
    for (size_t i = 0; i < p.textureTransforms.size(); ++i)
        if (p.textureTransforms[i] >= 0)
            glUniformMatrix3fv(p.textureTransforms[i], 1, GL_FALSE,
                               glm::value_ptr(textureTransformMatrix(*transforms[i])));
    if (p.metallic >= 0) glUniform1f(p.metallic, m.metallic);
    if (p.roughness >= 0) glUniform1f(p.roughness, m.roughness);
    if (p.occlusionStrength >= 0) glUniform1f(p.occlusionStrength, m.occlusionStrength);
    const struct {
        TextureUnit unit;
        GLuint texture;
        const TextureSampling& sampling;
    } textures[] = {{TextureUnit::BaseColor, d.baseColorTexture, m.baseColorSampling},
                    {TextureUnit::Normal, d.normalTexture, m.normalSampling},
                    {TextureUnit::Emissive, d.emissiveTexture, m.emissiveSampling},
                    {TextureUnit::MetalRough, key.material.metalRoughTexture ? d.metalRoughTexture : 0,
                     m.metallicRoughnessSampling},
                    {TextureUnit::Occlusion, key.material.occlusionTexture ? d.occlusionTexture : 0,
                     m.occlusionSampling}};
    for (const auto& t : textures) {
        if (!t.texture) continue;
        glActiveTexture(textureUnit(t.unit));
        glBindTexture(GL_TEXTURE_2D, t.texture);
        glBindSampler(GLuint(t.unit), targets.materialSampler(t.sampling, fast));
    }
}

int MeshPass::litClassOf(const FrameContext& frame, const PassScene& scene, const GpuDraw& d,
                         const GpuModel* source) {
    if (!frame.features.linking || d.mesh < 0) return 0;
    const SceneDescription& described = *frame.scene;
    const bool ground = source && source != scene.model;
    const std::size_t part = ground ? described.groundPart(std::size_t(d.mesh)) : std::size_t(d.mesh);
    const std::vector<std::uint8_t>& classes = described.links().litClass;
    return part < classes.size() ? int(classes[part]) : 0;
}

void MeshPass::unbindMaterialSamplers() {
    for (const TextureUnit unit : {TextureUnit::BaseColor, TextureUnit::Normal, TextureUnit::Emissive,
                                   TextureUnit::MetalRough, TextureUnit::Occlusion})
        glBindSampler(GLuint(unit), 0);
}

bool MeshPass::drawMeshes(const FrameContext& frame, PassScene& scene,
                          const std::vector<std::pair<FeatureKey, const GpuDraw*>>& order, bool clustered,
                          bool blended, const GpuModel* source) {
    const RenderSettings& settings = *frame.settings;
    const Rig& rig = frame.scene->rig();
    const Model* model = (source ? source : scene.model)->model();
    const glm::dmat4 modelView = frame.view * glm::translate(glm::dmat4(1.0), model->origin);
    const glm::mat4 mv(modelView), proj(frame.projection);
    const glm::mat3 normalMatrix(glm::transpose(glm::inverse(glm::dmat3(modelView))));
    const bool useProxies = !source && settings.interactive && scene.model->updateProxies(this);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    // Blended surfaces: depth-tested against the opaque ones, not written; premultiplied "over".
    glDepthMask(blended ? GL_FALSE : GL_TRUE);
    if (blended) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    } else {
        glDisable(GL_BLEND);
    }
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    if (!order.empty() && order.front().first.attributes) { // the attribute G-pass's stencil values
        glEnable(GL_STENCIL_TEST);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        glStencilMask(0xFF);
    }
    scene.inputs->bind(this, frame, clustered);
    bool ok = true;
    MeshProgram* current = nullptr;
    for (const auto& [key, d] : order) {
        QString error;
        MeshProgram* p = scene.programs->meshProgram(key, &error);
        if (!p) {
            ok = fail(scene, error);
            continue;
        }
        if (p != current) {
            current = p;
            p->program->bind();
            glUniformMatrix4fv(p->modelView, 1, GL_FALSE, glm::value_ptr(mv));
            glUniformMatrix3fv(p->normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
            glUniformMatrix4fv(p->projection, 1, GL_FALSE, glm::value_ptr(proj));
            scene.inputs->setUniforms(this, *p, key, frame);
            if (p->exposureScale >= 0) glUniform1f(p->exposureScale, frame.exposureScale);
        }
        bindMaterial(key, *p, *d, *model, rig, *scene.targets, key.quality == Quality::Fast);
        if (p->linkClass >= 0) glUniform1i(p->linkClass, litClassOf(frame, scene, *d, source));
        if (key.attributes)
            glStencilFunc(GL_ALWAYS,
                          (source ? source : scene.model)->materialSlot(frame.attributeMaterials, *d), 0xFF);
        if (settings.cullBackFaces && !d->features.doubleSided)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        const bool proxy = useProxies && d->lodVao;
        glBindVertexArray(proxy ? d->lodVao : d->vao);
        const GLsizei indices = proxy ? d->lodIndexCount : d->indexCount;
        glDrawElements(GL_TRIANGLES, indices, GL_UNSIGNED_INT, nullptr);
        scene.stats->trianglesDrawn += indices / 3;
        ++scene.stats->drawCalls;
    }
    glBindVertexArray(0);
    unbindMaterialSamplers();
    glDisable(GL_STENCIL_TEST);
    scene.inputs->unbind(this);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glActiveTexture(GL_TEXTURE0);
    return ok;
}

} // namespace lr::render
