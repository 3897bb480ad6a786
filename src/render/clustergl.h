// GL side of clustered shading: the per-cluster (offset, count) ranges (RG32UI) and the light-index list
// (R32UI) as texture buffers, orphaned and refilled each time the binning changes.
#pragma once

#include "cluster.h"

#include <QOpenGLFunctions_3_3_Core>

namespace lr::render {

class ClusterBuffers {
  public:
    void upload(QOpenGLFunctions_3_3_Core* gl, const ClusterData& data);
    void bind(QOpenGLFunctions_3_3_Core* gl) const; // to TextureUnit::ClusterRanges / ClusterIndices
    void release(QOpenGLFunctions_3_3_Core* gl);
    bool empty() const { return m_rangeBuffer == 0; }

  private:
    GLuint m_rangeBuffer = 0, m_rangeTexture = 0, m_indexBuffer = 0, m_indexTexture = 0;
};

} // namespace lr::render
