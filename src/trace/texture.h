// Texture lookups of the path tracer: every texture the raster reads (base colour and emissive as sRGB,
// normal, metal-rough and occlusion as linear; shaders/surface.glsl), through the role's
// KHR_texture_transform, bilinear (nearest where the glTF sampler magnifies with NEAREST) with the sampler's
// wrap modes on the full-resolution image (no mip levels: the pixel's many samples average what a mip level
// would). The 8-bit texels stay as the model holds them
// (a lookup table decodes sRGB), so a traced scene costs no copy of its textures.
#pragma once

#include "model/model.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace lr::trace {

// uv' = offset + R(rotation) · (scale ⊙ uv), as the raster's textureTransformMatrix.
glm::vec2 transformUv(const TextureTransform& t, const glm::vec2& uv);

class TextureSampler {
  public:
    TextureSampler() = default;
    // `image` must outlive the sampler (the model's texture); converted to RGBA8888 when it is not.
    TextureSampler(const QImage& image, bool srgb, const TextureSampling& sampling = {});
    bool isNull() const { return m_width <= 0 || m_height <= 0; }
    // Linear RGBA at uv (0, 0 = the top-left texel's corner, as Vertex::uv).
    glm::vec4 sample(const glm::vec2& uv) const;

  private:
    glm::vec4 texel(int x, int y) const;
    // The sampler's wrap of a texture coordinate along one axis, into [0, 1] (repeat), [0, 2) (mirrored
    // repeat: a period of two images) or [0, 1] (clamp), then of a texel index into the image.
    static float reduce(float t, TextureWrap wrap);
    static int wrapIndex(int i, int n, TextureWrap wrap);
    QImage m_converted; // only when the model's image was not RGBA8888
    const uchar* m_bits = nullptr;
    qsizetype m_stride = 0;
    int m_width = 0, m_height = 0;
    bool m_srgb = false;
    TextureSampling m_sampling;
};

} // namespace lr::trace
