#include "shadowmaps.h"

#include "gpumodel.h"
#include "textureunits.h"

#include <QElapsedTimer>
#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

namespace lr::render {

bool ShadowMaps::initialize(QOpenGLFunctions_3_3_Core* gl) {
    gl->glGenFramebuffers(1, &m_fbo);
    gl->glGenSamplers(1, &m_compare);
    gl->glGenSamplers(1, &m_raw);
    const GLfloat border[4] = {1.0f, 1.0f, 1.0f, 1.0f}; // outside a map: nothing in the way
    for (GLuint s : {m_compare, m_raw}) {
        const GLint filter = s == m_compare ? GL_LINEAR : GL_NEAREST;
        gl->glSamplerParameteri(s, GL_TEXTURE_MIN_FILTER, filter);
        gl->glSamplerParameteri(s, GL_TEXTURE_MAG_FILTER, filter);
        gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        gl->glSamplerParameteri(s, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        gl->glSamplerParameterfv(s, GL_TEXTURE_BORDER_COLOR, border);
        gl->glSamplerParameteri(s, GL_TEXTURE_COMPARE_MODE,
                                s == m_compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
        gl->glSamplerParameteri(s, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    }
    return true;
}

void ShadowMaps::freeArray(QOpenGLFunctions_3_3_Core* gl) {
    gl->glDeleteTextures(1, &m_texture);
    m_texture = 0;
    m_resolution = m_layers = 0;
    m_bytes = 0;
    m_rendered.clear();
}

void ShadowMaps::release(QOpenGLFunctions_3_3_Core* gl) {
    freeArray(gl);
    gl->glDeleteFramebuffers(1, &m_fbo);
    gl->glDeleteSamplers(1, &m_compare);
    gl->glDeleteSamplers(1, &m_raw);
    m_fbo = m_compare = m_raw = 0;
    m_modelGeneration = -1;
}

bool ShadowMaps::update(QOpenGLFunctions_3_3_Core* gl, const std::vector<ShadowView>& views,
                        const GpuModel& model, int modelGeneration, GLuint depthProgram, int matrixLocation,
                        bool wait, RenderStats* stats, QString* error) {
    stats->shadowMapsRendered = 0;
    stats->shadowLayersRendered = 0;
    stats->shadowMapMs = 0.0;
    stats->shadowCasters = int(views.size());
    if (views.empty() || !model.model()) {
        if (m_texture) freeArray(gl);
        stats->shadowMapBytes = 0;
        return true;
    }
    int layers = 0;
    for (const ShadowView& v : views)
        layers += v.layers();
    const int res = views.front().resolution;
    if (res != m_resolution || layers != m_layers) {
        freeArray(gl);
        while (gl->glGetError() != GL_NO_ERROR) {
        }
        gl->glGenTextures(1, &m_texture);
        gl->glBindTexture(GL_TEXTURE_2D_ARRAY, m_texture);
        gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAX_LEVEL, 0);
        gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl->glTexParameteri(GL_TEXTURE_2D_ARRAY, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl->glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_DEPTH_COMPONENT32F, res, res, layers, 0,
                         GL_DEPTH_COMPONENT, GL_FLOAT, nullptr);
        gl->glBindTexture(GL_TEXTURE_2D_ARRAY, 0);
        if (const GLenum e = gl->glGetError(); e != GL_NO_ERROR) {
            freeArray(gl);
            *error = QStringLiteral("cannot allocate the shadow maps (%1 layers of %2², GL error 0x%3)")
                         .arg(layers)
                         .arg(res)
                         .arg(e, 0, 16);
            return false;
        }
        m_resolution = res;
        m_layers = layers;
        m_bytes = qint64(res) * res * 4 * layers;
    }
    stats->shadowMapBytes = m_bytes;
    const bool newModel = modelGeneration != m_modelGeneration;
    m_rendered.resize(views.size());
    const Model* m = model.model();
    const glm::dmat4 toOrigin = glm::translate(glm::dmat4(1.0), m->origin);
    bool bound = false;
    QElapsedTimer timer;
    for (size_t i = 0; i < views.size(); ++i) {
        const ShadowView& v = views[i];
        if (!newModel && m_rendered[i].resolution > 0 && m_rendered[i].sameMap(v)) continue;
        if (!bound) {
            timer.start();
            gl->glBindFramebuffer(GL_FRAMEBUFFER, m_fbo);
            gl->glDrawBuffer(GL_NONE);
            gl->glReadBuffer(GL_NONE);
            gl->glViewport(0, 0, res, res);
            gl->glEnable(GL_DEPTH_TEST);
            gl->glDepthFunc(GL_LESS);
            gl->glDepthMask(GL_TRUE);
            gl->glDisable(GL_CULL_FACE); // open meshes cast from both sides
            gl->glDisable(GL_BLEND);
            // Slope-scaled depth offset: the receiver-side bias (shadows.glsl) handles the rest.
            gl->glEnable(GL_POLYGON_OFFSET_FILL);
            gl->glPolygonOffset(1.5f, 2.0f);
            gl->glUseProgram(depthProgram);
            bound = true;
        }
        for (int face = 0; face < v.layers(); ++face) {
            gl->glFramebufferTextureLayer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, m_texture, 0, v.layer + face);
            gl->glClear(GL_DEPTH_BUFFER_BIT);
            const glm::mat4 mvp(v.faceViewProj(face) * toOrigin);
            gl->glUniformMatrix4fv(matrixLocation, 1, GL_FALSE, glm::value_ptr(mvp));
            // Opaque and MASK meshes cast (MASK without its cutout); BLEND meshes do not, nor those shadow
            // linking leaves out of this light's shadow.
            for (const GpuDraw& d : model.draws()) {
                if (d.features.alphaBlend) continue;
                if (!v.casters.empty() && !(size_t(d.mesh) < v.casters.size() && v.casters[size_t(d.mesh)]))
                    continue;
                gl->glBindVertexArray(d.vao);
                gl->glDrawElements(GL_TRIANGLES, d.indexCount, GL_UNSIGNED_INT, nullptr);
            }
            ++stats->shadowLayersRendered;
        }
        m_rendered[i] = v;
        ++stats->shadowMapsRendered;
    }
    m_modelGeneration = modelGeneration;
    if (bound) {
        if (wait) gl->glFinish(); // then the time is the maps' own
        stats->shadowMapMs = double(timer.nsecsElapsed()) * 1e-6;
        gl->glBindVertexArray(0);
        gl->glDisable(GL_POLYGON_OFFSET_FILL);
        gl->glUseProgram(0);
        gl->glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
    return true;
}

void ShadowMaps::bind(QOpenGLFunctions_3_3_Core* gl) const {
    if (!m_texture) return;
    gl->glActiveTexture(textureUnit(TextureUnit::ShadowMaps));
    gl->glBindTexture(GL_TEXTURE_2D_ARRAY, m_texture);
    gl->glBindSampler(GLuint(TextureUnit::ShadowMaps), m_compare);
    gl->glActiveTexture(textureUnit(TextureUnit::ShadowDepths));
    gl->glBindTexture(GL_TEXTURE_2D_ARRAY, m_texture);
    gl->glBindSampler(GLuint(TextureUnit::ShadowDepths), m_raw);
    gl->glActiveTexture(GL_TEXTURE0);
}

void ShadowMaps::unbind(QOpenGLFunctions_3_3_Core* gl) const {
    if (!m_texture) return;
    gl->glBindSampler(GLuint(TextureUnit::ShadowMaps), 0);
    gl->glBindSampler(GLuint(TextureUnit::ShadowDepths), 0);
}

} // namespace lr::render
