#include "gpumodel.h"

#include <QImage>
#include <QtConcurrent/QtConcurrentMap>
#include <QtConcurrent/QtConcurrentRun>
#include <algorithm>
#include <cstddef>
#include <glm/common.hpp>

namespace lr::render {

GLuint GpuModel::texture(QOpenGLFunctions_3_3_Core* gl, const MipChain& chain, TextureStore store) {
    if (chain.levels.empty()) return 0;
    // The chain is RGBA8888; GL keeps the components the internal format has (BGRA order puts B, the
    // metallic, in R and G, the roughness, in G).
    GLint internal = GL_RGBA8;
    GLenum format = GL_RGBA;
    GLint swizzle[4] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
    switch (store) {
    case TextureStore::Srgb:
        internal = GL_SRGB8_ALPHA8;
        break;
    case TextureStore::Rgba:
        break;
    case TextureStore::Occlusion:
        internal = GL_R8;
        break;
    case TextureStore::MetalRough:
        internal = GL_RG8;
        format = GL_BGRA;
        swizzle[0] = GL_ZERO, swizzle[1] = GL_GREEN, swizzle[2] = GL_RED, swizzle[3] = GL_ONE;
        break;
    }
    GLuint name = 0;
    gl->glGenTextures(1, &name);
    gl->glBindTexture(GL_TEXTURE_2D, name);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, GLint(chain.levels.size()) - 1);
    gl->glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    // model.h: UV (0, 0) is the top-left texel = the first QImage row, so the rows upload as they are.
    for (size_t level = 0; level < chain.levels.size(); ++level) {
        const QImage& image = chain.levels[level];
        gl->glPixelStorei(GL_UNPACK_ROW_LENGTH, int(image.bytesPerLine() / 4));
        gl->glTexImage2D(GL_TEXTURE_2D, GLint(level), internal, image.width(), image.height(), 0, format,
                         GL_UNSIGNED_BYTE, image.constBits());
    }
    gl->glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    gl->glTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl->glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    return name;
}

void GpuModel::uploadTextures(QOpenGLFunctions_3_3_Core* gl) {
    // Every (texture, store) pair some draw samples; the mipmap chains (one per image and colour space,
    // whatever the stores) are built on worker threads, each uploaded as soon as it is ready while the
    // next ones are still being built.
    std::vector<TextureKey> keys;
    for (const GpuDraw& d : m_draws) {
        if (d.material < 0) continue;
        const Material& m = m_model->materials[size_t(d.material)];
        if (d.features.baseColorTexture) keys.emplace_back(m.baseColorTexture, TextureStore::Srgb);
        if (d.features.normalMap) keys.emplace_back(m.normalTexture, TextureStore::Rgba);
        if (d.features.emissiveTexture) keys.emplace_back(m.emissiveTexture, TextureStore::Srgb);
        if (d.features.metalRoughTexture)
            keys.emplace_back(m.metallicRoughnessTexture, TextureStore::MetalRough);
        if (d.features.occlusionTexture) keys.emplace_back(m.occlusionTexture, TextureStore::Occlusion);
    }
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    using ChainKey = std::pair<int, bool>; // (texture index, sRGB)
    const auto chainOf = [](const TextureKey& k) {
        return ChainKey{k.first, k.second == TextureStore::Srgb};
    };
    QList<ChainKey> chainKeys;
    for (const TextureKey& k : keys)
        if (!chainKeys.contains(chainOf(k))) chainKeys.push_back(chainOf(k));
    const Model* model = m_model.get();
    const QFuture<MipChain> chains = QtConcurrent::mapped(chainKeys, [model](const ChainKey& k) {
        return buildMipChain(model->textures[size_t(k.first)].image, k.second);
    });
    for (const TextureKey& k : keys) // in chainKeys' order: resultAt waits for that chain alone
        m_textures.emplace(k, texture(gl, chains.resultAt(chainKeys.indexOf(chainOf(k))), k.second));
    for (GpuDraw& d : m_draws) {
        if (d.material < 0) continue;
        const Material& m = m_model->materials[size_t(d.material)];
        if (d.features.baseColorTexture)
            d.baseColorTexture = textureName(m.baseColorTexture, TextureStore::Srgb);
        if (d.features.normalMap) d.normalTexture = textureName(m.normalTexture, TextureStore::Rgba);
        if (d.features.emissiveTexture)
            d.emissiveTexture = textureName(m.emissiveTexture, TextureStore::Srgb);
        if (d.features.metalRoughTexture)
            d.metalRoughTexture = textureName(m.metallicRoughnessTexture, TextureStore::MetalRough);
        if (d.features.occlusionTexture)
            d.occlusionTexture = textureName(m.occlusionTexture, TextureStore::Occlusion);
    }
}

int GpuModel::materialSlot(const std::vector<AttributeMaterial>& materials, const GpuDraw& d) const {
    for (size_t i = 0; i < materials.size(); ++i)
        if (materials[i].source == this && materials[i].draw->material == d.material &&
            materials[i].draw->features == d.features)
            return int(i) + 1;
    return 0;
}

bool GpuModel::appendMaterials(std::vector<AttributeMaterial>& out) const {
    const size_t before = out.size();
    for (const GpuDraw& d : m_draws) {
        if (d.features.alphaBlend || materialSlot(out, d)) continue;
        if (d.features.vertexColors || d.features.alphaMask || out.size() >= size_t(kMaxAttributeMaterials)) {
            out.resize(before);
            return false;
        }
        out.push_back({&d, this});
    }
    return true;
}

GLuint GpuModel::textureName(int index, TextureStore store) const {
    const auto it = m_textures.find({index, store});
    return it == m_textures.end() ? 0 : it->second;
}

bool GpuModel::upload(QOpenGLFunctions_3_3_Core* gl, std::shared_ptr<const Model> model, QString* error) {
    release(gl);
    m_model = std::move(model);
    if (!m_model) return true;
    while (gl->glGetError() != GL_NO_ERROR) {
    }
    for (size_t i = 0; i < m_model->meshes.size(); ++i) {
        const Mesh& mesh = m_model->meshes[i];
        if (mesh.vertices.empty() || mesh.indices.size() < 3) continue;
        GpuDraw d;
        d.mesh = int(i);
        d.material =
            mesh.material >= 0 && size_t(mesh.material) < m_model->materials.size() ? mesh.material : -1;
        d.features = materialFeatures(*m_model, mesh);
        d.indexCount = GLsizei(mesh.indices.size() / 3 * 3);
        glm::vec3 lo(mesh.vertices.front().position), hi(lo);
        for (const Vertex& v : mesh.vertices)
            lo = glm::min(lo, v.position), hi = glm::max(hi, v.position);
        d.center = 0.5f * (lo + hi);
        gl->glGenVertexArrays(1, &d.vao);
        gl->glBindVertexArray(d.vao);
        gl->glGenBuffers(1, &d.vbo);
        gl->glBindBuffer(GL_ARRAY_BUFFER, d.vbo);
        gl->glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(mesh.vertices.size() * sizeof(Vertex)),
                         mesh.vertices.data(), GL_STATIC_DRAW);
        gl->glGenBuffers(1, &d.ibo);
        gl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, d.ibo);
        gl->glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(size_t(d.indexCount) * sizeof(std::uint32_t)),
                         mesh.indices.data(), GL_STATIC_DRAW);
        setAttributes(gl);
        gl->glBindVertexArray(0);
        m_draws.push_back(d);
        if (const GLenum e = gl->glGetError(); e != GL_NO_ERROR) {
            if (error)
                *error = QStringLiteral("uploading mesh %1 of %2 failed (GL error 0x%3)")
                             .arg(i)
                             .arg(m_model->path)
                             .arg(e, 0, 16);
            release(gl);
            return false;
        }
    }
    uploadTextures(gl);
    if (const GLenum e = gl->glGetError(); e != GL_NO_ERROR) {
        if (error)
            *error = QStringLiteral("uploading the textures of %1 failed (GL error 0x%2)")
                         .arg(m_model->path)
                         .arg(e, 0, 16);
        release(gl);
        return false;
    }
    if (std::int64_t(m_model->triangleCount()) >= kLodMinTriangles)
        m_proxies = QtConcurrent::run([model = m_model] { return buildInteractionLods(*model); });
    return true;
}

void GpuModel::setAttributes(QOpenGLFunctions_3_3_Core* gl) {
    const auto attrib = [&](GLuint loc, GLint n, std::size_t offset) {
        gl->glEnableVertexAttribArray(loc);
        gl->glVertexAttribPointer(loc, n, GL_FLOAT, GL_FALSE, GLsizei(sizeof(Vertex)),
                                  reinterpret_cast<const void*>(offset));
    };
    attrib(0, 3, offsetof(Vertex, position));
    attrib(1, 3, offsetof(Vertex, normal));
    attrib(2, 2, offsetof(Vertex, uv));
    attrib(3, 4, offsetof(Vertex, tangent));
    attrib(4, 4, offsetof(Vertex, color));
}

bool GpuModel::updateProxies(QOpenGLFunctions_3_3_Core* gl, bool wait) {
    if (m_proxiesUploaded) return true;
    if (!m_proxies.isValid() || (!wait && !m_proxies.isFinished())) return false;
    const std::vector<MeshLod> lods = m_proxies.result(); // waits
    m_proxies = {};
    for (const MeshLod& lod : lods) {
        auto d = std::find_if(m_draws.begin(), m_draws.end(),
                              [&](const GpuDraw& x) { return x.mesh == lod.mesh; });
        if (d == m_draws.end()) continue;
        gl->glGenVertexArrays(1, &d->lodVao);
        gl->glBindVertexArray(d->lodVao);
        gl->glBindBuffer(GL_ARRAY_BUFFER, d->vbo);
        gl->glGenBuffers(1, &d->lodIbo);
        gl->glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, d->lodIbo);
        gl->glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(lod.indices.size() * sizeof(std::uint32_t)),
                         lod.indices.data(), GL_STATIC_DRAW);
        setAttributes(gl);
        gl->glBindVertexArray(0);
        d->lodIndexCount = GLsizei(lod.indices.size());
    }
    m_proxiesUploaded = true;
    return true;
}

void GpuModel::release(QOpenGLFunctions_3_3_Core* gl) {
    for (GpuDraw& d : m_draws) {
        gl->glDeleteVertexArrays(1, &d.vao);
        gl->glDeleteBuffers(1, &d.vbo);
        gl->glDeleteBuffers(1, &d.ibo);
        gl->glDeleteVertexArrays(1, &d.lodVao);
        gl->glDeleteBuffers(1, &d.lodIbo);
    }
    m_draws.clear();
    m_proxies = {}; // a build still running finishes on its own copy of the model
    m_proxiesUploaded = false;
    for (auto& [key, name] : m_textures)
        gl->glDeleteTextures(1, &name);
    m_textures.clear();
    m_model.reset();
}

} // namespace lr::render
