// The raster's IES profiles and gobo images on the GPU (issue 39): shapinglayers.h's layers as two
// GL_TEXTURE_2D_ARRAYs, bound to TextureUnit::Ies and ::Gobos for shaders/shaping.glsl.
#pragma once

#include "shapinglayers.h"

#include <QOpenGLFunctions_3_3_Core>

namespace lr::render {

// The two arrays on the GPU, remade when the set of profiles or images changes.
class LightShapingGl {
  public:
    void release(QOpenGLFunctions_3_3_Core* gl);
    // Uploads what `layers` names that is not there yet (the same profiles and images: nothing).
    void update(QOpenGLFunctions_3_3_Core* gl, const ShapingLayers& layers);
    // Binds the arrays (TextureUnit::Ies, ::Gobos) that exist.
    void bind(QOpenGLFunctions_3_3_Core* gl) const;
    std::size_t bytes() const { return m_bytes; } // GPU memory the arrays hold

  private:
    GLuint m_ies = 0, m_gobos = 0;
    std::vector<std::shared_ptr<const IesProfile>> m_profiles;
    std::vector<std::shared_ptr<const GoboImage>> m_images;
    std::size_t m_bytes = 0;
};

} // namespace lr::render
