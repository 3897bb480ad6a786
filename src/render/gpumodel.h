// A Model uploaded to GL: one vertex array per mesh, textures (sRGB for base colour and emissive, linear
// for normal maps and the metal-rough and occlusion maps) with mipmap chains built on worker threads
// (mipchain.h). Needs the current context of the owning Renderer.
#pragma once

#include "lod.h"
#include "mipchain.h"
#include "model/model.h"
#include "shadergen.h"

#include <QFuture>
#include <QOpenGLFunctions_3_3_Core>
#include <map>
#include <memory>
#include <vector>

namespace lr::render {

struct GpuDraw {
    GLuint vao = 0, vbo = 0, ibo = 0;
    GLsizei indexCount = 0;
    int mesh = -1;
    int material = -1; // valid index into Model::materials, or -1 for the default material
    MaterialFeatures features;
    GLuint baseColorTexture = 0, normalTexture = 0, emissiveTexture = 0;
    GLuint metalRoughTexture = 0, occlusionTexture = 0; // linear (physically based shading)
    GLuint lodVao = 0, lodIbo = 0; // the interaction proxy (lod.h) over the same vertices; 0: none
    GLsizei lodIndexCount = 0;
    glm::vec3 center{0.0f}; // of the mesh's bounds, relative to Model::origin: the blend pass sorts by it
};

class GpuModel;

// A material of the attribute G-buffer (FrameContext::attributeMaterials): a draw that has it and the
// model the draw belongs to.
struct AttributeMaterial {
    const GpuDraw* draw = nullptr;
    const GpuModel* source = nullptr;
};
// At most this many, so that a frame runs as many lighting passes (one per material, each over the
// model's screen rectangle, stencil-tested); more fall back to the Surface G-buffer.
constexpr int kMaxAttributeMaterials = 8;

class GpuModel {
  public:
    // Uploads every non-empty mesh. On failure (e.g. out of GPU memory) releases what it made.
    bool upload(QOpenGLFunctions_3_3_Core* gl, std::shared_ptr<const Model> model, QString* error);
    void release(QOpenGLFunctions_3_3_Core* gl);

    const Model* model() const { return m_model.get(); }
    const std::vector<GpuDraw>& draws() const { return m_draws; }
    // Appends one entry per distinct material (index and features) of the opaque (not BLEND) draws not
    // already in `out`, for the attribute G-buffer (FrameContext::attributeMaterials). False, `out` left
    // as it was, when a draw has vertex colours or alpha MASK (the G-pass would have to read textures) or
    // the list would exceed kMaxAttributeMaterials.
    bool appendMaterials(std::vector<AttributeMaterial>& out) const;
    // The index + 1 of `d`'s material in `materials` (its stencil value), 0 when it is not there.
    int materialSlot(const std::vector<AttributeMaterial>& materials, const GpuDraw& d) const;

    // Interaction proxies of a dense model (lod.h), built on a worker thread after upload(): uploads them
    // once they are ready (with wait, blocks until then). True when the draws have them now.
    bool updateProxies(QOpenGLFunctions_3_3_Core* gl, bool wait = false);

  private:
    // How an image is stored for the role a draw samples it in: colours as sRGB8_ALPHA8, normals as
    // RGBA8; the occlusion (read in R) as R8 and the metallic-roughness (G, B) as RG8, swizzled back to
    // G and B: the shaders read the same texel values from a quarter and a half of the memory (the first
    // frame's upload is mostly fresh memory faulted in, docs/performance.md).
    enum class TextureStore { Srgb, Rgba, Occlusion, MetalRough };
    using TextureKey = std::pair<int, TextureStore>; // (texture index, store)
    void uploadTextures(QOpenGLFunctions_3_3_Core* gl);
    static GLuint texture(QOpenGLFunctions_3_3_Core* gl, const MipChain& chain, TextureStore store);
    static void setAttributes(QOpenGLFunctions_3_3_Core* gl); // of the bound vertex array
    GLuint textureName(int index, TextureStore store) const;

    std::shared_ptr<const Model> m_model;
    std::vector<GpuDraw> m_draws;
    std::map<TextureKey, GLuint> m_textures; // -> GL name
    QFuture<std::vector<MeshLod>> m_proxies;
    bool m_proxiesUploaded = false;
};

} // namespace lr::render
