#include "clustergl.h"

#include "textureunits.h"

namespace lr::render {

namespace {

void fill(QOpenGLFunctions_3_3_Core* gl, GLuint buffer, GLuint texture, GLenum format,
          const std::vector<std::uint32_t>& v) {
    static const std::uint32_t zero[2] = {0, 0}; // a texture buffer needs storage even when empty
    const GLsizeiptr bytes = GLsizeiptr(v.size() * sizeof(std::uint32_t));
    gl->glBindBuffer(GL_TEXTURE_BUFFER, buffer);
    gl->glBufferData(GL_TEXTURE_BUFFER, bytes ? bytes : GLsizeiptr(sizeof zero), nullptr,
                     GL_STREAM_DRAW); // orphan
    gl->glBufferSubData(GL_TEXTURE_BUFFER, 0, bytes ? bytes : GLsizeiptr(sizeof zero),
                        bytes ? v.data() : zero);
    gl->glBindTexture(GL_TEXTURE_BUFFER, texture);
    gl->glTexBuffer(GL_TEXTURE_BUFFER, format, buffer);
}

} // namespace

void ClusterBuffers::upload(QOpenGLFunctions_3_3_Core* gl, const ClusterData& data) {
    if (!m_rangeBuffer) {
        gl->glGenBuffers(1, &m_rangeBuffer);
        gl->glGenBuffers(1, &m_indexBuffer);
        gl->glGenTextures(1, &m_rangeTexture);
        gl->glGenTextures(1, &m_indexTexture);
    }
    gl->glActiveTexture(textureUnit(TextureUnit::ClusterRanges));
    fill(gl, m_rangeBuffer, m_rangeTexture, GL_RG32UI, data.ranges);
    gl->glActiveTexture(textureUnit(TextureUnit::ClusterIndices));
    fill(gl, m_indexBuffer, m_indexTexture, GL_R32UI, data.indices);
    gl->glBindBuffer(GL_TEXTURE_BUFFER, 0);
    gl->glActiveTexture(GL_TEXTURE0);
}

void ClusterBuffers::bind(QOpenGLFunctions_3_3_Core* gl) const {
    gl->glActiveTexture(textureUnit(TextureUnit::ClusterRanges));
    gl->glBindTexture(GL_TEXTURE_BUFFER, m_rangeTexture);
    gl->glActiveTexture(textureUnit(TextureUnit::ClusterIndices));
    gl->glBindTexture(GL_TEXTURE_BUFFER, m_indexTexture);
    gl->glActiveTexture(GL_TEXTURE0);
}

void ClusterBuffers::release(QOpenGLFunctions_3_3_Core* gl) {
    if (!m_rangeBuffer) return;
    gl->glDeleteBuffers(1, &m_rangeBuffer);
    gl->glDeleteBuffers(1, &m_indexBuffer);
    gl->glDeleteTextures(1, &m_rangeTexture);
    gl->glDeleteTextures(1, &m_indexTexture);
    m_rangeBuffer = m_rangeTexture = m_indexBuffer = m_indexTexture = 0;
}

} // namespace lr::render
