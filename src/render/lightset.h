// The GPU light set: one rig's lights prepared in view space and packed (lightpack.h) into a texture
// buffer of kLightTexels RGBA32F texels per light, re-uploading only the texels that changed; and, per
// frame, their clustered binning (cluster.h, clustergl.h). Separate from the GPU scene (GpuModel), so two
// rigs can be drawn over one model. Needs the current context of the owning Renderer.
#pragma once

#include "cluster.h"
#include "clustergl.h"
#include "core/lightlink.h"
#include "core/prepare.h"
#include "core/rig.h"
#include "rendersettings.h"

#include <QOpenGLFunctions_3_3_Core>
#include <QSize>
#include <glm/mat4x4.hpp>
#include <vector>

namespace lr::render {

struct MeshProgram;
struct ShadowView;
struct ShapingLayers;

// Where shade.glsl's single-inversesqrt light direction stops being exact is |toLight| = 1e15; a
// decade of margin covers the float rounding of the view-space positions.
inline constexpr double kFarLightDistance = 1e14;

class LightSet {
  public:
    void initialize(QOpenGLFunctions_3_3_Core* gl);
    void release(QOpenGLFunctions_3_3_Core* gl);

    void setRig(const Rig& rig); // cheap: uploaded by the next update()
    const Rig& rig() const { return m_rig; }
    void invalidate() { m_dirty = true; } // the scene frame changed (a new model)

    // Prepares and uploads every enabled light that can reach the scene, for `view`, when the rig or the
    // view changed since the last upload. Sets stats->lightsUploaded and lightBytesUploaded.
    // `shadows` (planShadows for this rig and model): each caster's kShadowTexels vec4s (view -> light
    // matrices for this view) become the uShadowRecords uniforms, and its light's texel 1.w (the type)
    // gains kShadowSlotScale × (slot + 1).
    // `reach`: the sphere lights are culled against (the model's and the ground's; nullptr: `frame`).
    // `links` (SceneDescription::links(), per rig light; nullptr or inactive: no linking): when active each
    // light gets one more texel, its lit-class mask (kLinkedLightTexels, lightpack.h packLinkTexel). It
    // changes only with the rig or the model, which mark the set dirty.
    // `shaping` (lightshapinggl.h; nullptr: none loaded): when the rig has IES profiles or gobos
    // (RigFeatures::ies, ::gobo) each light gets their texels, naming its layers; a profile's level
    // "profile" sets the light's colours (core/iesshade.h applyIesProfile). It changes only with the rig.
    void update(QOpenGLFunctions_3_3_Core* gl, const SceneFrame& frame, const glm::dmat4& view,
                RenderStats* stats, const std::vector<ShadowView>* shadows = nullptr,
                const SceneFrame* reach = nullptr, const LinkResolution* links = nullptr,
                const ShapingLayers* shaping = nullptr);
    int shadowCount() const { return m_shadowCount; }
    int count() const { return m_count; }
    // Whether an uploaded point or spot light may be kFarLightDistance or more from the model's bounding
    // sphere in view space (or its bound is not finite): physically based programs then rescale the
    // direction to the light before normalising it (LR_FAR_LIGHTS, shaders/shade.glsl lightArrival).
    bool farLights() const { return m_farLights; }

    // Bins the uploaded lights for this projection and target; false when clustering is off for this
    // frame (settings, too few bounded lights, or a projection without a usable near plane).
    bool cluster(QOpenGLFunctions_3_3_Core* gl, const glm::dmat4& projection, QSize target,
                 int clusteredShading, RenderStats* stats);

    // Binds the light buffer (TextureUnit::Lights) and, when clustered, the cluster lists.
    void bind(QOpenGLFunctions_3_3_Core* gl, bool clustered) const;
    // The bound program's light uniforms: scene ambient, distance scale, light count, cluster grid.
    void setUniforms(QOpenGLFunctions_3_3_Core* gl, const MeshProgram& p,
                     const lighting::ShadeSettings<double>& shade, bool clustered) const;

  private:
    Rig m_rig;
    bool m_ies = false, m_gobo = false; // RigFeatures::ies, ::gobo of m_rig: its lights' extra texels
    bool m_dirty = true;
    glm::dmat4 m_uploadedView{0.0};
    int m_count = 0;
    bool m_farLights = false;
    GLuint m_buffer = 0, m_texture = 0;
    // The area lights' LTC table (ltcgl.h), made when the first one is uploaded.
    GLuint m_ltc = 0;
    std::vector<float> m_packed;        // what the buffer holds, to upload only what changed
    int m_capacity = 0;                 // texels the buffer holds
    int m_shadowCount = 0;              // casters with a record
    std::vector<float> m_shadowRecords; // kShadowTexels vec4s per caster, for this view
    std::vector<LightBounds> m_bounds;  // per uploaded light, view space
    int m_boundedLights = 0;
    ClusterBuffers m_clusters;
    glm::vec4 m_clusterUniforms{0.0f}; // tile scale x, y, near, slice scale
    glm::ivec3 m_clusterGrid{0};
    long long m_maxTextureBuffer = 0; // GL_MAX_TEXTURE_BUFFER_SIZE, once (clusterGridFor)
    int m_clusterGlobal = 0;
};

} // namespace lr::render
