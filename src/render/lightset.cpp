#include "lightset.h"

#include "lightpack.h"
#include "ltcgl.h"
#include "programcache.h"
#include "shadergen.h"
#include "shadowplan.h"
#include "shapinglayers.h"
#include "textureunits.h"

#include "core/iesshade.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <limits>

namespace lr::render {

void LightSet::initialize(QOpenGLFunctions_3_3_Core* gl) {
    gl->glGenBuffers(1, &m_buffer);
    gl->glGenTextures(1, &m_texture);
    m_capacity = 0;
    m_dirty = true;
}

void LightSet::release(QOpenGLFunctions_3_3_Core* gl) {
    m_clusters.release(gl);
    gl->glDeleteBuffers(1, &m_buffer);
    gl->glDeleteTextures(1, &m_texture);
    if (m_ltc) gl->glDeleteTextures(1, &m_ltc);
    m_buffer = m_texture = m_ltc = 0;
    m_capacity = 0;
    m_packed.clear();
    m_dirty = true;
}

void LightSet::setRig(const Rig& rig) {
    m_rig = rig;
    const RigFeatures f = rigFeatures(rig);
    m_ies = f.ies, m_gobo = f.gobo;
    m_dirty = true;
}

void LightSet::update(QOpenGLFunctions_3_3_Core* gl, const SceneFrame& frame, const glm::dmat4& view,
                      RenderStats* stats, const std::vector<ShadowView>* shadows, const SceneFrame* reach,
                      const LinkResolution* links, const ShapingLayers* shaping) {
    if (!m_dirty && view == m_uploadedView) return;
    const bool linking = links && links->active;
    const LightTexelLayout layout = lightTexelLayout(linking, m_ies, m_gobo);
    const auto layerOf = [&](std::vector<int> ShapingLayers::*layers, size_t i) {
        return shaping && i < (shaping->*layers).size() ? (shaping->*layers)[i] : -1;
    };
    static const std::vector<ShadowView> none;
    const std::vector<ShadowView>& casters = shadows ? *shadows : none;
    const SceneFrame sphere = reach ? *reach : frame;
    std::vector<float> data;
    data.reserve(m_rig.lights.size() * 4 * size_t(layout.texels));
    std::vector<int> uploadedAs(m_rig.lights.size(), -1);
    int count = 0;
    const double scale = prepareSettings(m_rig, frame).distanceScale;
    m_bounds.clear();
    m_boundedLights = 0;
    m_farLights = false;
    // The farthest a visible surface can be from the eye: the model's bounding sphere in view space.
    const double surfaceReach =
        glm::length(glm::dvec3(view * glm::dvec4(sphere.center, 1.0))) + sphere.radius;
    for (size_t i = 0; i < m_rig.lights.size(); ++i) {
        const Light& l = m_rig.lights[i];
        if (!lightReaches(m_rig, frame, l, sphere.center, sphere.radius)) continue;
        lighting::ShadeLight<double> prepared = prepareLight(m_rig, frame, view, l);
        const int iesLayer = m_ies ? layerOf(&ShapingLayers::iesLayer, i) : -1;
        if (iesLayer >= 0) applyIesProfile(prepared, l, shaping->profiles[size_t(iesLayer)].get(), view);
        if (l.usesPosition() && !(glm::length(prepared.position) + surfaceReach < kFarLightDistance))
            m_farLights = true;
        m_bounds.push_back(lightBounds(prepared, scale));
        m_boundedLights += m_bounds.back().bounded ? 1 : 0;
        if (l.isArea() && !m_ltc) m_ltc = createLtcTexture(gl);
        const lighting::ShadeLight<float> packed = castLight<float>(prepared);
        LightTexels t = packLight(packed);
        for (size_t k = 0; k < casters.size(); ++k)
            if (casters[k].rigIndex == int(i))
                t[1 * 4 + 3] += float(kShadowSlotScale * (k + 1)); // type + slot
        data.insert(data.end(), t.begin(), t.end());
        if (linking) { // rig index i: the resolution is per rig light, disabled ones included
            const auto link = packLinkTexel(links->litMask[i]);
            data.insert(data.end(), link.begin(), link.end());
        }
        if (m_ies) {
            const auto ies = packIesTexels(packed, iesLayer, iesLayer >= 0 ? shaping->iesNorm[i] : 1.0f);
            data.insert(data.end(), ies.begin(), ies.end());
        }
        if (m_gobo) {
            const int layer = layerOf(&ShapingLayers::goboLayer, i);
            const GoboImage* g = layer >= 0 ? shaping->gobos[size_t(layer)].get() : nullptr;
            const auto gobo =
                packGoboTexels(packed, g ? layer : -1, g ? g->width : 0, g ? g->height : 0,
                               shaping ? shaping->goboWidth : 0, shaping ? shaping->goboHeight : 0);
            data.insert(data.end(), gobo.begin(), gobo.end());
        }
        uploadedAs[i] = count;
        ++count;
    }
    // The casters' records, in slot order: uniforms (shaders/shadows.glsl loadShadow), set per program.
    m_shadowRecords.clear();
    for (const ShadowView& v : casters) {
        const auto t = packShadow(v, view, uploadedAs[size_t(v.rigIndex)]);
        m_shadowRecords.insert(m_shadowRecords.end(), t.begin(), t.end());
    }
    m_shadowCount = int(casters.size());
    const int texels = int(data.size() / 4);
    gl->glBindBuffer(GL_TEXTURE_BUFFER, m_buffer);
    if (texels > m_capacity || m_capacity == 0) {
        m_capacity = std::max({texels, 2 * m_capacity, 16 * kLightTexels});
        gl->glBufferData(GL_TEXTURE_BUFFER, GLsizeiptr(m_capacity) * 16, nullptr, GL_DYNAMIC_DRAW);
        gl->glBindTexture(GL_TEXTURE_BUFFER, m_texture);
        gl->glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, m_buffer);
        m_packed.clear(); // the new store holds nothing yet
    }
    // Only the texels that changed go up: dragging one light of many sends that light's 128 bytes (a view
    // change moves every view-space light, and then everything differs).
    const auto same = [](float a, float b) {
        return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
    };
    size_t first = 0, last = data.size();
    if (m_packed.size() == data.size()) {
        first = size_t(std::mismatch(data.begin(), data.end(), m_packed.begin(), same).first - data.begin());
        while (last > first && same(data[last - 1], m_packed[last - 1]))
            --last;
    }
    if (last > first)
        gl->glBufferSubData(GL_TEXTURE_BUFFER, GLintptr(first * sizeof(float)),
                            GLsizeiptr((last - first) * sizeof(float)), data.data() + first);
    stats->lightBytesUploaded = qint64((last - first) * sizeof(float));
    m_packed = std::move(data);
    gl->glBindBuffer(GL_TEXTURE_BUFFER, 0);
    m_count = count;
    stats->lightsUploaded = count;
    m_uploadedView = view;
    m_dirty = false;
}

bool LightSet::cluster(QOpenGLFunctions_3_3_Core* gl, const glm::dmat4& projection, QSize target,
                       int clusteredShading, RenderStats* stats) {
    stats->clustered = false;
    stats->clusterLightRefs = 0;
    const bool wanted =
        clusteredShading > 0 || (clusteredShading < 0 && m_boundedLights > kClusterMinBoundedLights);
    if (!wanted) return false;
    ClusterView cv;
    cv.projection = projection;
    cv.width = std::max(1, target.width());
    cv.height = std::max(1, target.height());
    // near and far back from the projection: P22 = -(f+n)/(f-n), P32 = -2fn/(f-n) (f infinite: P22 = -1)
    const double p22 = projection[2][2], p32 = projection[3][2];
    cv.znear = p32 / (p22 - 1.0);
    cv.zfar = p22 > -1.0 ? p32 / (p22 + 1.0) : std::numeric_limits<double>::infinity();
    if (!(cv.znear > 0.0) || !std::isfinite(cv.znear)) return false;
    if (m_maxTextureBuffer == 0) {
        GLint most = 0;
        gl->glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &most);
        m_maxTextureBuffer = std::max<GLint>(most, 65536); // GL 3.3's minimum
    }
    const ClusterData data = binLights(m_bounds, cv, clusterGridFor(cv.width, cv.height, m_maxTextureBuffer));
    m_clusters.upload(gl, data);
    stats->clustered = true;
    stats->clusterLightRefs = qint64(data.indices.size());
    m_clusterUniforms = {float(data.lookup.tileScale.x), float(data.lookup.tileScale.y),
                         float(data.lookup.znear), float(data.lookup.sliceScale)};
    m_clusterGlobal = data.globalCount;
    m_clusterGrid = {data.grid.tilesX, data.grid.tilesY, data.grid.slices};
    return true;
}

void LightSet::bind(QOpenGLFunctions_3_3_Core* gl, bool clustered) const {
    gl->glActiveTexture(textureUnit(TextureUnit::Lights));
    gl->glBindTexture(GL_TEXTURE_BUFFER, m_texture);
    if (m_ltc) {
        gl->glActiveTexture(textureUnit(TextureUnit::Ltc));
        gl->glBindTexture(GL_TEXTURE_2D_ARRAY, m_ltc);
    }
    if (clustered) m_clusters.bind(gl);
    gl->glActiveTexture(GL_TEXTURE0);
}

void LightSet::setUniforms(QOpenGLFunctions_3_3_Core* gl, const MeshProgram& p,
                           const lighting::ShadeSettings<double>& shade, bool clustered) const {
    gl->glUniform3fv(p.ambient, 1, glm::value_ptr(glm::vec3(shade.ambient)));
    gl->glUniform1f(p.distanceScale, float(shade.distanceScale));
    gl->glUniform1i(p.lightCount, m_count);
    if (p.shadowCount >= 0) gl->glUniform1i(p.shadowCount, m_shadowCount);
    if (p.shadowRecords >= 0 && m_shadowCount > 0)
        gl->glUniform4fv(p.shadowRecords, GLsizei(m_shadowRecords.size() / 4), m_shadowRecords.data());
    if (!clustered) return;
    const GLuint id = p.program->programId();
    gl->glUniform1i(gl->glGetUniformLocation(id, "uGlobalLightCount"), m_clusterGlobal);
    gl->glUniform3i(gl->glGetUniformLocation(id, "uClusterGrid"), m_clusterGrid.x, m_clusterGrid.y,
                    m_clusterGrid.z);
    gl->glUniform2f(gl->glGetUniformLocation(id, "uClusterTileScale"), m_clusterUniforms.x,
                    m_clusterUniforms.y);
    gl->glUniform1f(gl->glGetUniformLocation(id, "uClusterNear"), m_clusterUniforms.z);
    gl->glUniform1f(gl->glGetUniformLocation(id, "uClusterSliceScale"), m_clusterUniforms.w);
}

} // namespace lr::render
